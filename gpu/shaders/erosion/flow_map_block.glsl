// Buffers, parameters and texel access of seed 000's flow map (§4.7; digest 000 §4.7):
// flow_map_droplets.comp and flow_map_plug.comp. The uniform block is mirrored by FlowBlock in
// gpu/erosion/flow_map.cpp, whose offsets are checked against this block when the program links (GlProgram::check_block).
//
// Heights are read only; a texel off the grid or masked (valid == 0) reads 0 and takes no flow. The
// concentration lives in `flow` (race, disjoint: floats written in place, eq. 4.12) or, with
// FLOW_BATCH, in `flow_weights` (ints: each visit's weight in units of 2^-10, by atomicAdd) that
// flow_map_plug.comp turns into F = 1 - Π batch_powers[i] over the set bits i. The plug pass writes
// `plugged`.
// Inputs:  declares FlowBlock (uniform binding 0), heights (1), valid (2), flow or flow_weights (3),
//          plugged (4).
// Outputs: the texel access (open_cell, load_height) the two passes use.
// Twin:    reference/erosion/flow_map.cpp; host: gpu/erosion/flow_map.cpp.
#ifndef FLOW_MAP_BLOCK_GLSL
#define FLOW_MAP_BLOCK_GLSL

#include "erosion/hydra_motion.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = 0) uniform FlowBlock {
  ivec2 grid_size;          // width, height (texels)
  ivec2 droplet_grid;       // ceil(width / spacing), ceil(height / spacing): droplets per pass
  int droplet_spacing;      // the flow map's own spacing
  int lifetime;             // steps of one droplet
  uint interpolated_flow;   // 1: eq. 4.12 over erode4's 4 corners with factor f_c·w
  float acceleration;       // a
  float max_velocity;       // v_max, texels per step
  float drag;               // velocity multiplier (1 - UI drag)
  float flow_factor;        // f_c of eq. 4.12 (eq. 4.13 of the contrast)
  float no_limit;           // the largest float: Algorithm 4 without drop_max
  vec4 batch_powers[8];     // FLOW_BATCH: (1 - f_c)^(2^i · 2^-10), i = 0..30, [i / 4][i % 4]
};

layout(std430, binding = 1) readonly buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };  // 1 = valid, 0 = no data
#ifdef FLOW_BATCH
layout(std430, binding = 3) buffer FlowWeights { int flow_weights[]; };  // Σ w in units of 2^-10
#else
layout(std430, binding = 3) buffer Flow { float flow[]; };  // the concentration F
#endif
layout(std430, binding = 4) buffer Plugged { float plugged[]; };  // after the plug pass

// Whether `cell` is inside the grid and valid.
bool open_cell(ivec2 cell) {
  if (!inside_grid(cell, grid_size)) return false;
  return valid[cell_index(cell, grid_size)] != 0u;
}

// The height of an open cell, 0 elsewhere.
float load_height(ivec2 cell) {
  if (!open_cell(cell)) return 0.0;
  return heights[cell_index(cell, grid_size)];
}

#endif
