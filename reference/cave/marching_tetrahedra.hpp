// Marching tetrahedra on the cave's lattice (seed 004, digest §2.6), CPU reference.
//
// Kuhn decomposition and the oriented case table of the digest's "Re-implementation table".
// marching_tetrahedra<Real>(density, threshold, solid, lattice_origin[, placement]) -> TriangleMesh<Real>
// kuhn_tetrahedra, tet_edges, tet_case_table: the Kuhn decomposition and the digest's oriented case
//   table for a positively oriented tet (bit v set iff vertex v is rock): codes 1, 2, 4, 8 one
//   triangle, 3, 5, 6 a quad split along its first vertex; code 15 - w is the polygon of w reversed,
//   (p0, p1, ..., pk) -> (p0, pk, ..., p1), split the same way.
//
// Output specification (the GPU twin reproduces it exactly; cube walk, pad, rock test, vertex
// position and welding as in lattice_cubes.hpp):
//   1. Cubes in order: x fastest, then y, then z, over lower corners first..first + count - 1.
//   2. In each cube, tetrahedra 0..5, each a list of four cube corners (c = dx + 2·dy + 4·dz):
//        T0 {0,1,3,7}  T1 {0,5,1,7}  T2 {0,3,2,7}  T3 {0,2,6,7}  T4 {0,4,5,7}  T5 {0,6,4,7}
//      These are the Kuhn tetrahedra of the digest with v1 and v2 swapped in the mirrored T1, T2
//      and T5 (its "winding flip"), so that all six are positively oriented and share one table.
//   3. code = Σ_v 2^v over the tet's vertices v (0..3, in the order above) that are rock.
//   4. The triangles of tet_case_table[code] in table order; each triangle's three corners in table
//      order. Table entries are tet edges: 0 = (v0,v1), 1 = (v0,v2), 2 = (v0,v3), 3 = (v1,v2),
//      4 = (v1,v3), 5 = (v2,v3). A tet edge joins two cube corners of which one's bits are a
//      subset of the other's; the subset corner is the lower endpoint a, d = upper - lower.
//   5. Vertex index: order of first use (lattice_cubes.hpp); edge_keys[i] = key of vertex i's edge.
//   6. Vertex position, each operation rounded once in Real: t = (threshold - v_a) / (v_b - v_a)
//      on the canonically ordered edge, clamped to [δ, 1 - δ] (core/params/cave.hpp edge_margin;
//      0.5 at the pad or with midpoint placement), then
//      position_c = Real(a_c) + t·Real(d_c) (exact for d_c = 0 and the product exact for d_c = 1,
//      so a fused multiply-add changes nothing).
//
// Inputs:  density (Volume<Real>); threshold; lattice_origin: global lattice coordinates of density
//          sample (0, 0, 0); solid: pad with air (closed mesh), otherwise an open chunk whose boundary
//          lies on the block's faces; placement: linear (the seed's "shifting along the edge",
//          default) or midpoint (the seed's first version, Fig. 3.5).
// Outputs: TriangleMesh<Real>: indexed, welded by lattice edge key (edge_keys filled), triangles wound
//          counter-clockwise seen from the air, i.e. their normals point from rock into air (+∇f);
//          positions are global lattice coordinates.
// Units:   world units of the cave (global lattice coordinates).
// Throws:  InputError for non-finite samples or a block outside the edge-key range.
// Twin:    gpu/cave/marching_tetrahedra.hpp (MarchingTetrahedra) with gpu/shaders/cave/*.comp and *.glsl.
// Decisions: counts (ties): the digest's 3828 triangles on 12³ cells and 60,292 on the 30³ big cube
//   (§2.6, §2.7) count samples exactly at the threshold as rock and divide by the scale. The seed's
//   lattice has many samples that are zero or zero up to rounding (93 exact zeros in the big cube), so
//   the tie rule matters: with rock iff f < threshold (volume.hpp) and the reciprocal (density.hpp)
//   the counts are 3790 and 60,290 (tests/marching_tetrahedra_test.cpp reproduces the digest's numbers
//   with its conventions).
#pragma once

#include <array>
#include <cstdint>

#include "core/mesh.hpp"
#include "core/volume.hpp"
#include "reference/cave/lattice_cubes.hpp"

namespace gt::reference {

inline constexpr std::array<std::array<int, 4>, 6> kuhn_tetrahedra{
    {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}}};

inline constexpr std::array<std::array<int, 2>, 6> tet_edges{{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};

struct TetCase {
  int triangle_count;
  std::array<std::array<int, 3>, 2> triangles;  // tet edge indices
};

// The digest's table for a positively oriented tet (bit v set iff vertex v is rock): codes 1, 2, 4,
// 8 one triangle, 3, 5, 6 a quad split along its first vertex; code 15 - w is the polygon of w
// reversed, (p0, p1, ..., pk) -> (p0, pk, ..., p1), split the same way.
inline constexpr std::array<TetCase, 16> tet_case_table{{
    {0, {}},                                  // 0: all air
    {1, {{{0, 1, 2}}}},                       // 1
    {1, {{{0, 4, 3}}}},                       // 2
    {2, {{{1, 2, 4}, {1, 4, 3}}}},            // 3: quad (e02, e03, e13, e12)
    {1, {{{1, 3, 5}}}},                       // 4
    {2, {{{0, 3, 5}, {0, 5, 2}}}},            // 5: quad (e01, e12, e23, e03)
    {2, {{{0, 4, 5}, {0, 5, 1}}}},            // 6: quad (e01, e13, e23, e02)
    {1, {{{2, 4, 5}}}},                       // 7 = 15 - 8
    {1, {{{2, 5, 4}}}},                       // 8
    {2, {{{0, 1, 5}, {0, 5, 4}}}},            // 9 = 15 - 6
    {2, {{{0, 2, 5}, {0, 5, 3}}}},            // 10 = 15 - 5
    {1, {{{1, 5, 3}}}},                       // 11 = 15 - 4
    {2, {{{1, 3, 4}, {1, 4, 2}}}},            // 12 = 15 - 3
    {1, {{{0, 3, 4}}}},                       // 13 = 15 - 2
    {1, {{{0, 2, 1}}}},                       // 14 = 15 - 1
    {0, {}},                                  // 15: all rock
}};

template <class Real>
TriangleMesh<Real> marching_tetrahedra(const Volume<Real>& density, Real threshold, bool solid,
                                       const std::array<std::int64_t, 3>& lattice_origin,
                                       EdgePlacement placement = EdgePlacement::linear);

}  // namespace gt::reference
