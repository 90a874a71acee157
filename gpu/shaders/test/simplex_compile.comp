#version 450
// Test shader of tests/simplex_test.cpp (SimplexGlsl.Compiles): calls every function of
// noise/simplex.glsl, so that loading it compiles them all. At points[i] (i < count) it writes 10
// floats from results[10·i]: gt_simplex2, gt_simplex2_gradient (3), gt_simplex3,
// gt_simplex3_gradient (4), gt_simplex4; 3-D and 4-D with kernel_radius_squared.
// Inputs:  points (binding 0), the permutation (binding 5), the uniforms count and
//          kernel_radius_squared.
// Outputs: results (binding 1): 10 floats per point.
// Twin:    reference/noise/simplex.hpp, compared by tests/simplex_test.cpp.
#include "noise/simplex.glsl"

layout(local_size_x = 64, local_size_y = 1) in;

layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
layout(std430, binding = 1) writeonly buffer Results { float results[]; };

uniform uint count;
uniform float kernel_radius_squared;

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= count) return;
  vec4 p = points[index];
  vec3 gradient2 = gt_simplex2_gradient(p.xy);
  vec4 gradient3 = gt_simplex3_gradient(p.xyz, kernel_radius_squared);
  uint base = 10u * index;
  results[base] = gt_simplex2(p.xy);
  results[base + 1u] = gradient2.x;
  results[base + 2u] = gradient2.y;
  results[base + 3u] = gradient2.z;
  results[base + 4u] = gt_simplex3(p.xyz, kernel_radius_squared);
  results[base + 5u] = gradient3.x;
  results[base + 6u] = gradient3.y;
  results[base + 7u] = gradient3.z;
  results[base + 8u] = gradient3.w;
  results[base + 9u] = gt_simplex4(p, kernel_radius_squared);
}
