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
// bounding_box(mesh): the smallest axis-aligned box holding every position (low = +inf, high =
//   -inf on each axis for a mesh without positions).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace gt {

template <class Real>
struct TriangleMesh {
  std::vector<std::array<Real, 3>> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint64_t> edge_keys;
};

using Mesh = TriangleMesh<double>;

template <class Real>
struct Box3 {
  std::array<Real, 3> low, high;
};

template <class Real>
Box3<Real> bounding_box(const TriangleMesh<Real>& mesh) {
  Box3<Real> box;
  box.low.fill(std::numeric_limits<Real>::infinity());
  box.high.fill(-std::numeric_limits<Real>::infinity());
  for (const auto& position : mesh.positions) {
    for (int axis = 0; axis < 3; ++axis) {
      box.low[axis] = std::min(box.low[axis], position[axis]);
      box.high[axis] = std::max(box.high[axis], position[axis]);
    }
  }
  return box;
}

}  // namespace gt
