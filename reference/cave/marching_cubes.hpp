// The seed's marching cubes (seed 004, digest §2.5), kept as the variant that fails, CPU reference.
//
// 256 cases built at start-up from 14 base configurations by rotating and mirroring the cube,
// vertices at edge midpoints, no disambiguation. Two cubes that meet on an ambiguous face (two
// diagonal rock corners) may cut it differently, leaving a hole; the mesh checks must catch it (an
// expected failure in datasets/expectations.txt).
// marching_cubes<Real>(density, threshold, solid, lattice_origin[, placement]) -> TriangleMesh<Real>
//   The same conventions as marching_tetrahedra.hpp (cube walk, pad, rock test, edge keys with axis
//   directions 1, 2, 4, welding in first-use order; lattice_cubes.hpp): cubes x fastest, then y,
//   then z; in each cube the triangles of marching_cubes_table()[code] in table order, code = Σ 2^c
//   over the rock corners c. Placement midpoint (the seed's, default) or linear.
// marching_cubes_table() -> the 256 CubeCases, built once:
//   - Base configurations 1..14 (the thesis's 14, Fig. 2.6; its numbering and drawings are not in
//     the text, so these are numbered by shape: corner, edge, face diagonal, body diagonal, three on
//     a face, edge + far corner, three scattered, face, corner + 3 neighbours, two opposite edges,
//     skew chain, three on a face + far corner, four scattered, mirrored skew chain), as
//     Lorensen & Cline: every rock corner group gets its own polygon, so rock corners that meet
//     only diagonally on a face are kept apart.
//   - Symmetries: the 48 cube symmetries generated breadth first from the thesis's operations
//     rotateByAxe(x, y, z) (90°: the two other coordinates (u, v) -> (1 - v, u), in cyclic order)
//     and flipByAxe(x, y, z) (coordinate -> 1 - coordinate), in that generator order.
//   - Case c takes the first match in this order: not complemented before complemented (rock and
//     air swapped), symmetries in breadth-first order, bases 1..14.
//   - Orientation: each base polygon is wound so that its Newell normal points from rock into air
//     (positive dot product with the sum of air-minus-rock corner vectors over its edges), then split
//     as a fan from its first vertex. A mirror or a complement reverses the winding ((a, b, c) ->
//     (a, c, b)), so every case is wound from rock into air; nothing in the table forbids it. The
//     holes come from the ambiguity alone: up to 4 rock corners the rock groups are kept apart, from
//     5 on (complemented bases) the air groups are, so a face shared by such cubes is cut twice.
//
// Inputs:  as marching_tetrahedra.hpp: density, threshold, solid, lattice_origin, placement.
// Outputs: the welded mesh with edge_keys; the case table.
// Units:   world units (global lattice coordinates).
// Throws:  InputError for non-finite samples or a block outside the edge-key range (lattice_cubes.hpp).
// Twin:    none: the seed's failing variant is kept on the CPU only; the GPU meshes with marching
//          tetrahedra (gpu/cave/marching_tetrahedra.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"
#include "core/volume.hpp"
#include "reference/cave/lattice_cubes.hpp"

namespace gt::reference {

struct CubeCase {
  int base = 0;               // 1..14; 0 for the empty cases 0 and 255
  bool complemented = false;  // built from the base with rock and air swapped
  bool mirrored = false;      // the symmetry includes an odd number of flips
  std::vector<std::array<CornerPair, 3>> triangles;
};

const std::array<CubeCase, 256>& marching_cubes_table();

template <class Real>
TriangleMesh<Real> marching_cubes(const Volume<Real>& density, Real threshold, bool solid,
                                  const std::array<std::int64_t, 3>& lattice_origin,
                                  EdgePlacement placement = EdgePlacement::midpoint);

}  // namespace gt::reference
