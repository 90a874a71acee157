#version 450
// The memory-bandwidth probe of the performance table (gpu/memory/copy_bandwidth.cpp): each
// invocation copies one vec4 (four floats), so a dispatch reads 4 B and writes 4 B per float and
// does no arithmetic. A vec4 rather than a float per invocation: on llvmpipe, a float copy is
// bound by the cost of an invocation, not by memory, and read 2 GB/s where kernels moving more
// bytes per invocation went faster.
// Inputs:  source (binding 0), the uniform vector_count.
// Outputs: target (binding 1).
// Twin:    none: a bandwidth probe, not an algorithm (host: gpu/memory/copy_bandwidth.cpp).
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"

layout(std430, binding = 0) readonly buffer Source { vec4 source[]; };
layout(std430, binding = 1) writeonly buffer Target { vec4 target[]; };

uniform uint vector_count;

void main() {
  const uint vector = linear_invocation();
  if (vector < vector_count) target[vector] = source[vector];
}
