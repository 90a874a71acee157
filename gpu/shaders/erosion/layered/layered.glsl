// What the passes of the layered ground's talus and creep share (digest 001 §3.1, §3.10-3.11; CPU
// twin: core/layered/layered_ground.hpp, reference/erosion/layered/{column,transfer}.cpp; host:
// gpu/erosion/layered/ground_buffers.cpp): the parameter block, the state buffers and their
// indexing, neighbours, the random factor, layer thicknesses, the topmost non-empty layer and the
// availability clamp; the parameters of vegetation and weathering (vegetation.comp, weathering.comp).
//
// State layout (structure of arrays, cell c = y·width + x, `cells` = width·height):
//   soil[(j·5 + i)·cells + c]: component i of soil layer j; bedrock[k·cells + c]: bedrock layer k.
//   `soil` and `bedrock` hold two halves: the current state first, then the step's snapshot
//   (copied there by the host before each step; see soil_at, bedrock_at). The outflow pass reads
//   the current half (equal to the snapshot then); the apply pass writes column c's current half
//   and reads its neighbours from the snapshot, as the reference reads `before`.
// Arithmetic: every float `precise` (no fused multiply-add) in the reference<float>'s order;
// divisions through gt_div, rounded to nearest like the CPU's, so the twins agree bit for bit.
// Units: metres.
// Inputs:  declares LayeredBlock (uniform binding 0) and the state buffers surface (1), soil (2),
//          bedrock (3), bedrock_type (4, read only), vegetation (5), bedrock_types (6, read only),
//          outflow (7); local size 16 x 16.
// Outputs: the helpers above (soil_at, bedrock_at, neighbours, the random factor, thicknesses, the
//          topmost non-empty layer, the availability clamp) for the passes that include it.
// Twin:    core/layered/layered_ground.hpp, reference/erosion/layered/column.cpp and transfer.cpp.
#ifndef GT_EROSION_LAYERED_GLSL
#define GT_EROSION_LAYERED_GLSL

#include "common/grid.glsl"
#include "common/rng.glsl"
#include "erosion/layered/division.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

// Mirrored by LayeredBlock in gpu/erosion/layered/ground_buffers.hpp (std140 offsets checked in its .cpp).
layout(std140, binding = 0) uniform LayeredBlock {
  vec4 repose_tan_a;            // tan φ of org, sand, gravel, stones (eq. 3.1)
  vec4 distance_a;              // l_k for k = 0..3 (L, R, T, B), m
  vec4 distance_b;              // k = 4..7 (diagonals), m
  ivec2 grid_size;
  int bedrock_layer_count;
  int periodic;                 // 1: the code's wrap; 0: closed walls
  float repose_boulders;
  float time_step;              // Δt, s
  float vegetation_repose;      // K_sveg
  float depth_factor;           // K_depth
  float topsoil_max;            // m
  float creep_rate;             // K_z, m/s
  float critical_slope;         // S_c
  float creep_denominator_floor;
  float random_base;            // float(0.9): rand(0.9, 1) = random_base + random_span·u
  float random_span;            // float(0.1)
  uint seed;
  uint step_number;            // the step counter of the random keys
  int talus_thesis_amount;      // 1: eq. 3.3; 0: the seed001_code amount
  int talus_random;
  int creep_random;
  int creep_floored;            // 1: the seed001_code denominator
  // Vegetation (§3.15) and weathering (§3.16).
  vec4 vegetation_quality_a;    // K_v of org, sand, gravel, stones
  vec4 weathering_shares;       // K_org, K_1,0, K_2,1, K_3,2
  float vegetation_quality_boulders;
  float vegetation_rate;        // K_veg, 1/s
  float vegetation_equilibrium; // K_eveg
  float vegetation_neighbours;  // K_nveg
  float root_depth;             // K_vd, m
  float root_depth_deep;        // m (seed001_code)
  float vegetation_base;        // (seed001_code)
  int vegetation_code;          // 1: the seed001_code quality
  float weathering_rate;        // K_conv, m/s
  float weathering_reach;       // m
};

struct BedrockTypeRecord {
  vec4 fragments;  // K_rock: sand, gravel, stones, boulders
  float repose_tan;
  float soil_rate;              // K_t of bedrock → soil, m/s (§3.16)
  vec4 soil_composition_a;      // K_t,i of org, sand, gravel, stones (boulders: the remainder)
  vec4 erosion_slopes;          // A^rock row of the type: sand .. boulders (§3.12)
  vec4 erosion_thresholds;      // B^rock row, m
};

layout(std430, binding = 1) buffer Surface { float surface[]; };
layout(std430, binding = 2) buffer Soil { float soil[]; };
layout(std430, binding = 3) buffer Bedrock { float bedrock[]; };
layout(std430, binding = 4) readonly buffer BedrockTypeIndex { int bedrock_type[]; };
layout(std430, binding = 5) buffer Vegetation { float vegetation[]; };
layout(std430, binding = 6) readonly buffer BedrockTypes { BedrockTypeRecord bedrock_types[]; };
layout(std430, binding = 7) buffer Outflows { float outflow[]; };  // 8 per column, to neighbour k, m

const int SOIL_LAYERS = 2;
const int COMPONENTS = 5;
const int NEIGHBOURS = 8;
const bool CURRENT = false;
const bool SNAPSHOT = true;
// gt::pipe_offsets: L, R, T, B, TL, BR, TR, BL (k and k^1 opposite).
const ivec2 neighbour_offsets[8] =
    ivec2[8](ivec2(-1, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, -1), ivec2(-1, 1), ivec2(1, -1), ivec2(1, 1),
             ivec2(-1, -1));

uint cell_count() { return uint(grid_size.x) * uint(grid_size.y); }
// Indices into `soil` and `bedrock`, in the current half or the snapshot's.
uint soil_at(bool snapshot, int layer, int component, uint c) {
  uint half_offset = snapshot ? uint(SOIL_LAYERS * COMPONENTS) * cell_count() : 0u;
  return half_offset + uint(layer * COMPONENTS + component) * cell_count() + c;
}
uint bedrock_at(bool snapshot, int layer, uint c) {
  uint half_offset = snapshot ? uint(bedrock_layer_count) * cell_count() : 0u;
  return half_offset + uint(layer) * cell_count() + c;
}
int type_at(int layer, uint c) { return bedrock_type[uint(layer) * cell_count() + c]; }

float unbounded() { return uintBitsToFloat(0x7f800000u); }  // +∞, as the reference's
float neighbour_distance(int k) { return k < 4 ? distance_a[k] : distance_b[k - 4]; }
float component_repose(int component) { return component < 4 ? repose_tan_a[component] : repose_boulders; }

// Neighbour k of `cell`, or −1 outside a closed border (layered_neighbour).
int neighbour(ivec2 cell, int k) {
  ivec2 n = cell + neighbour_offsets[k];
  if (periodic != 0) return int(cell_index((n + grid_size) % grid_size, grid_size));
  return inside_grid(n, grid_size) ? int(cell_index(n, grid_size)) : -1;
}

// rand(0.9, 1) on the reference's key (seed, c, step, stream); 1 when off.
float random_factor(bool on, uint c, uint stream) {
  if (!on) return 1.0;
  precise float u = uniform01(random_u32(seed, c, step_number, stream));
  precise float factor = random_base + random_span * u;
  return factor;
}

// Components summed in order org .. boulders.
float soil_thickness(bool snapshot, int layer, uint c) {
  precise float sum = 0.0;
  for (int i = 0; i < COMPONENTS; ++i) sum += soil[soil_at(snapshot, layer, i, c)];
  return sum;
}

// 0 topsoil, 1 subsoil, 2 + k bedrock layer k: the topmost with thickness > 0; −1 none.
int top_nonempty_layer(bool snapshot, uint c) {
  for (int layer = 0; layer < SOIL_LAYERS; ++layer) {
    if (soil_thickness(snapshot, layer, c) > 0.0) return layer;
  }
  for (int layer = 0; layer < bedrock_layer_count; ++layer) {
    if (bedrock[bedrock_at(snapshot, layer, c)] > 0.0) return SOIL_LAYERS + layer;
  }
  return -1;
}

// Surface heights of the 8 neighbours; +∞ where a closed border has none.
void neighbour_surfaces(ivec2 cell, out float surfaces[8]) {
  for (int k = 0; k < NEIGHBOURS; ++k) {
    int n = neighbour(cell, k);
    surfaces[k] = n >= 0 ? surface[n] : unbounded();
  }
}

// The availability clamp: when Σ amounts > available, every amount × available/Σ.
void clamp_to_available(inout float amounts[8], float available) {
  precise float total = 0.0;
  for (int k = 0; k < NEIGHBOURS; ++k) total += amounts[k];
  if (total <= available) return;
  precise float factor = gt_div(available, total);
  for (int k = 0; k < NEIGHBOURS; ++k) {
    precise float scaled = amounts[k] * factor;
    amounts[k] = scaled;
  }
}

void store_outflows(uint c, float amounts[8]) {
  for (int k = 0; k < NEIGHBOURS; ++k) outflow[uint(NEIGHBOURS) * c + uint(k)] = amounts[k];
}

#endif
