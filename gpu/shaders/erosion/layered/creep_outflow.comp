#version 450
// Compute pass of soil creep on the layered ground (digest 001 §3.11, Roering's law, eq. 3.4): each
// column's outflow to its 8 neighbours, from the current state. GPU twin of
// reference/erosion/layered/creep.cpp (column_outflow; decisions there: K_z a height rate at unit
// slope, the singular law's limit moves the whole layer ∝ slope), operation for operation in float.
// Units: metres, K_z in m/s, Δt in seconds.
// Inputs:  LayeredBlock (uniform binding 0), surface (1), soil (2) and the rest of the current
//          state (layered.glsl).
// Outputs: outflow (7): 8 per column, to neighbour k, m.
// Twin:    reference/erosion/layered/creep.cpp (column_outflow).
#include "erosion/layered/layered.glsl"

// Roering's q_k = K_z·s_k/D_k towards each lower neighbour; where D_k ≤ 0 (the singular law at
// s_k ≥ S_c) `weights` are the slopes of those neighbours instead and the result is true.
bool creep_weights(uint c, float surfaces[8], out float weights[8]) {
  float steep[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  bool unbounded_flux = false;
  for (int k = 0; k < NEIGHBOURS; ++k) {
    weights[k] = 0.0;
    precise float drop = surface[c] - surfaces[k];
    if (!(drop > 0.0)) continue;
    float slope = gt_div(drop, neighbour_distance(k));
    float ratio = gt_div(slope, critical_slope);
    precise float denominator = 1.0 - ratio * ratio;
    if (creep_floored != 0) denominator = max(denominator, creep_denominator_floor);
    if (denominator <= 0.0) {
      unbounded_flux = true;
      steep[k] = slope;
    } else {
      precise float rate_slope = creep_rate * slope;
      weights[k] = gt_div(rate_slope, denominator);
    }
  }
  if (unbounded_flux) weights = steep;
  return unbounded_flux;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  float amounts[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  int layer = top_nonempty_layer(CURRENT, c);
  if (layer >= 0 && layer < SOIL_LAYERS) {
    float thickness = soil_thickness(CURRENT, layer, c);
    float organic_share = gt_div(soil[soil_at(CURRENT, layer, 0, c)], thickness);
    float surfaces[8];
    neighbour_surfaces(cell, surfaces);
    float weights[8];
    bool unbounded_flux = creep_weights(c, surfaces, weights);
    precise float weight_sum = 0.0;
    for (int k = 0; k < NEIGHBOURS; ++k) weight_sum += weights[k];
    if (weight_sum > 0.0 && organic_share > 0.0) {
      precise float rate_part = time_step * organic_share * weight_sum * random_factor(creep_random != 0, c, 9u) * 0.5;
      float total = min(unbounded_flux ? thickness : rate_part, thickness);
      for (int k = 0; k < NEIGHBOURS; ++k) {
        precise float amount = total * gt_div(weights[k], weight_sum);
        amounts[k] = amount;
      }
    }
  }
  store_outflows(c, amounts);
}
