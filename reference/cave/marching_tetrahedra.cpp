// Marching tetrahedra (seed 004 digest §2.6): six Kuhn tetrahedra per cube, the digest's oriented
// case table; the order of the output is specified in marching_tetrahedra.hpp.
//
// Memory traffic per voxel (meshing only, as the performance table times it; its floor column):
// 16 B read (the density's finite check and the cube walk, 8 B each), plus 12 B per triangle
// and 32 B per vertex written, and the edge map's nodes (not counted).
#include "reference/cave/marching_tetrahedra.hpp"

#include <utility>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

using CaseTable = std::array<TetCase, 16>;

// The table the walk reads: tet_case_table, or under one of the both-twins mutants the
// table with its bug (the GPU twin makes the same change in gpu/shaders/cave/tetrahedra.glsl).
CaseTable walked_case_table() {
  CaseTable table = tet_case_table;
  if (mutant_active("cave.marching_tetrahedra.quad_half")) table[5].triangle_count = 1;
  if (mutant_active("cave.marching_tetrahedra.complement_unreversed")) table[9] = table[6];
  // Code 1's fan runs one step too far: a second triangle after its first, the first again
  // (triangle_doubled) or its last corner repeated (fan_one_too_many). Either uses no new edge.
  const std::array<int, 3> single = table[1].triangles[0];
  if (mutant_active("cave.marching_tetrahedra.triangle_doubled")) table[1] = {2, {single, single}};
  if (mutant_active("cave.marching_tetrahedra.fan_one_too_many")) {
    table[1] = {2, {single, std::array<int, 3>{single[0], single[2], single[2]}}};
  }
  if (mutant_active("cave.marching_tetrahedra.winding_reversed")) {
    for (TetCase& tet_case : table) {
      for (auto& triangle : tet_case.triangles) std::swap(triangle[1], triangle[2]);
    }
  }
  return table;
}

// Bit v of the result is bit kuhn_tetrahedra[tet][v] of the cube's rock corners.
unsigned tet_code(unsigned cube_rock_corners, int tet) {
  unsigned code = 0;
  for (int vertex = 0; vertex < 4; ++vertex) code |= ((cube_rock_corners >> kuhn_tetrahedra[tet][vertex]) & 1u) << vertex;
  return code;
}

// The cube edge under tet edge `edge`, lower corner (the bit subset) first.
CornerPair cube_edge(int tet, int edge) {
  const int first = kuhn_tetrahedra[tet][tet_edges[edge][0]];
  const int second = kuhn_tetrahedra[tet][tet_edges[edge][1]];
  return first < second ? CornerPair{first, second} : CornerPair{second, first};
}

template <class Real>
void add_tet_triangles(CaveMeshBuilder<Real>& builder, const CaseTable& table, const LatticePoint& cube,
                       unsigned rock_corners, int tet) {
  const TetCase& tet_case = table[tet_code(rock_corners, tet)];
  for (int triangle = 0; triangle < tet_case.triangle_count; ++triangle) {
    const auto& edges = tet_case.triangles[triangle];
    builder.add_triangle(cube, {cube_edge(tet, edges[0]), cube_edge(tet, edges[1]), cube_edge(tet, edges[2])});
  }
}

}  // namespace

template <class Real>
TriangleMesh<Real> marching_tetrahedra(const Volume<Real>& density, Real threshold, bool solid,
                                       const std::array<std::int64_t, 3>& lattice_origin, EdgePlacement placement) {
  CaveMeshBuilder<Real> builder("marching tetrahedra", density, threshold, solid, lattice_origin, placement);
  const CaseTable table = walked_case_table();
  for_each_cube(builder, [&builder, &table](const LatticePoint& cube) {
    const unsigned rock_corners = builder.rock_corners(cube);
    if (rock_corners == 0 || rock_corners == 0xFFu) return;
    for (int tet = 0; tet < 6; ++tet) add_tet_triangles(builder, table, cube, rock_corners, tet);
  });
  return builder.take_mesh();
}

template TriangleMesh<float> marching_tetrahedra(const Volume<float>&, float, bool, const std::array<std::int64_t, 3>&,
                                                 EdgePlacement);
template TriangleMesh<double> marching_tetrahedra(const Volume<double>&, double, bool,
                                                  const std::array<std::int64_t, 3>&, EdgePlacement);

}  // namespace gt::reference
