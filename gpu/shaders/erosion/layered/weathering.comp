#version 450
// Weathering on the layered ground (digest 001 §3.16), GPU twin of
// reference/erosion/layered/weathering.cpp (decisions there: every amount clamped to its source,
// bedrock → subsoil within the reach, boulders the remainder, the surface untouched), operation for
// operation in float, one invocation per column, in place (no column reads another).
// Per column it writes 16 floats of `weathering_record` for the host to count in double:
//   [0..3] topsoil a_0..a_3, [4..7] subsoil a_0..a_3 (sand → org, ..., boulders → stones), m;
//   [8] bedrock turned into soil, m; [9] its type (as a float); [10..14] the parts of org .. boulders, m.
// Units: metres, Δt in seconds, K_conv and K_t in m/s.
// Inputs:  LayeredBlock (uniform binding 0), soil (2), bedrock (3), bedrock_type (4), vegetation (5),
//          bedrock_types (6) (layered.glsl).
// Outputs: soil (2) and bedrock (3) in place; weathering_record (9): 16 floats per column.
// Twin:    reference/erosion/layered/weathering.cpp.
#include "erosion/layered/layered.glsl"

layout(std430, binding = 9) writeonly buffer WeatheringRecords { float weathering_record[]; };

const uint RECORD = 16u;

// Roots break rock in soil layer `layer`: a_p = min(base·K_p, V_{p+1}) moves component p + 1 into p.
void break_rock(int layer, uint c, float base) {
  float old[5];
  for (int i = 0; i < COMPONENTS; ++i) old[i] = soil[soil_at(CURRENT, layer, i, c)];
  float amounts[4];
  for (int p = 0; p < 4; ++p) {
    precise float wanted = base * weathering_shares[p];
    amounts[p] = min(wanted, old[p + 1]);
    weathering_record[RECORD * c + uint(4 * layer + p)] = amounts[p];
  }
#ifdef GT_MUTANT_EROSION_LAYERED_WEATHERING_LOSES_ORGANIC
  precise float organic = old[0];
#else
  precise float organic = old[0] + amounts[0];
#endif
  soil[soil_at(CURRENT, layer, 0, c)] = organic;
  for (int i = 1; i < 4; ++i) {
    precise float changed = old[i] + amounts[i] - amounts[i - 1];
    soil[soil_at(CURRENT, layer, i, c)] = changed;
  }
  precise float boulders = old[4] - amounts[3];
  soil[soil_at(CURRENT, layer, 4, c)] = boulders;
}

// The top non-empty bedrock layer under a soil thinner than the reach becomes subsoil.
void form_soil(uint c, float veg) {
  precise float soil_total = soil_thickness(CURRENT, 0, c) + soil_thickness(CURRENT, 1, c);
  if (!(soil_total < weathering_reach)) return;
  for (int layer = 0; layer < bedrock_layer_count; ++layer) {
    uint at = bedrock_at(CURRENT, layer, c);
    precise float thickness = bedrock[at];
    if (thickness <= 0.0) continue;
    int type = type_at(layer, c);
    precise float wanted = bedrock_types[type].soil_rate * time_step * veg;
    float formed = min(wanted, thickness);
    if (formed <= 0.0) return;
    precise float left = thickness - formed;
    bedrock[at] = left;
    weathering_record[RECORD * c + 8u] = formed;
    weathering_record[RECORD * c + 9u] = float(type);
    precise float given = 0.0;
    for (int i = 0; i < COMPONENTS; ++i) {
      precise float rest = formed - given;
      precise float share_part = bedrock_types[type].soil_composition_a[min(i, 3)] * formed;
      float part = i + 1 == COMPONENTS ? max(rest, 0.0) : share_part;
      given += part;
      uint into = soil_at(CURRENT, 1, i, c);
      precise float sum = soil[into] + part;
      soil[into] = sum;
      weathering_record[RECORD * c + 10u + uint(i)] = part;
    }
    return;
  }
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  for (uint i = 0u; i < RECORD; ++i) weathering_record[RECORD * c + i] = 0.0;
  float veg = vegetation[c];
  if (veg <= 0.0) return;
  precise float rate_step = weathering_rate * time_step;
  precise float base = rate_step * veg;
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) break_rock(layer, c, base);
  form_soil(c, veg);
}
