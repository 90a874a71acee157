#version 450
// Pass 0 of the GPU marching tetrahedra, once per mesher: fills the cube-case tables of
// cave/cube_cases.glsl by walking each rock pattern (one invocation per pattern) and, in the
// first eight invocations, the own-edge sets of the ownership rule (cave/tetrahedra.glsl).
// Inputs:  none but the invocation index (the rock pattern).
// Outputs: the cube-case tables (storage binding 0, cave/cube_cases.glsl).
// Twin:    reference/cave/marching_tetrahedra.hpp (the walk of a cube, spec 2-4).
layout(local_size_x = 256) in;

#include "cave/cube_cases.glsl"

// Every nested corner pair (a Kuhn edge) the rule gives a cube first on the axes of first_on.
uvec2 owned_edge_set(uint first_on) {
  uvec2 owned = uvec2(0u);
  for (int upper = 1; upper < 8; ++upper) {
    for (int lower = 0; lower < upper; ++lower) {
      ivec2 edge = ivec2(lower, upper);
      if ((lower & upper) == lower && owns_edge(first_on, edge)) owned = edge_set_with(owned, edge);
    }
  }
  return owned;
}

void main() {
  uint rock = gl_LocalInvocationID.x;
  for (uint slot = 0u; slot < 64u; ++slot) case_met_before[64u * rock + slot] = uvec2(0u);
  uvec2 met = uvec2(0u);
  uint triangles = 0u;
  for (int tet = 0; tet < 6; ++tet) {
    uint code = tet_code(rock, tet);
    for (int triangle = 0; triangle < tet_triangle_count(code); ++triangle) {
      ++triangles;
      for (int corner = 0; corner < 3; ++corner) {
        ivec2 edge = corner_edge(tet, code, triangle, corner);
        if (edge_set_has(met, edge)) continue;
        case_met_before[64u * rock + edge_slot(edge)] = met;
        met = edge_set_with(met, edge);
      }
    }
  }
  case_triangles[rock] = triangles;
  case_edges[rock] = met;
  if (rock < 8u) owned_edges[rock] = owned_edge_set(rock);
}
