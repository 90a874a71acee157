#version 450
// Stage 6b' of the pipe erosion, seed 001 §3.8 (only when w > 0): diffusion of the sediment (and,
// with REGOLITH_DIFFUSION, of the regolith: the thesis; seed 001's code diffuses the sediment only)
// from the state after transport. Each valid cell sends σ_k·s to
// each of its 4 axis neighbours k whose pipe is not exterior (with 8 pipes too: the seed's stencil)
// and keeps max(0, s - Σ σ_k·s); it then holds what it kept
// plus what its neighbours sent it (the same numbers they lost, each recomputed here from the
// neighbour's own data with the same operations, so the exchange conserves bit for bit).
//   uniform weighting: σ_k = w;
//   water weighting (DIFFUSION_WATER, the seed's code): σ_k = ½d_k / (d + ½Σ d_n) with the depths
//     d_B after the flow (water[].z); nothing moves when that sum is 0.
// Reads s and r of the neighbours, so it writes the next values into the `staying` buffers, which
// the host then swaps with s and r.
// Inputs:  PipeBlock (uniform binding 0), cells (1), water (4: d_B), sediment (7), regolith (12)
//          (pipes_block.glsl).
// Outputs: staying (8) and regolith_staying (13): the diffused s and r.
// Twin:    reference/erosion/pipes.cpp (diffusion_shares, diffuse).
layout(local_size_x = 16, local_size_y = 16) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

vec4 diffusion_shares(ivec2 cell, uint index, uint flags) {
  precise vec4 shares = vec4(0.0);
#ifdef DIFFUSION_WATER
  precise vec4 weights = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    if (!exterior(flags, k)) weights[k] = 0.5 * water[neighbour_index(cell, k)].z;
  }
  precise float base = water[index].z + pipe_sum(weights);
  if (!(base > 0.0)) return shares;
  for (int k = 0; k < 4; ++k) shares[k] = weights[k] / base;
#else
  for (int k = 0; k < 4; ++k) shares[k] = exterior(flags, k) ? 0.0 : diffusion_weight;
#endif
  return shares;
}

float diffused(float value, vec4 own_shares, vec4 neighbour_values, vec4 neighbour_shares) {
  precise vec4 sending = vec4(value * own_shares[0], value * own_shares[1], value * own_shares[2], value * own_shares[3]);
  // A dry cell under water weighting sends all of it (Σσ = 1); rounding can make Σ sent exceed the
  // value by an ulp, which the clamp removes (as the reference).
  precise float kept = ref_max(0.0, value - pipe_sum(sending));
  precise vec4 received = vec4(neighbour_values[0] * neighbour_shares[0], neighbour_values[1] * neighbour_shares[1],
                               neighbour_values[2] * neighbour_shares[2], neighbour_values[3] * neighbour_shares[3]);
  precise float total = kept + pipe_sum(received);
  return total;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  uint flags = cells[index].flags;
  if (!cell_valid(flags)) return;

  vec4 own_shares = diffusion_shares(cell, index, flags);
  // What neighbour k sends this cell: its value times its share towards this cell (its pipe k^1);
  // 0 through exterior pipes.
  vec4 towards_here = vec4(0.0);
  vec4 neighbour_sediment = vec4(0.0);
  vec4 neighbour_regolith = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    if (exterior(flags, k)) continue;
    ivec2 neighbour_cell = cell + pipe_offsets[k];
    uint neighbour = cell_index(neighbour_cell, grid_size);
    towards_here[k] = diffusion_shares(neighbour_cell, neighbour, cells[neighbour].flags)[opposite(k)];
    neighbour_sediment[k] = sediment[neighbour];
#ifdef REGOLITH_DIFFUSION
    neighbour_regolith[k] = regolith[neighbour];
#endif
  }
  staying[index] = diffused(sediment[index], own_shares, neighbour_sediment, towards_here);
#ifdef REGOLITH_DIFFUSION
  regolith_staying[index] = diffused(regolith[index], own_shares, neighbour_regolith, towards_here);
#endif
}
