// Parameters of the endless-cave block (seed 004, digest §2.2–2.4, §2.7) and the global key of a
// lattice edge that both cave twins weld vertices by (digest §2.6 "bit-exact watertightness", §8).
//
// A block is `size` cells per axis starting at lattice point `origin`: samples origin + (0..size)
// on every axis (size + 1 samples; the digest leaves cells vs samples open, §2.4 / §8.2, and cells
// make neighbouring blocks share their face samples). Lattice spacing is 1 world unit; the density
// at world point p is simplex3(p / scale) with rock where it is below `threshold` (digest §2.3).
// `solid` pads the block with one layer of air so the rock is capped at the block's faces and the
// mesh is closed (issue 5, "Watertightness"); without it the block is an open chunk.
//
// Lattice edge keys. Marching tetrahedra on the Kuhn decomposition (digest §2.6) uses seven edge
// directions per cube, all with components in {0, 1}: direction = dx + 2·dy + 4·dz, 1..7 (the
// three axes 1, 2, 4, the face diagonals 3, 5, 6 and the main diagonal 7); marching cubes uses the
// axes only. An edge is named by its lower endpoint (the one the direction is added to) and its
// direction. The key packs direction (3 bits) and each coordinate offset by 2^19 (20 bits each):
//   key = direction | (x + 2^19) << 3 | (y + 2^19) << 23 | (z + 2^19) << 43      (63 bits used)
// so every coordinate must satisfy -2^19 <= c < 2^19 (= 524,288). (The brief asked for 21 bits per
// coordinate and 3 for the direction: 66 bits, which does not fit in 64; 20 bits each does.)
#pragma once

#include <array>
#include <cstdint>

#include "core/param_table.hpp"

namespace gt {

struct CaveParams {
  double scale = 10.0;                  // world units per noise unit (SCALE_FACTOR, digest §2.2.2)
  double threshold = 0.0;               // rock iff density < threshold (TRESHOLD, digest §2.3)
  double kernel_radius_squared = 0.6;   // simplex kernel r²: 0.6 as the seed, 0.5 corrected (§2.2.5)
  std::uint32_t seed = 0;               // permutation: 0 = Perlin's reference table (the seed's)
  std::array<int, 3> origin{0, 0, 0};   // lattice coordinates of the block's first sample
  std::array<int, 3> size{30, 30, 30};  // cells per axis (BIG_CUBE_SIZE, digest §2.4); samples = size + 1
  bool solid = true;                    // pad with air: rock capped at the block's faces, mesh closed
};

// The declarations (core/param_table.hpp), their ParamSpecs, and the struct from resolve_params'
// output, checked by require_noise_range.
const ParamTable<CaveParams>& cave_param_table();
const ParamSpecs& cave_param_specs();
CaveParams cave_params_from_json(const nlohmann::json& resolved);

// Throws InputError when the density would sample simplex noise beyond largest_lattice_coordinate
// (the twins' lattice indices overflow 32 bits) anywhere in the block, its pad or up to 2000 slabs
// of an endless path beyond it.
void require_noise_range(const CaveParams& params);

// Lattice coordinates an edge key can hold: lattice_coordinate_min <= c <= lattice_coordinate_max.
inline constexpr std::int64_t lattice_coordinate_min = -(std::int64_t{1} << 19);
inline constexpr std::int64_t lattice_coordinate_max = (std::int64_t{1} << 19) - 1;

struct LatticeEdge {
  std::array<std::int64_t, 3> lower_point;  // global lattice coordinates of the lower endpoint
  int direction;                            // dx + 2·dy + 4·dz of the upper endpoint minus the lower, 1..7
};

// The key of the edge from `lower_point` to lower_point + (direction bits). Coordinates outside
// [lattice_coordinate_min, lattice_coordinate_max] or a direction outside 1..7 are the caller's
// error (the meshers check their block once, see lattice_range_fits).
std::uint64_t lattice_edge_key(const std::array<std::int64_t, 3>& lower_point, int direction);

// The edge margin δ of a lattice edge: the meshers clamp the edge parameter t to [δ, 1 - δ], so
// that no vertex lands on a lattice point. Without it a sample exactly at the threshold (the
// seed's noise has many: 93 in the 30³ big cube, digest §2.2.6) pulls every crossing edge it ends
// onto itself with t = 1: distinct vertices at one point, zero-area triangles, and faces touching
// where the surface should pass by (CGAL counts them as self-intersections). With every t strictly
// inside its edge, the surface in each tetrahedron is a proper triangle or quad and pieces of
// different tetrahedra meet only on shared faces.
//   m = the largest |coordinate| of the edge's two endpoints, e = floor(log2(m + 1)) (exact, from
//   the integer's highest bit), δ = 2^max(-10, e - 21) = max(2^-10, 4·ulp_float(m + 1))
// so that a + δ and a + 1 - δ stay distinct from the lattice points after float rounding (2^-10
// up to |coordinates| of 2047, 2^-9 at 5000, 2^-3 near the keys' limit 2^19). δ depends on the
// edge alone, so every block and chunk sharing an edge clamps it alike; a power of two, so 1 - δ
// is exact in float and double. The shift is at most δ·√3 lattice units.
double edge_margin(const std::array<std::int64_t, 3>& lower_point, int direction);

// The largest block (cubes, pad included) a case meshes and checks: a 128³ block took 3.7 GB and
// 97 s with both backends' meshes, CGAL and OpenMesh (about 1.8 kB per cube), so 2^22 cubes (161³)
// stays near 7.5 GB. Larger blocks belong to the benchmark, which only meshes.
inline constexpr std::int64_t largest_checked_cubes = std::int64_t{1} << 22;

// Throws InputError naming the block when its cubes (pad included) exceed largest_checked_cubes.
void require_checkable_block(const CaveParams& params);

// The inverse of lattice_edge_key.
LatticeEdge lattice_edge_from_key(std::uint64_t key);

// Whether every lattice point of a block of `samples` points per axis starting at `origin` (widened
// by one pad point on every side when `padded`) lies in the keys' range; then so does every lower
// edge endpoint the meshers use.
bool lattice_range_fits(const std::array<std::int64_t, 3>& origin, const std::array<std::int64_t, 3>& samples,
                        bool padded);

}  // namespace gt
