#version 450
// Pass 2 of the GPU marching tetrahedra: per cube (in output order, cave/cave_block.glsl), its
// rock corners (for the emit pass, which reads them for the cube and its neighbours), how many
// triangles it emits and how many vertices it owns (edges whose first use in the whole mesh is in
// this cube, cave/tetrahedra.glsl), both looked up in the cube-case tables (cave/cube_cases.glsl).
// Invocation cube_counts.w writes zero counts: the exclusive scans then leave the totals in that
// last element.
// Inputs:  CaveBlock (uniform binding 0), density (1) (cave/lattice.glsl), the cube-case tables (storage
//          binding 0, cave/cube_cases.glsl).
// Outputs: triangle_counts (2), vertex_counts (3), cube_rock (5).
// Twin:    reference/cave/marching_tetrahedra.hpp (the triangles and vertices each cube adds).
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"
#include "cave/cube_cases.glsl"

layout(std430, binding = 2) writeonly buffer TriangleCounts { uint triangle_counts[]; };
layout(std430, binding = 3) writeonly buffer VertexCounts { uint vertex_counts[]; };
layout(std430, binding = 5) writeonly buffer CubeRock { uint cube_rock[]; };

void main() {
  uint index = linear_invocation();
  uint cube_total = uint(cube_counts.w);
  if (index > cube_total) return;
  uvec2 counts = uvec2(0u);
  if (index < cube_total) {
    ivec3 cube = cube_of(index);
    uint rock = rock_corners(cube);
    counts = uvec2(case_triangles[rock], owned_vertex_count(rock, cube));
    cube_rock[index] = rock;
  }
  triangle_counts[index] = counts.x;
  vertex_counts[index] = counts.y;
}
