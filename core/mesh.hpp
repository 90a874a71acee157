// Triangle meshes shared by the cave twins, the mesh checks and mesh IO.
//
// TriangleMesh<Real>: indexed triangles.
//   positions   vertex positions (world units: lattice spacing 1 for cave meshes)
//   triangles   three vertex indices each; counter-clockwise seen from the side the normal points
//               to (right-hand rule), for cave meshes from rock into air (+∇f, digest 004 §2.6)
//   edge_keys   optional, one per vertex: the global lattice edge the vertex lies on (marching
//               tetrahedra), so that meshes of neighbouring chunks or of two backends can be
//               welded and compared exactly; empty when unknown
// Mesh = TriangleMesh<double>.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gt {

template <class Real>
struct TriangleMesh {
  std::vector<std::array<Real, 3>> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint64_t> edge_keys;
};

using Mesh = TriangleMesh<double>;

}  // namespace gt
