#version 450
// Test probe of gt_sqrt (square_root.glsl): roots[i] = gt_sqrt(values[i]), compared with the CPU's
// std::sqrt(float) by tests/layered_gpu_test.cpp. Dimensionless.
// Inputs:  values (binding 0).
// Outputs: roots (binding 1).
// Twin:    the CPU's std::sqrt(float) (tests/layered_gpu_test.cpp).
#include "erosion/layered/square_root.glsl"

layout(local_size_x = 64, local_size_y = 1) in;
layout(std430, binding = 0) readonly buffer Values { float values[]; };
layout(std430, binding = 1) writeonly buffer Roots { float roots[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(values.length())) return;
  roots[i] = gt_sqrt(values[i]);
}
