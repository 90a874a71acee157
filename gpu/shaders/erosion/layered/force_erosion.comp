#version 450
// Force erosion and deposition on the layered ground (digest 001 §3.4, §3.5, §3.12), GPU twin of
// reference/erosion/layered/force_erosion.cpp (decisions there: slopes from the surface snapshot,
// K_e on the rock requests, x as the bedrock's input, one deposit after all erosion), operation for
// operation in float. One invocation per column: it reads its neighbours' flux (no pass writes it
// here) and their surfaces from SURFACE_BEFORE (copied by the host), and writes only its own words.
// Per column it writes 24 floats of `erosion_record` for the host to count in double: [4j + i] the
// size j broken into size i (i < j), [16 + i] bedrock eroded into size i, [20 + i] its bedrock type.
// Units: m, m/s, m³/s.
// Inputs:  the ground state of layered.glsl (LayeredBlock 0, soil 2, bedrock 3, bedrock_type 4,
//          vegetation 5, bedrock_types 6), LayeredWaterBlock (uniform binding 1) and the water state
//          (10: depths, fluxes, carried sediment, SURFACE_BEFORE) of water.glsl.
// Outputs: the column's layers and surface, its carried sediment in the water state (10), and
//          erosion_record (11): 24 floats per column.
// Twin:    reference/erosion/layered/force_erosion.cpp.
#include "erosion/layered/column.glsl"
#include "erosion/layered/water.glsl"

layout(std430, binding = 11) writeonly buffer ErosionRecords { float erosion_record[]; };

const uint RECORD = 24u;

// |v| (eq. 2.2 with the w̄ floor).
float water_speed(ivec2 cell, uint c) {
  vec2 flux = net_flux(cell, c);
  float mean = mean_depth(c);
  if (mean <= 0.0) return 0.0;
  precise float across_x = cell_size_y * mean;
  precise float across_y = cell_size_x * mean;
  float speed_x = gt_div(abs(flux.x), across_x);
  float speed_y = gt_div(abs(flux.y), across_y);
  precise float squared = speed_x * speed_x + speed_y * speed_y;
  return gt_sqrt(squared);
}

float height_before(ivec2 cell, uint c, int k) {
  int n = neighbour(cell, k);
  return water_state[water_at(CURRENT, SURFACE_BEFORE, n >= 0 ? uint(n) : c)];
}

// max(sin φ, slope_floor) from the surface snapshot.
float slope_sine(ivec2 cell, uint c) {
  precise float gradient_x = (height_before(cell, c, 1) - height_before(cell, c, 0)) * slope_scale_x;
  precise float gradient_y = (height_before(cell, c, 2) - height_before(cell, c, 3)) * slope_scale_y;
  precise float squared = gradient_x * gradient_x + gradient_y * gradient_y;
  precise float whole = 1.0 + squared;
  return max(gt_sqrt(gt_div(squared, whole)), slope_floor);
}

float water_strength(ivec2 cell, uint c) {
  float depth = water_state[water_at(CURRENT, WATER, c)];
  if (!(depth > 0.0)) return 0.0;
  float speed = water_speed(cell, c);
  float sine = slope_sine(cell, c);
  float ramp = min(gt_div(depth, depth_ramp), 1.0);
  precise float protection = 1.0 + vegetation_protection * vegetation[c];
  precise float drive = erosion_strength * sine * speed * ramp;
  return gt_div(drive, protection);
}

float erode(uint c, int component, float request) {
  return erode_component(c, component, request, least_share, transparency_depth, share_code != 0);
}

void add_carried(uint c, int kind, float amount) {
  uint at = water_at(CURRENT, CARRIED + uint(kind), c);
  precise float sum = water_state[at] + amount;
  water_state[at] = sum;
}

int first_bedrock_layer(uint c) {
  for (int layer = 0; layer < bedrock_layer_count; ++layer) {
    if (bedrock[bedrock_at(CURRENT, layer, c)] > 0.0) return layer;
  }
  return -1;
}

void erode_into_size(uint c, int size, float strength) {
  for (int source = size; source < 4; ++source) {
    precise float request = erosion_rate * breakdown(breakdown_slopes[source][size], breakdown_thresholds[source][size],
                                                     strength);
    if (request <= 0.0) continue;
    float taken = erode(c, source + 1, request);
    add_carried(c, size + 1, taken);
    if (source != size) erosion_record[RECORD * c + uint(4 * source + size)] = taken;
  }
  int layer = first_bedrock_layer(c);
  if (layer < 0) return;
  int type = type_at(layer, c);
  precise float request = erosion_rate *
                          breakdown(bedrock_types[type].erosion_slopes[size], bedrock_types[type].erosion_thresholds[size],
                                    strength) *
                          soil_transparency(c, transparency_depth);
  if (request <= 0.0) return;
  int taken_layer;
  float taken = erode_bedrock(c, request, taken_layer);
  add_carried(c, size + 1, taken);
  erosion_record[RECORD * c + 16u + uint(size)] = taken;
  erosion_record[RECORD * c + 20u + uint(size)] = float(type);
}

// K_d of the gap above `capacity` leaves the water; 0 at or below it.
float settle(uint c, int kind, float capacity) {
  uint at = water_at(CURRENT, CARRIED + uint(kind), c);
  float suspended = water_state[at];
  if (!(suspended > capacity)) return 0.0;
  precise float amount = deposition_rate * (suspended - capacity);
  precise float left = suspended - amount;
  bool whole = left < NEGLIGIBLE;
  water_state[at] = whole ? 0.0 : left;
  return whole ? suspended : amount;
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint c = cell_index(cell, grid_size);
  for (uint i = 0u; i < RECORD; ++i) erosion_record[RECORD * c + i] = 0.0;
  float strength = water_strength(cell, c);
  float deposited[5] = float[5](0.0, 0.0, 0.0, 0.0, 0.0);
  precise float organic_capacity_here = organic_capacity * strength;
  float organic = water_state[water_at(CURRENT, CARRIED, c)];
  if (organic < organic_capacity_here) {
    precise float request = erosion_rate * (organic_capacity_here - organic);
    add_carried(c, 0, erode(c, 0, request));
  } else {
    deposited[0] = settle(c, 0, organic_capacity_here);
  }
  for (int size = 0; size < 4; ++size) erode_into_size(c, size, strength);
  for (int size = 0; size < 4; ++size) {
    float capacity = breakdown(breakdown_slopes[size][size], breakdown_thresholds[size][size], strength);
    deposited[size + 1] = settle(c, size + 1, capacity);
  }
  deposit_soil(c, deposited);
}
