#version 450
// Stages 6b and 7 of the virtual-pipe erosion (Mei 2007, digest 000 eqs. 2.24-2.26), per cell:
//   flux form (TRANSPORT_FLUX): s = staying + Σ what the neighbours sent this cell through the 4
//     or 8 pipes, the same numbers they lost, summed (L + R) + (T + B) [+ ((TL + BR) + (TR + BL))];
//   semi-Lagrangian: s(x) = staying(x - (u, v)·Δt), bilinear, a corner off the grid or on a
//     no-data cell reading the cell itself; weights ceil(p) - p and p - floor(p)
//     (erosion/pipes_trace.glsl); with TRANSPORT_MACCORMACK the result φ̂ that
//     pipes_maccormack.comp then corrects;
//   the regolith (REGOLITH, seed 001 §3.9) the same way, from its own buffers;
//   evaporation d = d_B·(1 - K_e·Δt) (the diffusion pass, when there is one, reads d_B, not d).
// Inputs:  PipeBlock (uniform binding 0), cells (1), water (4: d_B), velocity (6), staying (8),
//          sent (9), regolith_staying (13), regolith_sent (14) (pipes_block.glsl).
// Outputs: sediment (7), regolith (12), water (4: d after evaporation).
// Twin:    reference/erosion/pipes.cpp (transport_*, gather_sent, traced_sediment, evaporate).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

const int carried_sediment = 0, carried_regolith = 1;

#ifdef TRANSPORT_FLUX
float gathered(ivec2 cell, uint index, uint flags, int carried) {
  vec4 received[2] = vec4[2](vec4(0.0), vec4(0.0));
  for (int k = 0; k < pipe_count; ++k) {
    if (exterior(flags, k)) continue;
    uint slot = pipe_slot(neighbour_index(cell, k), k);
#ifdef GT_MUTANT_EROSION_PIPE_GPU_GATHER_WRONG_PIPE
    int from = k % 4;  // mutant: the neighbour's pipe k, not the one towards this cell
#else
    int from = opposite(k) % 4;
#endif
    received[k / 4][k % 4] = carried == carried_sediment ? sent[slot][from] : regolith_sent[slot][from];
  }
  precise float kept = carried == carried_sediment ? staying[index] : regolith_staying[index];
  precise float total = kept + pipe_total(received);
  return total;
}
#else
#include "erosion/pipes_trace.glsl"
#endif

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  uint flags = cells[index].flags;
  if (!cell_valid(flags)) return;

#ifdef TRANSPORT_FLUX
  sediment[index] = gathered(cell, index, flags, carried_sediment);
#ifdef REGOLITH
  regolith[index] = gathered(cell, index, flags, carried_regolith);
#endif
#else
  vec2 speed = velocity[index];
#ifdef GT_MUTANT_EROSION_PIPE_GPU_BACKTRACE_DOWNSTREAM
  precise float displacement_x = speed.x * backtrace_x;  // mutant: traced downstream along x
#else
  precise float displacement_x = -speed.x * backtrace_x;
#endif
  precise float displacement_y = -speed.y * backtrace_y;
  AxisTaps taps_x = axis_taps(displacement_x);
  AxisTaps taps_y = axis_taps(displacement_y);
  sediment[index] = traced(cell, index, taps_x, taps_y, from_staying);
#ifdef REGOLITH
  regolith[index] = traced(cell, index, taps_x, taps_y, from_regolith_staying);
#endif
#endif

#ifdef GT_MUTANT_EROSION_PIPE_DOUBLE_EVAPORATION
  precise float evaporated = water[index].z * (2.0 * evaporation_kept - 1.0);  // mutant: 2·K_e
#else
  precise float evaporated = water[index].z * evaporation_kept;
#endif
  water[index].x = evaporated;
}
