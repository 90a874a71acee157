#version 450
// End of one pass of Beyer's particle erosion in batch ordering (seed 000 §2.7, digest 000 §3.7;
// core/params/droplets.hpp): each valid cell adds what the pass's droplets moved into or out of it,
// h = h + float(delta) · quantum (float(delta) rounded to nearest, the product exact as quantum is a
// power of two, the sum rounded once), and clears its delta for the next pass. Masked cells and
// their delta (never written) are left alone. Heights in the caller's units.
// Mutants (compare/mutants/beyer.cpp): APPLY_SCALED (both twins: reference/erosion/droplets.hpp).
// Inputs:  BeyerBlock (uniform binding 0), valid (2), delta (3): beyer_block.glsl.
// Outputs: heights (1) of the valid cells; delta (3) cleared.
// Twin:    reference/erosion/beyer.cpp (PassTerrain::apply).
#ifndef BEYER_BATCH
#error beyer_apply.comp runs in the batch ordering only: compile it with BEYER_BATCH
#endif
#include "common/grid.glsl"
#include "erosion/beyer_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!open_cell(cell)) return;
  uint index = cell_index(cell, grid_size);
  precise float change = float(delta[index]) * quantum;
#if defined(GT_MUTANT_EROSION_BEYER_APPLY_SCALED)
  change = change * 1.0009765625;  // 1 + 2^-10
#elif defined(GT_MUTANT_EROSION_BEYER_APPLY_SCALED_ABOVE_BOUND)
  change = change * (1.0 + 1.0 / 32768.0);  // 1 + 2^-15
#elif defined(GT_MUTANT_EROSION_BEYER_APPLY_SCALED_BELOW_BOUND)
  change = change * (1.0 + 1.0 / 8388608.0);  // 1 + 2^-23
#endif
  precise float height = heights[index] + change;
  heights[index] = height;
  delta[index] = 0;
}
