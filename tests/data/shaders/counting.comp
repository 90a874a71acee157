#version 450
// Test shader of tests/shader_program_test.cpp: writes library_answer() + OFFSET (a define) and
// counts its invocations, so the test sees includes, defines and the dispatch size at work.
#include "lib/answer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) buffer Result {
  uint answer;
  uint invocations;
};

void main() {
  if (gl_GlobalInvocationID.xy == uvec2(0)) answer = library_answer() + OFFSET;
  atomicAdd(invocations, 1u);
}
