#version 450
// Wetness of the layered ground (digest 001 §3.15, eq. 3.12), GPU twin of
// reference/erosion/layered/wetness.cpp: wet + Δt·w under water, wet·K_dry^Δt when dry (the factor
// from the host, rounded once from double as the reference's). One invocation per column, in place.
// Units: m·s.
// Inputs:  LayeredBlock (uniform binding 0: Δt), LayeredWaterBlock (uniform binding 1: K_dry^Δt) and
//          the water state (10: w, wetness) (water.glsl).
// Outputs: WETNESS in the water state (10), in place.
// Twin:    reference/erosion/layered/wetness.cpp.
#include "erosion/layered/water.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  uint at = water_at(CURRENT, WETNESS, c);
  float depth = water_state[water_at(CURRENT, WATER, c)];
  precise float soaked = water_state[at] + time_step * depth;
  precise float dried = water_state[at] * drying_factor;
  float wetness = depth > 0.0 ? soaked : dried;
  water_state[at] = wetness < NEGLIGIBLE ? 0.0 : wetness;
}
