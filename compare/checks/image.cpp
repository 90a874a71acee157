// Image differences (see image.hpp for the conventions).
//
// The global numbers come from ImageBufAlgo::compare itself rather than a re-implementation, so
// that they are OpenImageIO's to the last bit; only the tolerance counts, which need the tie
// slack, and the neighbourhood comparison are computed here, on float copies of the pixels.
// Files are read with ImageInput (not through the shared image cache, which could serve a stale
// copy of a file rewritten under the same name).
#include "compare/checks/image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>

#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/io/text_file.hpp"
#include "core/grid.hpp"

namespace gt {

namespace {

using Rgb = std::array<float, 3>;

constexpr Rgb identical_grey = {0.5f, 0.5f, 0.5f};
constexpr Rgb within_tolerance_green = {0.0f, 0.75f, 0.0f};
constexpr Rgb neighbour_blue = {0.15f, 0.45f, 1.0f};
constexpr Rgb fails_red = {1.0f, 0.0f, 0.0f};

// Heat-map colour stops, evenly spaced over [0, scale].
constexpr std::array<Rgb, 4> heat_stops = {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}}};

// The channel values of an image as floats, row-major, channels interleaved.
struct FloatPixels {
  int width = 0, height = 0, channels = 0;
  std::vector<float> values;

  const float* at(int x, int y) const {
    return values.data() + (static_cast<std::size_t>(y) * width + x) * static_cast<std::size_t>(channels);
  }
  std::size_t pixel_count() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};

FloatPixels float_pixels(const OIIO::ImageBuf& image) {
  const OIIO::ImageSpec& spec = image.spec();
  FloatPixels pixels{spec.width, spec.height, spec.nchannels, {}};
  pixels.values.resize(pixels.pixel_count() * static_cast<std::size_t>(spec.nchannels));
  if (!image.get_pixels(image.roi(), OIIO::TypeDesc::FLOAT, pixels.values.data())) {
    throw InputError(fmt::format("{}: cannot read pixels: {}", image.name(), image.geterror()));
  }
  return pixels;
}

// Equal, NaN counting as equal to NaN (as in OpenImageIO).
bool channel_equal(float a, float b) { return a == b || (std::isnan(a) && std::isnan(b)); }

bool channel_within(float a, float b, double tolerance) {
  if (std::isfinite(a) && std::isfinite(b)) {
    return std::abs(static_cast<double>(a) - static_cast<double>(b)) <= tolerance + tie_slack;
  }
  return channel_equal(a, b);
}

// |a - b|, 0 for equal non-finite values and +inf for any other non-finite pair.
double channel_difference(float a, float b) {
  if (channel_equal(a, b)) return 0.0;
  if (std::isfinite(a) && std::isfinite(b)) return std::abs(static_cast<double>(a) - static_cast<double>(b));
  return std::numeric_limits<double>::infinity();
}

bool pixel_within(const float* a, const float* b, int channels, double tolerance) {
  for (int c = 0; c < channels; ++c) {
    if (!channel_within(a[c], b[c], tolerance)) return false;
  }
  return true;
}

bool pixel_identical(const float* a, const float* b, int channels) {
  for (int c = 0; c < channels; ++c) {
    if (!channel_equal(a[c], b[c])) return false;
  }
  return true;
}

// Is `value` within tolerance of some pixel of `other`'s 3x3 neighbourhood of (x, y)?
bool matched_nearby(const float* value, const FloatPixels& other, int x, int y, double tolerance) {
  for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, other.height - 1); ++ny) {
    for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, other.width - 1); ++nx) {
      if (pixel_within(value, other.at(nx, ny), other.channels, tolerance)) return true;
    }
  }
  return false;
}

PixelVerdict verdict_at(const FloatPixels& a, const FloatPixels& b, int x, int y, double tolerance) {
  const float* pa = a.at(x, y);
  const float* pb = b.at(x, y);
  if (pixel_identical(pa, pb, a.channels)) return PixelVerdict::identical;
  if (pixel_within(pa, pb, a.channels, tolerance)) return PixelVerdict::within_tolerance;
  if (matched_nearby(pa, b, x, y, tolerance) && matched_nearby(pb, a, x, y, tolerance)) {
    return PixelVerdict::matched_by_neighbour;
  }
  return PixelVerdict::fails;
}

// Per-pixel max |a - b| over channels (channel_difference).
std::vector<double> largest_channel_differences(const FloatPixels& a, const FloatPixels& b) {
  std::vector<double> largest(a.pixel_count(), 0.0);
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    double& pixel = largest[i / static_cast<std::size_t>(a.channels)];
    pixel = std::max(pixel, channel_difference(a.values[i], b.values[i]));
  }
  return largest;
}

Rgb verdict_colour(PixelVerdict verdict) {
  switch (verdict) {
    case PixelVerdict::identical:
      return identical_grey;
    case PixelVerdict::within_tolerance:
      return within_tolerance_green;
    case PixelVerdict::matched_by_neighbour:
      return neighbour_blue;
    case PixelVerdict::fails:
      break;
  }
  return fails_red;
}

// Writes one colour per pixel as 8-bit RGB, under a temporary name renamed into place, signed
// Software = groundtruth (how diff-image tells its own mask from a user's picture of that name).
void write_rgb_picture(int width, int height, const std::vector<Rgb>& colours, const std::filesystem::path& file) {
  OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("Software", groundtruth_software_tag);
  write_image_atomically(file, spec, OIIO::TypeDesc::FLOAT, colours.data());
}

}  // namespace

bool written_by_groundtruth(const std::filesystem::path& picture) {
  const auto input = OIIO::ImageInput::open(picture.string());
  return input && input->spec().get_string_attribute("Software") == groundtruth_software_tag;
}

namespace {

std::string describe_shape(const OIIO::ImageSpec& spec) {
  std::string shape = fmt::format("{}x{}", spec.width, spec.height);
  if (spec.x != 0 || spec.y != 0) shape += fmt::format(" at ({}, {})", spec.x, spec.y);
  return shape;
}

std::string image_label(const OIIO::ImageBuf& image, const char* fallback) {
  return image.name().empty() ? std::string(fallback) : std::string(image.name());
}

void require_flat(const OIIO::ImageBuf& image, const std::string& label) {
  if (image.deep() || image.spec().depth != 1) {
    throw InputError(fmt::format("{}: deep and volume images are not compared", label));
  }
}

}  // namespace

std::array<float, 3> heat_colour(double difference, double scale) {
  if (difference <= 0.0) return heat_stops.front();
  const double position = std::min(difference / scale, 1.0) * (heat_stops.size() - 1);
  const std::size_t stop = std::min(static_cast<std::size_t>(position), heat_stops.size() - 2);
  const double t = position - static_cast<double>(stop);
  Rgb colour;
  for (int c = 0; c < 3; ++c) {
    colour[c] = static_cast<float>(heat_stops[stop][c] + (heat_stops[stop + 1][c] - heat_stops[stop][c]) * t);
  }
  return colour;
}

OIIO::ImageBuf read_image(const std::filesystem::path& file) {
  require_regular_file(file, "cannot read");
  check_exr_attribute_sizes(file);
  const auto input = OIIO::ImageInput::open(file.string());
  if (!input) throw InputError(fmt::format("cannot read {}: {}", file.string(), OIIO::geterror()));
  OIIO::ImageSpec spec = input->spec();
  // A comparison holds two images, each in its own type and as floats, and draws the heat map and
  // the mask as float RGB with 8-bit copies and a verdict a pixel: 2 c (s + 4) + 40 B, above the
  // 63 B a pixel that diff-image --out of two 8-bit RGB PNGs measured (peak RSS at 2000² and
  // 4000²; the formula gives 70).
  const long long bytes_per_pixel =
      2LL * spec.nchannels * static_cast<long long>(spec.format.size() + sizeof(float)) + 40;
  check_grid_fits(spec.width, spec.height, bytes_per_pixel, file.string());
  OIIO::ImageBuf image(file.string(), spec, OIIO::InitializePixels::No);
  const bool read = input->read_image(0, 0, 0, spec.nchannels, spec.format, image.localpixels());
  const std::string reader_error = input->geterror();
  if (!read || !reader_error.empty()) {
    throw InputError(fmt::format("cannot read the pixels of {}: {}", file.string(), reader_error));
  }
  return image;
}

void require_comparable(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  const std::string label_a = image_label(a, "A"), label_b = image_label(b, "B");
  require_flat(a, label_a);
  require_flat(b, label_b);
  const OIIO::ImageSpec &spec_a = a.spec(), &spec_b = b.spec();
  if (describe_shape(spec_a) != describe_shape(spec_b)) {
    throw InputError(fmt::format("{} and {} differ in size: {} against {}", label_a, label_b, describe_shape(spec_a),
                                 describe_shape(spec_b)));
  }
  if (spec_a.nchannels != spec_b.nchannels) {
    throw InputError(fmt::format("{} and {} differ in channels: {} ({}) against {} ({})", label_a, label_b,
                                 spec_a.nchannels, fmt::join(spec_a.channelnames, ","), spec_b.nchannels,
                                 fmt::join(spec_b.channelnames, ",")));
  }
}

ImageDifference compare_images(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, double tolerance) {
  require_comparable(a, b);
  // The failure threshold is infinite: `error` also reports failing values, and the tolerance
  // counts are made below with the tie slack.
  constexpr float no_threshold = std::numeric_limits<float>::infinity();
  const auto oiio = OIIO::ImageBufAlgo::compare(a, b, no_threshold, no_threshold);
  if (oiio.error) {
    throw InputError(fmt::format("cannot compare {} and {}: {}", image_label(a, "A"), image_label(b, "B"),
                                 OIIO::geterror()));
  }
  ImageDifference difference;
  difference.tolerance = tolerance;
  difference.max_abs = oiio.maxerror;
  difference.max_x = oiio.maxx;
  difference.max_y = oiio.maxy;
  difference.max_channel = oiio.maxc;
  difference.mean_abs = oiio.meanerror;
  difference.rms = oiio.rms_error;
  difference.psnr_db = oiio.rms_error == 0.0 ? std::numeric_limits<double>::infinity() : oiio.PSNR;

  const FloatPixels pa = float_pixels(a), pb = float_pixels(b);
  difference.pixels = pa.pixel_count();
  for (std::size_t i = 0; i < difference.pixels; ++i) {
    const std::size_t offset = i * static_cast<std::size_t>(pa.channels);
    if (!pixel_within(&pa.values[offset], &pb.values[offset], pa.channels, tolerance)) {
      ++difference.pixels_beyond_tolerance;
    }
  }
  difference.share_beyond_tolerance =
      static_cast<double>(difference.pixels_beyond_tolerance) / static_cast<double>(difference.pixels);
  return difference;
}

NeighbourhoodComparison compare_neighbourhoods(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, double tolerance) {
  require_comparable(a, b);
  const FloatPixels pa = float_pixels(a), pb = float_pixels(b);
  NeighbourhoodComparison comparison;
  comparison.tolerance = tolerance;
  comparison.width = pa.width;
  comparison.height = pa.height;
  comparison.verdicts.reserve(pa.pixel_count());
  for (int y = 0; y < pa.height; ++y) {
    for (int x = 0; x < pa.width; ++x) comparison.verdicts.push_back(verdict_at(pa, pb, x, y, tolerance));
  }
  comparison.failing_pixels = static_cast<std::size_t>(
      std::count(comparison.verdicts.begin(), comparison.verdicts.end(), PixelVerdict::fails));
  comparison.failing_share =
      static_cast<double>(comparison.failing_pixels) / static_cast<double>(comparison.verdicts.size());
  return comparison;
}

void write_verdict_mask(const NeighbourhoodComparison& comparison, const std::filesystem::path& file) {
  std::vector<Rgb> colours;
  colours.reserve(comparison.verdicts.size());
  for (const PixelVerdict verdict : comparison.verdicts) colours.push_back(verdict_colour(verdict));
  write_rgb_picture(comparison.width, comparison.height, colours, file);
}

double write_difference_heat_map(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::filesystem::path& file,
                                 double scale) {
  require_comparable(a, b);
  const FloatPixels pa = float_pixels(a), pb = float_pixels(b);
  const std::vector<double> differences = largest_channel_differences(pa, pb);
  if (scale <= 0.0) {
    for (const double difference : differences) {
      if (std::isfinite(difference)) scale = std::max(scale, difference);
    }
  }
  std::vector<Rgb> colours;
  colours.reserve(differences.size());
  for (const double difference : differences) colours.push_back(heat_colour(difference, scale));
  write_rgb_picture(pa.width, pa.height, colours, file);
  return scale;
}

}  // namespace gt
