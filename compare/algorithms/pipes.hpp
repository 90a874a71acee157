// The parameters of an `erosion.pipe` case (compare/algorithms/pipes.cpp): erosion.pipe's own
// (core/params/hydraulic.hpp) and the scenario's — the initial water, the rain map, one point
// source and the checkpoints (see pipes.cpp for their meaning).
#pragma once

#include <array>

#include "core/param_table.hpp"
#include "core/params/hydraulic.hpp"

namespace gt {

enum class InitialWater { dry, depth, sea_level };
enum class RainMap { none, orographic };

struct PipeCaseParams {
  HydraulicParams hydraulic;
  InitialWater initial_water = InitialWater::depth;
  double initial_depth = 0.1;  // m
  double sea_level = 0.0;      // m
  RainMap rain_map = RainMap::none;
  double rain_map_rate = 0.0;  // m/s on the highest cell
  double source_rate = 0.0;    // m³/s; 0 = no source
  double source_x = 0.5;       // shares of the width and height
  double source_y = 0.5;
  int checkpoints = 16;
  // Šťava's layers' initial thicknesses where no input field layer_k gives them, m.
  std::array<double, max_pipe_layers> layer_thickness{0.5, 0.5, 0.5};
};

// The declarations (core/param_table.hpp: erosion.pipe's, then the scenario's).
const ParamTable<PipeCaseParams>& pipe_case_param_table();

}  // namespace gt
