// The sampled lattice as the cave meshers read it (reference/cave/lattice_cubes.hpp): the air pad,
// the rock test, cube corners, where a vertex sits on its edge and the edge's global key.
//
// Rock: a sample inside the block is rock iff density < threshold (strict); pad samples (outside
// 0..sample_counts - 1, solid blocks only) are air.
// Cube corner c = dx + 2·dy + 4·dz at the cube's lower corner + (dx, dy, dz). An edge of a cube is
// a pair of corners (lower, upper) whose bits nest; its direction is upper - lower.
// Vertex on the edge from lower point a to a + d: t = clamp((threshold - v_a) / (v_b - v_a), δ,
// 1 - δ) with linear placement and both endpoints inside (δ = edge_margin below, a power of two, as
// core/params/cave.hpp defines it), else 0.5; position_c = float(global a_c) + t·float(d_c),
// all `precise` (no fused multiply-add), so llvmpipe repeats the float reference bit for bit. The
// division is the reference's; GLSL only promises 2.5 ulp for it, so another GPU (NVIDIA) may
// differ by that much in t where llvmpipe, which divides correctly rounded, does not.
// Edge key (core/params/cave.hpp): direction | (x + 2^19) << 3 | (y + 2^19) << 23 | (z + 2^19) << 43
// as (low word, high word).
// Guarded: several cave programs include it.
// Inputs:  declares density (storage binding 1, read only); CaveBlock (cave/cave_block.glsl).
// Outputs: the rock test, the vertex position on an edge, the edge key.
// Twin:    reference/cave/lattice_cubes.hpp (lattice_cubes.cpp).
#ifndef GT_CAVE_LATTICE_GLSL
#define GT_CAVE_LATTICE_GLSL

#include "cave/cave_block.glsl"

layout(std430, binding = 1) readonly buffer Density { float density[]; };

ivec3 corner_offset(int corner) { return ivec3(corner & 1, (corner >> 1) & 1, corner >> 2); }

bool is_pad(ivec3 point) { return any(lessThan(point, ivec3(0))) || any(greaterThanEqual(point, sample_counts.xyz)); }

// The threshold the mesher compares with (the block's, or its negation under the both-twins mutant
// threshold_negated, as reference/cave/lattice_cubes.cpp does).
float rock_threshold() {
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_THRESHOLD_NEGATED
  return -threshold;
#else
  return threshold;
#endif
}

bool is_rock(ivec3 point) {
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_THRESHOLD_INCLUSIVE
  return !is_pad(point) && density[sample_index(point)] <= rock_threshold();  // mutant (GPU only)
#else
  return !is_pad(point) && density[sample_index(point)] < rock_threshold();
#endif
}

// Bit c set iff corner c of the cube is rock.
uint rock_corners(ivec3 cube) {
  uint bits = 0u;
  for (int corner = 0; corner < 8; ++corner) {
    if (is_rock(cube + corner_offset(corner))) bits |= 1u << uint(corner);
  }
  return bits;
}

// δ of the edge from global point a to a + step: 2^max(-10, e - 21) with 2^e <= m + 1 < 2^(e+1),
// m the largest |coordinate| of the two endpoints (exact: the highest bit of an integer).
float edge_margin(ivec3 global_lower, ivec3 step) {
  uvec3 magnitudes = uvec3(max(abs(global_lower), abs(global_lower + step)));
  uint largest = max(magnitudes.x, max(magnitudes.y, magnitudes.z));
  return ldexp(1.0, max(-10, findMSB(largest + 1u) - 21));
}

// Where on the edge from local point `lower` to lower + step the vertex sits (0 at lower).
float edge_parameter(ivec3 lower, ivec3 step) {
  ivec3 upper = lower + step;
#if defined(GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_MIDPOINT_OFF) || defined(GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_MIDPOINT_OFF)
  // Mutants: midpoint placement a quarter along the edge (GPU only, or both twins).
  if (linear_placement == 0u && !is_pad(lower) && !is_pad(upper)) return 0.25;
#endif
  if (linear_placement == 0u || is_pad(lower) || is_pad(upper)) return 0.5;
  precise float lower_value = density[sample_index(lower)];
  precise float upper_value = density[sample_index(upper)];
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_T_FROM_UPPER
  precise float t = (rock_threshold() - upper_value) / (lower_value - upper_value);  // mutant (GPU only)
#else
  precise float t = (rock_threshold() - lower_value) / (upper_value - lower_value);
#endif
  float margin = edge_margin(lattice_origin.xyz + lower, step);
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_VERTEX_WRONG_END
  return 1.0 - clamp(t, margin, 1.0 - margin);  // mutant (both twins): measured from the upper end
#else
  return clamp(t, margin, 1.0 - margin);
#endif
}

vec3 vertex_position(ivec3 lower, int direction) {
  ivec3 step = corner_offset(direction);
  precise float t = edge_parameter(lower, step);
  precise vec3 position = vec3(lattice_origin.xyz + lower) + t * vec3(step);
  return position;
}

uvec2 lattice_edge_key(ivec3 global_lower, int direction) {
  uvec3 biased = uvec3(global_lower + ivec3(1 << 19)) & uvec3(0xFFFFFu);
  uint low = uint(direction) | (biased.x << 3) | (biased.y << 23);
  uint high = (biased.y >> 9) | (biased.z << 11);
  return uvec2(low, high);
}

#endif
