// Height and difference pictures for reports (see images.hpp for the conventions).
//
// Pipeline: one RGB colour per grid cell (or per f x f block when reducing) in float, then
// OpenImageIO for the box-filtered reduction, the nearest-neighbour enlargement and the 8-bit
// PNG output.
#include "compare/report/images.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include "core/sum.hpp"

namespace gt {

namespace {

using Rgb = std::array<float, 3>;

constexpr int min_picture_side = 256;
constexpr int max_picture_side = 1024;
constexpr double target_median_slope = 0.4;
constexpr int checker_cells = 4;
constexpr Rgb non_finite_colour = {0.0f, 0.0f, 0.0f};
constexpr Rgb no_data_grey = {0.62f, 0.62f, 0.62f};
constexpr Rgb no_data_grey_light = {0.74f, 0.74f, 0.74f};

// How a grid maps to the picture: reduce by `reduce`, then enlarge by `enlarge`.
struct PictureScale {
  int reduce = 1;
  int enlarge = 1;
};

PictureScale picture_scale(int width, int height) {
  const int longer = std::max(width, height);
  if (longer < min_picture_side) return {1, (min_picture_side + longer - 1) / longer};
  if (longer > max_picture_side) return {(longer + max_picture_side - 1) / max_picture_side, 1};
  return {};
}

int reduced(int side, int factor) { return (side + factor - 1) / factor; }

void require_cells(const Heightmap& grid) {
  if (grid.width <= 0 || grid.height <= 0) {
    throw std::invalid_argument(fmt::format("no picture of an empty {}x{} grid", grid.width, grid.height));
  }
}

OIIO::ImageBuf rgb_image(int width, int height, const std::vector<Rgb>& colours) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  image.set_pixels(image.roi(), OIIO::TypeDesc::FLOAT, colours.data());
  return image;
}

OIIO::ROI picture_roi(int width, int height) { return OIIO::ROI(0, width, 0, height, 0, 1, 0, 3); }

void write_png(const OIIO::ImageBuf& image, const std::filesystem::path& png) {
  if (image.has_error() || !image.write(png.string(), OIIO::TypeDesc::UINT8)) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", png.string(), image.geterror()));
  }
}

// Enlarges by an integer factor (each pixel becomes a block) and writes the PNG.
void write_enlarged(const OIIO::ImageBuf& image, int factor, const std::filesystem::path& png) {
  if (factor == 1) return write_png(image, png);
  const OIIO::ROI roi = picture_roi(image.spec().width * factor, image.spec().height * factor);
  write_png(OIIO::ImageBufAlgo::resample(image, false, roi), png);
}

Rgb mix(const Rgb& a, const Rgb& b, double t) {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(a[c] + (b[c] - a[c]) * t);
  return out;
}

Rgb scaled(const Rgb& colour, double factor) {
  return {static_cast<float>(colour[0] * factor), static_cast<float>(colour[1] * factor),
          static_cast<float>(colour[2] * factor)};
}

// ---- height pictures -------------------------------------------------------------------------

struct RampStop {
  double at;
  Rgb colour;
};

constexpr std::array<RampStop, 6> terrain_ramp = {{{0.00, {0.06f, 0.32f, 0.16f}},
                                                   {0.30, {0.36f, 0.60f, 0.26f}},
                                                   {0.55, {0.80f, 0.73f, 0.42f}},
                                                   {0.75, {0.60f, 0.45f, 0.30f}},
                                                   {0.90, {0.84f, 0.79f, 0.74f}},
                                                   {1.00, {1.00f, 1.00f, 1.00f}}}};

Rgb terrain_colour(double height, double low, double high) {
  const double t = high > low ? std::clamp((height - low) / (high - low), 0.0, 1.0) : 0.5;
  for (std::size_t i = 1; i < terrain_ramp.size(); ++i) {
    const RampStop& below = terrain_ramp[i - 1];
    const RampStop& above = terrain_ramp[i];
    if (t <= above.at) return mix(below.colour, above.colour, (t - below.at) / (above.at - below.at));
  }
  return terrain_ramp.back().colour;
}

bool usable(const Heightmap& heights, int x, int y) {
  return heights.inside(x, y) && heights.is_valid(x, y) && std::isfinite(heights.at(x, y));
}

// Derivative along one axis from the usable neighbours: central, one-sided, or 0.
double derivative(const Heightmap& heights, int x, int y, int dx, int dy, double spacing) {
  const bool before = usable(heights, x - dx, y - dy);
  const bool after = usable(heights, x + dx, y + dy);
  if (before && after) return (heights.at(x + dx, y + dy) - heights.at(x - dx, y - dy)) / (2.0 * spacing);
  if (after) return (heights.at(x + dx, y + dy) - heights.at(x, y)) / spacing;
  if (before) return (heights.at(x, y) - heights.at(x - dx, y - dy)) / spacing;
  return 0.0;
}

// Height change per unit distance towards east (x) and towards south (rows grow southwards).
struct Gradient {
  double east = 0.0;
  double south = 0.0;
};

Gradient gradient(const Heightmap& heights, int x, int y) {
  return {derivative(heights, x, y, 1, 0, heights.cell_size_x), derivative(heights, x, y, 0, 1, heights.cell_size_y)};
}

double automatic_exaggeration(const Heightmap& heights) {
  std::vector<double> magnitudes;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!usable(heights, x, y)) continue;
      const Gradient g = gradient(heights, x, y);
      const double magnitude = std::hypot(g.east, g.south);
      if (magnitude > 0.0 && std::isfinite(magnitude)) magnitudes.push_back(magnitude);
    }
  }
  if (magnitudes.empty()) return 1.0;
  const auto middle = magnitudes.begin() + static_cast<std::ptrdiff_t>(magnitudes.size() / 2);
  std::nth_element(magnitudes.begin(), middle, magnitudes.end());
  return target_median_slope / *middle;
}

// Lambert shading by a light from the north-west, 45° above the horizon, plus ambient light;
// 1 on flat ground, darker on slopes facing away, up to 1 / flat_shade on slopes facing the light
// (clamped when written).
double hillshade(const Gradient& g, double exaggeration) {
  constexpr double ambient = 0.3;
  const double altitude = std::numbers::pi / 4.0;
  const double horizontal = std::cos(altitude) / std::numbers::sqrt2;
  const double light[3] = {-horizontal, -horizontal, std::sin(altitude)};  // east, south, up
  const double normal[3] = {-g.east * exaggeration, -g.south * exaggeration, 1.0};
  const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + 1.0);
  const double lambert = std::max(0.0, (normal[0] * light[0] + normal[1] * light[1] + light[2]) / length);
  const double flat_shade = ambient + (1.0 - ambient) * light[2];
  return (ambient + (1.0 - ambient) * lambert) / flat_shade;
}

Rgb no_data_colour(int x, int y) {
  return ((x / checker_cells + y / checker_cells) % 2 == 0) ? no_data_grey : no_data_grey_light;
}

std::vector<Rgb> height_colours(const Heightmap& heights, double low, double high, double exaggeration) {
  std::vector<Rgb> colours(heights.size());
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      Rgb& colour = colours[heights.index(x, y)];
      if (!heights.is_valid(x, y)) {
        colour = no_data_colour(x, y);
      } else if (!std::isfinite(heights.at(x, y))) {
        colour = non_finite_colour;
      } else {
        colour = scaled(terrain_colour(heights.at(x, y), low, high), hillshade(gradient(heights, x, y), exaggeration));
      }
    }
  }
  return colours;
}

// ---- difference pictures ---------------------------------------------------------------------

// b - a per cell, or per f x f block the cell of largest |b - a| (non-finite counts as largest).
struct DifferenceField {
  int width = 0;
  int height = 0;
  std::vector<double> difference;
  std::vector<std::uint8_t> compared;  // 0: no data in a or b (in every cell of the block)
};

bool larger_difference(double candidate, double current) {
  if (!std::isfinite(current)) return false;
  return !std::isfinite(candidate) || std::abs(candidate) > std::abs(current);
}

DifferenceField pooled_difference(const Heightmap& a, const Heightmap& b, int factor) {
  DifferenceField field{reduced(a.width, factor), reduced(a.height, factor), {}, {}};
  field.difference.assign(static_cast<std::size_t>(field.width) * field.height, 0.0);
  field.compared.assign(field.difference.size(), 0);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (!a.is_valid(x, y) || !b.is_valid(x, y)) continue;
      const double difference = b.at(x, y) - a.at(x, y);
      const std::size_t block = static_cast<std::size_t>(y / factor) * field.width + x / factor;
      if (!field.compared[block] || larger_difference(difference, field.difference[block])) {
        field.difference[block] = difference;
        field.compared[block] = 1;
      }
    }
  }
  return field;
}

DifferenceStats difference_stats(const Heightmap& a, const Heightmap& b) {
  DifferenceStats stats;
  double largest_finite = 0.0;
  bool any_non_finite = false;
  CompensatedSum sum_of_squares;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a.is_valid(i) || !b.is_valid(i)) continue;
    const double difference = b.values[i] - a.values[i];
    ++stats.compared_cells;
    if (!std::isfinite(difference)) {
      any_non_finite = true;
      continue;
    }
    largest_finite = std::max(largest_finite, std::abs(difference));
    sum_of_squares.add(difference * difference);
  }
  const double infinity = std::numeric_limits<double>::infinity();
  stats.max_abs = any_non_finite ? infinity : largest_finite;
  stats.rms = any_non_finite ? infinity
                             : stats.compared_cells == 0 ? 0.0
                                                         : std::sqrt(sum_of_squares.value() / stats.compared_cells);
  stats.scale_used = largest_finite;
  return stats;
}

constexpr Rgb diverging_low = {0.13f, 0.30f, 0.75f};   // blue: −scale
constexpr Rgb diverging_zero = {1.0f, 1.0f, 1.0f};     // white: 0
constexpr Rgb diverging_high = {0.75f, 0.08f, 0.08f};  // red: +scale

Rgb diverging_colour(double difference, double scale) {
  if (!std::isfinite(difference)) return non_finite_colour;
  const double t = scale > 0.0 ? std::clamp(difference / scale, -1.0, 1.0) : 0.0;
  return t < 0.0 ? mix(diverging_zero, diverging_low, -t) : mix(diverging_zero, diverging_high, t);
}

std::vector<Rgb> difference_colours(const DifferenceField& field, double scale) {
  std::vector<Rgb> colours(field.difference.size());
  for (std::size_t i = 0; i < colours.size(); ++i) {
    colours[i] = field.compared[i] ? diverging_colour(field.difference[i], scale) : no_data_grey;
  }
  return colours;
}

}  // namespace

void write_colour_image(int width, int height, const std::vector<Rgb>& colours, const std::filesystem::path& png) {
  if (width <= 0 || height <= 0 || colours.size() != std::size_t(width) * std::size_t(height)) {
    throw std::invalid_argument(fmt::format("{} colours for a {}x{} picture", colours.size(), width, height));
  }
  write_png(rgb_image(width, height, colours), png);
}

double write_height_image(const Heightmap& heights, double low, double high, const std::filesystem::path& png,
                          double vertical_exaggeration) {
  require_cells(heights);
  const double exaggeration = vertical_exaggeration > 0.0 ? vertical_exaggeration : automatic_exaggeration(heights);
  OIIO::ImageBuf image = rgb_image(heights.width, heights.height, height_colours(heights, low, high, exaggeration));
  const PictureScale scale = picture_scale(heights.width, heights.height);
  if (scale.reduce > 1) {
    const OIIO::ROI roi = picture_roi(reduced(heights.width, scale.reduce), reduced(heights.height, scale.reduce));
    image = OIIO::ImageBufAlgo::resize(image, "box", 1.0f, roi);
  }
  write_enlarged(image, scale.enlarge, png);
  return exaggeration;
}

DifferenceStats write_difference_image(const Heightmap& a, const Heightmap& b, const std::filesystem::path& png,
                                       double scale) {
  if (a.width != b.width || a.height != b.height) {
    throw std::invalid_argument(
        fmt::format("difference of a {}x{} and a {}x{} grid", a.width, a.height, b.width, b.height));
  }
  require_cells(a);
  DifferenceStats stats = difference_stats(a, b);
  if (scale > 0.0) stats.scale_used = scale;
  const PictureScale picture = picture_scale(a.width, a.height);
  const DifferenceField field = pooled_difference(a, b, picture.reduce);
  write_enlarged(rgb_image(field.width, field.height, difference_colours(field, stats.scale_used)), picture.enlarge, png);
  return stats;
}

ColourScale sampled_scale(std::string palette, double low, double high, std::string unit,
                          const std::function<std::array<float, 3>(double)>& colour_of) {
  constexpr int samples = 33;
  ColourScale scale{.palette = std::move(palette), .low = low, .high = high, .unit = std::move(unit), .colours = {}};
  for (int i = 0; i < samples; ++i) scale.colours.push_back(colour_of(low + (high - low) * i / (samples - 1)));
  return scale;
}

ColourScale height_scale(double low, double high, std::string unit) {
  return sampled_scale("terrain", low, high, std::move(unit), [&](double height) { return terrain_colour(height, low, high); });
}

ColourScale difference_scale(const DifferenceStats& drawn, std::string unit) {
  const double scale = drawn.scale_used;
  return sampled_scale("diverging", -scale, scale, std::move(unit),
                       [&](double difference) { return diverging_colour(difference, scale); });
}

}  // namespace gt
