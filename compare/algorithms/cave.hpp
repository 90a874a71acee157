// The parameters of the cave cases: a meshed block (cave.marching_tetrahedra, cave.marching_cubes;
// compare/algorithms/cave.cpp) and an endless path (cave.endless; cave_endless.cpp), each the
// block's (core/params/cave.hpp) and its own.
#pragma once

#include <cstddef>
#include <string>

#include "core/param_table.hpp"
#include "core/params/cave.hpp"
#include "reference/cave/lattice_cubes.hpp"

namespace gt {

struct CaveMeshParams {
  CaveParams block;
  // Linear for marching tetrahedra (the seed's final version), midpoint for marching cubes: the
  // latter's declarations take cave_mesh_defaults_for_cubes().
  reference::EdgePlacement placement = reference::EdgePlacement::linear;
  std::string mesh_format = "ply";  // of the meshes written beside the report
};

// The meshed block's defaults with marching cubes: midpoint placement.
CaveMeshParams cave_mesh_defaults_for_cubes();

struct CaveEndlessParams {
  CaveParams big_cube{.solid = false};  // an endless cave is made of open chunks
  int slabs = 20;
  std::string direction = "+x";         // +x, -x, +y, -y, +z or -z
  std::size_t max_vertices = 200000;    // ring-buffer capacity
};

// The declarations (core/param_table.hpp: the block's, then the case's own).
const ParamTable<CaveMeshParams>& cave_mesh_param_table();
const ParamTable<CaveEndlessParams>& cave_endless_param_table();

}  // namespace gt
