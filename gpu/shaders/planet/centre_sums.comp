#version 450
// Step 4, the sums (core/params/planet.hpp; §9.3 step 4): every region adds its position to its
// plate's sum (centre `mean`, the thesis) or only edge regions do (PLANET_CENTRE_EDGE_SUM, the
// code), in the order-independent fixed point of planet/fixed_point.glsl. Needs centre_sums
// cleared to 0 by the host.
// Inputs:  PlanetBlock (uniform binding 0), positions (2), plate (3), is_edge (6) (planet.glsl).
// Outputs: centre_sums (9): 6 uints per plate, by atomicAdd.
// Twin:    reference/planet/elevation.cpp (plate_centres' sums, in double there).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"
#include "planet/fixed_point.glsl"

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
#ifdef PLANET_CENTRE_EDGE_SUM
  if (is_edge[region] == 0u) return;
#endif
  uint slot = 6u * uint(plate[region]);
  vec3 position = positions[region].xyz;
  for (int axis = 0; axis < 3; ++axis) add_fixed_point(slot + 2u * uint(axis), position[axis]);
}
