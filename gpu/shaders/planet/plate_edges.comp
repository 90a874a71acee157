#version 450
// Step 3 (§4.4.2, §9.3 step 3; core/params/planet.hpp), twin of reference::edge_regions:
// is_edge(i) = 1 when some valid neighbour has another plate, else 0.
// Inputs:  PlanetBlock (uniform binding 0), neighbours (0), plate (3) (planet.glsl).
// Outputs: is_edge (6).
// Twin:    reference/planet/plates.cpp (edge_regions).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
  uint edge = 0u;
#ifdef GT_MUTANT_PLANET_PLATES_EDGES_WITHOUT_DIAGONALS
  for (int k = 0; k < neighbour_count; k += 2) {  // mutant (both twins): the cardinal neighbours only
#else
  for (int k = 0; k < neighbour_count; ++k) {
#endif
    int neighbour = neighbours[neighbour_count * region + k];
    if (neighbour >= 0 && plate[neighbour] != plate[region]) edge = 1u;
  }
  is_edge[region] = edge;
}
