#version 450
// Pass 1 of the pipe flow on the layered ground (digest 001 §3.3 steps 1-6), GPU twin of
// `outflows` in reference/erosion/layered/water.cpp: F_k ← max(0, F_k + P_k·Δ(h + w)) per pipe to a
// neighbour (0 to none), then scaled by l_x·l_y·w/ΔV when ΔV = Δt·ΣF exceeds what the column holds
// (DRAINED records it for a column that holds water).
// One invocation per column; it reads its own old flux and its neighbours' w and h (which no
// invocation writes here) and writes its own flux, so the pass runs in place. Units: m, m³/s.
// Inputs:  LayeredBlock (uniform binding 0) and surface (1) of layered.glsl; LayeredWaterBlock
//          (uniform binding 1) and the water state (10: w, fluxes) of water.glsl.
// Outputs: the fluxes and DRAINED in the water state (10).
// Twin:    reference/erosion/layered/water.cpp (outflows).
#include "erosion/layered/water.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  float depth = water_state[water_at(CURRENT, WATER, c)];
  precise float level = surface[c] + depth;
  float flux[4];
  for (int k = 0; k < PIPES; ++k) {
    int n = neighbour(cell, k);
    flux[k] = 0.0;
    if (n < 0) continue;
    precise float other = surface[n] + water_state[water_at(CURRENT, WATER, uint(n))];
    precise float difference = level - other;
    precise float updated = water_state[water_at(CURRENT, FLUX + uint(k), c)] + pipe_coefficient[k] * difference;
    flux[k] = max(0.0, updated);
  }
  precise float leaving = time_step * (((flux[0] + flux[1]) + flux[2]) + flux[3]);
  precise float held = cell_area * depth;
#ifdef GT_MUTANT_EROSION_LAYERED_GPU_FLUX_UNSCALED
  bool drained = false;  // mutant (this twin alone): fluxes never scaled to what the column holds
#else
  bool drained = leaving > held;
#endif
  // A dry column sends nothing, so it keeps what it carries (sediment diffusion can bring some).
  water_state[water_at(CURRENT, DRAINED, c)] = drained && held > 0.0 ? 1.0 : 0.0;
  if (drained) {
    float scale = gt_div(held, leaving);
    for (int k = 0; k < PIPES; ++k) {
      precise float scaled = flux[k] * scale;
      flux[k] = scaled;
    }
  }
  for (int k = 0; k < PIPES; ++k) water_state[water_at(CURRENT, FLUX + uint(k), c)] = flux[k];
}
