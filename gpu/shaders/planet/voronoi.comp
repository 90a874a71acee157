#version 450
// Spherical Voronoi of the region centroids by Algorithm 1's cell-grid search
// (planet/voronoi_search.glsl), per query direction. Host: gpu/planet/voronoi.cpp.
// Inputs:  VoronoiBlock (uniform binding 0), neighbours (0), positions (1) (voronoi_search.glsl);
//          directions (2).
// Outputs: labels (3): one region per direction.
// Twin:    reference/planet/voronoi.cpp (nearest_sites: an exact k-d tree search).
layout(local_size_x = 64) in;

#include "planet/voronoi_search.glsl"

layout(std430, binding = 2) readonly buffer Directions { vec4 directions[]; };
layout(std430, binding = 3) writeonly buffer Labels { int labels[]; };

void main() {
  int index = int(gl_GlobalInvocationID.x);
  if (index >= direction_count) return;
  labels[index] = nearest_region(directions[index].xyz);
}
