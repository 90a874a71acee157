#version 450
// Stage 1, point sources: each entry of source_cells is one cell with sources; its depths
// rate·Δt/(l_x·l_y) are added to d_A one after the other in the order the sources were given, as
// the reference adds them (reference/erosion/pipes.cpp, add_water). One invocation per cell, so no
// two invocations write the same cell.
// Inputs:  PipeBlock (uniform binding 0) (pipes_block.glsl), source_cells (10: cell, first, count),
//          source_depths (11), water (4: d_A).
// Outputs: water (4: d_A) of the cells with sources.
// Twin:    reference/erosion/pipes.cpp (add_water).
layout(local_size_x = 64, local_size_y = 1) in;
#include "common/grid.glsl"
#include "erosion/pipes_block.glsl"

layout(std430, binding = 10) readonly buffer SourceCells { uvec4 source_cells[]; };  // cell, first, count, 0
layout(std430, binding = 11) readonly buffer SourceDepths { float source_depths[]; };

void main() {
  uint entry_index = gl_GlobalInvocationID.x;
  if (entry_index >= source_cell_count) return;
  uvec4 entry = source_cells[entry_index];
  precise float depth = water[entry.x].y;
  for (uint n = 0u; n < entry.z; ++n) depth = depth + source_depths[entry.y + n];
  water[entry.x].y = depth;
}
