#version 450
// Test shader: lib/cycle_b.glsl and lib/cycle_c.glsl include each other.
#include "lib/cycle_b.glsl"

layout(local_size_x = 1) in;

void main() {}
