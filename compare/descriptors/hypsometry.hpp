// Hypsometry of a terrain: the elevation histogram, the hypsometric curve and its integral.
//
// Input: a heightmap; no-data cells are left out. Every valid cell counts with the same area
// (a projected grid: cell_size_x·cell_size_y).
// Output, with H = max - min over valid cells:
//   integral          HI = (mean - min) / (max - min) (Pike & Wilson 1971's elevation-relief ratio,
//                     equal to the area under Strahler 1952's hypsometric curve): 1/2 for a plane,
//                     1/3 for a cone, 1/2 for a paraboloid of revolution over its disc.
//   relative_height   h/H at `points` evenly spaced levels from 0 to 1;
//   relative_area     a/A: the share of valid cells at or above min + h·H (1 at h = 0);
//   histogram         counts of valid cells in `points - 1` equal bins of [min, max] (the top
//                     value in the last bin).
// Throws InputError when no cell is valid or when H = 0 (a flat terrain has no hypsometry).
#pragma once

#include <cstddef>
#include <vector>

#include "core/grid.hpp"

namespace gt {

struct Hypsometry {
  double min = 0.0;
  double max = 0.0;
  double mean = 0.0;
  double integral = 0.0;
  std::vector<double> relative_height;
  std::vector<double> relative_area;
  std::vector<std::size_t> histogram;
};

Hypsometry hypsometry(const Heightmap& dem, int points = 21);

}  // namespace gt
