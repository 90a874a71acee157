#version 450
// Pass 1 of the GPU marching tetrahedra: the cave's density at every sample of the block, in float:
// sample (i, j, k) = gt_simplex3(float(origin + (i, j, k)) ·
// world_to_noise, kernel_radius_squared), the integer world coordinate converted once, multiplied
// (not divided) by the reciprocal the host rounded once. Writes density[sample_index].
// Inputs:  CaveBlock (uniform binding 0: origin, sample counts, world_to_noise,
//          kernel_radius_squared), the permutation (binding 5, noise/permutation.glsl).
// Outputs: density (1).
// Twin:    reference/cave/density.cpp.
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"
#include "cave/cave_block.glsl"
#include "noise/simplex.glsl"

layout(std430, binding = 1) writeonly buffer Density { float density[]; };

void main() {
  uint index = linear_invocation();
  if (index >= uint(sample_counts.w)) return;
  vec3 world = vec3(lattice_origin.xyz + sample_of(index));
  precise vec3 noise_point = world * world_to_noise;
  density[index] = gt_simplex3(noise_point, kernel_radius_squared);
}
