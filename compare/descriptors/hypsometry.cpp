// Hypsometric curve and integral: Strahler 1952 ("Hypsometric (area-altitude) analysis of erosional
// topography", the curve a/A against h/H and the area under it) and Pike & Wilson 1971 (the
// elevation-relief ratio (mean - min)/(max - min), shown there to equal that area). Heights in the
// DEM's vertical unit; the shares are dimensionless. The mean is a compensated sum, so HI is exact
// to rounding for any grid size.
#include "compare/descriptors/hypsometry.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/sum.hpp"

namespace gt {

Hypsometry hypsometry(const Heightmap& dem, int points) {
  if (points < 2) throw InputError("hypsometry needs at least two levels");
  auto heights = valid_values(dem);
  if (heights.empty()) throw InputError("hypsometry: no valid cell");
  std::sort(heights.begin(), heights.end());
  Hypsometry out;
  out.min = heights.front();
  out.max = heights.back();
  const double relief = out.max - out.min;
  if (!(relief > 0.0)) throw InputError(fmt::format("hypsometry: the terrain is flat (every valid cell at {})", out.min));
  CompensatedSum total;
  for (double h : heights) total.add(h);
  out.mean = total.value() / static_cast<double>(heights.size());
  out.integral = (out.mean - out.min) / relief;

  const double cells = static_cast<double>(heights.size());
  out.histogram.assign(static_cast<std::size_t>(points - 1), 0);
  for (int level = 0; level < points; ++level) {
    const double share = static_cast<double>(level) / (points - 1);
    const double threshold = out.min + share * relief;
    const auto first_at_or_above = std::lower_bound(heights.begin(), heights.end(), threshold);
    out.relative_height.push_back(share);
    out.relative_area.push_back(static_cast<double>(heights.end() - first_at_or_above) / cells);
  }
  for (double h : heights) {
    const auto bin = static_cast<std::size_t>((h - out.min) / relief * (points - 1));
    ++out.histogram[std::min(bin, out.histogram.size() - 1)];
  }
  return out;
}

}  // namespace gt
