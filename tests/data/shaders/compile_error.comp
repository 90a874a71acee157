#version 450
// Test shader: the compile error is in the included file, on its line 5.
#include "lib/broken.glsl"

layout(local_size_x = 1) in;

void main() {}
