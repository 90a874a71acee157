#version 450
// Stage 1 of the virtual-pipe erosion (Mei 2007, digest 000 eq. 2.10 with Δt): the water
// increment d_A = d + Δt·(r + r_map) of every valid cell. Point sources follow in
// pipes_sources.comp.
// Inputs:  PipeBlock (uniform binding 0), cells (1: Δt·(r + r_map) as `rain`, flags), water (4: d)
//          (pipes_block.glsl).
// Outputs: water (4: d_A) of every valid cell.
// Twin:    reference/erosion/pipes.cpp (add_water).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  if (!cell_valid(cells[index].flags)) return;  // no-data cells hold d = d_A = d_B = 0
#ifdef GT_MUTANT_EROSION_PIPE_HALF_RAIN
  precise float depth = water[index].x + 0.5 * cells[index].rain;  // mutant: half the rain
#else
  precise float depth = water[index].x + cells[index].rain;
#endif
  water[index].y = depth;
}
