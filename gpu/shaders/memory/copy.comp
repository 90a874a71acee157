#version 450
// The memory-bandwidth probe of the performance table (gpu/memory/copy_bandwidth.cpp): each
// invocation copies one float, so a dispatch reads 4 B and writes 4 B per element and does no
// arithmetic. Its time is the floor any kernel touching as many bytes cannot go below.
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"

layout(std430, binding = 0) readonly buffer Source { float source[]; };
layout(std430, binding = 1) writeonly buffer Target { float target[]; };

uniform uint element_count;

void main() {
  const uint element = linear_invocation();
  if (element < element_count) target[element] = source[element];
}
