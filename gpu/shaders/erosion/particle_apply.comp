#version 450
// End of one pass of seed 000's particle erosion in batch ordering (digest 000 §4.4, Appendix A;
// core/params/particle.hpp): each valid cell adds what the pass's droplets moved into or out of it,
// h = h + float(delta) · quantum (float(delta) rounded to nearest, the product exact as quantum is a
// power of two, the sum rounded once), and clears its delta for the next pass. Masked cells and
// their delta (never written) are left alone. Heights in the caller's units. With PARTICLE_COLOUR
// each valid cell with deposits also takes the weighted mean of its colour (weight 1) and the pass's
// colour deposits, per channel C = (C + float(Σ factor·col)·2^-20) / (1 + float(Σ factor)·2^-20)
// (numerator and denominator each rounded as written, then one division), and clears its 5 sums.
// Mutants (compare/mutants/particle.cpp): none in this file.
// Inputs:  ParticleBlock (uniform binding 0), valid (2), delta (3); with PARTICLE_COLOUR colour (6)
//          and colour_sums (7) (particle_block.glsl).
// Outputs: heights (1) of the valid cells, delta (3) cleared; with PARTICLE_COLOUR colour (6) and
//          colour_sums (7) cleared.
// Twin:    reference/erosion/particle.cpp (ColourDelta in reference/erosion/droplets.hpp).
#ifndef PARTICLE_BATCH
#error particle_apply.comp runs in the batch ordering only: compile it with PARTICLE_BATCH
#endif
#include "common/grid.glsl"
#include "erosion/particle_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!open_cell(cell)) return;
  uint index = cell_index(cell, grid_size);
  precise float change = float(delta[index]) * quantum;
  precise float height = heights[index] + change;
  heights[index] = height;
  delta[index] = 0;
#ifdef PARTICLE_COLOUR
  uint base = 5u * index;
  ivec4 weighted_sums = ivec4(colour_sums[base + 1u], colour_sums[base + 2u], colour_sums[base + 3u], colour_sums[base + 4u]);
  int factor_sum = colour_sums[base];
  if (factor_sum == 0 && weighted_sums == ivec4(0)) return;  // no deposit: the colour stays as it is
  const float unit = 1.0 / 1048576.0;  // 2^-20, exact
  precise float denominator = 1.0 + float(factor_sum) * unit;
  precise vec4 numerator = colour[index] + vec4(weighted_sums) * unit;
  precise vec4 mean = vec4(numerator.x / denominator, numerator.y / denominator, numerator.z / denominator,
                           numerator.w / denominator);
  colour[index] = mean;
  for (uint k = 0u; k < 5u; ++k) colour_sums[base + k] = 0;
#endif
}
