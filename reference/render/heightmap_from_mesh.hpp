// Heightmap from a mesh (seed 000, digest 000_water_erosion.md §4.3, eqs. 4.1–4.4), CPU reference.
//
// The mesh rendered orthographically from above (along its local -z) by the reference rasterizer,
// keeping the highest surface. Slow by design.
// heightmap_from_mesh(mesh, width, height, subpixel_bits = 8) -> MeshHeightmap
// require_visible_from_above(mesh): the refusal heightmap_from_mesh makes, available before any work
//   (the driver's bad input).
//
// The mapping (eqs. 4.1, 4.2): the bounding box of all vertex positions (Blender's bound_box) goes
// to x, y ∈ [-1, 1] with s_x = 2/Δx, s_y = 2/Δy and to z' = 0.5 - s_z·(z - c_z) ∈ [0, 1], s_z = 1/Δz
// (top 0, bottom 1), c the box centre; w = 1. The depth test LESS keeps the smallest z', i.e. the
// highest surface, and the fragment writes red = 1 - z' (eq. 4.4: top 1, bottom 0) with z'
// interpolated over the triangle. Colour is cleared to 0 (uncovered texels are 0, as the seed's
// fresh texture) and depth to 1 (the seed clears to 2.0, which GL clamps to 1).
//
// Inputs:  mesh            double positions (any unit), uint32 triangles; face orientation is ignored
//                          (the seed renders without culling)
//          width, height   texels of the heightmap
//          subpixel_bits   GL_SUBPIXEL_BITS of the GL implementation to match (see rasterizer.hpp)
// Outputs: heights in [0, 1] (1 - z' where covered, 0 elsewhere; row 0 = largest y), the coverage mask
//          (1 where a surface was drawn) and the aspect ratios of eq. 4.3: d_xy = s_x/s_y = Δy/Δx,
//          d_z = s_x/s_z = 2Δz/Δx.
// Units:   heights dimensionless (vertical_unit "1"); cell sizes in the mesh's unit (below).
// Throws:  InputError when the mesh has no triangles or no extent in x or y (nothing is seen from
//          above); std::invalid_argument from the rasterizer for width or height outside [1, 16384] or
//          subpixel_bits outside [0, 16].
// Twin:    gpu/render/heightmap_from_mesh.hpp (HeightmapFromMesh) with
//          gpu/shaders/render/heightmap_from_mesh.{vert,frag}.
// Decisions where the seed is vague:
//   - Coverage: a texel is covered when a fragment passed the depth test, i.e. its depth is < 1. A
//     surface exactly at the bottom of the box (z' = 1, depth 1) fails LESS against the cleared 1
//     and leaves its texels uncovered with height 0, which is its height anyway.
//   - Rows: GL's row 0 is the bottom (smallest y); the grid's row 0 is the top of the picture
//     (core/grid.hpp: north for DEMs), so grid row r holds GL row height - 1 - r and +y points to
//     row 0, like a DEM seen from above with north up.
//   - Degenerate boxes: Δz = 0 (a flat mesh) takes s_z = 1, so the surface sits at z' = 0.5 (height
//     0.5) and d_z = s_x; Δx = 0 or Δy = 0 (nothing seen from above) and a mesh without triangles
//     throw InputError.
//   - Cell size: cell_size_x = Δx/width, cell_size_y = Δy/height in the mesh's unit
//     (horizontal_unit "mesh").
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/mesh.hpp"

namespace gt::reference {

struct MeshHeightmap {
  Heightmap heights;            // 1 - z' where covered, 0 elsewhere; row 0 = largest y
  Grid<std::uint8_t> covered;   // 1 where a surface was drawn, same rows
  double d_xy = 1.0;            // s_x / s_y = Δy/Δx (eq. 4.3)
  double d_z = 1.0;             // s_x / s_z = 2Δz/Δx (eq. 4.3)
};

// Throws InputError when the mesh has no triangles or no extent in x or y (nothing is seen from
// above): the refusal heightmap_from_mesh makes, available before any work (the driver's bad input).
void require_visible_from_above(const Mesh& mesh);

MeshHeightmap heightmap_from_mesh(const Mesh& mesh, int width, int height, int subpixel_bits = 8);

}  // namespace gt::reference
