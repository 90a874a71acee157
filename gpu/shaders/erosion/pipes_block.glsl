// Buffers, parameters and helpers of the virtual-pipe erosion (Mei 2007) shaders pipes_*.comp.
// The uniform block is mirrored by PipeBlock in gpu/erosion/pipes.cpp, whose offsets are checked
// against this block when the program links (GlProgram::check_block). The algorithm, its decisions
// and the float-trap storage are described at the top of gpu/erosion/pipes.cpp.
//
// Pipes 0-3 are L, R, T, B: (-1,0), (1,0), (0,1), (0,-1); with PIPES_8 also the diagonals 4-7, TL,
// BR, TR, BL: (-1,1), (1,-1), (1,1), (-1,-1); pipe k and k ^ 1 are opposite. Per-pipe values are
// two vec4 (`vec4 v[2]`, pipe k in v[k / 4][k % 4]); the buffers outflow, sent and regolith_sent
// hold pipe_groups vec4 per cell (1 with 4 pipes, 2 with 8).
// Terrain = base + change: `cells[i].base` is the initial height b0 (float, never written) and
// `delta` the change Δb (starts at 0), so height differences are formed as
// (b0_a - b0_b) + (Δb_a - Δb_b) and an erosion amount far below the float spacing of b0 is kept.
// Every arithmetic result is `precise` (no fused multiply-add, no reassociation), and max/min/clamp
// are written as std::max/std::min/std::clamp evaluate them (NaN handling included), so the float
// reference repeats the shaders operation by operation.
// Inputs:  declares PipeBlock (uniform binding 0) and the buffers cells (1), delta (2), delta_next (3),
//          water (4), outflow (5), velocity (6), sediment (7), staying (8), sent (9), regolith (12),
//          regolith_staying (13), regolith_sent (14), thermal_outflows (15), layers (18).
// Outputs: the pipe helpers (pipe offsets, exterior, terrain_difference, ref_max/ref_min) the
//          pipes_*.comp passes use.
// Twin:    reference/erosion/pipes.cpp; host: gpu/erosion/pipes.cpp.
#ifndef PIPES_BLOCK_GLSL
#define PIPES_BLOCK_GLSL

#ifdef PIPES_8
const int pipe_count = 8;
#else
const int pipe_count = 4;
#endif
const int pipe_groups = pipe_count / 4;  // vec4 per cell of outflow, sent, regolith_sent

layout(std140, binding = 0) uniform PipeBlock {
  vec4 flux_gain[2];        // Δt·A·g/l for pipes L, R, T, B (l = l_x, l_x, l_y, l_y), then the
                            // diagonals (l = l_d = sqrt(l_x² + l_y²))
  vec2 slope_span_x;        // 1·l_x, 2·l_x: one- and two-sided difference spans of the tilt
  vec2 slope_span_y;        // 1·l_y, 2·l_y (both 1 for seed 001's code tilt: raw differences)
  ivec2 grid_size;          // width, height
  float area_per_time;      // l_x·l_y/Δt
  float volume_to_depth;    // Δt/(l_x·l_y)
  float depth_floor;        // lower bound of the mean depth in the velocity, m
  float length_x;           // l_x, m
  float length_y;           // l_y, m
  float capacity_constant;  // K_c, s
  float depth_ramp;         // K_w, m; 0 = off
  float dissolving;         // min(1, K_s·Δt)
  float deposition;         // min(1, K_d·Δt)
  float min_tilt_sine;
  float backtrace_x;        // Δt/l_x: cells per (m/s) along x
  float backtrace_y;        // Δt/l_y
  float reach;              // width + height: the backtrace's clamp, cells
  float evaporation_kept;   // 1 - K_e·Δt
  uint boundary_open;       // 1: exterior pipes drain (open boundary); 0: walls
  uint source_cell_count;   // entries of source_cells
  float regolith_depth;       // K_r, m (the REGOLITH stage runs only when it is > 0)
  float regolith_dissolving;  // min(1, K_re·Δt): terrain loosened into regolith
  float regolith_deposition;  // min(1, K_rd·Δt): regolith settled back into terrain
  float diffusion_weight;     // w per neighbour (uniform weighting)
  vec2 diagonal_share;        // l_x/l_d, l_y/l_d: a diagonal pipe's flux share along x and y
  vec4 talus_limit_cardinal;  // thermal step: T·l for its pipes 0-3, (-1,0) (0,1) (1,0) (0,-1)
  vec4 talus_limit_diagonal;  // T·l for its pipes 4-7, (-1,-1) (-1,1) (1,1) (1,-1)
  float thermal_rate;         // Jákó's rate Δt·C_t·R per iteration
  vec4 layer_capacity;        // Šťava's C_1, C_2, C_3 (s) of the layers above the bedrock (LAYERS)
};

// Per-cell constants, uploaded once: the base height b0, the rain depth Δt·(r + r_map) added per
// step, and flags: bits 0-7 = pipe k is exterior (off the grid or into a no-data cell), bit 8 =
// the cell is valid.
struct CellConstants {
  float base;
  float rain;
  uint flags;
  uint unused;
};

layout(std430, binding = 1) readonly buffer Cells { CellConstants cells[]; };
layout(std430, binding = 2) buffer Delta { float delta[]; };            // Δb, current
layout(std430, binding = 3) buffer DeltaNext { float delta_next[]; };   // Δb, next (ping-pong)
layout(std430, binding = 4) buffer Water { vec4 water[]; };             // d, d_A, d_B, drained (1: K < 1)
layout(std430, binding = 5) buffer Outflow { vec4 outflow[]; };         // f per pipe, m³/s (pipe_groups per cell)
layout(std430, binding = 6) buffer Velocity { vec2 velocity[]; };       // u, v, m/s
layout(std430, binding = 7) buffer Sediment { float sediment[]; };      // s, m
// The sediment a cell keeps before transport; the diffusion pass writes the next s here instead
// (the host then swaps the two buffers).
layout(std430, binding = 8) buffer Staying { float staying[]; };
// Flux transport: sediment sent down each pipe this step (pipe_groups vec4 per cell).
// Semi-Lagrangian: x of the cell's first vec4 = sediment that left through exterior pipes (for the
// ledger), the rest 0.
layout(std430, binding = 9) buffer Sent { vec4 sent[]; };
// Bindings 10 and 11: point sources (pipes_sources.comp). The regolith r (seed 001 §3.9) and its
// transport buffers, used only with REGOLITH, as s's.
layout(std430, binding = 12) buffer Regolith { float regolith[]; };
layout(std430, binding = 13) buffer RegolithStaying { float regolith_staying[]; };
layout(std430, binding = 14) buffer RegolithSent { vec4 regolith_sent[]; };
// The thermal step's 8 outflows per cell as two vec4 (its pipes 0-3, then 4-7).
layout(std430, binding = 15) buffer ThermalOutflows { vec4 thermal_outflows[]; };
// Bindings 16 and 17: MacCormack's corrected s and r (pipes_maccormack.comp). Šťava's layer
// thicknesses b_1..b_LAYERS per cell, bottom first (only with LAYERS; read and written by the cell's
// own invocation of pipes_flow.comp alone).
layout(std430, binding = 18) buffer Layers { float layers[]; };

const ivec2 pipe_offsets[8] = ivec2[8](ivec2(-1, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, -1),
                                       ivec2(-1, 1), ivec2(1, -1), ivec2(1, 1), ivec2(-1, -1));
const int pipe_left = 0, pipe_right = 1, pipe_top = 2, pipe_bottom = 3;
const uint valid_flag = 256u;

bool cell_valid(uint flags) { return (flags & valid_flag) != 0u; }
bool exterior(uint flags, int k) { return ((flags >> uint(k)) & 1u) != 0u; }
int opposite(int k) { return k ^ 1; }
uint neighbour_index(ivec2 cell, int k) { return cell_index(cell + pipe_offsets[k], grid_size); }
// The element of outflow, sent or regolith_sent holding group `group` (0: pipes 0-3, 1: 4-7) of
// cell `index`; pipe k's value is [pipe_slot(index, k)][k % 4].
uint group_slot(uint index, int group) { return uint(pipe_groups) * index + uint(group); }
uint pipe_slot(uint index, int k) { return group_slot(index, k / 4); }

// std::max(a, b) = a < b ? b : a and std::min(a, b) = b < a ? b : a, NaN cases included.
float ref_max(float a, float b) { return a < b ? b : a; }
float ref_min(float a, float b) { return b < a ? b : a; }

// (v0 + v1) + (v2 + v3): (L + R) + (T + B) of the axis pipes, (TL + BR) + (TR + BL) of the
// diagonals, the fixed, mirror-invariant order of the reference.
float pipe_sum(vec4 values) {
  precise float sum = (values[0] + values[1]) + (values[2] + values[3]);
  return sum;
}

// The sum over all pipes in use: axis pipes, + diagonals with 8 pipes (the reference's pipe_sum).
float pipe_total(vec4 values[2]) {
  precise float total = pipe_sum(values[0]);
  if (pipe_groups > 1) total = total + pipe_sum(values[1]);
  return total;
}

// b_a - b_b from the base + change storage: (b0_a - b0_b) + (Δb_a - Δb_b). At a high base the
// first difference is exact (Sterbenz) and the second is formed at the precision of the changes.
float terrain_difference(uint a, uint b) {
  precise float difference = (cells[a].base - cells[b].base) + (delta[a] - delta[b]);
  return difference;
}

bool is_nan_bits(float value) { return (floatBitsToUint(value) & 0x7fffffffu) > 0x7f800000u; }

#endif
