// Pictures of heightmaps for reports, written as 8-bit RGB PNG.
//
// Conventions
//   - Row 0 of a grid is the top of the picture (north for DEMs), x grows to the right (east).
//   - Picture size: a grid whose longer side is under 256 cells is enlarged by the smallest
//     integer factor that makes it at least 256 px, each cell a block of identical pixels
//     (nearest neighbour); one whose longer side exceeds 1024 cells is reduced by the smallest
//     integer factor f that makes it at most 1024 px, to ceil(width / f) x ceil(height / f).
//     Height pictures average the colours under each output pixel (box filter); difference
//     pictures keep the cell with the largest |difference| of each f x f block, so an isolated
//     disagreement stays visible. Both kinds of picture of one grid therefore have equal sizes.
//   - No-data cells (mask 0) are grey: a checker of 4-cell squares in height pictures, flat grey
//     in difference pictures. Valid cells holding NaN or infinity are black in both.
//   - Failures to write throw std::runtime_error; grids of different sizes std::invalid_argument.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "compare/result.hpp"
#include "core/grid.hpp"

namespace gt {

// Terrain colours over [low, high] (deep green, green, yellow-brown, brown, white; heights
// outside are clamped), multiplied by a hillshade lit from the north-west at 45° altitude.
// Slopes use the grid's cell sizes; heights are multiplied by `vertical_exaggeration`, or when it
// is 0 by one chosen so that the median non-zero |gradient| becomes 0.4 (about 22°). Returns the
// exaggeration used: pass it, with the same low and high, to the picture of the same terrain
// after an algorithm ran so the two pictures are comparable.
double write_height_image(const Heightmap& heights, double low, double high, const std::filesystem::path& png,
                          double vertical_exaggeration = 0.0);

// Writes colours (row-major from the top-left, each channel in [0, 1] as stored: no transfer
// function applied) as an 8-bit RGB PNG of width x height pixels, without resizing.
void write_colour_image(int width, int height, const std::vector<std::array<float, 3>>& colours,
                        const std::filesystem::path& png);

struct DifferenceStats {
  double max_abs = 0.0;     // max |b - a| over cells valid in both; +inf if one of them is NaN/inf
  double rms = 0.0;         // root mean square of b - a over the same cells
  double scale_used = 0.0;  // |b - a| drawn at full colour; 0 when every difference is 0
  std::size_t compared_cells = 0;
};

// Diverging picture of b - a: blue negative, white zero, red positive, linear in the difference
// and saturated at ±scale. scale = 0 means the largest finite |b - a|. An all-zero difference
// gives an all-white picture (no-data cells still grey). Cells valid in only one grid count as
// no data.
DifferenceStats write_difference_image(const Heightmap& a, const Heightmap& b, const std::filesystem::path& png,
                                       double scale = 0.0);

// The colour bars of these pictures: heights over [low, high] in the terrain palette (before the
// hillshade), and a difference picture's ±scale_used in the diverging one.
ColourScale height_scale(double low, double high, std::string unit);
ColourScale difference_scale(const DifferenceStats& drawn, std::string unit);

// A colour bar for any colour function of the value: `colour_of` sampled at 33 values evenly from
// low to high.
ColourScale sampled_scale(std::string palette, double low, double high, std::string unit,
                          const std::function<std::array<float, 3>(double)>& colour_of);

}  // namespace gt
