#version 450
// Stage 2 of the virtual-pipe erosion (Mei 2007, digest 000 eqs. 2.11-2.13): the outflow flux of
// every valid cell, f̂_k = max(0, f_k + Δt·A·g·Δh_k/l_k) scaled by K = min(1, d_A·l_x·l_y/(Σf̂·Δt)),
// over 4 pipes or (PIPES_8) 8, the diagonals of length l_d.
// The head Δh_k = (b + d_A) - (b_k + d_A,k) is formed as terrain_difference + (d_A - d_A,k) from
// the base + change storage (see pipes_block.glsl). Exterior pipes: closed = no flux; open = a dry
// cell at the cell's own terrain height, Δh = d_A. Each cell writes only its own fluxes and reads
// its old ones and its neighbours' d_A, so updating in place is synchronous.
// Inputs:  PipeBlock (uniform binding 0), cells (1), delta (2), water (4: d_A), outflow (5: last
//          step's fluxes) (pipes_block.glsl).
// Outputs: outflow (5) in place; water (4).w, the drained flag (1 when K < 1).
// Twin:    reference/erosion/pipes.cpp (update_outflow).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  uint flags = cells[index].flags;
  if (!cell_valid(flags)) return;  // no-data cells keep f = 0
  precise float depth = water[index].y;
  precise vec4 tentative[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (int k = 0; k < pipe_count; ++k) {
    bool outside = exterior(flags, k);
    if (outside && boundary_open == 0u) continue;
#ifdef GT_MUTANT_EROSION_PIPE_GPU_DROPS_BOTTOM_PIPE
    if (k == pipe_bottom) continue;  // mutant: the B pipe never carries water
#endif
    precise float head;
    if (outside) {
      head = depth;
    } else {
      uint neighbour = neighbour_index(cell, k);
      head = terrain_difference(index, neighbour) + (depth - water[neighbour].y);
    }
    precise float raised = outflow[pipe_slot(index, k)][k % 4] + flux_gain[k / 4][k % 4] * head;
    tentative[k / 4][k % 4] = ref_max(0.0, raised);
  }
  precise float total = pipe_total(tentative);
  precise float scale = 1.0;
#ifndef GT_MUTANT_EROSION_PIPE_UNSCALED_OUTFLOW  // mutant: K = 1, a cell may send more than it holds
  if (total > 0.0) {
    precise float available = depth * area_per_time / total;
    scale = ref_min(1.0, available);
  }
#endif
  for (int group = 0; group < pipe_groups; ++group) {
    precise vec4 scaled = vec4(scale * tentative[group][0], scale * tentative[group][1], scale * tentative[group][2],
                               scale * tentative[group][3]);
    outflow[group_slot(index, group)] = scaled;
  }
  water[index].w = scale < 1.0 ? 1.0 : 0.0;  // drained: K sent all of d_A (stage 3 keeps exactly 0)
}
