#version 450
// Gather pass of Jákó & Tóth's thermal erosion (digest 000 §3.6): a cell loses what it sends and
// gains what its neighbours send to it, the same numbers, so material is conserved.
// Mutants (compare/mutants/thermal.cpp): SWAPPED_INFLOW (GPU only), FIRST_OUTFLOW_KEPT (both twins).
// Inputs:  ThermalJakoBlock (uniform binding 0), heights (1), valid (2), outflows (3)
//          (thermal_jako_block.glsl).
// Outputs: next_heights (4).
// Twin:    reference/erosion/thermal_jako.cpp.
#include "common/grid.glsl"
#include "erosion/thermal_jako_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float height = heights[index];
  if (valid[index] != 0u) {
#ifdef GT_MUTANT_EROSION_THERMAL_JAKO_FIRST_OUTFLOW_KEPT
    for (int k = 1; k < 8; ++k) height = height - outflow(index, k);
#else
    for (int k = 0; k < 8; ++k) height = height - outflow(index, k);
#endif
    for (int k = 0; k < 8; ++k) {
      if (!pipe_open(cell, k)) continue;
#ifdef GT_MUTANT_EROSION_THERMAL_JAKO_SWAPPED_INFLOW
      height = height + outflow(cell_index(cell + pipe_offsets[k], grid_size), k);
#else
      height = height + outflow(cell_index(cell + pipe_offsets[k], grid_size), opposite_pipe(k));
#endif
    }
  }
  next_heights[index] = height;
}
