#version 450
// Stage 8 of the pipe erosion (THERMAL step), gather pass: Δb' = Δb - what the cell sends + what
// its neighbours send it, in the reference's order (reference/erosion/thermal_jako.cpp,
// gathered_height), written to the next Δb buffer. The same numbers leave one cell and reach the
// other, so material is conserved to the rounding of Δb.
// Inputs:  PipeBlock (uniform binding 0), cells (1), delta (2), thermal_outflows (15)
//          (pipes_block.glsl, pipes_thermal.glsl).
// Outputs: delta_next (3): the next Δb.
// Twin:    reference/erosion/thermal_jako.cpp (gathered_height), in reference/erosion/pipes.cpp's step 8.
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"
#include "erosion/pipes_thermal.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float change = delta[index];
  if (cell_valid(cells[index].flags)) {
    for (int k = 0; k < 8; ++k) change = change - thermal_outflow(index, k);
    for (int k = 0; k < 8; ++k) {
      if (!thermal_pipe_open(cell, k)) continue;
      change = change + thermal_outflow(cell_index(cell + thermal_offsets[k], grid_size), thermal_opposite(k));
    }
  }
  delta_next[index] = change;
}
