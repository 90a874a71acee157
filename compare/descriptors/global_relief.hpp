// Area-weighted relief of a global latitude-longitude grid (core/io/global_grid.hpp), the figures
// issue 13 sets a generated planet beside the Earth's: land fraction (ETOPO: 0.290), the
// hypsometric curve and the elevation histogram (the Earth's is bimodal: continents near +0.1 km,
// ocean floor near -4 km), the elevation range.
//
// Each valid cell weighs its area on the unit sphere, Δλ·(sin φ_north - sin φ_south) with Δλ and
// the latitude edges halfway between neighbouring centres (the outer rows' outer edges mirrored,
// then clamped to ±90°); a last column 360° after the first (etopo20 repeats it) is left out.
// No-data cells are left out; fractions are of the valid area.
// Output:
//   land_fraction       the area share not below sea_level (the grid's vertical unit): ocean is
//                       what lies below it (ETOPO 1° has 0.09 % of its area at exactly 0 m)
//   mean, min, max      area-weighted mean and the range of valid cells
//   hypsometry          the elevation below which each area fraction lies, at fractions 0, 1/(n-1),
//                       ..., 1 (n = points; the first is min, the last max): the hypsometric curve
//   histogram           area shares of bins of bin_width from floor(min / bin_width)·bin_width up
//                       (or, given a bin edge, from the edge on that grid of bins at or below min:
//                       elevations on a lattice k·q + o bin without aliasing when bin_width is a
//                       multiple of q and an edge sits at o − q/2, halfway between two of them)
// Throws InputError when no cell is valid, points < 2 or bin_width <= 0.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "core/io/global_grid.hpp"

namespace gt {

struct GlobalRelief {
  double land_fraction = 0.0;
  double mean = 0.0;
  double min = 0.0;
  double max = 0.0;
  double valid_area = 0.0;  // steradians; 4π for a whole sphere without no-data
  std::vector<double> hypsometry;
  double histogram_start = 0.0;  // the first bin's lower edge
  double bin_width = 0.0;
  std::vector<double> histogram;
};

struct AreaSample {
  double elevation = 0.0;
  double area = 0.0;  // steradians
};

// The grid's valid cells with their areas (the weights above).
std::vector<AreaSample> area_samples(const GlobalGrid& grid);

GlobalRelief global_relief(const GlobalGrid& grid, double sea_level = 0.0, int points = 101, double bin_width = 500.0);

// The same figures of any surface given as (elevation, area) samples with areas > 0 (a generated
// planet's regions and their solid angles); valid_area is the sum of the areas.
GlobalRelief weighted_relief(std::vector<AreaSample> samples, double sea_level = 0.0, int points = 101,
                             double bin_width = 500.0, double bin_edge = 0.0);

// The grid as a function on the unit sphere, for spherical_spectrum.hpp: at direction (x, y, z) the
// cell whose centre is nearest in latitude asin(z) and in longitude atan2(y, x) (taken round the
// circle), or `no_data_value` where that cell is no-data. The grid must outlive the function.
std::function<double(const std::array<double, 3>&)> nearest_cell_sampler(const GlobalGrid& grid, double no_data_value);

// Sarle's bimodality coefficient of the area-weighted distribution, (γ² + 1)/κ with the population
// skewness γ = m3/m2^1.5 and kurtosis κ = m4/m2² (not in excess): 1/3 for a normal distribution, 5/9
// for a uniform one, 1 for two equal point masses; above 5/9 suggests two modes (SAS Institute
// 1990; Pfister et al. 2013, Front. Psychol. 4:700). 0 for a distribution without spread.
double bimodality_coefficient(const std::vector<AreaSample>& samples);

}  // namespace gt
