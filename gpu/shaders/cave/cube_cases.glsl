// What the walk of a cube (cave/tetrahedra.glsl) does for each of the 256 rock patterns of its
// corners, tabulated once by cube_cases.comp so that the count and emit passes look it up instead
// of repeating the walk for every vertex they number. The host mirrors the layout (std430) as
// cube_cases_bytes in gpu/cave/marching_tetrahedra.cpp.
//   case_triangles[rock]           triangles the walk emits
//   case_edges[rock]               the edges its triangles use
//   case_met_before[64·rock + s]   the edges the walk meets before it first meets edge slot s
//   owned_edges[first_on]          the edges a cube owns when it is the first cube on the axes
//                                  of first_on (first_axes bits)
// so the rank of an own edge among the owner's first meetings is
// |case_met_before[rock, edge] ∩ owned_edges[first_on]|.
// Guarded: included by the cube-case, count and emit passes.
// Inputs:  declares the cube-case tables (storage binding 0, std430).
// Outputs: the lookups of the count and emit passes.
// Twin:    reference/cave/marching_tetrahedra.hpp (the walk it tabulates).
#ifndef GT_CAVE_CUBE_CASES_GLSL
#define GT_CAVE_CUBE_CASES_GLSL

#include "cave/tetrahedra.glsl"

layout(std430, binding = 0) buffer CubeCases {
  uint case_triangles[256];
  uvec2 case_edges[256];
  uvec2 owned_edges[8];
  uvec2 case_met_before[256 * 64];
};

// How many vertices the cube owns: the own edges its triangles use.
uint owned_vertex_count(uint rock, ivec3 cube) { return edge_set_size(case_edges[rock] & owned_edges[first_axes(cube)]); }

// The vertex number of an own edge relative to the cube's first.
uint owned_rank(uint rock, ivec3 cube, ivec2 edge) {
  return edge_set_size(case_met_before[64u * rock + edge_slot(edge)] & owned_edges[first_axes(cube)]);
}

#endif
