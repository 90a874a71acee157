// Area-weighted relief of a global grid; see global_relief.hpp.
#include "compare/descriptors/global_relief.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

constexpr double degree = std::numbers::pi / 180.0;

// Edges halfway between centres; the outer edges mirrored from the neighbouring half-spacing.
std::vector<double> cell_edges(const std::vector<double>& centres) {
  std::vector<double> edges(centres.size() + 1);
  for (std::size_t i = 1; i < centres.size(); ++i) edges[i] = 0.5 * (centres[i - 1] + centres[i]);
  edges.front() = centres.front() - (edges[1] - centres.front());
  edges.back() = centres.back() + (centres.back() - edges[centres.size() - 1]);
  return edges;
}

// Area of each row's cells per unit of longitude (radians): |sin φ_north - sin φ_south|.
std::vector<double> row_weights(const std::vector<double>& latitudes) {
  const std::vector<double> edges = cell_edges(latitudes);
  std::vector<double> weights(latitudes.size());
  for (std::size_t row = 0; row < latitudes.size(); ++row) {
    const double low = std::clamp(edges[row], -90.0, 90.0), high = std::clamp(edges[row + 1], -90.0, 90.0);
    weights[row] = std::abs(std::sin(high * degree) - std::sin(low * degree));
  }
  return weights;
}

// Each column's width in radians; a last column 360° after the first gets none.
std::vector<double> column_widths(const std::vector<double>& longitudes) {
  const std::vector<double> edges = cell_edges(longitudes);
  std::vector<double> widths(longitudes.size());
  for (std::size_t column = 0; column < longitudes.size(); ++column) {
    widths[column] = std::abs(edges[column + 1] - edges[column]) * degree;
  }
  const double half_spacing = 0.5 * std::abs(longitudes[1] - longitudes[0]);
  if (std::abs(std::abs(longitudes.back() - longitudes.front()) - 360.0) < half_spacing) widths.back() = 0.0;
  return widths;
}

void check_relief_options(int points, double bin_width) {
  if (points < 2 || !(bin_width > 0.0)) {
    throw InputError(fmt::format("global relief: {} curve points and bins of {} (at least 2 points, bins above 0)",
                                 points, bin_width));
  }
}

// The index of the centre nearest `value` among ascending `centres`.
std::size_t nearest_ascending(const std::vector<double>& centres, double value) {
  const auto above = std::lower_bound(centres.begin(), centres.end(), value);
  if (above == centres.begin()) return 0;
  if (above == centres.end()) return centres.size() - 1;
  const auto below = above - 1;
  return static_cast<std::size_t>((value - *below <= *above - value ? below : above) - centres.begin());
}

}  // namespace

std::function<double(const std::array<double, 3>&)> nearest_cell_sampler(const GlobalGrid& grid, double no_data_value) {
  if (grid.latitudes.empty() || grid.longitudes.empty()) {
    throw InputError(fmt::format("sampling {}: no latitudes or longitudes", grid.variable));
  }
  // Latitudes ascending with their rows; longitudes wrapped into [0, 360) and sorted with their
  // columns, then the first repeated 360° on and the last 360° back, so the nearest is found
  // round the circle.
  std::vector<std::pair<double, std::size_t>> rows, columns;
  for (std::size_t row = 0; row < grid.latitudes.size(); ++row) rows.push_back({grid.latitudes[row], row});
  for (std::size_t column = 0; column < grid.longitudes.size(); ++column) {
    columns.push_back({std::fmod(std::fmod(grid.longitudes[column], 360.0) + 360.0, 360.0), column});
  }
  std::sort(rows.begin(), rows.end());
  std::sort(columns.begin(), columns.end());
  columns.insert(columns.begin(), {columns.back().first - 360.0, columns.back().second});
  columns.push_back({columns[1].first + 360.0, columns[1].second});
  const auto firsts = [](const std::vector<std::pair<double, std::size_t>>& pairs) {
    std::vector<double> values;
    for (const auto& pair : pairs) values.push_back(pair.first);
    return values;
  };
  return [&grid, no_data_value, rows, columns, latitudes = firsts(rows), longitudes = firsts(columns)](
             const std::array<double, 3>& direction) {
    const double latitude = std::asin(std::clamp(direction[2], -1.0, 1.0)) / degree;
    const double longitude = std::fmod(std::atan2(direction[1], direction[0]) / degree + 360.0, 360.0);
    const std::size_t row = rows[nearest_ascending(latitudes, latitude)].second;
    const std::size_t column = columns[nearest_ascending(longitudes, longitude)].second;
    const std::size_t cell = row * static_cast<std::size_t>(grid.elevation.width) + column;
    const bool valid = grid.elevation.valid.empty() || grid.elevation.valid[cell];
    return valid ? grid.elevation.values[cell] : no_data_value;
  };
}

std::vector<AreaSample> area_samples(const GlobalGrid& grid) {
  const Grid<double>& elevation = grid.elevation;
  if (grid.latitudes.size() < 2 || grid.longitudes.size() < 2) {
    throw InputError(fmt::format("global relief of {}: fewer than 2 latitudes or longitudes", grid.variable));
  }
  const std::vector<double> rows = row_weights(grid.latitudes);
  const std::vector<double> columns = column_widths(grid.longitudes);
  std::vector<AreaSample> cells;
  cells.reserve(elevation.values.size());
  for (int row = 0; row < elevation.height; ++row) {
    for (int column = 0; column < elevation.width; ++column) {
      const std::size_t cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(elevation.width) +
                               static_cast<std::size_t>(column);
      const double area = rows[static_cast<std::size_t>(row)] * columns[static_cast<std::size_t>(column)];
      if (area > 0.0 && (elevation.valid.empty() || elevation.valid[cell])) cells.push_back({elevation.values[cell], area});
    }
  }
  if (cells.empty()) throw InputError(fmt::format("global relief of {}: no valid cell", grid.variable));
  return cells;
}

GlobalRelief global_relief(const GlobalGrid& grid, double sea_level, int points, double bin_width) {
  check_relief_options(points, bin_width);
  return weighted_relief(area_samples(grid), sea_level, points, bin_width);
}

GlobalRelief weighted_relief(std::vector<AreaSample> cells, double sea_level, int points, double bin_width,
                             double bin_edge) {
  check_relief_options(points, bin_width);
  if (cells.empty()) throw InputError("global relief: no sample");
  std::sort(cells.begin(), cells.end(), [](const AreaSample& a, const AreaSample& b) { return a.elevation < b.elevation; });

  GlobalRelief relief;
  relief.min = cells.front().elevation;
  relief.max = cells.back().elevation;
  double land = 0.0, weighted = 0.0;
  for (const auto& [height, area] : cells) {
    relief.valid_area += area;
    weighted += height * area;
    if (height >= sea_level) land += area;
  }
  relief.land_fraction = land / relief.valid_area;
  relief.mean = weighted / relief.valid_area;

  relief.hypsometry.resize(static_cast<std::size_t>(points));
  double below = 0.0;
  std::size_t next = 0;
  for (int point = 0; point < points; ++point) {
    const double fraction = double(point) / double(points - 1);
    while (next + 1 < cells.size() && (below + cells[next].area) / relief.valid_area < fraction) below += cells[next++].area;
    relief.hypsometry[static_cast<std::size_t>(point)] = point == 0 ? relief.min : cells[next].elevation;
  }
  relief.hypsometry.back() = relief.max;

  relief.bin_width = bin_width;
  relief.histogram_start = bin_edge + std::floor((relief.min - bin_edge) / bin_width) * bin_width;
  relief.histogram.assign(static_cast<std::size_t>(std::floor((relief.max - relief.histogram_start) / bin_width)) + 1, 0.0);
  for (const auto& [height, area] : cells) {
    relief.histogram[static_cast<std::size_t>(std::floor((height - relief.histogram_start) / bin_width))] +=
        area / relief.valid_area;
  }
  return relief;
}

double bimodality_coefficient(const std::vector<AreaSample>& samples) {
  double total = 0.0, mean = 0.0;
  for (const auto& [elevation, area] : samples) {
    total += area;
    mean += elevation * area;
  }
  mean /= total;
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (const auto& [elevation, area] : samples) {
    const double deviation = elevation - mean, squared = deviation * deviation;
    m2 += squared * area / total;
    m3 += squared * deviation * area / total;
    m4 += squared * squared * area / total;
  }
  if (!(m2 > 0.0)) return 0.0;
  const double skewness = m3 / std::pow(m2, 1.5), kurtosis = m4 / (m2 * m2);
  return (skewness * skewness + 1.0) / kurtosis;
}

}  // namespace gt
