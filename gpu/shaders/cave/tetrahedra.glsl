// Marching tetrahedra inside one cube, and which cube a vertex belongs to: the shader side of the
// output specification in reference/cave/marching_tetrahedra.hpp (seed 004 digest §2.6).
//
// Walk of a cube (spec 2-4): tetrahedra 0..5 (the Kuhn split with v1, v2 swapped in the mirrored
// T1, T2, T5), code = Σ 2^v over the tet's rock vertices, the triangles of the case table in
// table order, each triangle's corners in table order; a corner is a tet edge, i.e. a cube edge
// (lower corner, upper corner). Callers repeat the walk with three nested loops:
//   for tet 0..5: code = tet_code(rock, tet); for triangle < tet_triangle_count(code):
//     for corner 0..2: edge = corner_edge(tet, code, triangle, corner)
//
// Welding without an edge table. A lattice edge (lower point p, direction d) lies in the cubes
// p - s for every s with no bit in common with d (4 cubes for an axis, 2 for a face diagonal, 1
// for the main diagonal), and in every one of them it is an edge of the Kuhn split (every nested
// corner pair is). When its endpoints differ in rock, every tetrahedron holding it has a triangle
// corner on it, so every cube of the walk that holds it uses it. Its first use in output order is
// therefore in the first of those cubes in cube order, its owner: per axis outside d, p - 1 when
// that is still a cube, else p. So a cube owns an edge iff on every axis outside d the edge lies
// on the cube's upper face or the cube is the first on that axis (an inner cube owns the seven
// edges into its corner 7). Cube indices grow with every coordinate, so the vertex number (order
// of first use, lattice_cubes.hpp) is: vertices owned by the cubes before the owner (an exclusive
// scan of per-cube counts) + the edge's rank among the owner's own edges in the order the owner's
// walk first meets them (cave/cube_cases.glsl). Nothing is stored per edge or per corner.
// Edge sets: 64-bit masks held as two words (uvec2), bit 8·lower + upper.
// Guarded: included by the cube-case, count and emit passes.
// Inputs:  the rock bits of a cube's corners; the lattice of cave/lattice.glsl.
// Outputs: tet_code, tet_triangle_count, corner_edge and the ownership rule.
// Twin:    reference/cave/marching_tetrahedra.hpp (the output specification, spec 2-5).
#ifndef GT_CAVE_TETRAHEDRA_GLSL
#define GT_CAVE_TETRAHEDRA_GLSL

#include "cave/lattice.glsl"

// Cube corners of tetrahedron t: [4t .. 4t + 3].
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_KUHN_VERTEX
// Mutant (GPU only): T0 written with corner 5 for 3, a second copy of T1's corners, so
// the cube is not tiled (every corner pair still nests: all buffers stay in range).
const int KUHN_TETRAHEDRA[24] = int[24](0, 1, 5, 7, 0, 5, 1, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 4, 5, 7, 0, 6, 4, 7);
#else
const int KUHN_TETRAHEDRA[24] = int[24](0, 1, 3, 7, 0, 5, 1, 7, 0, 3, 2, 7, 0, 2, 6, 7, 0, 4, 5, 7, 0, 6, 4, 7);
#endif

// Tet edge e joins tet vertices [2e] and [2e + 1].
const int TET_EDGES[12] = int[12](0, 1, 0, 2, 0, 3, 1, 2, 1, 3, 2, 3);

// Per code (bit v set iff tet vertex v is rock): how many triangles, and their tet edges
// [6·code + 3·triangle + corner] (unused entries 0); code 15 - w is w's polygon reversed.
const int TET_TRIANGLE_COUNT[16] = int[16](0, 1, 1, 2, 1, 2, 2, 1, 1, 2, 2, 1, 2, 1, 1, 0);
const int TET_TRIANGLE_EDGES[96] = int[96](
    0, 0, 0, 0, 0, 0,   // 0: all air
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_GPU_CASE_FLIPPED
    0, 2, 1, 0, 0, 0,   // 1, mutant (GPU only): wound the other way
#else
    0, 1, 2, 0, 0, 0,   // 1
#endif
    0, 4, 3, 0, 0, 0,   // 2
    1, 2, 4, 1, 4, 3,   // 3: quad (e02, e03, e13, e12)
    1, 3, 5, 0, 0, 0,   // 4
    0, 3, 5, 0, 5, 2,   // 5: quad (e01, e12, e23, e03)
    0, 4, 5, 0, 5, 1,   // 6: quad (e01, e13, e23, e02)
    2, 4, 5, 0, 0, 0,   // 7 = 15 - 8
    2, 5, 4, 0, 0, 0,   // 8
    0, 1, 5, 0, 5, 4,   // 9 = 15 - 6
    0, 2, 5, 0, 5, 3,   // 10 = 15 - 5
    1, 5, 3, 0, 0, 0,   // 11 = 15 - 4
    1, 3, 4, 1, 4, 2,   // 12 = 15 - 3
    0, 3, 4, 0, 0, 0,   // 13 = 15 - 2
    0, 2, 1, 0, 0, 0,   // 14 = 15 - 1
    0, 0, 0, 0, 0, 0);  // 15: all rock

// Mutants in both twins (the reference applies the same change to its table,
// reference/cave/marching_tetrahedra.cpp): the table as the walk reads it.
int walked_triangle_count(uint code) {
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_QUAD_HALF
  if (code == 5u) return 1;  // the quad of code 5 loses its second triangle: holes
#endif
#if defined(GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_TRIANGLE_DOUBLED) || defined(GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_FAN_ONE_TOO_MANY)
  if (code == 1u) return 2;  // code 1's fan runs one step too far (its second triangle below)
#endif
  return TET_TRIANGLE_COUNT[code];
}

int walked_tet_edge(uint code, int triangle, int corner) {
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_COMPLEMENT_UNREVERSED
  if (code == 9u) code = 6u;  // 9 = 15 - 6 copied from 6 without reversing its polygon
#endif
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_TRIANGLE_DOUBLED
  if (code == 1u) triangle = 0;  // the second triangle is the first again: a duplicate
#endif
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_FAN_ONE_TOO_MANY
  if (code == 1u && triangle == 1) {  // the second triangle (first, last, last) of the first: degenerate
    triangle = 0;
    corner = corner == 0 ? 0 : 2;
  }
#endif
#ifdef GT_MUTANT_CAVE_MARCHING_TETRAHEDRA_WINDING_REVERSED
  if (corner != 0) corner = 3 - corner;  // every triangle's corners 0, 2, 1: normals into the rock
#endif
  return TET_TRIANGLE_EDGES[6 * int(code) + 3 * triangle + corner];
}

uint tet_code(uint rock, int tet) {
  uint code = 0u;
  for (int vertex = 0; vertex < 4; ++vertex) code |= ((rock >> uint(KUHN_TETRAHEDRA[4 * tet + vertex])) & 1u) << uint(vertex);
  return code;
}

int tet_triangle_count(uint code) { return walked_triangle_count(code); }

// The cube edge under a triangle corner: (lower corner, upper corner).
ivec2 corner_edge(int tet, uint code, int triangle, int corner) {
  int tet_edge = walked_tet_edge(code, triangle, corner);
  int first = KUHN_TETRAHEDRA[4 * tet + TET_EDGES[2 * tet_edge]];
  int second = KUHN_TETRAHEDRA[4 * tet + TET_EDGES[2 * tet_edge + 1]];
  return first < second ? ivec2(first, second) : ivec2(second, first);
}

uint edge_slot(ivec2 edge) { return uint(8 * edge.x + edge.y); }

bool edge_set_has(uvec2 set, ivec2 edge) {
  uint bit = edge_slot(edge);
  return ((set[bit >> 5u] >> (bit & 31u)) & 1u) != 0u;
}

uvec2 edge_set_with(uvec2 set, ivec2 edge) {
  uint bit = edge_slot(edge);
  set[bit >> 5u] |= 1u << (bit & 31u);
  return set;
}

uint edge_set_size(uvec2 set) { return uint(bitCount(set.x) + bitCount(set.y)); }

// Bit a set iff the cube is the first cube on axis a.
uint first_axes(ivec3 cube) {
  bvec3 first = equal(cube, ivec3(first_cube));
  return (first.x ? 1u : 0u) | (first.y ? 2u : 0u) | (first.z ? 4u : 0u);
}

// The ownership rule for a cube that is first on `first_on` (first_axes bits).
bool owns_edge(uint first_on, ivec2 edge) {
  uint across = 7u & ~uint(edge.y - edge.x);
  return (across & ~uint(edge.x) & ~first_on) == 0u;
}

struct OwnedEdge {
  ivec3 cube;  // the first cube holding the edge
  ivec2 edge;  // the same lattice edge as a pair of that cube's corners
};

// Per axis outside the direction: one cube lower when that is still a cube.
OwnedEdge owner_of(ivec3 cube, ivec2 edge) {
  int direction = edge.y - edge.x;
  ivec3 lower = cube + corner_offset(edge.x);
  ivec3 owner = max(lower - (ivec3(1) - corner_offset(direction)), ivec3(first_cube));
  ivec3 offset = lower - owner;
  int owner_lower = offset.x + 2 * offset.y + 4 * offset.z;
  return OwnedEdge(owner, ivec2(owner_lower, owner_lower + direction));
}

#endif
