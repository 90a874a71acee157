// Buffers and parameters of Jákó & Tóth's thermal erosion (thermal_jako_outflow.comp and
// thermal_jako_gather.comp). The uniform block is mirrored by ThermalJakoBlock in
// gpu/erosion/thermal_jako.cpp, whose offsets are checked against this block when the program links
// (GlProgram::check_block).
// Pipes 0-3 are (-1,0) (0,1) (1,0) (0,-1), pipes 4-7 the diagonals (-1,-1) (-1,1) (1,1) (1,-1);
// outflows of a cell are stored as two vec4: pipes 0-3, then 4-7.
// Inputs:  declares ThermalJakoBlock (uniform binding 0), heights (1, read only), valid (2), outflows
//          (3), next_heights (4, write only), cell constants (5, read only: per cell the thresholds
//          (C_a·R(n) + C_i)·l_k of its 8 pipes, then its rate·R, each rounded once from double by the
//          host, core/params/thermal.hpp's jako_cell_constants).
// Outputs: the block, buffers, talus_limit(index, k), cell_rate(index) and outflow(index, k) of the
//          two passes; the pipes (common/moore_pipes.glsl).
// Twin:    reference/erosion/thermal_jako.cpp; host: gpu/erosion/thermal_jako.cpp.
layout(local_size_x = 16, local_size_y = 16) in;

layout(std140, binding = 0) uniform ThermalJakoBlock {
  ivec2 grid_size;  // width, height
};

layout(std430, binding = 1) readonly buffer Heights { float heights[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
layout(std430, binding = 3) buffer Outflows { vec4 outflows[]; };
layout(std430, binding = 4) writeonly buffer NextHeights { float next_heights[]; };
layout(std430, binding = 5) readonly buffer CellConstants { float cell_constants[]; };

#include "common/moore_pipes.glsl"

const uint CELL_CONSTANTS = 9u;  // floats per cell: 8 thresholds, the rate

float talus_limit(uint index, int k) { return cell_constants[CELL_CONSTANTS * index + uint(k)]; }
float cell_rate(uint index) { return cell_constants[CELL_CONSTANTS * index + 8u]; }

float outflow(uint index, int k) { return outflows[2u * index + uint(k / 4)][k % 4]; }
