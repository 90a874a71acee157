// The reference rasterizer; its rules and conventions are in rasterizer.hpp.
#include "reference/render/rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

constexpr int max_side = 16384;  // with 16 subpixel bits, snapped coordinates stay below 2^31

struct ClipVertex {
  std::array<double, 4> position;
  std::vector<double> attributes;
};

// A vertex after the viewport transform: window position (unsnapped), snapped x, y in units of
// 2^-(subpixel_bits + 1) pixels (so that pixel centres are integers too), 1/w and attributes.
struct WindowVertex {
  double x, y, z, inverse_w;
  std::int64_t snapped_x, snapped_y;
  const std::vector<double>* attributes;
};

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  ClipVertex out{a.position, a.attributes};
  for (int k = 0; k < 4; ++k) out.position[k] = a.position[k] + t * (b.position[k] - a.position[k]);
  for (std::size_t k = 0; k < out.attributes.size(); ++k) out.attributes[k] += t * (b.attributes[k] - a.attributes[k]);
  return out;
}

// Sutherland–Hodgman against the plane w + sign·position[axis] >= 0 (inclusive, as GL's volume).
std::vector<ClipVertex> clip_against(const std::vector<ClipVertex>& polygon, int axis, double sign) {
  std::vector<ClipVertex> out;
  const auto distance = [&](const ClipVertex& v) { return v.position[3] + sign * v.position[axis]; };
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const ClipVertex& a = polygon[k];
    const ClipVertex& b = polygon[(k + 1) % polygon.size()];
    const double da = distance(a), db = distance(b);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(lerp(a, b, da / (da - db)));
  }
  return out;
}

std::vector<ClipVertex> clip_to_view_volume(std::vector<ClipVertex> polygon) {
  for (int axis = 0; axis < 3 && !polygon.empty(); ++axis) {
    polygon = clip_against(polygon, axis, 1.0);
    if (!polygon.empty()) polygon = clip_against(polygon, axis, -1.0);
  }
  return polygon;
}

std::int64_t snap(double window_coordinate, int subpixel_bits) {
  return 2 * static_cast<std::int64_t>(std::nearbyint(std::ldexp(window_coordinate, subpixel_bits)));
}

WindowVertex to_window(const ClipVertex& v, const RasterTarget& target, int subpixel_bits) {
  const double inverse_w = 1.0 / v.position[3];
  WindowVertex out{};
  out.x = (v.position[0] * inverse_w + 1.0) * 0.5 * target.width;
  out.y = (v.position[1] * inverse_w + 1.0) * 0.5 * target.height;
  out.z = (v.position[2] * inverse_w + 1.0) * 0.5;
  out.inverse_w = inverse_w;
  out.snapped_x = snap(out.x, subpixel_bits);
  out.snapped_y = snap(out.y, subpixel_bits);
  out.attributes = &v.attributes;
  return out;
}

// Edge function of a -> b at p, twice the signed area of (a, b, p): > 0 left of a -> b.
template <class T>
T edge(T ax, T ay, T bx, T by, T px, T py) {
  return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

// Whether pixel centres exactly on the edge a -> b of a counter-clockwise triangle belong to it.
// Mutant render.heightmap_from_mesh.right_edges_owned (this reference only): right edges
// own their centres instead of left ones.
bool owns_edge(const WindowVertex& a, const WindowVertex& b, TieRule rule) {
  const std::int64_t dx = b.snapped_x - a.snapped_x, dy = b.snapped_y - a.snapped_y;
  if (dy != 0) return mutant_active("render.heightmap_from_mesh.right_edges_owned") ? dy > 0 : dy < 0;  // interior at +x: a left edge
  return rule == TieRule::lower_left ? dx > 0 : dx < 0;
}

class TriangleRasterizer {
 public:
  TriangleRasterizer(const FragmentShader& shade, RasterTarget& target, const RasterSettings& settings)
      : shade_(shade), target_(target), settings_(settings), colour_(std::size_t(target.channels)) {}

  void draw(WindowVertex v0, WindowVertex v1, WindowVertex v2) {
    const std::int64_t snapped_area =
        edge(v0.snapped_x, v0.snapped_y, v1.snapped_x, v1.snapped_y, v2.snapped_x, v2.snapped_y);
    if (snapped_area == 0) return;
    if (snapped_area < 0) std::swap(v1, v2);  // no culling: both windings drawn counter-clockwise
    const double area = edge(v0.x, v0.y, v1.x, v1.y, v2.x, v2.y);
    if (area == 0.0) return;  // no plane to interpolate on (a sliver that snapping widened)
    vertices_ = {v0, v1, v2};
    area_ = area;
    for (int k = 0; k < 3; ++k) owns_[k] = owns_edge(vertices_[k], vertices_[(k + 1) % 3], settings_.tie_rule);
    const double unit = std::ldexp(1.0, settings_.subpixel_bits + 1);  // snapped units per pixel
    const auto [low_x, high_x] = std::minmax({v0.snapped_x, v1.snapped_x, v2.snapped_x});
    const auto [low_y, high_y] = std::minmax({v0.snapped_y, v1.snapped_y, v2.snapped_y});
    const int first_x = std::max(0, int(std::floor(double(low_x) / unit - 0.5)));
    const int last_x = std::min(target_.width - 1, int(std::ceil(double(high_x) / unit - 0.5)));
    const int first_y = std::max(0, int(std::floor(double(low_y) / unit - 0.5)));
    const int last_y = std::min(target_.height - 1, int(std::ceil(double(high_y) / unit - 0.5)));
    for (int y = first_y; y <= last_y; ++y) {
      for (int x = first_x; x <= last_x; ++x) {
        if (covers(x, y)) shade_fragment(x, y);
      }
    }
  }

 private:
  // Exact coverage test of the centre of pixel (x, y) with the tie rule.
  bool covers(int x, int y) const {
    const std::int64_t half = std::int64_t{1} << settings_.subpixel_bits;
    const std::int64_t px = (2 * std::int64_t{x} + 1) * half, py = (2 * std::int64_t{y} + 1) * half;
    for (int k = 0; k < 3; ++k) {
      const WindowVertex& a = vertices_[k];
      const WindowVertex& b = vertices_[(k + 1) % 3];
      const std::int64_t value = edge(a.snapped_x, a.snapped_y, b.snapped_x, b.snapped_y, px, py);
      if (value < 0 || (value == 0 && !owns_[k])) return false;
    }
    return true;
  }

  void shade_fragment(int x, int y) {
    const double px = x + 0.5, py = y + 0.5;
    std::array<double, 3> weight{};  // λ_k: the edge opposite vertex k over the area
    for (int k = 0; k < 3; ++k) {
      const WindowVertex& a = vertices_[(k + 1) % 3];
      const WindowVertex& b = vertices_[(k + 2) % 3];
      weight[k] = edge(a.x, a.y, b.x, b.y, px, py) / area_;
    }
    const double depth =
        std::clamp(weight[0] * vertices_[0].z + weight[1] * vertices_[1].z + weight[2] * vertices_[2].z, 0.0, 1.0);
    const std::size_t pixel = target_.pixel(x, y);
    if (!(depth < target_.depth[pixel])) return;
    interpolate_attributes(weight);
    shade_(attributes_, colour_);
    target_.depth[pixel] = depth;
    std::copy(colour_.begin(), colour_.end(), target_.colour.begin() + std::ptrdiff_t(pixel * colour_.size()));
  }

  void interpolate_attributes(const std::array<double, 3>& weight) {
    const std::size_t count = vertices_[0].attributes->size();
    attributes_.assign(count, 0.0);
    double normaliser = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double q = weight[k] * vertices_[k].inverse_w;
      normaliser += q;
      for (std::size_t c = 0; c < count; ++c) attributes_[c] += q * (*vertices_[k].attributes)[c];
    }
    for (double& value : attributes_) value /= normaliser;
  }

  const FragmentShader& shade_;
  RasterTarget& target_;
  const RasterSettings& settings_;
  std::array<WindowVertex, 3> vertices_{};
  std::array<bool, 3> owns_{};
  double area_ = 0.0;
  std::vector<double> attributes_;
  std::vector<double> colour_;
};

void validate(const RasterInput& input, const RasterTarget& target, const RasterSettings& settings) {
  if (settings.subpixel_bits < 0 || settings.subpixel_bits > 16) {
    throw std::invalid_argument("rasterize: subpixel_bits must lie in [0, 16]");
  }
  if (target.width < 1 || target.height < 1 || target.width > max_side || target.height > max_side) {
    throw std::invalid_argument("rasterize: the target's sides must lie in [1, 16384]");
  }
  if (input.attribute_count < 0 ||
      input.attributes.size() != input.clip_positions.size() * std::size_t(input.attribute_count)) {
    throw std::invalid_argument("rasterize: attributes must hold attribute_count values per vertex");
  }
  for (const auto& triangle : input.triangles) {
    for (std::uint32_t index : triangle) {
      if (index >= input.clip_positions.size()) {
        throw std::invalid_argument("rasterize: vertex index " + std::to_string(index) + " out of range");
      }
    }
  }
}

ClipVertex clip_vertex(const RasterInput& input, std::uint32_t index) {
  const auto first = input.attributes.begin() + std::ptrdiff_t(index) * input.attribute_count;
  return {input.clip_positions[index], std::vector<double>(first, first + input.attribute_count)};
}

}  // namespace

RasterTarget::RasterTarget(int width_, int height_, int channels_, double clear_colour, double clear_depth)
    : width(width_),
      height(height_),
      channels(channels_),
      colour(std::size_t(std::max(width_, 0)) * std::size_t(std::max(height_, 0)) * std::size_t(std::max(channels_, 0)),
             clear_colour),
      depth(std::size_t(std::max(width_, 0)) * std::size_t(std::max(height_, 0)), std::clamp(clear_depth, 0.0, 1.0)) {}

void rasterize(const RasterInput& input, const FragmentShader& shade, RasterTarget& target,
               const RasterSettings& settings) {
  validate(input, target, settings);
  TriangleRasterizer rasterizer(shade, target, settings);
  for (const auto& triangle : input.triangles) {
    const auto polygon = clip_to_view_volume(
        {clip_vertex(input, triangle[0]), clip_vertex(input, triangle[1]), clip_vertex(input, triangle[2])});
    const bool finite_w = std::all_of(polygon.begin(), polygon.end(), [](const ClipVertex& v) { return v.position[3] > 0; });
    if (polygon.size() < 3 || !finite_w) continue;  // w = 0 survives clipping only at x = y = z = 0
    std::vector<WindowVertex> window;
    for (const auto& vertex : polygon) window.push_back(to_window(vertex, target, settings.subpixel_bits));
    for (std::size_t k = 1; k + 1 < window.size(); ++k) rasterizer.draw(window[0], window[k], window[k + 1]);
  }
}

}  // namespace gt::reference
