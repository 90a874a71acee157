// Differences of two images of equal size and channel count: the numeric comparison of
// OpenImageIO, a neighbourhood-tolerant comparison for rasterized edges, and two pictures of the
// difference (a heat map and a verdict mask), written with OpenImageIO.
//
// Conventions
//   - Channel values are OpenImageIO's: integer formats normalised to [0, 1] (v / 255 for 8 bits,
//     v / 65535 for 16 bits), float formats as stored. Every channel counts, alpha included;
//     colour channels are read as OpenImageIO reads them (a PNG's RGB premultiplied by its
//     alpha), as idiff does.
//   - max, mean, RMS and PSNR are ImageBufAlgo::compare's, so they equal what `idiff` and
//     `oiiotool --diff` print for the same pair: mean and RMS over all channel values,
//     PSNR = 20 log10(peak / RMS) with peak 1 for images in [0, 1]; +infinity when identical.
//   - A channel is within `tolerance` when |a - b| <= tolerance + tie_slack. OpenImageIO converts
//     an 8-bit level k to the float k * (1/255f), so a difference of exactly 4 levels comes out
//     up to 6e-8 above or below the float 4/255; tie_slack = 2^-22 (2.4e-7, far below one 16-bit
//     level, 1.5e-5) makes a difference of exactly `tolerance` pass every time (idiff's count
//     "pixels over T" has no slack: it agrees for a T between levels, not always for one on a
//     level). A pixel is within tolerance when all its channels are. NaN matches NaN and an
//     infinity the same infinity (OpenImageIO also matches +inf with -inf); any other non-finite
//     difference is beyond every tolerance and drawn white in the heat map.
//   - Neighbourhood-tolerant comparison: pixel p passes when a(p) is within tolerance of some
//     b(q) with q in the 3x3 neighbourhood of p (clipped at the image border), and b(p) of some
//     a(q) likewise; it fails when either direction finds no match. A one-pixel shift of an edge
//     therefore passes; a changed shading fails on exactly the changed pixels (those whose new
//     value matches no old value nearby).
//   - Images that cannot be compared — different sizes, data windows or channel counts, deep or
//     volume images — and files that cannot be read or written throw gt::InputError naming the
//     files and what differs.
//   - Pictures are 8-bit RGB, written under a temporary name in the target's folder and renamed
//     into place; the format follows the extension (.png for the pictures of reports).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <OpenImageIO/imagebuf.h>

namespace gt {

constexpr double tie_slack = 0x1p-22;

// The pixels of an image file, read completely into memory (no image cache), in the file's own
// pixel type. Throws InputError for a missing, unreadable or non-image file.
OIIO::ImageBuf read_image(const std::filesystem::path& file);

// Throws InputError unless a and b have the same size, data window and channel count and are
// flat 2-D images; the message names both (ImageBuf::name(), or "A"/"B" for images in memory).
void require_comparable(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b);

struct ImageDifference {
  double tolerance = 0.0;
  double max_abs = 0.0;  // largest |a - b| over all channel values (+inf for a non-finite mismatch)
  int max_x = 0, max_y = 0, max_channel = 0;  // where it is
  double mean_abs = 0.0;
  double rms = 0.0;
  double psnr_db = 0.0;  // +infinity when rms is 0
  std::size_t pixels = 0;
  std::size_t pixels_beyond_tolerance = 0;  // pixels with some channel beyond the tolerance
  double share_beyond_tolerance = 0.0;      // of all pixels, in [0, 1]
};

ImageDifference compare_images(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, double tolerance);

enum class PixelVerdict : std::uint8_t {
  identical,             // every channel equal at the same pixel
  within_tolerance,      // every channel within tolerance at the same pixel
  matched_by_neighbour,  // not within tolerance at the same pixel, but matched nearby both ways (edge shift)
  fails,                 // some direction finds no match in the 3x3 neighbourhood
};

struct NeighbourhoodComparison {
  double tolerance = 0.0;
  int width = 0, height = 0;
  std::vector<PixelVerdict> verdicts;  // row-major, row 0 at the top
  std::size_t failing_pixels = 0;      // verdicts == fails
  double failing_share = 0.0;          // of all pixels, in [0, 1]
};

NeighbourhoodComparison compare_neighbourhoods(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, double tolerance);

// The verdicts as a picture: identical grey, within tolerance green, matched by a neighbour blue,
// fails red.
void write_verdict_mask(const NeighbourhoodComparison& comparison, const std::filesystem::path& file);

// The heat maps' colour of a difference d >= 0 (channels in [0, 1]): black at 0, red at scale/3,
// yellow at 2 scale/3, white at scale and beyond, linear between.
std::array<float, 3> heat_colour(double difference, double scale);

// Heat map of the per-pixel max |a - b| over channels, d: black at 0, red at scale/3, yellow at
// 2 scale/3, white at scale and beyond (linear between). scale 0 means the largest finite d (an
// all-black picture when the images are equal); non-finite mismatches are white. Returns the
// scale used.
double write_difference_heat_map(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b, const std::filesystem::path& file,
                                 double scale = 0.0);

// Both pictures above carry Software = groundtruth_software_tag. True when `picture` is a file
// OpenImageIO reads that carries it: one groundtruth wrote, which it may replace.
inline constexpr const char* groundtruth_software_tag = "groundtruth";
bool written_by_groundtruth(const std::filesystem::path& picture);

}  // namespace gt
