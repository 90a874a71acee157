#version 450
// Steps 1-3 of Beneš's dissolution erosion (digest 000 §3.3, eqs. 2.1-2.5) on each cell alone:
// rain, evaporation with its threshold, then dissolution or deposition towards S = K_s·d.
// Decisions: reference/erosion/dissolution.cpp. All arithmetic is `precise` (no fused multiply-add),
// in the reference's order, so that ref<float> repeats it.
// Mutants (compare/mutants/dissolution.cpp): EVAPORATED_UNCOUNTED (GPU only), FLOAT_EVAPORATED_UNCOUNTED
// (the float twins: ref<float> makes the same change), THRESHOLD_IGNORED, DEPOSITION_KEPT (both twins).
// Inputs:  DissolutionBlock (uniform binding 0), terrain (1), valid (2), water (4), dissolved (5),
//          evaporated (6) (dissolution_block.glsl).
// Outputs: terrain, water, dissolved, evaporated, in place.
// Twin:    reference/erosion/dissolution.cpp.
#include "common/grid.glsl"
#include "erosion/dissolution_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  if (valid[index] == 0u) return;
  precise float depth = water[index] + rain;
  precise float kept = depth * retained;
#ifdef GT_MUTANT_EROSION_DISSOLUTION_THRESHOLD_IGNORED
  precise float remaining = kept;
#else
  precise float remaining = kept < threshold ? 0.0 : kept - threshold;
#endif
#if defined(GT_MUTANT_EROSION_DISSOLUTION_EVAPORATED_UNCOUNTED) || \
    defined(GT_MUTANT_EROSION_DISSOLUTION_FLOAT_EVAPORATED_UNCOUNTED)
  evaporated[index] = evaporated[index] + (kept - remaining);
#else
  evaporated[index] = evaporated[index] + (depth - remaining);
#endif
  water[index] = remaining;
  precise float capacity = saturation * remaining;
  precise float carried = dissolved[index];
  if (carried < capacity) {
    precise float taken = dissolution_rate * (capacity - carried);
    terrain[index] = terrain[index] - taken;
    dissolved[index] = carried + taken;
  } else {
    precise float laid = deposition_rate * (carried - capacity);
    terrain[index] = terrain[index] + laid;
#ifndef GT_MUTANT_EROSION_DISSOLUTION_DEPOSITION_KEPT
    dissolved[index] = carried - laid;
#endif
  }
}
