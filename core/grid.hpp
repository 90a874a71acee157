// Grid<T>: a row-major 2-D field with physical cell size, units and an optional no-data mask.
//
// Conventions
//   - value(x, y) with x in [0, width) (columns, east) and y in [0, height) (rows). Row 0 is the
//     first row stored in the source file (north for DEMs, top for images); no flip is applied.
//   - cell_size_x, cell_size_y: spacing of cell centres in `horizontal_unit` (default metres).
//   - values are in `vertical_unit` (default metres). A heightmap is Grid<double>.
//   - valid: empty means every cell is valid; otherwise one byte per cell, 0 = no data. Values of
//     invalid cells are unspecified (readers store 0) and are never used by algorithms or sums.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gt {

// A neighbour's offset in cells.
struct CellOffset {
  int dx;
  int dy;
};

// The Moore neighbourhood in the order of the 8-neighbour cellular models (Jákó & Tóth's thermal
// erosion, Beneš's dissolution): the cardinal (-1,0) (0,1) (1,0) (0,-1), then the diagonal (-1,-1)
// (-1,1) (1,1) (1,-1). GLSL twin: gpu/shaders/common/moore_pipes.glsl.
inline constexpr CellOffset moore_offsets[8] = {{-1, 0}, {0, 1}, {1, 0}, {0, -1}, {-1, -1}, {-1, 1}, {1, 1}, {1, -1}};

// Where a user sets a cell size, for the messages that ask for one (an assumed 1 m, a size out of range).
inline constexpr const char* cell_size_settings = "--cell-size, cell_size= from Python, or \"cell_size\" in a case file";

template <class T>
struct Grid {
  int width = 0;
  int height = 0;
  double cell_size_x = 1.0;
  double cell_size_y = 1.0;
  std::string horizontal_unit = "m";
  std::string vertical_unit = "m";
  std::vector<T> values;
  std::vector<std::uint8_t> valid;

  Grid() = default;
  Grid(int width_, int height_, T fill = T{}) : width(width_), height(height_),
      values(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), fill) {}

  std::size_t size() const { return values.size(); }
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
  T& at(int x, int y) { return values[index(x, y)]; }
  const T& at(int x, int y) const { return values[index(x, y)]; }
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  bool has_mask() const { return !valid.empty(); }
  bool is_valid(std::size_t i) const { return valid.empty() || valid[i] != 0; }
  bool is_valid(int x, int y) const { return is_valid(index(x, y)); }

  // Same geometry, units and mask; values converted to U.
  template <class U>
  Grid<U> cast() const {
    Grid<U> out = same_geometry<U>();
    out.values.assign(values.begin(), values.end());
    return out;
  }

  // Same geometry, units and mask; each value v becomes value(v) (a conversion that is not
  // implicit: a number type's own parts).
  template <class U, class Value>
  Grid<U> map(Value value) const {
    Grid<U> out = same_geometry<U>();
    out.values.reserve(values.size());
    for (const T& v : values) out.values.push_back(value(v));
    return out;
  }

 private:
  template <class U>
  Grid<U> same_geometry() const {
    Grid<U> out;
    out.width = width;
    out.height = height;
    out.cell_size_x = cell_size_x;
    out.cell_size_y = cell_size_y;
    out.horizontal_unit = horizontal_unit;
    out.vertical_unit = vertical_unit;
    out.valid = valid;
    return out;
  }
};

using Heightmap = Grid<double>;

// Throws InputError when a width x height grid of `bytes_per_cell` bytes per cell (all the
// buffers the caller keeps for it, summed) is empty, has a side beyond 2^20 cells, or needs more
// memory than this process may use (core/memory.hpp require_memory, the estimate in the message).
// `what` names the grid in the message.
void check_grid_fits(long long width, long long height, long long bytes_per_cell, const std::string& what);

// Throws InputError naming the first NaN or infinite valid cell.
template <class T>
void check_finite(const Grid<T>& grid, const std::string& what);

// Throws InputError unless both cell sizes are finite and within [1e-9, 1e9] (the range the
// inputs' "cell_size" accepts): zero, negative, NaN or infinite spacings make no slope.
template <class T>
void check_cell_size(const Grid<T>& grid, const std::string& what);

// Throws InputError naming the first valid cell whose magnitude exceeds FLT_MAX/16: the GPU twins
// hold heights as 32-bit floats and sum up to 8 differences of them, which must stay finite.
template <class T>
void check_fits_float(const Grid<T>& grid, const std::string& what);

// Lowest and highest value over valid cells; low > high (+inf, -inf) when no cell is valid.
template <class T>
std::pair<double, double> valid_range(const Grid<T>& grid);

// Number of valid cells.
template <class T>
std::size_t count_valid(const Grid<T>& grid);

// The values of the valid cells, in storage order, as double.
template <class T>
std::vector<double> valid_values(const Grid<T>& grid);

}  // namespace gt
