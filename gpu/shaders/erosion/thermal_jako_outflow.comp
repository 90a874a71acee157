#version 450
// Outflow pass of Jákó & Tóth's thermal erosion (digest 000 §3.6, eqs. 2.30-2.34): what each cell
// sends down each of its 8 pipes. Decisions: reference/erosion/thermal_jako.cpp.
// All arithmetic is `precise` so that no multiply-add is fused: ref<float> repeats it exactly.
// Mutants (compare/mutants/thermal.cpp): DROPPED_DIRECTION, LIMIT_OF_OPPOSITE_PIPE (GPU only),
// UNHALVED_TRANSFER (both twins).
// Inputs:  ThermalJakoBlock (uniform binding 0), heights (1), valid (2), cell constants (5)
//          (thermal_jako_block.glsl).
// Outputs: outflows (3): 8 per cell, two vec4.
// Twin:    reference/erosion/thermal_jako.cpp.
#include "common/grid.glsl"
#include "erosion/thermal_jako_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float drop[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  precise float largest_drop = 0.0;
  precise float drop_total = 0.0;
  if (valid[index] != 0u) {
    precise float height = heights[index];
#ifdef GT_MUTANT_EROSION_THERMAL_JAKO_DROPPED_DIRECTION
    for (int k = 0; k < 7; ++k) {
#else
    for (int k = 0; k < 8; ++k) {
#endif
      if (!pipe_open(cell, k)) continue;
      precise float difference = height - heights[cell_index(cell + pipe_offsets[k], grid_size)];
#ifdef GT_MUTANT_EROSION_THERMAL_JAKO_GPU_LIMIT_OF_OPPOSITE_PIPE
      // mutant (this twin alone): the threshold of the pipe pointing the other way
      if (difference > talus_limit(index, k < 4 ? (k + 2) % 4 : 4 + (k - 2) % 4)) {
#else
      if (difference > talus_limit(index, k)) {
#endif
        drop[k] = difference;
        largest_drop = max(largest_drop, difference);
        drop_total = drop_total + difference;
      }
    }
  }
  precise float sent[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  if (drop_total > 0.0) {
#ifdef GT_MUTANT_EROSION_THERMAL_JAKO_UNHALVED_TRANSFER
    precise float moved = cell_rate(index) * largest_drop * 1.0;
#else
    precise float moved = cell_rate(index) * largest_drop * 0.5;
#endif
    for (int k = 0; k < 8; ++k) sent[k] = moved * drop[k] / drop_total;
  }
  outflows[2u * index] = vec4(sent[0], sent[1], sent[2], sent[3]);
  outflows[2u * index + 1u] = vec4(sent[4], sent[5], sent[6], sent[7]);
}
