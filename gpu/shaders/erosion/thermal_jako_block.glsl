// Buffers and parameters of Jákó & Tóth's thermal erosion (thermal_jako_outflow.comp and
// thermal_jako_gather.comp). The uniform block is mirrored by ThermalJakoBlock in
// gpu/erosion/thermal_jako.cpp, whose offsets are checked against this block when the program links
// (GlProgram::check_block).
// Pipes 0-3 are (-1,0) (0,1) (1,0) (0,-1), pipes 4-7 the diagonals (-1,-1) (-1,1) (1,1) (1,-1);
// outflows of a cell are stored as two vec4: pipes 0-3, then 4-7.
// Inputs:  declares ThermalJakoBlock (uniform binding 0), heights (1, read only), valid (2), outflows
//          (3), next_heights (4, write only).
// Outputs: the block, buffers, talus_limit(k) and outflow(index, k) of the two passes; the pipes
//          (common/moore_pipes.glsl).
// Twin:    reference/erosion/thermal_jako.cpp; host: gpu/erosion/thermal_jako.cpp.
layout(local_size_x = 16, local_size_y = 16) in;

layout(std140, binding = 0) uniform ThermalJakoBlock {
  vec4 talus_limit_cardinal;  // T·l for pipes 0-3
  vec4 talus_limit_diagonal;  // T·l for pipes 4-7
  ivec2 grid_size;            // width, height
  float rate;                 // Δt·C_t·R of eq. 2.32
};

layout(std430, binding = 1) readonly buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
layout(std430, binding = 3) buffer Outflows { vec4 outflows[]; };
layout(std430, binding = 4) writeonly buffer NextHeights { float next_heights[]; };

#include "common/moore_pipes.glsl"

float talus_limit(int k) { return k < 4 ? talus_limit_cardinal[k] : talus_limit_diagonal[k - 4]; }

float outflow(uint index, int k) { return outflows[2u * index + uint(k / 4)][k % 4]; }
