#version 450
// Pass A of seed 000's thermal erosion (digest 000 §4.6, Algorithms 9-10): each cell's request
// per pipe: negative = material this cell offers, positive = material it asks for. Decisions
// (0/0, borders, masks) are listed in the reference.
// All arithmetic is `precise` so that no multiply-add is fused: ref<float> repeats it exactly.
// Mutants (compare/mutants/thermal.cpp): DEMAND_TOTAL_THREE_PIPES (GPU only), DOUBLED_RATE and
// MIRRORED_SLOPE (both twins).
// Inputs:  ThermalBlock (uniform binding 0), heights (1), valid (2) (thermal_block.glsl).
// Outputs: requests (3): one vec4 per cell, a request per pipe.
// Twin:    reference/erosion/thermal.cpp.
#include "common/grid.glsl"
#include "erosion/thermal_block.glsl"

void main() {
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (!inside_grid(cell, grid_size)) return;
  uint index = cell_index(cell, grid_size);
  if (valid[index] == 0u) {
    requests[index] = vec4(0.0);
    return;
  }
  precise float height = heights[index];
  precise vec4 demand = vec4(0.0);
  precise vec4 supply = vec4(0.0);
  for (int k = 0; k < 4; ++k) {
    if (!pipe_open(cell, k)) continue;
#ifdef GT_MUTANT_EROSION_THERMAL_MIRRORED_SLOPE
    int read = pipe_open(cell, (k + 2) % 4) ? (k + 2) % 4 : k;
#else
    int read = k;
#endif
    precise float difference = heights[cell_index(pipe_target(cell, read), grid_size)] - height;
    if (difference > talus_limit[k]) {
      demand[k] = difference - talus_limit[k];
    } else if (difference < -talus_limit[k]) {
      supply[k] = difference + talus_limit[k];
    }
  }
  precise float largest_demand = max(max(demand[0], demand[1]), max(demand[2], demand[3]));
  precise float largest_supply = min(min(supply[0], supply[1]), min(supply[2], supply[3]));
#ifdef GT_MUTANT_EROSION_THERMAL_DEMAND_TOTAL_THREE_PIPES
  precise float demand_total = (demand[0] + demand[1]) + demand[2];
#else
  precise float demand_total = ((demand[0] + demand[1]) + demand[2]) + demand[3];
#endif
  precise float supply_total = ((supply[0] + supply[1]) + supply[2]) + supply[3];
#ifdef GT_MUTANT_EROSION_THERMAL_DOUBLED_RATE
  precise float factor = 2.0 * request_factor;
#else
  precise float factor = request_factor;
#endif
  precise float demand_share = 0.0;
  precise float supply_share = 0.0;
  if (demand_total > 0.0) demand_share = clamp(factor * largest_demand / demand_total, 0.0, 1.0);
  if (supply_total < 0.0) supply_share = clamp(factor * largest_supply / supply_total, 0.0, 1.0);
  precise vec4 request;
  for (int k = 0; k < 4; ++k) request[k] = supply[k] * supply_share + demand[k] * demand_share;
  requests[index] = request;
}
