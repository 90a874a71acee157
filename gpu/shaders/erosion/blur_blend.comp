#version 450
// Beyer's blend with a blurred map (seed 000 §2.7, eq. 2.43; digest 000 §3.7): each open cell a
// receives w·(h_b - h_a), w = c_b/9 rounded to float on the host, from each of its 8 Moore
// neighbours b that is inside the grid and valid, summed in pipe order from 0 and then added to its
// height (the 3x3 box blur's blend written as exchanges, so the pairs cancel and the volume is
// kept; decisions in reference/erosion/blur_blend.hpp). Every cell reads the heights as the pass
// found them (Jacobi). All arithmetic is `precise`, in the reference's order.
// Without BLUR_BLEND_BATCH the blended height goes to `blended`, which the host copies over the
// heights; with it each exchange becomes roundEven(w·(h_b - h_a)·inverse_quantum) quanta, their sum
// the cell's delta, which the caller's apply pass adds (beyer_apply.comp). Heights in the caller's
// units.
// Mutants (compare/mutants/beyer.cpp): EROSION_BEYER_BLUR_RENORMALISED_AT_BORDER (both twins: the
// weight c_b/(1 + open neighbours), `renormalised_weight`), EROSION_BEYER_GPU_BLUR_TRUNCATED (this
// twin only: the batch count int(x) rounds toward zero instead of to nearest).
// Inputs:  uniforms grid_size, weight (c_b/9), renormalised_weights (the mutant's), inverse_quantum; heights (binding 1), valid (2).
// Outputs: delta (3) with BLUR_BLEND_BATCH (written, not added: the caller's apply cleared it);
//          blended (4) otherwise; masked cells keep their height and get delta 0.
// Twin:    reference/erosion/blur_blend.cpp; host: gpu/erosion/blur_blend.cpp.
#include "common/grid.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

uniform ivec2 grid_size;
uniform float weight;
uniform float renormalised_weights[9];  // the mutant's c_b/(1 + n), n = 0..8 open neighbours
uniform float inverse_quantum;

layout(std430, binding = 1) readonly buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
#ifdef BLUR_BLEND_BATCH
layout(std430, binding = 3) writeonly buffer Delta { int delta[]; };
#else
layout(std430, binding = 4) writeonly buffer Blended { float blended[]; };
#endif

#include "common/moore_pipes.glsl"

// c_b/9, or under the mutant c_b/(1 + open neighbours), each rounded once from double on the host.
float exchange_weight(ivec2 cell) {
#if defined(GT_MUTANT_EROSION_BEYER_BLUR_RENORMALISED_AT_BORDER)
  int open = 0;
  for (int k = 0; k < 8; ++k) open += pipe_open(cell, k) ? 1 : 0;
  return open == 8 ? weight : renormalised_weights[open];  // keeps `weight` active
#else
  return weight;
#endif
}

int exchange_quanta(float exchange) {
  precise float scaled = exchange * inverse_quantum;
#if defined(GT_MUTANT_EROSION_BEYER_GPU_BLUR_TRUNCATED)
  return int(scaled);
#else
  return int(roundEven(scaled));
#endif
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  bool open = valid[index] != 0u;
  float own = heights[index];
#ifdef BLUR_BLEND_BATCH
  int received = 0;
#else
  precise float received = 0.0;
#endif
  if (open) {
    float cell_weight = exchange_weight(cell);
    for (int k = 0; k < 8; ++k) {
      if (!pipe_open(cell, k)) continue;
      precise float difference = heights[cell_index(cell + pipe_offsets[k], grid_size)] - own;
      precise float exchange = cell_weight * difference;
#ifdef BLUR_BLEND_BATCH
      received += exchange_quanta(exchange);
#else
      received = received + exchange;
#endif
    }
  }
#ifdef BLUR_BLEND_BATCH
  delta[index] = received;
#else
  precise float height = own + received;
  blended[index] = open ? height : own;
#endif
}
