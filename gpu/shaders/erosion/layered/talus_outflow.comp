#version 450
// Compute pass of per-material talus collapse on the layered ground (digest 001 §3.10, eq. 3.1-3.3):
// each column's outflow to its 8 neighbours, from the current state. GPU twin of
// reference/erosion/layered/talus.cpp (column_outflow; decisions there), operation for operation in
// float. Units: metres, Δt in seconds.
// Inputs:  LayeredBlock (uniform binding 0), surface (1), soil (2), bedrock (3), vegetation (5),
//          bedrock_types (6) (layered.glsl), current half.
// Outputs: outflow (7): 8 per column, to neighbour k, m.
// Twin:    reference/erosion/layered/talus.cpp (column_outflow).
#include "erosion/layered/layered.glsl"

// (Σ_i tan φ_i·V_i)/V of soil layer `layer` (eq. 3.1 without the vegetation factor).
float layer_repose(int layer, uint c, float thickness) {
  precise float weighted = 0.0;
  for (int i = 0; i < COMPONENTS; ++i) weighted += component_repose(i) * soil[soil_at(CURRENT, layer, i, c)];
  return gt_div(weighted, thickness);
}

// tan φ_min over the non-empty soil layers, with K_depth^j and (1 + K_sveg·veg).
float soil_repose(uint c) {
  precise float vegetation_factor = 1.0 + vegetation_repose * vegetation[c];
#ifdef GT_MUTANT_EROSION_LAYERED_REPOSE_DOUBLED
  precise float depth = 2.0;
#else
  precise float depth = 1.0;
#endif
  precise float least = unbounded();
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    float thickness = soil_thickness(CURRENT, layer, c);
    if (thickness > 0.0) {
      precise float repose = depth * layer_repose(layer, c, thickness) * vegetation_factor;
      least = min(least, repose);
    }
    depth *= depth_factor;
  }
  return least;
}

// The least tan φ of the non-empty bedrock layers whose top lies above `lowest_neighbour`.
float bedrock_repose(uint c, float lowest_neighbour) {
  float repose = unbounded();
  precise float layer_top = surface[c];
  for (int layer = 0; layer < bedrock_layer_count && layer_top > lowest_neighbour; ++layer) {
    float thickness = bedrock[bedrock_at(CURRENT, layer, c)];
    if (thickness > 0.0) repose = min(repose, bedrock_types[type_at(layer, c)].repose_tan);
    layer_top -= thickness;
  }
  return repose;
}

// Δh_k where Δh_k > 0 and Δh_k/l_k ≥ tan φ, else 0.
void unstable_drops(uint c, float surfaces[8], float threshold, out float drops[8]) {
  for (int k = 0; k < NEIGHBOURS; ++k) {
    precise float drop = surface[c] - surfaces[k];
    drops[k] = drop > 0.0 && gt_div(drop, neighbour_distance(k)) >= threshold ? drop : 0.0;
  }
}

// Eq. 3.3: Δt·Δh_k·rand_k/2 per neighbour, then the availability clamp.
void thesis_amounts(uint c, float drops[8], float available, out float amounts[8]) {
  for (int k = 0; k < NEIGHBOURS; ++k) {
    amounts[k] = 0.0;
    if (drops[k] <= 0.0) continue;
    precise float amount = time_step * drops[k] * random_factor(talus_random != 0, c, uint(k)) * 0.5;
    amounts[k] = amount;
  }
  clamp_to_available(amounts, available);
}

// The code's min(½·max Δh·rand, h_layer) split ∝ Δh_k.
void code_amounts(uint c, float drops[8], float available, out float amounts[8]) {
  float largest = 0.0;
  precise float sum = 0.0;
  for (int k = 0; k < NEIGHBOURS; ++k) {
    largest = max(largest, drops[k]);
    sum += drops[k];
  }
  for (int k = 0; k < NEIGHBOURS; ++k) amounts[k] = 0.0;
  if (sum <= 0.0) return;
  precise float wanted = 0.5 * largest * random_factor(talus_random != 0, c, 8u);
  float total = min(wanted, available);
  for (int k = 0; k < NEIGHBOURS; ++k) {
    precise float amount = total * gt_div(drops[k], sum);
    amounts[k] = amount;
  }
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  float amounts[8] = float[8](0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
  int layer = top_nonempty_layer(CURRENT, c);
  if (layer >= 0) {
    float surfaces[8];
    neighbour_surfaces(cell, surfaces);
    bool on_soil = layer < SOIL_LAYERS;
    float lowest = surfaces[0];
    for (int k = 1; k < NEIGHBOURS; ++k) lowest = min(lowest, surfaces[k]);
    float threshold = on_soil ? soil_repose(c) : bedrock_repose(c, lowest);
    float available = on_soil ? soil_thickness(CURRENT, layer, c) : bedrock[bedrock_at(CURRENT, layer - SOIL_LAYERS, c)];
    float drops[8];
    unstable_drops(c, surfaces, threshold, drops);
    if (talus_thesis_amount != 0) {
      thesis_amounts(c, drops, available, amounts);
    } else {
      code_amounts(c, drops, available, amounts);
    }
  }
  store_outflows(c, amounts);
}
