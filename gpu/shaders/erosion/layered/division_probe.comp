#version 450
// Test probe of gt_div (division.glsl): quotient[i] = gt_div(a, b) for pairs[i] = (a, b), compared
// with the CPU's float division by tests/layered_gpu_test.cpp. Dimensionless.
// Inputs:  pairs (binding 0): (a, b) per entry.
// Outputs: quotients (binding 1).
// Twin:    the CPU's float division (tests/layered_gpu_test.cpp).
#include "erosion/layered/division.glsl"

layout(local_size_x = 64, local_size_y = 1) in;
layout(std430, binding = 0) readonly buffer Pairs { vec2 pairs[]; };
layout(std430, binding = 1) writeonly buffer Quotients { float quotients[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(pairs.length())) return;
  quotients[i] = gt_div(pairs[i].x, pairs[i].y);
}
