#version 450
// Step 2, one sub-step s of the synchronous rule (§9.3 step 2; core/params/planet.hpp), twin of
// reference::grow_plates (PlateRule::synchronous): plate k is active when s < expansions(k, cycle);
// every region without a plate takes the lowest active plate index among its valid neighbours'
// plates as they were before the sub-step (a Jacobi step: reads `plate`, writes `plate_next`, the
// host swaps them). Regions with a plate keep it. Each claim adds 1 to assigned_count, which the
// host reads after a cycle to stop when it reaches N. Integers only: the twins agree exactly.
// Inputs:  PlanetBlock (uniform binding 0), neighbours (0), plate (3), plates (7: expansions) (planet.glsl);
//          the uniform sub_step.
// Outputs: plate_next (4); assigned_count (8) by atomicAdd.
// Twin:    reference/planet/plates.cpp (grow_plates, synchronous rule).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

uniform int sub_step;

int lowest_active_neighbour_plate(int region) {
  int lowest = -1;
  for (int k = 0; k < neighbour_count; ++k) {
    int neighbour = neighbours[neighbour_count * region + k];
    if (neighbour < 0) continue;
    int candidate = plate[neighbour];
    bool expanding = candidate >= 0 && sub_step < plates[candidate].expansions;
#ifdef GT_MUTANT_PLANET_PLATES_GPU_HIGHEST_INDEX
    if (expanding && (lowest < 0 || candidate > lowest)) lowest = candidate;  // mutant (this twin alone)
#else
    if (expanding && (lowest < 0 || candidate < lowest)) lowest = candidate;
#endif
  }
  return lowest;
}

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
  int owner = plate[region];
  if (owner < 0) {
    owner = lowest_active_neighbour_plate(region);
#ifdef GT_MUTANT_PLANET_PLATES_GPU_COUNTS_VISITS
    atomicAdd(assigned_count, 1u);  // mutant (this twin alone): every visit counted, claimed or not
#else
    if (owner >= 0) atomicAdd(assigned_count, 1u);
#endif
  }
  plate_next[region] = owner;
}
