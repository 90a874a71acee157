// A user's copy of thermal_block.glsl with two members of ThermalBlock swapped (request_factor and
// clamp_unit): the host's C++ mirror no longer matches, and the program's link must say which
// member (tests/external_cli_test.cpp). Otherwise the built-in file: buffers and parameters of
// seed 000's thermal erosion (thermal_requests.comp and thermal_transfer.comp). The uniform block is mirrored by ThermalBlock in gpu/erosion/thermal.cpp,
// whose offsets are checked against this block when the program links (GlProgram::check_block).
// Inputs:  declares ThermalBlock (uniform binding 0), heights (1, read only), valid (2), requests
//          (3), next_heights (4, write only).
// Outputs: the block and buffers of the two passes.
// Twin:    reference/erosion/thermal.cpp; host: gpu/erosion/thermal.cpp.
layout(local_size_x = 16, local_size_y = 16) in;

layout(std140, binding = 0) uniform ThermalBlock {
  vec4 talus_limit;      // T·l_k for the four pipes of this iteration
  ivec4 pipe_dx;         // pipe k points to (pipe_dx[k], pipe_dy[k]); k and (k+2)%4 are opposite
  ivec4 pipe_dy;
  ivec2 grid_size;       // width, height
  uint clamp_unit;       // 1: clamp results to [0, 1] (normalised heights)
  float request_factor;  // f_s
};

layout(std430, binding = 1) readonly buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
layout(std430, binding = 3) buffer Requests { vec4 requests[]; };
layout(std430, binding = 4) writeonly buffer NextHeights { float next_heights[]; };

ivec2 pipe_target(ivec2 cell, int k) { return cell + ivec2(pipe_dx[k], pipe_dy[k]); }

bool pipe_open(ivec2 cell, int k) {
  ivec2 target = pipe_target(cell, k);
  return inside_grid(target, grid_size) && valid[cell_index(target, grid_size)] != 0u;
}
