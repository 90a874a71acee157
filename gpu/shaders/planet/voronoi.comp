#version 450
// Spherical Voronoi of the region centroids by Algorithm 1's cell-grid search
// (planet/voronoi_search.glsl), per query direction; twin of reference::nearest_sites (an exact
// k-d tree search). Host: gpu/planet/voronoi.cpp.
layout(local_size_x = 64) in;

#include "planet/voronoi_search.glsl"

layout(std430, binding = 2) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 3) writeonly buffer Labels { int labels[]; };

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= direction_count) return;
  labels[index] = nearest_region(directions[index].xyz);
}
