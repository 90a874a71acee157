// The cube sphere as a closed triangle mesh (digest 002 §4.3: the demo draws the planet as a
// procedural sphere mesh): a vertex at every cell corner on the unit sphere (through the warp, as
// the cells are), corners shared by neighbouring faces welded into one vertex, two triangles per cell
// wound counter-clockwise seen from outside. 6R² + 2 vertices, 12R² triangles, genus 0; region i
// owns triangles 2i and 2i + 1. What the mesh checks prove watertight and a renderer draws.
#pragma once

#include "core/mesh.hpp"
#include "core/planet/cube_sphere.hpp"

namespace gt {

Mesh sphere_mesh(const CubeSphere& sphere, CubeWarp cube_warp = {});

}  // namespace gt
