// What the water passes of the layered ground share (digest 001 §3.3-3.5, §3.12-3.15, §3.19; CPU
// twin: core/layered/layered_water.hpp, reference/erosion/layered/{water,force_erosion,dissolution,
// wetness}.cpp; host: gpu/erosion/layered/water_buffers.cpp): the water's parameter block and its
// storage buffer.
//
// Water buffer layout, sections of `cells` floats (cell c = y·width + x):
//   WATER, PREVIOUS (w before the step's flow), WETNESS, FLUX + k (pipe k = L, R, T, B), CARRIED + q
//   (q = 0..4 suspended org .. boulders, 5..6 regolith org, sand), SURFACE_BEFORE (the surface
//   snapshot force erosion reads), DRAINED (1.0 where the flux pass scaled the outflows); then a second half of the same sections, the snapshot the flow's
//   move pass reads (copied by the host).
// Arithmetic as layered.glsl: every float `precise`, divisions through gt_div and roots through
// gt_sqrt, in the reference<float>'s order, so the twins agree bit for bit. Units: metres, m/s, m³/s.
// Inputs:  declares LayeredWaterBlock (uniform binding 1) and the water state water_state (10).
// Outputs: the section indexing of the water state for the water passes.
// Twin:    core/layered/layered_water.hpp; reference/erosion/layered/water.cpp, force_erosion.cpp,
//          dissolution.cpp, wetness.cpp.
#ifndef GT_EROSION_LAYERED_WATER_GLSL
#define GT_EROSION_LAYERED_WATER_GLSL

#include "erosion/layered/layered.glsl"
#include "erosion/layered/square_root.glsl"

// Mirrored by LayeredWaterBlock in gpu/erosion/layered/water_buffers.hpp (std140 offsets checked in
// its .cpp).
layout(std140, binding = 1) uniform LayeredWaterBlock {
  vec4 pipe_coefficient;         // P_k = Δt·l_x·l_y·g/l_k for L, R, T, B
  vec4 breakdown_slopes[4];      // A (eq. 3.8), row j = source size
  vec4 breakdown_thresholds[4];  // B (eq. 3.9)
  float cell_area;               // l_x·l_y, m²
  float rain_depth;              // Δt·rain_rate, m
  float river_depth;             // m
  int river;                     // 1: the river's source and sink rows
  int river_source;              // its source column's cell index
  int sink_row_start;            // the first sink row
  float velocity_depth_floor;    // m
  float depth_ramp;              // K_w, m
  float slope_floor;
  float slope_scale_x;           // ½/l_x (thesis) or 1 (seed001_code)
  float slope_scale_y;
  float cell_size_x;             // m
  float cell_size_y;             // m
  float erosion_strength;        // K_c, s
  float organic_capacity;
  float erosion_rate;            // K_e
  float deposition_rate;         // K_d
  float vegetation_protection;   // K_wveg
  int breakdown_code;            // 1: the code's max(a·x − b, 0)
  int share_code;                // 1: the code's min(V_j, m)·share
  float least_share;             // K_emin
  float transparency_depth;      // K_pmin, m
  float regolith_depth;          // K_r, m
  float regolith_erosion;        // K_re
  float regolith_deposition;     // K_rd
  float drying_factor;           // K_dry^Δt
  float flood_wetness;           // m·s
  float impact_scale;            // K_i·Δt/(l_x·l_y), 1/m (§3.14)
  float sediment_diffusion;      // σ (§3.8)
  int diffusion_water;           // 1: the code's weights by water depth
  int regolith_diffusion;        // 1: the regolith diffuses too
  int rain_steps;                // rain on iterations below it; 0: on every one
  int drain_step;                // the iteration at whose start every column drains; 0: never
};

layout(std430, binding = 10) buffer LayeredWaterState { float water_state[]; };

const uint WATER = 0u, PREVIOUS = 1u, WETNESS = 2u, FLUX = 3u, CARRIED = 7u, SURFACE_BEFORE = 14u, DRAINED = 15u;
const uint WATER_SECTIONS = 16u;
const float NEGLIGIBLE = 5.42101086e-20;  // gt::negligible_amount, 2^-64
const int PIPES = 4;
const int CARRIED_KINDS = 7;
const int REGOLITH = 5;  // kind of the regolith's org; sand follows

uint water_at(bool snapshot, uint section, uint c) {
  return (snapshot ? WATER_SECTIONS * cell_count() : 0u) + section * cell_count() + c;
}

float flux_of(int pipe, int n) { return n >= 0 ? water_state[water_at(CURRENT, FLUX + uint(pipe), uint(n))] : 0.0; }

// The column's net flux (eq. 2.2's ½-averaged pipe pairs; reference net_flux), m³/s: x toward +x,
// y toward +y; a missing neighbour's flux is 0.
vec2 net_flux(ivec2 cell, uint c) {
  int left = neighbour(cell, 0), right = neighbour(cell, 1), top = neighbour(cell, 2), bottom = neighbour(cell, 3);
  int self = int(c);
  precise float flux_x = 0.5 * ((flux_of(1, left) - flux_of(0, self)) + (flux_of(1, self) - flux_of(0, right)));
  precise float flux_y = 0.5 * ((flux_of(2, bottom) - flux_of(3, self)) + (flux_of(2, self) - flux_of(3, top)));
  return vec2(flux_x, flux_y);
}

// w̄ = max(½(w + w_prev), velocity_depth_floor) (reference mean_depth), m.
float mean_depth(uint c) {
  precise float depths = water_state[water_at(CURRENT, WATER, c)] + water_state[water_at(CURRENT, PREVIOUS, c)];
  precise float half_depths = 0.5 * depths;
  return max(half_depths, velocity_depth_floor);
}

// a(x) of one matrix entry: max(A·(x − B), 0), or max(A·x − B, 0) with breakdown_code.
float breakdown(float slope, float threshold, float strength) {
  precise float thesis = slope * (strength - threshold);
  precise float code = slope * strength - threshold;
  return max(breakdown_code != 0 ? code : thesis, 0.0);
}

#endif
