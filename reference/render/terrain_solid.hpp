// A heightmap as a closed solid: surface, skirts and base as one watertight triangle mesh, CPU reference.
//
// The terrain surface, vertical skirts along the boundary of its valid region and a flat base below
// it, as one watertight, consistently oriented triangle mesh (terrain before and after erosion,
// rendered by the Phong twins; `groundtruth render`).
// terrain_solid(heights, options = {}) -> TerrainSolid
//
// World coordinates (right-handed, y up, which is what reference/render/phong.hpp's orbit camera
// expects: it orbits around +y):
//   sample (i, j) of column i (east) and row j (row 0 = first stored row, north for DEMs) is the
//   vertex x = (i - (W-1)/2)·cell_size_x, y = vertical_scale·h(i, j), z = (j - (H-1)/2)·cell_size_y
//   so x points east, y up, z south (x × y = z), the grid is centred on x = z = 0 (keeps the GPU's
//   float coordinates small) and y keeps the heights' datum (metres above sea level for DEMs).
//
// Surface: one vertex per sample, two triangles per quad of 2×2 neighbouring samples when all four
// are valid, split along the diagonal (i, j)–(i+1, j+1): (p00, p11, p10) and (p00, p01, p11), where
// p_ab is sample (i + a, j + b). A quad with a no-data corner is left out, so no-data cells cut the
// surface along quad edges: the valid region is a union of closed squares of the sample lattice,
// and a no-data sample removes the up to four quads around it (its valid neighbours stay as
// boundary vertices). Heights are never invented for no-data samples.
//   Pinches: where two kept quads meet only at a shared corner (diagonal neighbours, the other two
//   quads at that corner left out), the surface would not be a manifold there and the skirts would
//   meet along one vertical edge four times. The later of the two quads in row-major order is
//   dropped (counted in dropped_quads) and the test repeats until no pinch is left; a single
//   no-data sample never makes one, a mask with diagonal gaps does.
// Skirts: every quad side that borders a left-out quad (or the grid's edge) is a boundary edge;
//   below it hangs a vertical wall of two triangles down to the base. Holes in the mask get walls
//   too (facing into the hole).
// Base: a copy of the kept quads' triangulation at y = base_y, reversed so that it faces down.
//   base_y = min over kept surface vertices of y, minus base_depth; the automatic depth is
//   max(0.2·(y_max - y_min), 0.02·max((W-1)·cell_size_x, (H-1)·cell_size_y)), y over the kept
//   surface vertices, so the slab is a fifth of the relief and never thin for flat terrain. The
//   base is strictly below every surface vertex, so no wall triangle has zero area.
// Orientation: every triangle is counter-clockwise seen from outside (outward normals by the right-
// hand rule): the surface faces +y, the base -y, the walls away from the region they bound.
// Topology: each connected part of the kept surface gives one closed solid (the part doubled,
// glued along its boundary): genus = number of holes of that part; a full grid is a sphere
// (genus 0, Euler characteristic 2).
// Volume: exactly Σ over kept triangles of (cell_size_x·cell_size_y / 2)·(mean of its three y
//   - base_y): the prisms between the piecewise-linear surface and the base.
// Order: surface vertices (row-major over used samples), then base vertices in the same order;
// surface triangles (row-major over quads), base triangles likewise, then the walls.
//
// Inputs:  heights   Grid<double> (core/grid.hpp): values are heights in `vertical_unit`, cell centres
//                    cell_size_x and cell_size_y apart in `horizontal_unit`; an optional validity mask
//                    (0 = no data).
//          options   vertical_scale  multiplies every height (vertical exaggeration; 1 keeps them)
//                    base_depth      how far the base lies below the lowest surface vertex, in the
//                                    mesh's unit; 0 chooses it (see "Base" above)
// Outputs: the mesh and what was decided: the base height, the counts of surface, base and skirt
//          triangles, and the quads dropped to keep the surface manifold.
// Units:   both units should be metres (the readers of core/io give metres) so that the solid is not
//          distorted; the function does not convert units.
// Throws:  InputError for: a non-positive or non-finite cell size, vertical_scale or base_depth out
//          of range (vertical_scale > 0 and finite, base_depth >= 0 and finite), values or a mask that
//          do not match the grid's size, a NaN or infinite valid height, no quad of four valid samples
//          (all masked, a single row or column, or no 2×2 valid block), a base depth that vanishes
//          below the heights' magnitude in double, and more vertices than 32-bit indices address.
// Twin:    none: the solid is built once on the CPU and both Phong twins draw it (phong.hpp).
#pragma once

#include <cstddef>

#include "core/grid.hpp"
#include "core/mesh.hpp"

namespace gt::reference {

struct TerrainSolidOptions {
  double vertical_scale = 1.0;
  double base_depth = 0.0;  // 0: automatic
};

struct TerrainSolid {
  Mesh mesh;
  double base_y = 0.0;          // height of the base plane (mesh unit)
  double base_depth = 0.0;      // lowest surface vertex minus base_y
  std::size_t surface_triangles = 0;
  std::size_t base_triangles = 0;
  std::size_t skirt_triangles = 0;
  std::size_t kept_quads = 0;
  std::size_t dropped_quads = 0;  // quads with four valid corners dropped at pinches
};

TerrainSolid terrain_solid(const Heightmap& heights, const TerrainSolidOptions& options = {});

}  // namespace gt::reference
