#version 450
// Test shader: line 4 includes a file that does not exist.

#include "lib/does_not_exist.glsl"

layout(local_size_x = 1) in;

void main() {}
