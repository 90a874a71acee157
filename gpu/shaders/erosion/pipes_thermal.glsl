// The 8-neighbour pipes of the pipe erosion's thermal step (pipes_thermal_*.comp), as
// gpu/shaders/erosion/thermal_jako_block.glsl numbers them.
// Inputs:  PipeBlock's talus limits and the thermal_outflows buffer (15) of pipes_block.glsl.
// Outputs: thermal_opposite, thermal_talus_limit, thermal_pipe_open, thermal_outflow.
// Twin:    reference/erosion/thermal_jako.cpp (its pipes), as used by reference/erosion/pipes.cpp.
#ifndef PIPES_THERMAL_GLSL
#define PIPES_THERMAL_GLSL

const ivec2 thermal_offsets[8] = ivec2[8](ivec2(-1, 0), ivec2(0, 1), ivec2(1, 0), ivec2(0, -1),
                                          ivec2(-1, -1), ivec2(-1, 1), ivec2(1, 1), ivec2(1, -1));

int thermal_opposite(int k) { return k < 4 ? (k + 2) % 4 : 4 + (k - 2) % 4; }

float thermal_talus_limit(int k) { return k < 4 ? talus_limit_cardinal[k] : talus_limit_diagonal[k - 4]; }

bool thermal_pipe_open(ivec2 cell, int k) {
  ivec2 target = cell + thermal_offsets[k];
  return inside_grid(target, grid_size) && cell_valid(cells[cell_index(target, grid_size)].flags);
}

float thermal_outflow(uint index, int k) { return thermal_outflows[2u * index + uint(k / 4)][k % 4]; }

#endif
