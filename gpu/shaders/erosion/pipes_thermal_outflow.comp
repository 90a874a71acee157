#version 450
// Stage 8 of the pipe erosion (THERMAL step, Jákó & Tóth 2011's combined step; only when
// thermal_step), outflow pass: one iteration of gpu/shaders/erosion/thermal_jako_outflow.comp on
// the terrain b = b0 + Δb, with every height difference formed as terrain_difference() (see
// pipes_block.glsl) so that it keeps the precision of the relief at a high base. What each cell
// sends down each of its 8 pipes (Jákó's order: (-1,0) (0,1) (1,0) (0,-1), then the diagonals
// (-1,-1) (-1,1) (1,1) (1,-1)).
// Inputs:  PipeBlock (uniform binding 0), cells (1: b0, flags), delta (2) (pipes_block.glsl).
// Outputs: thermal_outflows (15): 8 per cell, two vec4.
// Twin:    reference/erosion/thermal_jako.cpp (cell_outflows), in reference/erosion/pipes.cpp's step 8.
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"
#include "erosion/pipes_thermal.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float drop[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  precise float largest_drop = 0.0;
  precise float drop_total = 0.0;
  if (cell_valid(cells[index].flags)) {
    for (int k = 0; k < 8; ++k) {
      if (!thermal_pipe_open(cell, k)) continue;
      precise float difference = terrain_difference(index, cell_index(cell + thermal_offsets[k], grid_size));
      if (difference > thermal_talus_limit(k)) {
        drop[k] = difference;
        largest_drop = ref_max(largest_drop, difference);
        drop_total = drop_total + difference;
      }
    }
  }
  precise float sent_down[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  if (drop_total > 0.0) {
    precise float moved = thermal_rate * largest_drop * 0.5;
    for (int k = 0; k < 8; ++k) sent_down[k] = moved * drop[k] / drop_total;
  }
  thermal_outflows[2u * index] = vec4(sent_down[0], sent_down[1], sent_down[2], sent_down[3]);
  thermal_outflows[2u * index + 1u] = vec4(sent_down[4], sent_down[5], sent_down[6], sent_down[7]);
}
