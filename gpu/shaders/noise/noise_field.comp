#version 450
// Samples one noise function on a grid (core/params/noise.hpp): sample (i, j) at
// origin + (i·step, j·step, 0, 0) in noise units. The host chooses the function with the define
// NOISE_VALUE(p) (p a vec4; e.g. gt_simplex3(p.xyz, kernel_radius_squared)) and, for fractal sums,
// FRACTAL_BASIS(q) (e.g. gt_perlin3(q)) with NOISE_VALUE(p) = gt_fbm(p.xyz, fractal_terms).
// Sample (i, j) is values[j·width + i]; TILEABLE blends four samples (sample_at below).
// Inputs:  NoiseFieldBlock (uniform binding 0: grid size, origin, step, kernel_radius_squared and,
//          for fractal sums, fractal_terms), the permutation (binding 5, noise/permutation.glsl), for
//          perlin3_texture the texture on unit 0 (noise/perlin_texture.glsl).
// Outputs: values (binding 1).
// Twin:    reference/noise/noise_field.cpp (host: gpu/noise/noise_field.cpp).
layout(local_size_x = 16, local_size_y = 16) in;

#include "common/grid.glsl"

#include "noise/simplex.glsl"
#include "noise/perlin.glsl"
#include "noise/perlin_texture.glsl"
#include "noise/cellular.glsl"
#ifdef FRACTAL_BASIS
#include "noise/fractal.glsl"
#endif

// Mirrored by NoiseFieldBlock in gpu/noise/noise_field.cpp (std140 offsets checked there).
layout(std140, binding = 0) uniform NoiseFieldBlock {
  vec4 origin;                  // rounded once from double on the host
  ivec2 grid_size;              // width, height
  float step;
  float kernel_radius_squared;  // simplex 3-D/4-D
#ifdef FRACTAL_BASIS
  GtFractalTerms fractal_terms; // fractal sums
#endif
};

layout(std430, binding = 1) writeonly buffer Values { float values[]; };

// A sample as stored. Mutants (reference/noise/noise_field.cpp makes the same changes): the
// calibrated pair of the float precision model, the samples 2^-13 (above the bound) or 2^-17
// (below) high; and in both twins the texture convention v/2 + 1/2 instead of v.
float stored_sample(float value) {
#if defined(GT_MUTANT_NOISE_PERLIN3_FLOAT_OFF_ABOVE_BOUND)
  return value + 1.0 / 8192.0;
#elif defined(GT_MUTANT_NOISE_PERLIN3_FLOAT_OFF_BELOW_BOUND)
  return value + 1.0 / 131072.0;
#elif defined(GT_MUTANT_NOISE_PERLIN3_UNIT_INTERVAL)
  return value * 0.5 + 0.5;
#else
  return value;
#endif
}

// The point of sample (i, j), each coordinate rounded twice as the reference forms it.
vec4 sample_point(int i, int j) {
  precise vec4 p = origin;
  p.x = origin.x + float(i) * step;
  p.y = origin.y + float(j) * step;
  return p;
}

// Sample (i, j). TILEABLE (the host defines it, with TILE_INVERSE_WIDTH and TILE_INVERSE_HEIGHT,
// 1/width and 1/height rounded once from double): seed 001's cross-blend of four samples one grid
// extent apart, in the reference's order (reference/noise/noise_field.cpp sample_at).
// Mutants: TILE_WEIGHTS_MIRRORED (both twins: c_x and 1 − c_x exchanged), GPU_TILE_SHIFT_BY_WIDTH
// (GPU only: the samples above shifted by the width instead of the height).
float sample_at(ivec2 cell) {
#ifdef TILEABLE
  precise float near_x = float(cell.x) * TILE_INVERSE_WIDTH;
  precise float near_y = float(cell.y) * TILE_INVERSE_HEIGHT;
#ifdef GT_MUTANT_NOISE_HETERO_TERRAIN_TILE_WEIGHTS_MIRRORED
  precise float weight_x = 1.0 - near_x;
  precise float other_x = near_x;
#else
  precise float weight_x = near_x;
  precise float other_x = 1.0 - near_x;
#endif
#ifdef GT_MUTANT_NOISE_HETERO_TERRAIN_GPU_TILE_SHIFT_BY_WIDTH
  int shift_y = grid_size.x;
#else
  int shift_y = grid_size.y;
#endif
  precise float here = weight_x * NOISE_VALUE(sample_point(cell.x, cell.y)) +
                       other_x * NOISE_VALUE(sample_point(cell.x + grid_size.x, cell.y));
  precise float above = weight_x * NOISE_VALUE(sample_point(cell.x, cell.y + shift_y)) +
                        other_x * NOISE_VALUE(sample_point(cell.x + grid_size.x, cell.y + shift_y));
  precise float blended = near_y * here + (1.0 - near_y) * above;
  return blended;
#else
  return NOISE_VALUE(sample_point(cell.x, cell.y));
#endif
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  values[cell_index(cell, grid_size)] = stored_sample(sample_at(cell));
}
