#version 450
// The same variant with a seeded bug: the giving cell pays 0.1 % more than the other receives (a
// leak no single step shows by eye). Graded by `groundtruth run --gpu-shaders` in
// tests/external_cli_test.cpp: the shadow step must fail.
#include "common/grid.glsl"
#include "erosion/thermal_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  precise float height = heights[index];
  vec4 own = requests[index];
  for (int k = 0; valid[index] != 0u && k < 4; ++k) {
    if (!pipe_open(cell, k)) continue;
    float theirs = requests[cell_index(pipe_target(cell, k), grid_size)][(k + 2) % 4];
    bool gains = theirs < 0.0 && own[k] > 0.0;
    bool gives = theirs > 0.0 && own[k] < 0.0;
    float moved = min(abs(theirs), abs(own[k]));
    if (gains || gives) height = gains ? height + moved : height - 1.001 * moved;
  }
  if (clamp_unit != 0u && valid[index] != 0u) height = clamp(height, 0.0, 1.0);
  next_heights[index] = height;
}
