// Fields for the pipe-erosion tests (reference and GPU): a grid filled by a function of the cell,
// and uniform noise in [0, 1) from the project's counter-based hash (exact in float and double).
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/rng.hpp"

namespace gt::testing {

template <class Function>
Grid<double> field(int width, int height, double cell_x, double cell_y, Function value) {
  Grid<double> grid(width, height);
  grid.cell_size_x = cell_x;
  grid.cell_size_y = cell_y;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) grid.at(x, y) = value(x, y);
  }
  return grid;
}

inline double noise(int x, int y, std::uint32_t seed) {
  return uniform01(random_u32(seed, static_cast<std::uint32_t>(x * 7919 + y), 0, 0));
}

}  // namespace gt::testing
