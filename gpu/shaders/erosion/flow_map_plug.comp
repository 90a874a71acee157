#version 450
// The plug pass of seed 000's flow map (§4.7; upstream's plug.glsl as digest 000 §4.7 gives it):
// each open texel whose concentration is 0 or NaN takes the mean of its 4 neighbours' (off the grid
// and masked: 0), ((below + left) + right + above) / 4, read from the map before the pass, once;
// others keep theirs; masked texels get 0. With FLOW_BATCH the concentration of a texel is first made
// from its weight count n: 1 - Π batch_powers[i] over n's set bits i, ascending (n <= 0: 0).
// Mutants: none in this file.
// Inputs:  FlowBlock (uniform binding 0), valid (2), flow (3) or, with FLOW_BATCH, flow_weights (3)
//          (flow_map_block.glsl).
// Outputs: plugged (4): the concentration after the plug pass.
// Twin:    reference/erosion/flow_map.cpp.
#include "common/grid.glsl"
#include "erosion/flow_map_block.glsl"

// The concentration of an open cell before the plug pass, 0 elsewhere.
float concentration(ivec2 cell) {
  if (!open_cell(cell)) return 0.0;
  uint index = cell_index(cell, grid_size);
#ifdef FLOW_BATCH
  int count = flow_weights[index];
  if (count <= 0) return 0.0;
  precise float kept = 1.0;
  for (int bit = 0; bit < 31; ++bit) {
    if (((count >> bit) & 1) != 0) kept = kept * batch_powers[bit / 4][bit % 4];
  }
  precise float made = 1.0 - kept;
  return made;
#else
  return flow[index];
#endif
}

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  if (!open_cell(cell)) {
    plugged[index] = 0.0;
    return;
  }
  precise float own = concentration(cell);
  if (own == 0.0 || isnan(own)) {
    precise float sum = concentration(cell + ivec2(0, -1)) + concentration(cell + ivec2(-1, 0));
    sum = sum + concentration(cell + ivec2(1, 0));
    sum = sum + concentration(cell + ivec2(0, 1));
    precise float mean = sum / 4.0;
    plugged[index] = mean;
  } else {
    plugged[index] = own;
  }
}
