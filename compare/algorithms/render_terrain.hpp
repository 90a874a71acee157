// The parameters of a render.terrain case (compare/algorithms/render_terrain.cpp): the image and
// camera, the solid, the look, and the erosion applied first with the parameters of the erosion it
// names (erosion.thermal's in physical heights, erosion.pipe's, erosion.layered's case), declared
// under the prefixes thermal_, pipe_ and layered_.
#pragma once

#include <string>

#include "compare/layered_case.hpp"
#include "core/param_table.hpp"
#include "core/params/hydraulic.hpp"
#include "core/params/thermal.hpp"
#include "reference/render/phong.hpp"

namespace gt {

struct TerrainRenderParams {
  int width = 320;  // pixels
  int height = 240;
  double fov_deg = 37.0;
  double azimuth_deg = 35.0;
  double elevation_deg = 30.0;
  int subpixel_bits = 8;
  double vertical_scale = 1.0;
  double base_depth = 0.0;  // m; 0: automatic
  reference::Look look = reference::Look::terrain;
  std::string drape = "none";  // none, astronaut, grass or material
  double min_covered_share = 0.05;
  std::string erode = "none";  // none, thermal, pipe or layered
  ThermalParams thermal;       // without normalised and vertical_aspect: physical heights
  HydraulicParams pipe;
  LayeredCaseParams layered;
};

// The declarations (core/param_table.hpp).
const ParamTable<TerrainRenderParams>& terrain_render_param_table();

}  // namespace gt
