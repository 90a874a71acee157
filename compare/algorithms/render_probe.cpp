// The render family's probe scenes and their closed-form answers; see render_probe.hpp.
#include "compare/algorithms/render_probe.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace gt {
namespace {

using Point = std::array<double, 2>;

// Distance from p to the segment a-b.
double segment_distance(const Point& p, const Point& a, const Point& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double t = std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

// Distance from p to the closed polygon through `corners`.
template <std::size_t N>
double outline_distance(const Point& p, const std::array<Point, N>& corners) {
  double distance = INFINITY;
  for (std::size_t k = 0; k < N; ++k) distance = std::min(distance, segment_distance(p, corners[k], corners[(k + 1) % N]));
  return distance;
}

// The camera's frame (gluLookAt) and the scale of its image plane (gluPerspective).
struct Frame {
  Vec3 forward, right, up;
  double half_height, half_width;  // tan(fov/2) and tan(fov/2)·aspect at unit distance
};

Frame frame_of(const ProbeCamera& camera) {
  const Vec3 forward = normalised(camera.target - camera.eye);
  const Vec3 right = normalised(cross(forward, camera.up));
  const double half_height = std::tan(0.5 * camera.fov_y_deg * std::numbers::pi / 180.0);
  return {forward, right, cross(right, forward), half_height, half_height * camera.width / camera.height};
}

// Window position (GL: x right, y up, pixels) of a world point in front of the camera.
Point window_of(const ProbeCamera& camera, const Frame& frame, const Vec3& p) {
  const Vec3 e = p - camera.eye;
  const double depth = dot(e, frame.forward);
  const double ndc_x = dot(e, frame.right) / (depth * frame.half_width);
  const double ndc_y = dot(e, frame.up) / (depth * frame.half_height);
  return {0.5 * (ndc_x + 1.0) * camera.width, 0.5 * (ndc_y + 1.0) * camera.height};
}

// The ray through window position w.
Vec3 ray_through(const ProbeCamera& camera, const Frame& frame, const Point& w) {
  const double ndc_x = 2.0 * w[0] / camera.width - 1.0, ndc_y = 2.0 * w[1] / camera.height - 1.0;
  return frame.forward + (ndc_x * frame.half_width) * frame.right + (ndc_y * frame.half_height) * frame.up;
}

// The tent's footprint in texel units (x·W, y·H, y up).
std::array<Point, 3> tent_footprint(int width, int height) {
  return {Point{0.0, 0.0}, Point{double(width), 0.0}, Point{0.0, double(height)}};
}

bool inside_tent_footprint(double x, double y) { return x >= 0.0 && y >= 0.0 && x + y <= 1.0; }

}  // namespace

PhongQuadProbe phong_quad_probe() {
  PhongQuadProbe quad;
  quad.normal = normalised({0.15, 0.25, 1.0});
  quad.side_a = normalised(cross({0.0, 1.0, 0.0}, quad.normal));
  quad.side_b = cross(quad.normal, quad.side_a);
  return quad;
}

Mesh phong_quad_mesh(const PhongQuadProbe& quad) {
  Mesh mesh;
  for (const auto& [s, t] : std::array<Point, 4>{{{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}}) {
    mesh.positions.push_back(quad.centre + s * quad.side_a + t * quad.side_b);
  }
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

Vec3 seed_phong_closed_form(const Vec3& position, const Vec3& normal, const Vec3& eye, const Vec3& albedo,
                            double light_power) {
  const Vec3 to_eye = eye - position;
  const Vec3 v = normalised(to_eye);
  const double facing = dot(normal, v) < 0.0 ? -1.0 : 1.0;
  const double c = facing * dot(normal, v);
  const double irradiance = light_power / dot(to_eye, to_eye);
  const double specular = std::pow(std::max(0.0, 2.0 * c * c - 1.0), 5.0);
  Vec3 colour{};
  for (int k = 0; k < 3; ++k) {
    colour[k] = std::clamp(albedo[k] * (0.1 + irradiance * std::max(0.0, c)) + 0.3 * irradiance * specular, 0.0, 1.0);
  }
  return colour;
}

ProbeImageComparison compare_with_phong_quad(const PhongQuadProbe& quad, const ProbeCamera& camera, const Vec3& albedo,
                                             double light_power, const std::vector<std::uint8_t>& rgb) {
  const Frame frame = frame_of(camera);
  std::array<Point, 4> outline{};
  int corner = 0;
  for (const auto& [s, t] : std::array<Point, 4>{{{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}}}) {
    outline[corner++] = window_of(camera, frame, quad.centre + s * quad.side_a + t * quad.side_b);
  }
  ProbeImageComparison comparison;
  for (int row = 0; row < camera.height; ++row) {
    for (int x = 0; x < camera.width; ++x) {
      const Point centre{x + 0.5, (camera.height - 1 - row) + 0.5};
      if (outline_distance(centre, outline) < 1.0) continue;
      const Vec3 direction = ray_through(camera, frame, centre);
      const double along = dot(direction, quad.normal);
      const double t = along != 0.0 ? dot(quad.centre - camera.eye, quad.normal) / along : -1.0;
      const Vec3 p = camera.eye + t * direction;
      const bool on_quad = t > 0.0 && std::abs(dot(p - quad.centre, quad.side_a)) < 1.0 &&
                           std::abs(dot(p - quad.centre, quad.side_b)) < 1.0;
      const Vec3 expected = on_quad ? seed_phong_closed_form(p, quad.normal, camera.eye, albedo, light_power) : Vec3{};
      ++comparison.compared_pixels;
      comparison.quad_pixels += on_quad;
      for (int channel = 0; channel < 3; ++channel) {
        const std::size_t index = 3 * (std::size_t(row) * std::size_t(camera.width) + std::size_t(x)) + std::size_t(channel);
        const double difference = std::abs(rgb.at(index) / 255.0 - expected[channel]);
        if (difference > comparison.max_abs) {
          comparison.max_abs = difference;
          comparison.max_x = x;
          comparison.max_y = row;
        }
      }
    }
  }
  return comparison;
}

Mesh tent_mesh() {
  Mesh mesh;
  // Base corners 0-2, rim corners 3-5 above them, apex 6.
  mesh.positions = {{0.0, 0.0, 0.0},  {1.0, 0.0, 0.0},  {0.0, 1.0, 0.0}, {0.0, 0.0, 0.25},
                    {1.0, 0.0, 0.25}, {0.0, 1.0, 0.25}, {0.25, 0.25, 1.0}};
  mesh.triangles = {{0, 2, 1},                                                  // base, drawn first
                    {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 3}, {2, 3, 5},  // walls
                    {3, 4, 6}, {4, 5, 6}, {5, 3, 6}};                           // roof
  return mesh;
}

double tent_height(double x, double y) { return 0.25 + 0.75 * std::min({4.0 * x, 4.0 * y, 2.0 * (1.0 - x - y)}); }

TentComparison compare_with_tent(const Grid<double>& heights, const Grid<std::uint8_t>& covered, double unit_roundoff) {
  const int width = heights.width, height = heights.height;
  const auto footprint = tent_footprint(width, height);
  const double slope = std::max({3.0 / width, 3.0 / height, 1.5 / width + 1.5 / height});
  TentComparison comparison;
  comparison.height_bound = 16.0 * unit_roundoff * (1.0 + slope * (width + height));
  for (int row = 0; row < height; ++row) {
    for (int i = 0; i < width; ++i) {
      const double x = (i + 0.5) / width, y = 1.0 - (row + 0.5) / height;
      const double distance = outline_distance(Point{x * width, y * height}, footprint);
      const bool inside = inside_tent_footprint(x, y);
      if (distance > 0x1p-8) {
        ++comparison.coverage_compared;
        comparison.coverage_mismatches += (covered.at(i, row) != 0) != inside;
      }
      if (inside && distance >= 1.0) {
        ++comparison.height_compared;
        comparison.height_max_abs = std::max(comparison.height_max_abs, std::abs(heights.at(i, row) - tent_height(x, y)));
      }
    }
  }
  return comparison;
}

}  // namespace gt
