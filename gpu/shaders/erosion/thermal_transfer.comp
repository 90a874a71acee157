#version 450
// Pass B of seed 000's thermal erosion (digest 000 §4.6, Algorithm 11): across each pipe the two
// cells hold requests of opposite sign and the smaller magnitude moves; both ends compute the
// same minimum, so material is conserved.
// Mutants (compare/mutants/thermal.cpp): SWAPPED_GATHER (GPU only), UNCONSERVED_TRANSFER (both twins);
// the calibrated pair (GPU only): INFLOW_OFF_ABOVE_BOUND, ONE_ULP_OFF_BELOW_BOUND (must survive).
// Inputs:  ThermalBlock (uniform binding 0), heights (1), valid (2), requests (3) (thermal_block.glsl).
// Outputs: next_heights (4).
// Twin:    reference/erosion/thermal.cpp.
#include "common/grid.glsl"
#include "erosion/thermal_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float height = heights[index];
  if (valid[index] == 0u) {
    next_heights[index] = height;
    return;
  }
  vec4 own = requests[index];
  for (int k = 0; k < 4; ++k) {
    if (!pipe_open(cell, k)) continue;
#ifdef GT_MUTANT_EROSION_THERMAL_SWAPPED_GATHER
    float theirs = requests[cell_index(pipe_target(cell, k), grid_size)][k];
#else
    float theirs = requests[cell_index(pipe_target(cell, k), grid_size)][(k + 2) % 4];
#endif
    if (theirs < 0.0 && own[k] > 0.0) {
#ifdef GT_MUTANT_EROSION_THERMAL_INFLOW_OFF_ABOVE_BOUND
      height = height + min(-theirs, own[k]) * 1.0001220703125;  // 1 + 2^-13
#else
      height = height + min(-theirs, own[k]);
#endif
    } else if (theirs > 0.0 && own[k] < 0.0) {
#ifndef GT_MUTANT_EROSION_THERMAL_UNCONSERVED_TRANSFER
      height = height - min(theirs, -own[k]);
#endif
    }
  }
#ifdef GT_MUTANT_EROSION_THERMAL_ONE_ULP_OFF_BELOW_BOUND
  // Rounding the other way, as an honest twin may: one ulp up on even cells, one down on odd ones.
  if (height != 0.0) {
    uint bits = floatBitsToUint(height);
    height = uintBitsToFloat((cell.x + cell.y) % 2 == 0 ? bits + 1u : bits - 1u);
  }
#endif
  if (clamp_unit != 0u) height = clamp(height, 0.0, 1.0);
  next_heights[index] = height;
}
