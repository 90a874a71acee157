// Buffers and parameters of Beneš's dissolution erosion (dissolution_local.comp,
// dissolution_outflow.comp, dissolution_gather.comp). The uniform block is mirrored by
// DissolutionBlock in gpu/erosion/dissolution.cpp, whose offsets are checked against this block when
// the program links (GlProgram::check_block).
// Pipes 0-3 are (-1,0) (0,1) (1,0) (0,-1), pipes 4-7 the diagonals (-1,-1) (-1,1) (1,1) (1,-1), as
// in the reference; a cell's water outflows are two vec4: pipes 0-3, then 4-7.
// Inputs:  declares DissolutionBlock (uniform binding 0), terrain (1), valid (2, read only), outflows
//          (3), water (4), dissolved (5), evaporated (6), next_water (7), next_dissolved (8); the
//          host swaps water and dissolved with their next buffers after each gather.
// Outputs: the block, buffers and outflow(index, k) of the three passes; the pipes
//          (common/moore_pipes.glsl).
// Twin:    reference/erosion/dissolution.cpp; host: gpu/erosion/dissolution.cpp.
layout(local_size_x = 16, local_size_y = 16) in;

layout(std140, binding = 0) uniform DissolutionBlock {
  ivec2 grid_size;         // width, height
  float rain;              // K_r of eq. 2.1
  float retained;          // e^{-K_e} of eq. 2.2
  float threshold;         // T of eq. 2.3
  float saturation;        // K_s of eq. 2.4
  float dissolution_rate;  // share of S - s dissolved
  float deposition_rate;   // share of s - S deposited
  int mean_level;          // water_share: 0 pairwise (the thesis), 1 mean_level
};

layout(std430, binding = 1) buffer Terrain { float terrain[]; };
layout(std430, binding = 2) readonly buffer Valid { uint valid[]; };
layout(std430, binding = 3) buffer Outflows { vec4 outflows[]; };
layout(std430, binding = 4) buffer Water { float water[]; };
layout(std430, binding = 5) buffer Dissolved { float dissolved[]; };
layout(std430, binding = 6) buffer Evaporated { float evaporated[]; };
layout(std430, binding = 7) writeonly buffer NextWater { float next_water[]; };
layout(std430, binding = 8) writeonly buffer NextDissolved { float next_dissolved[]; };

#include "common/moore_pipes.glsl"

float outflow(uint index, int k) { return outflows[2u * index + uint(k / 4)][k % 4]; }
