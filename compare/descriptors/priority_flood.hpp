// Depression filling by Priority-Flood+ε (Barnes, Lehman & Mulla 2014), and what the drainage
// descriptors share: the D8 neighbourhood in its tie-breaking order and the checks of a DEM.
//
// fill_depressions(dem, raised_cells) -> filled
//   dem           Heightmap in metres (any consistent unit); no-data cells (valid == 0) take no
//                 part and stay no-data with their value untouched.
//   raised_cells  when not null, receives how many valid cells the filling raised.
//   filled        dem with every depression raised to its spill height plus the smallest steps a
//                 double can take (std::nextafter), so that every valid cell has a strictly
//                 descending D8 path to an outlet. Outlets are the valid cells on the grid's edge
//                 or with a no-data 8-neighbour; they keep their height.
//   Throws InputError for an empty grid, a grid without valid cells, inconsistent buffers,
//   NaN/infinite heights or an unusable cell size.
//
// check_drainage_dem(dem, what, bytes_per_cell) throws InputError, naming `what`, for the same
// unusable inputs (and when `bytes_per_cell` times the cell count exceeds the memory available).
//
// d8_steps: the 8 neighbours, counter-clockwise from east, with north = row − 1:
// E, NE, N, NW, W, SW, S, SE. Every drainage routine visits neighbours in this order and keeps the
// first of equal candidates, so ties are broken the same way everywhere.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include "core/grid.hpp"

namespace gt {

struct GridStep {
  int dx;  // columns, east positive
  int dy;  // rows, south positive (north = row − 1)
};

inline constexpr std::array<GridStep, 8> d8_steps{
    {{1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}}};

void check_drainage_dem(const Heightmap& dem, const std::string& what, long long bytes_per_cell);

Heightmap fill_depressions(const Heightmap& dem, std::size_t* raised_cells = nullptr);

}  // namespace gt
