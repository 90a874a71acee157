// The keyed Hausdorff distance (compare/checks/keyed_hausdorff.hpp) against CGAL's sampling of the
// whole meshes. Both sample the differing triangles on the same grid of spacing h, and the
// distance to a surface is 1-Lipschitz, so each is within h of the true one-sided maxima: they may
// differ by h at most. Twins that moved by less than 0.1 are bounded exactly by their corners.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/keyed_hausdorff.hpp"
#include "compare/checks/mesh.hpp"
#include "core/params/cave.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_tetrahedra.hpp"

namespace gt {
namespace {

constexpr double grid_spacing = 0.1;  // keyed_hausdorff's finest spacing, kept on these small meshes

template <class Real>
TriangleMesh<Real> seed_block(int side) {
  CaveParams params;
  params.size = {side, side, side};
  return reference::marching_tetrahedra(reference::cave_density<Real>(params), Real(params.threshold), true,
                                        {params.origin[0], params.origin[1], params.origin[2]});
}

double whole_mesh_hausdorff(const Mesh& a, const Mesh& b) {
  return std::max(approximate_one_sided_hausdorff_distance(a, b, grid_spacing),
                  approximate_one_sided_hausdorff_distance(b, a, grid_spacing));
}

TEST(KeyedHausdorff, TwinsThatBarelyMovedAreBoundedByTheirCorners) {
  const Mesh mesh = seed_block<double>(8);
  Mesh moved = mesh;
  moved.positions[10][2] += 0.05;
  const KeyedHausdorff distance = keyed_hausdorff(mesh, moved);
  EXPECT_EQ(distance.sampled_triangles, 0u);
  EXPECT_DOUBLE_EQ(distance.distance, 0.05);
  EXPECT_EQ(keyed_hausdorff(mesh, mesh).distance, 0.0);
}

TEST(KeyedHausdorff, AVertexMovedFartherIsSampledLikeTheWholeMesh) {
  const Mesh mesh = seed_block<double>(8);
  Mesh moved = mesh;
  moved.positions[10][2] += 0.2;  // more than 0.1, within its cube's 0.25 of rounding
  const KeyedHausdorff distance = keyed_hausdorff(mesh, moved);
  EXPECT_GT(distance.sampled_triangles, 0u);
  EXPECT_FALSE(distance.whole_mesh_fallback);
  EXPECT_NEAR(distance.distance, whole_mesh_hausdorff(mesh, moved), grid_spacing);
  EXPECT_GT(distance.distance, 0.0);
  EXPECT_LE(distance.distance, 0.2 + 1e-12) << "no point of a triangle moves farther than its corners";
}

TEST(KeyedHausdorff, FloatAgainstDoubleMatchesTheWholeMeshSampling) {
  const Mesh truth = seed_block<double>(12);
  const Mesh single = to_double_mesh(seed_block<float>(12));
  const KeyedHausdorff distance = keyed_hausdorff(single, truth);
  EXPECT_FALSE(distance.whole_mesh_fallback);
  EXPECT_NEAR(distance.distance, whole_mesh_hausdorff(single, truth), grid_spacing);
}

TEST(KeyedHausdorff, AVertexOutsideItsCubeFallsBackToTheWholeMesh) {
  const Mesh mesh = seed_block<double>(8);
  Mesh moved = mesh;
  moved.positions[10][0] += 5.0;
  const KeyedHausdorff distance = keyed_hausdorff(mesh, moved);
  EXPECT_TRUE(distance.whole_mesh_fallback);
  EXPECT_NEAR(distance.distance, whole_mesh_hausdorff(mesh, moved), grid_spacing);
}

TEST(KeyedHausdorff, EmptyAgainstNonEmptyIsInfinite) {
  EXPECT_TRUE(std::isinf(keyed_hausdorff(Mesh{}, seed_block<double>(8)).distance));
  EXPECT_EQ(keyed_hausdorff(Mesh{}, Mesh{}).distance, 0.0);
}

}  // namespace
}  // namespace gt
