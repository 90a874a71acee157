#include "core/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/memory.hpp"
#include "core/rounding_interval.hpp"

namespace gt {

void check_grid_fits(long long width, long long height, long long bytes_per_cell, const std::string& what) {
  if (width <= 0 || height <= 0) {
    throw InputError(fmt::format("{}: size {}x{} is empty", what, width, height));
  }
  constexpr long long max_side = 1 << 20;
  if (width > max_side || height > max_side) {
    throw InputError(fmt::format("{}: size {}x{} exceeds the largest supported side of {} cells", what, width,
                                 height, max_side));
  }
  const double bytes = static_cast<double>(width) * static_cast<double>(height) * static_cast<double>(bytes_per_cell);
  require_memory(bytes, fmt::format("{}x{} cells x {} B a cell", width, height, bytes_per_cell),
                 fmt::format("{} ({}x{})", what, width, height));
}

template <class T>
void check_finite(const Grid<T>& grid, const std::string& what) {
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (grid.is_valid(x, y) && !std::isfinite(static_cast<double>(grid.at(x, y)))) {
        throw InputError(fmt::format("{}: cell (x={}, y={}) is {}; mark no-data cells with a mask instead", what,
                                     x, y, static_cast<double>(grid.at(x, y))));
      }
    }
  }
}

template <class T>
void check_cell_size(const Grid<T>& grid, const std::string& what) {
  const auto sound = [](double size) { return std::isfinite(size) && size >= 1e-9 && size <= 1e9; };
  if (!sound(grid.cell_size_x) || !sound(grid.cell_size_y)) {
    throw InputError(fmt::format("{}: cell size {} x {} {} is not a length between 1e-9 and 1e9 (set it with {})", what,
                                 grid.cell_size_x, grid.cell_size_y, grid.horizontal_unit, cell_size_settings));
  }
}

template <class T>
void check_fits_float(const Grid<T>& grid, const std::string& what) {
  const double largest = std::numeric_limits<float>::max() / 16.0;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const double value = static_cast<double>(grid.at(x, y));
      if (grid.is_valid(x, y) && std::abs(value) > largest) {
        throw InputError(fmt::format("{}: cell (x={}, y={}) is {:g}, beyond ±{:.3g}: the GPU twins hold heights as "
                                     "32-bit floats and sum up to 8 differences of them, which must stay finite",
                                     what, x, y, value, largest));
      }
    }
  }
}

template <class T>
std::pair<double, double> valid_range(const Grid<T>& grid) {
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!grid.is_valid(i)) continue;
    low = std::min(low, static_cast<double>(grid.values[i]));
    high = std::max(high, static_cast<double>(grid.values[i]));
  }
  return {low, high};
}

template <class T>
std::size_t count_valid(const Grid<T>& grid) {
  if (!grid.has_mask()) return grid.size();
  std::size_t n = 0;
  for (auto v : grid.valid) n += v != 0;
  return n;
}

template <class T>
std::vector<double> valid_values(const Grid<T>& grid) {
  std::vector<double> values;
  values.reserve(count_valid(grid));
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.is_valid(i)) values.push_back(static_cast<double>(grid.values[i]));
  }
  return values;
}

template void check_finite(const Grid<float>&, const std::string&);
template void check_finite(const Grid<double>&, const std::string&);
template void check_finite(const Grid<RoundingInterval>&, const std::string&);
template void check_cell_size(const Grid<float>&, const std::string&);
template void check_cell_size(const Grid<double>&, const std::string&);
template void check_fits_float(const Grid<float>&, const std::string&);
template void check_fits_float(const Grid<double>&, const std::string&);
template std::pair<double, double> valid_range(const Grid<float>&);
template std::pair<double, double> valid_range(const Grid<double>&);
template std::size_t count_valid(const Grid<float>&);
template std::size_t count_valid(const Grid<double>&);
template std::size_t count_valid(const Grid<RoundingInterval>&);
template std::vector<double> valid_values(const Grid<float>&);
template std::vector<double> valid_values(const Grid<double>&);

}  // namespace gt
