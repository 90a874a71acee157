#version 450
// Second pass of step 4 of Beneš's dissolution erosion (digest 000 §3.3): a cell loses the water it
// sends and gains what its neighbours send to it, the same numbers, and the dissolved material
// goes with its water (s·Δw_n/d of the sender). Decisions: reference/erosion/dissolution.cpp.
// Mutants (compare/mutants/dissolution.cpp): DISSOLVED_LEFT_BEHIND (GPU only); the calibrated pair
// of the shadow step's bounds (GPU only): INFLOW_OFF_ABOVE_BOUND, ONE_ULP_OFF_BELOW_BOUND (must survive).
// Inputs:  DissolutionBlock (uniform binding 0), valid (2), outflows (3), water (4), dissolved (5)
//          (dissolution_block.glsl).
// Outputs: next_water (7), next_dissolved (8).
// Twin:    reference/erosion/dissolution.cpp.
#include "common/grid.glsl"
#include "erosion/dissolution_block.glsl"

#ifdef GT_MUTANT_EROSION_DISSOLUTION_INFLOW_OFF_ABOVE_BOUND
const float DRIFT = 1.0 + 1.0 / 32768.0;  // 1 + 2^-15
#endif

// The dissolved material that goes with `sent` of a cell's water.
float carried(uint index, float sent) {
#ifdef GT_MUTANT_EROSION_DISSOLUTION_DISSOLVED_LEFT_BEHIND
  return 0.0;
#else
  precise float share = sent > 0.0 ? dissolved[index] * sent / water[index] : 0.0;
  return share;
#endif
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float depth = water[index];
  precise float material = dissolved[index];
  if (valid[index] != 0u) {
    for (int k = 0; k < 8; ++k) {
      precise float sent = outflow(index, k);
      depth = depth - sent;
      material = material - carried(index, sent);
    }
    for (int k = 0; k < 8; ++k) {
      if (!pipe_open(cell, k)) continue;
      uint neighbour = cell_index(cell + pipe_offsets[k], grid_size);
      precise float received = outflow(neighbour, opposite_pipe(k));
#ifdef GT_MUTANT_EROSION_DISSOLUTION_INFLOW_OFF_ABOVE_BOUND
      depth = depth + received * DRIFT;
#else
      depth = depth + received;
#endif
      material = material + carried(neighbour, received);
    }
  }
#ifdef GT_MUTANT_EROSION_DISSOLUTION_ONE_ULP_OFF_BELOW_BOUND
  // Rounding the other way, as an honest twin may: one ulp up on even cells, one down on odd ones.
  if (depth != 0.0) {
    uint bits = floatBitsToUint(depth);
    depth = uintBitsToFloat((cell.x + cell.y) % 2 == 0 ? bits + 1u : bits - 1u);
  }
#endif
  next_water[index] = depth;
  next_dissolved[index] = material;
}
