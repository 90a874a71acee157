#version 450
// Second half of one level of the exclusive scan: adds to every value the scanned sum of the
// blocks before its block (block_sums, scanned by the next level), one invocation per value.
// Inputs:  values (binding 0), block_sums (1), the uniform value_count.
// Outputs: values (0), in place.
// Twin:    none: the scan has no reference of its own (host: gpu/cave/exclusive_scan.cpp).
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"
#include "cave/scan.glsl"

layout(std430, binding = 0) buffer Values { uint values[]; };
layout(std430, binding = 1) readonly buffer BlockSums { uint block_sums[]; };

uniform uint value_count;

void main() {
  uint index = linear_invocation();
  if (index >= value_count) return;
  values[index] += block_sums[index / SCAN_BLOCK_SIZE];
}
