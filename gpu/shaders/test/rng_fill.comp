#version 450
// Test shader of tests/rng_parity_test.cpp: element i of `bits` gets random_u32(rng_seed, i,
// rng_step, rng_stream) and element i of `uniforms` gets uniform01 of it, for i < count.
// Inputs:  the uniforms rng_seed, rng_step, rng_stream, count.
// Outputs: bits (binding 0), uniforms (binding 1).
// Twin:    core/rng.hpp (random_u32, uniform01), compared by tests/rng_parity_test.cpp.
#include "common/rng.glsl"

layout(local_size_x = 64, local_size_y = 1) in;

layout(std430, binding = 0) writeonly buffer Bits { uint bits[]; };
layout(std430, binding = 1) writeonly buffer Uniforms { float uniforms[]; };

uniform uint rng_seed;
uniform uint rng_step;
uniform uint rng_stream;
uniform uint count;

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= count) return;
  uint drawn = random_u32(rng_seed, index, rng_step, rng_stream);
  bits[index] = drawn;
  uniforms[index] = uniform01(drawn);
}
