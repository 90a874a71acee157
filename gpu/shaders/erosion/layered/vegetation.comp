#version 450
// Vegetation growth on the layered ground (digest 001 §3.15), GPU twin of
// reference/erosion/layered/vegetation.cpp (decisions there: death without organic matter, the flood
// death, q_s normalised by min(K_vd, h_soil), the clamp to [0, 1]), operation for
// operation in float. Double-buffered in two passes, as the reference reads only old densities:
//   grow (default): every column's new density into outflow[8·c] (the outflows as scratch);
//   with VEGETATION_STORE: vegetation[c] = outflow[8·c].
// With LAYERED_FLOOD (the ground has water), a column wetter than flood_wetness gets 0 (the flood
// death, reference vegetation_step's `water`).
// Units: K_veg in 1/s, Δt in s, depths in m.
// Inputs:  LayeredBlock (uniform binding 0), soil (2), vegetation (5) (layered.glsl); with
//          LAYERED_FLOOD the wetness in the water state (10) of water.glsl; VEGETATION_STORE:
//          outflow (7).
// Outputs: grow: outflow[8·c] (7) the new density; VEGETATION_STORE: vegetation (5).
// Twin:    reference/erosion/layered/vegetation.cpp.
#include "erosion/layered/layered.glsl"
#include "erosion/layered/water.glsl"

const uint VEGETATION_STREAM = 10u;  // gt::vegetation_cell_stream

float quality_weight(int component) {
  return component < 4 ? vegetation_quality_a[component] : vegetation_quality_boulders;
}

// q(d): Σ_i K_v,i·V*_i(d) / min(d, h_soil) over the soil sampled down to `depth`; 0 for no soil.
float soil_quality(uint c, float depth) {
  precise float weighted = 0.0;
  precise float left = depth;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    float thickness = soil_thickness(CURRENT, layer, c);
    if (thickness <= 0.0 || left <= 0.0) continue;
    bool whole_layer = left >= thickness;
    float share = whole_layer ? 1.0 : gt_div(left, thickness);
    for (int i = 0; i < COMPONENTS; ++i) {
      precise float sampled = soil[soil_at(CURRENT, layer, i, c)] * share;
      precise float term = quality_weight(i) * sampled;
      weighted += term;
    }
    precise float rest = left - thickness;
    left = whole_layer ? rest : 0.0;
  }
  precise float soil_total = soil_thickness(CURRENT, 0, c) + soil_thickness(CURRENT, 1, c);
  float sampled_depth = min(depth, soil_total);
  return sampled_depth > 0.0 ? gt_div(weighted, sampled_depth) : 0.0;
}

float quality(uint c, float veg) {
  float shallow = soil_quality(c, root_depth);
  if (vegetation_code == 0) return shallow;
  float deep = soil_quality(c, root_depth_deep);
  precise float blended = (1.0 - veg) * shallow + veg * deep - vegetation_base;
  return blended;
}

// The old densities of the 8 neighbours, after the column's own with seed001_code.
float neighbour_vegetation(ivec2 cell, uint c) {
  precise float sum = vegetation_code != 0 ? vegetation[c] : 0.0;
  for (int k = 0; k < NEIGHBOURS; ++k) {
    int n = neighbour(cell, k);
    if (n >= 0) sum += vegetation[n];
  }
  return sum;
}

float grown_vegetation(ivec2 cell, uint c) {
#ifdef LAYERED_FLOOD
  if (water_state[water_at(CURRENT, WETNESS, c)] > flood_wetness) return 0.0;
#endif
  if (!(soil[soil_at(CURRENT, 0, 0, c)] > 0.0 || soil[soil_at(CURRENT, 1, 0, c)] > 0.0)) return 0.0;
  float veg = vegetation[c];
  precise float drive = quality(c, veg) - vegetation_equilibrium * veg +
                        vegetation_neighbours * neighbour_vegetation(cell, c);
  precise float rate = vegetation_rate * time_step;
  float u = uniform01(random_u32(seed, c, step_number, VEGETATION_STREAM));
  precise float grown = veg + u * (rate * drive);
  return clamp(grown, 0.0, 1.0);
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
#ifdef VEGETATION_STORE
  vegetation[c] = outflow[uint(NEIGHBOURS) * c];
#else
  outflow[uint(NEIGHBOURS) * c] = grown_vegetation(cell, c);
#endif
}
