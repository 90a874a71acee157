#version 450
// First pass of step 4 of Beneš's dissolution erosion (digest 000 §3.3, eqs. 2.6-2.9): the water
// each cell sends to each of its 8 neighbours, Δw·Δh_n/ΣΔh with Δw = min(d, Σ min(d, Δh_n/2)), or
// with water_share = mean_level min(d, ΣΔh_n/(n + 1)).
// Decisions: reference/erosion/dissolution.cpp. All arithmetic is `precise`.
// Mutants (compare/mutants/dissolution.cpp): DROPPED_PIPE (GPU only), UNHALVED_PAIR (both twins).
// Inputs:  DissolutionBlock (uniform binding 0), terrain (1), valid (2), water (4)
//          (dissolution_block.glsl), the state after dissolution_local.comp.
// Outputs: outflows (3): 8 per cell, two vec4.
// Twin:    reference/erosion/dissolution.cpp.
#include "common/grid.glsl"
#include "erosion/dissolution_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
#ifdef GT_MUTANT_EROSION_DISSOLUTION_UNHALVED_PAIR
  const float pair_share = 1.0;
#else
  const float pair_share = 0.5;
#endif
  precise float fall[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  precise float fall_total = 0.0;
  precise float levelling_total = 0.0;
  int lower = 0;
  precise float depth = water[index];
  if (valid[index] != 0u && depth > 0.0) {
    precise float surface = terrain[index] + depth;
#ifdef GT_MUTANT_EROSION_DISSOLUTION_DROPPED_PIPE
    for (int k = 0; k < 7; ++k) {
#else
    for (int k = 0; k < 8; ++k) {
#endif
      if (!pipe_open(cell, k)) continue;
      uint neighbour = cell_index(cell + pipe_offsets[k], grid_size);
      precise float difference = surface - (terrain[neighbour] + water[neighbour]);
      if (difference > 0.0) {
        fall[k] = difference;
        fall_total = fall_total + difference;
        levelling_total = levelling_total + min(depth, difference * pair_share);
        ++lower;
      }
    }
  }
  precise float sent[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  if (fall_total > 0.0) {
    precise float given = min(depth, mean_level != 0 ? fall_total / float(lower + 1) : levelling_total);
    for (int k = 0; k < 8; ++k) sent[k] = given * fall[k] / fall_total;
  }
  outflows[2u * index] = vec4(sent[0], sent[1], sent[2], sent[3]);
  outflows[2u * index + 1u] = vec4(sent[4], sent[5], sent[6], sent[7]);
}
