#version 450
// Impact erosion on the layered ground (digest 001 §3.14), GPU twin of
// reference/erosion/layered/impact_erosion.cpp (decisions there: the thesis's target-side two-pass
// form, S = K_i·v·A·Δt/(l_x·l_y) as force erosion's water strength on the touched layer alone, the
// first non-empty bedrock layer only and one bedrock type a column a step), operation for operation
// in float. One invocation per column in each pass:
//   pass 1 (default): target c erodes its layers that its neighbours' water hits, reading the
//     neighbours' heights from SURFACE_BEFORE (copied by the host) and their water and flux (which
//     no invocation writes here); writes its own layers and its 48-float `impact_record`: [5k + q]
//     the load of its pipe k in suspended size q, [20 + 4j + i] size j broken into i, [36 + i]
//     bedrock eroded into size i, [40] that bedrock's type (−1 none);
//   with IMPACT_GATHER: column n adds its neighbours' loads toward it to its suspended sediment.
// Units: m, m/s, m³/s.
// Inputs:  the ground state of layered.glsl (LayeredBlock 0, surface 1, soil 2, bedrock 3,
//          bedrock_types 6), LayeredWaterBlock (uniform binding 1) and the water state (10: depths,
//          fluxes, SURFACE_BEFORE) of water.glsl; with IMPACT_GATHER, impact_record (11).
// Outputs: pass 1: the column's layers and surface, impact_record (11): 48 floats per column;
//          IMPACT_GATHER: the suspended sediment in the water state (10).
// Twin:    reference/erosion/layered/impact_erosion.cpp.
#include "erosion/layered/column.glsl"
#include "erosion/layered/water.glsl"

layout(std430, binding = 11) buffer ImpactRecords { float impact_record[]; };

const uint RECORD = 48u, BROKEN = 20u, ROCK = 36u, ROCK_TYPE = 40u;

#ifdef IMPACT_GATHER

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint n = cell_index(cell, grid_size);
#ifdef GT_MUTANT_EROSION_LAYERED_IMPACT_NEVER_DELIVERED
  return;
#endif
  for (int k = 0; k < PIPES; ++k) {
    int from = neighbour(cell, k);
    if (from < 0) continue;
    for (int kind = 0; kind < COMPONENTS; ++kind) {
      uint at = water_at(CURRENT, CARRIED + uint(kind), n);
      precise float sum = water_state[at] + impact_record[RECORD * uint(from) + uint(5 * (k ^ 1) + kind)];
      water_state[at] = sum;
    }
  }
}

#else

float broken_tally[16];
float rock_tally[4];
int rock_type = -1;

// v of neighbour n's water toward the target through the target's pipe k, m/s (0: it stands or
// moves away).
float speed_toward(int n, int k) {
  uint w = uint(n);
  if (!(water_state[water_at(CURRENT, WATER, w)] > 0.0)) return 0.0;
  float mean = mean_depth(w);
  if (mean <= 0.0) return 0.0;
  vec2 flux = net_flux(ivec2(n % grid_size.x, n / grid_size.x), w);
  float toward = k == 0 ? flux.x : k == 1 ? -flux.x : k == 2 ? -flux.y : flux.y;
  if (!(toward > 0.0)) return 0.0;
  precise float across = (k < 2 ? cell_size_y : cell_size_x) * mean;
  return gt_div(toward, across);
}

void erode_soil_layer(uint c, int layer, float strength, inout float load[5]) {
  precise float organic = erosion_rate * (organic_capacity * strength);
  precise float taken_total = 0.0;
  if (organic > 0.0 && soil[soil_at(CURRENT, layer, 0, c)] > 0.0) {
    float taken = take_from_layer(c, layer, 0, organic, least_share, share_code != 0);
    load[0] += taken;
    taken_total += taken;
  }
  for (int size = 0; size < 4; ++size) {
    for (int source = size; source < 4; ++source) {
      precise float request = erosion_rate * breakdown(breakdown_slopes[source][size],
                                                       breakdown_thresholds[source][size], strength);
      if (!(request > 0.0) || !(soil[soil_at(CURRENT, layer, source + 1, c)] > 0.0)) continue;
      float taken = take_from_layer(c, layer, source + 1, request, least_share, share_code != 0);
      precise float loaded = load[size + 1] + taken;
      load[size + 1] = loaded;
      taken_total += taken;
      if (source != size) broken_tally[4 * source + size] += taken;
    }
  }
  precise float lowered = surface[c] - taken_total;
  surface[c] = lowered;
}

void erode_bedrock_layer(uint c, int layer, float strength, inout float load[5]) {
  int type = type_at(layer, c);
  if (rock_type >= 0 && type != rock_type) return;
  for (int size = 0; size < 4; ++size) {
    precise float request = erosion_rate * breakdown(bedrock_types[type].erosion_slopes[size],
                                                     bedrock_types[type].erosion_thresholds[size], strength);
    uint at = bedrock_at(CURRENT, layer, c);
    float thickness = bedrock[at];
    if (!(request > 0.0) || !(thickness > 0.0)) continue;
    float taken = min(request, thickness);
    precise float left = thickness - taken;
    bedrock[at] = left;
    precise float lowered = surface[c] - taken;
    surface[c] = lowered;
    precise float loaded = load[size + 1] + taken;
    load[size + 1] = loaded;
    rock_tally[size] += taken;
    rock_type = type;
  }
}

// The strength of the contact between a layer from `top` down `thickness` and the water between
// water_bottom and water_top (0: no contact); `top` moves to the layer's bottom.
float contact_strength(inout float top, float thickness, float water_top, float water_bottom, float face,
                       float speed) {
  precise float bottom = top - thickness;
  precise float wet = min(top, water_top) - max(bottom, water_bottom);
  precise float contact = face * max(wet, 0.0);
  precise float strength = impact_scale * speed * contact;
  top = bottom;
  return contact > 0.0 ? strength : 0.0;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  for (int i = 0; i < 16; ++i) broken_tally[i] = 0.0;
  for (int i = 0; i < 4; ++i) rock_tally[i] = 0.0;
  for (int k = 0; k < PIPES; ++k) {
    float load[5] = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
    int n = neighbour(cell, k);
    float speed = n >= 0 ? speed_toward(n, k) : 0.0;
    if (speed > 0.0) {
      float face = k < 2 ? cell_size_y : cell_size_x;
      float water_bottom = water_state[water_at(CURRENT, SURFACE_BEFORE, uint(n))];
      precise float water_top = water_bottom + water_state[water_at(CURRENT, WATER, uint(n))];
      float top = surface[c];
      for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
        float thickness = soil_thickness(CURRENT, layer, c);
        if (!(thickness > 0.0)) continue;
        float strength = contact_strength(top, thickness, water_top, water_bottom, face, speed);
        if (strength > 0.0) erode_soil_layer(c, layer, strength, load);
      }
      for (int layer = 0; layer < bedrock_layer_count; ++layer) {
        float thickness = bedrock[bedrock_at(CURRENT, layer, c)];
        if (!(thickness > 0.0)) continue;
        float strength = contact_strength(top, thickness, water_top, water_bottom, face, speed);
        if (strength > 0.0) erode_bedrock_layer(c, layer, strength, load);
        break;
      }
    }
    for (int q = 0; q < COMPONENTS; ++q) impact_record[RECORD * c + uint(5 * k + q)] = load[q];
  }
  for (int i = 0; i < 16; ++i) impact_record[RECORD * c + BROKEN + uint(i)] = broken_tally[i];
  for (int i = 0; i < 4; ++i) impact_record[RECORD * c + ROCK + uint(i)] = rock_tally[i];
  impact_record[RECORD * c + ROCK_TYPE] = float(rock_type);
}

#endif
