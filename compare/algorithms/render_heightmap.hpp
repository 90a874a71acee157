// Comparing the two twins of seed 000's heightmap from a mesh (reference/render/heightmap_from_mesh
// and gpu/render/heightmap_from_mesh), used by the `render.heightmap_from_mesh` cases and the GPU
// test. Issue 6: interior texels must match (up to the GPU's float rounding), texels on silhouette
// edges within one texel.
//
// Texel classes (3×3 neighbourhoods; neighbours outside the grid count as uncovered):
//   interior     covered on both sides, and so are its 8 neighbours on both sides
//   silhouette   has an uncovered neighbour on either side
// Error model of an interior texel t (u = 2^-24, float's unit roundoff; W, H the texels; s(t) the
// local slope of the reference, in height units per texel: the larger one-sided difference to a
// covered neighbour along x plus the same along y, at least |∂h/∂x| + |∂h/∂y| of the triangle drawn
// there when the neighbours lie on it):
//   B(t) = 16·u·(1 + s(t)·(W + H))
// Terms, all as multiples of u: the GPU rounds the centred positions and the matrix entries to float
// and multiplies (per-vertex z' within about 3u, window x, y within about 3u·W/2 pixels, which moves
// the plane by s·1.5u·W); the rasterizer sets the plane up in float (gradients within about 4u
// relative, over distances up to W + H: 4u·s·(W + H)) and evaluates a0 + dadx·x + dady·y with terms
// up to s·(W + H) (about 3u of their sum); 1 - z' rounds once more (u). That sums to about
// 6u + 8.5u·s·(W + H); 16 leaves room for the depth test choosing, among surfaces closer than the
// same error, another one than the reference (their heights then differ by no more).
// Beyond interior texels nothing is exact: a silhouette texel's edge may move by one texel, so its
// GPU height must be one of the reference heights around it, within the same B(t).
// Exact coverage: when every window coordinate is exact in float (exact_window_coordinates below),
// both twins snap the same vertices and apply GL's coverage rules to the same numbers, so they must
// cover the same texels, silhouettes included, except where a surface lies at the bottom of the box:
// its depth 1 - h/2 may round to the cleared depth 1 in float, so a texel covered on one side only
// with a height there of at most B(t) is not counted (coverage_differences_beyond_bottom).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/grid.hpp"
#include "core/mesh.hpp"
#include "core/param_table.hpp"

namespace gt {

struct HeightmapParity {
  std::size_t interior_texels = 0;
  double interior_max_abs = 0.0;    // max |gpu - cpu| over interior texels
  double interior_bound = 0.0;      // max B(t) over interior texels
  double interior_model_ratio = 0.0;  // max |gpu - cpu| / B(t) over interior texels (<= 1 passes)
  std::size_t coverage_differences = 0;                 // texels covered on one side only
  std::size_t coverage_differences_off_silhouette = 0;  // of those, not silhouette texels (must be 0)
  std::size_t silhouette_texels_both_covered = 0;
  // Silhouette texels covered on both sides whose GPU height lies outside [min, max] of the covered
  // reference heights in its 3×3 neighbourhood, widened by B(t): more than a one-texel shift.
  std::size_t silhouette_beyond_one_texel = 0;
  std::size_t covered_cpu = 0, covered_gpu = 0;
  // Coverage differences whose covered side's height exceeds B(t) (that side's local slope).
  std::size_t coverage_differences_beyond_bottom = 0;
};

// Whether both twins' window coordinates of every vertex are exact, so that coverage must agree
// texel for texel: each vertex's offset from the box centre is exact in float, the scales 2/Δx and
// 2/Δy are powers of two, NDC + 1 is exact in float, and the window coordinates are multiples of
// 2^-subpixel_bits below 2^(23 - subpixel_bits) (so every float operation of the transform has a
// representable exact result, and snapping moves nothing).
bool exact_window_coordinates(const Mesh& mesh, int width, int height, int subpixel_bits);

HeightmapParity compare_mesh_heightmaps(const Heightmap& cpu, const Grid<std::uint8_t>& cpu_covered,
                                        const Grid<float>& gpu, const Grid<std::uint8_t>& gpu_covered);

// The parameters of a render.heightmap_from_mesh case and their declarations (core/param_table.hpp).
struct HeightmapRenderParams {
  int width = 256;
  int height = 256;
  int subpixel_bits = 8;
  bool tent = false;  // generated = tent: the probe tent instead of a mesh input (render_probe.hpp)
};
const ParamTable<HeightmapRenderParams>& heightmap_render_param_table();

}  // namespace gt
