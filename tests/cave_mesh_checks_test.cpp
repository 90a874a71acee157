// The keyed-mesh comparisons behind the cave cases (compare/checks/cave_mesh.hpp) on meshes whose
// answers are known: a single rock sample (a closed octahedron-like polyhedron of 24 triangles),
// open chunks of the seed's noise, and copies of them broken on purpose, so that every check is
// seen to fail when it should.
#include <algorithm>
#include <cmath>
#include <array>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/keyed_hausdorff.hpp"
#include "compare/checks/mesh.hpp"
#include "core/params/cave.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_tetrahedra.hpp"

namespace gt {
namespace {

Mesh single_rock_sample() {
  const Volume<double> volume(1, 1, 1, -1.0);
  return reference::marching_tetrahedra(volume, 0.0, true, {5, 6, 7});
}

CaveParams open_chunk(std::array<int, 3> origin, std::array<int, 3> size) {
  CaveParams params;
  params.origin = origin;
  params.size = size;
  params.solid = false;
  return params;
}

Mesh seed_chunk(const CaveParams& params) {
  return reference::marching_tetrahedra(reference::cave_density<double>(params), params.threshold, false,
                                        {params.origin[0], params.origin[1], params.origin[2]});
}

TEST(CaveMeshChecks, KeyTrianglesKeepOrientationAndIgnoreNumbering) {
  const Mesh mesh = single_rock_sample();
  Mesh renumbered = mesh;
  std::reverse(renumbered.positions.begin(), renumbered.positions.end());
  std::reverse(renumbered.edge_keys.begin(), renumbered.edge_keys.end());
  const auto last = static_cast<std::uint32_t>(mesh.positions.size() - 1);
  for (auto& triangle : renumbered.triangles) {
    for (auto& vertex : triangle) vertex = last - vertex;
    std::rotate(triangle.begin(), triangle.begin() + 1, triangle.end());  // same orientation, other start
  }
  EXPECT_EQ(triangle_difference(key_triangles(mesh), key_triangles(renumbered)), 0u);
  Mesh flipped = mesh;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_EQ(triangle_difference(key_triangles(mesh), key_triangles(flipped)), 2u) << "one triangle in each mesh only";
}

// A broken mesh (a GPU bug) may name a vertex it lacks: the comparisons count it, never read past
// the mesh's vertices.
TEST(CaveMeshChecks, TrianglesNamingMissingVerticesDifferAndStayOffTheBox) {
  const Mesh mesh = single_rock_sample();
  Mesh broken = mesh;
  const auto missing = static_cast<std::uint32_t>(mesh.positions.size() + 7);
  broken.triangles[0][1] = missing;
  const auto keyed = key_triangles(broken);
  EXPECT_TRUE(std::any_of(keyed.begin(), keyed.end(), [](const KeyTriangle& triangle) {
    return std::find(triangle.begin(), triangle.end(), missing_vertex_key) != triangle.end();
  }));
  EXPECT_EQ(triangle_difference(key_triangles(mesh), keyed), 2u);
  EXPECT_GT(border_edges_off_box(broken, LatticeBox{{-100, -100, -100}, {100, 100, 100}}), 0u);
  EXPECT_TRUE(std::isfinite(approximate_one_sided_hausdorff_distance(broken, mesh, 0.1)));
  EXPECT_TRUE(std::isfinite(approximate_one_sided_hausdorff_distance(mesh, broken, 0.1)));
  EXPECT_TRUE(std::isfinite(keyed_hausdorff(broken, mesh).distance));
}

TEST(CaveMeshChecks, VerticesAreComparedByKeyAgainstTheirBound) {
  const Mesh mesh = single_rock_sample();
  Mesh moved = mesh;
  moved.positions[4][1] += 0.25;
  moved.edge_keys.push_back(lattice_edge_key({0, 0, 0}, 1));  // a vertex only the second mesh has
  moved.positions.push_back({0.5, 0.0, 0.0});
  const VertexComparison comparison = compare_vertices(mesh, moved, [](std::uint64_t) { return 0.5; });
  EXPECT_EQ(comparison.matched, mesh.positions.size());
  EXPECT_EQ(comparison.only_in_a, 0u);
  EXPECT_EQ(comparison.only_in_b, 1u);
  EXPECT_EQ(comparison.bit_differences, 1u);
  EXPECT_DOUBLE_EQ(comparison.max_distance, 0.25);
  EXPECT_DOUBLE_EQ(comparison.max_bound_ratio, 0.5);
}

// An open chunk's border lies on its box; cutting one triangle out of its inside opens a hole
// whose three edges are off the box.
TEST(CaveMeshChecks, BorderEdgesOffTheBoxFindAHole) {
  const CaveParams params = open_chunk({0, 0, 0}, {12, 12, 12});
  Mesh mesh = seed_chunk(params);
  const LatticeBox box = lattice_box(params);
  ASSERT_FALSE(border_edges(mesh).empty());
  EXPECT_EQ(border_edges_off_box(mesh, box), 0u);
  const auto interior = std::find_if(mesh.triangles.begin(), mesh.triangles.end(), [&](const auto& triangle) {
    return std::none_of(triangle.begin(), triangle.end(), [&](std::uint32_t vertex) {
      for (int axis = 0; axis < 3; ++axis) {
        if (key_on_plane(mesh.edge_keys[vertex], axis, box.low[axis]) ||
            key_on_plane(mesh.edge_keys[vertex], axis, box.high[axis])) {
          return true;
        }
      }
      return false;
    });
  });
  ASSERT_NE(interior, mesh.triangles.end());
  mesh.triangles.erase(interior);
  EXPECT_EQ(border_edges_off_box(mesh, box), 3u);
}

// Two neighbouring chunks name their shared face's vertices by the same keys: their border edges
// on the shared plane are each other's reverses.
TEST(CaveMeshChecks, NeighbouringChunksMeetOnTheirPlane) {
  const Mesh left = seed_chunk(open_chunk({0, 0, 0}, {10, 12, 12}));
  const Mesh right = seed_chunk(open_chunk({10, 0, 0}, {1, 12, 12}));
  std::vector<std::array<std::uint64_t, 2>> left_edges, right_edges;
  for (const auto& edge : border_edges(left)) {
    if (key_on_plane(left.edge_keys[edge[0]], 0, 10) && key_on_plane(left.edge_keys[edge[1]], 0, 10)) {
      left_edges.push_back({left.edge_keys[edge[1]], left.edge_keys[edge[0]]});  // reversed
    }
  }
  for (const auto& edge : border_edges(right)) {
    if (key_on_plane(right.edge_keys[edge[0]], 0, 10) && key_on_plane(right.edge_keys[edge[1]], 0, 10)) {
      right_edges.push_back({right.edge_keys[edge[0]], right.edge_keys[edge[1]]});
    }
  }
  ASSERT_FALSE(left_edges.empty());
  std::sort(left_edges.begin(), left_edges.end());
  std::sort(right_edges.begin(), right_edges.end());
  EXPECT_EQ(left_edges, right_edges);
  EXPECT_EQ(compare_vertices(left, right).bit_differences, 0u);
  EXPECT_GT(compare_vertices(left, right).matched, 0u);
}

// One rock sample padded with air: 1 rock sample, the 8 cubes around it each with one rock corner
// (bound 8 · 7/8 = 7), and the polyhedron around it (vertices at the midpoints of the 14 lattice
// edges from the sample) enclosing a positive volume within that bound of 1.
TEST(CaveMeshChecks, VolumeOfOneRockSampleIsWithinTheCutCubeBound) {
  const Volume<double> volume(1, 1, 1, -1.0);
  const FieldVolume field = volume_bound_from_field(volume, 0.0);
  EXPECT_EQ(field.rock_samples, 1.0);
  EXPECT_EQ(field.cut_cubes, 8u);
  EXPECT_DOUBLE_EQ(field.bound, 7.0);
  const MeshReport report = check_mesh(single_rock_sample());
  ASSERT_TRUE(report.cgal.volume.has_value());
  EXPECT_GT(*report.cgal.volume, 0.0);
  EXPECT_LE(std::abs(*report.cgal.volume - field.rock_samples), field.bound);
}

// One rock sample in the air pad is a corner of the 24 Kuhn tetrahedra around it (6 in the cubes
// where it is corner 0 or 7, 2 in each of the other six), each cut at its edges' midpoints: 24 ×
// (1/6)/8 = 1/2 lattice units³, which the mesh encloses. On a 2x2x1 block of two rock and two air
// samples the quads mix interpolated crossings with midpoints at the pad (not planar, so the spec's
// diagonal matters), and the mesh meets the spec there too, linear or midpoint.
TEST(CaveMeshChecks, OneRockSampleEnclosesHalfALatticeCell) {
  const Volume<double> volume(1, 1, 1, -1.0);
  const std::array<std::int64_t, 3> origin{0, 0, 0};
  const PiecewiseLinearVolume field = piecewise_linear_volume(volume, 0.0, origin, true);
  EXPECT_EQ(field.cut_tetrahedra, 24u);
  EXPECT_NEAR(field.volume, 0.5, 1e-15);
  EXPECT_NEAR(enclosed_volume(reference::marching_tetrahedra(volume, 0.0, true, origin), origin), 0.5, 1e-15);
}

TEST(CaveMeshChecks, TheMeshEnclosesThePiecewiseLinearRockOfItsField) {
  Volume<double> volume(2, 2, 1);
  volume.values = {-1.0, -0.5, 2.0, 3.0};  // (0,0) and (1,0) rock, (0,1) and (1,1) air
  const std::array<std::int64_t, 3> origin{10, 20, 30};
  const Mesh mesh = reference::marching_tetrahedra(volume, 0.0, true, origin);
  const PiecewiseLinearVolume field = piecewise_linear_volume(volume, 0.0, origin, true);
  EXPECT_NEAR(enclosed_volume(mesh, origin), field.volume, 1e-13);
  // Midpoints everywhere give another volume, which the midpoint mesh encloses.
  const PiecewiseLinearVolume midpoints = piecewise_linear_volume(volume, 0.0, origin, false);
  EXPECT_GT(std::abs(midpoints.volume - field.volume), 1e-3);
  const Mesh midpoint_mesh = reference::marching_tetrahedra(volume, 0.0, true, origin, reference::EdgePlacement::midpoint);
  EXPECT_NEAR(enclosed_volume(midpoint_mesh, origin), midpoints.volume, 1e-13);
}

// Two samples -1 and 3 padded with air: the x edge between them crosses 0 at t = 1/4, every other
// crossing edge runs into the pad (midpoints). Moving the inner vertex to 3/4 (measured from the
// wrong end) or asking about another threshold is caught; the bound holds the clamp margin.
TEST(CaveMeshChecks, VerticesSitOnTheFieldsCrossings) {
  Volume<double> volume(2, 1, 1);
  volume.values = {-1.0, 3.0};
  const std::array<std::int64_t, 3> origin{10, 20, 30};
  const Mesh mesh = reference::marching_tetrahedra(volume, 0.0, true, origin);
  const VertexCrossings clean = vertex_crossings(mesh, volume, 0.0, origin, true);
  EXPECT_EQ(clean.vertices, mesh.positions.size());
  EXPECT_EQ(clean.not_crossing, 0u);
  EXPECT_EQ(clean.off_crossing, 0u);
  EXPECT_LE(clean.max_bound_ratio, 1.0);
  const std::uint64_t inner_key = lattice_edge_key({10, 20, 30}, 1);
  const auto inner = std::find(mesh.edge_keys.begin(), mesh.edge_keys.end(), inner_key) - mesh.edge_keys.begin();
  ASSERT_LT(std::size_t(inner), mesh.edge_keys.size());
  EXPECT_DOUBLE_EQ(mesh.positions[inner][0], 10.25);

  Mesh wrong_end = mesh;
  wrong_end.positions[inner][0] = 10.75;
  const VertexCrossings moved = vertex_crossings(wrong_end, volume, 0.0, origin, true);
  EXPECT_EQ(moved.off_crossing, 1u);
  EXPECT_DOUBLE_EQ(moved.max_distance, 0.5);
  EXPECT_EQ(vertex_crossings(mesh, volume, 0.0, origin, false).off_crossing, 1u) << "midpoint placement expects 10.5";
  EXPECT_EQ(vertex_crossings(mesh, volume, -2.0, origin, true).not_crossing, mesh.positions.size())
      << "at threshold -2 nothing is rock";
}

// A candidate's density errs by e: on the edge between -1 and 3 the crossing may move by
// 2e/(4 - 2e) of the edge; a vertex there within that passes, beyond it fails; an edge with an
// endpoint within e of the threshold is excused rather than judged.
TEST(CaveMeshChecks, ACandidatesVerticesMayMoveByItsDensityError) {
  Volume<double> volume(2, 1, 1);
  volume.values = {-1.0, 3.0};
  const std::array<std::int64_t, 3> origin{10, 20, 30};
  Mesh mesh = reference::marching_tetrahedra(volume, 0.0, true, origin);
  const std::uint64_t inner_key = lattice_edge_key({10, 20, 30}, 1);
  const auto inner = std::find(mesh.edge_keys.begin(), mesh.edge_keys.end(), inner_key) - mesh.edge_keys.begin();
  ASSERT_LT(std::size_t(inner), mesh.edge_keys.size());
  const CrossingModel model{.unit_roundoff = 0x1p-24, .density_error = 0.02};
  const double shift = 2.0 * 0.02 / (4.0 - 2.0 * 0.02);  // 0.0101: within it, and twice it
  mesh.positions[inner][0] = 10.25 + 0.5 * shift;
  EXPECT_EQ(vertex_crossings(mesh, volume, 0.0, origin, true, model).off_crossing, 0u);
  mesh.positions[inner][0] = 10.25 + 2.0 * shift;
  EXPECT_EQ(vertex_crossings(mesh, volume, 0.0, origin, true, model).off_crossing, 1u);
  EXPECT_EQ(vertex_crossings(mesh, volume, 0.0, origin, true).off_crossing, 1u) << "no density error: no shift";
  volume.values = {-0.01, 3.0};  // within e of the threshold: this edge may cross or not
  const VertexCrossings excused = vertex_crossings(mesh, volume, 0.0, origin, true, model);
  EXPECT_EQ(excused.off_crossing, 0u);
  EXPECT_GE(excused.excused, 1u);
}

// A mesh file's vertices get the keys of the Kuhn edges they lie on: an axis edge, a face
// diagonal, the body diagonal, each up to float rounding; a vertex between edges or on a lattice
// point gets none.
TEST(CaveMeshChecks, FileVerticesAreKeyedByTheKuhnEdgeTheyLieOn) {
  Mesh mesh;
  mesh.positions = {{1.25, 2.0, 3.0},
                    {1.5, 2.5, 3.0},
                    {1.3, 2.3, 3.3},
                    {1.25 + 1e-6, 2.0 - 1e-6, 3.0},
                    {1.3, 2.6, 3.0},
                    {1.0, 2.0, 3.0},
                    {-0.75, 5.0, 2.0}};
  EXPECT_EQ(key_by_lattice_edges(mesh), 2u);
  EXPECT_EQ(mesh.edge_keys[0], lattice_edge_key({1, 2, 3}, 1));
  EXPECT_EQ(mesh.edge_keys[1], lattice_edge_key({1, 2, 3}, 3));
  EXPECT_EQ(mesh.edge_keys[2], lattice_edge_key({1, 2, 3}, 7));
  EXPECT_EQ(mesh.edge_keys[3], lattice_edge_key({1, 2, 3}, 1));
  EXPECT_EQ(mesh.edge_keys[4], missing_vertex_key) << "fractions 0.3 and 0.6: between edges";
  EXPECT_EQ(mesh.edge_keys[5], missing_vertex_key) << "a lattice point";
  EXPECT_EQ(mesh.edge_keys[6], lattice_edge_key({-1, 5, 2}, 1));
}

// Edges with a vertex in one mesh only count unless an endpoint may change side; the Hausdorff
// bound is 2√3 without such samples and grows by their distance to the truth's vertices.
TEST(CaveMeshChecks, CrossingEdgesAndTheHausdorffBoundExcuseOnlyChangingSamples) {
  Mesh truth, candidate;
  truth.positions = {{0.5, 0.0, 0.0}, {0.0, 0.5, 0.0}};
  truth.edge_keys = {lattice_edge_key({0, 0, 0}, 1), lattice_edge_key({0, 0, 0}, 2)};
  candidate.positions = {{0.5, 0.0, 0.0}, {5.0, 0.5, 0.0}};
  candidate.edge_keys = {lattice_edge_key({0, 0, 0}, 1), lattice_edge_key({5, 0, 0}, 2)};
  EXPECT_EQ(crossing_edges_unexplained(candidate, truth, {}), 2u);
  EXPECT_EQ(crossing_edges_unexplained(candidate, truth, {{5, 1, 0}}), 1u) << "the edge to (5, 1, 0) is excused";
  EXPECT_EQ(crossing_edges_unexplained(candidate, truth, {{5, 1, 0}, {0, 1, 0}}), 0u);
  EXPECT_DOUBLE_EQ(keyed_hausdorff_bound(truth, {}), 2.0 * std::sqrt(3.0));
  // (5, 1, 0) is sqrt(4.5² + 1) from the truth's nearest vertex: the bound grows by that.
  EXPECT_DOUBLE_EQ(keyed_hausdorff_bound(truth, {{5, 1, 0}}), 2.0 * std::sqrt(3.0) + std::sqrt(4.5 * 4.5 + 1.0));
  EXPECT_TRUE(std::isinf(keyed_hausdorff_bound(truth, {{50, 1, 0}}))) << "no truth vertex within 8 points";
}

TEST(CaveMeshChecks, VertexCrossingBoundIsTheMarginPlusRounding) {
  EXPECT_DOUBLE_EQ(vertex_crossing_bound(0.0, 0.0), 16.0 * 0x1p-53);
  EXPECT_DOUBLE_EQ(vertex_crossing_bound(0x1p-10, 1000.0), 0x1p-10 + 8.0 * 0x1p-53 * 1002.0);
}

TEST(CaveMeshChecks, TriangleCubeSpansTheCubeItCameFrom) {
  const KeyTriangle around_corner = {lattice_edge_key({4, 5, 6}, 1), lattice_edge_key({4, 5, 6}, 2),
                                     lattice_edge_key({4, 5, 6}, 4)};
  const LatticeBox cube = triangle_cube(around_corner);
  EXPECT_EQ(cube.low, (std::array<std::int64_t, 3>{4, 5, 6}));
  EXPECT_EQ(cube.high, (std::array<std::int64_t, 3>{5, 6, 7}));
  const KeyTriangle in_a_face = {lattice_edge_key({0, 0, 3}, 1), lattice_edge_key({0, 0, 3}, 3),
                                 lattice_edge_key({0, 0, 3}, 2)};  // all in the plane z = 3
  const LatticeBox both = triangle_cube(in_a_face);
  EXPECT_EQ(both.low[2], 2);
  EXPECT_EQ(both.high[2], 4);
  EXPECT_TRUE(both.contains({1, 1, 2}));
  EXPECT_FALSE(both.contains({2, 1, 3}));
}

TEST(CaveMeshChecks, GpuVertexBoundGrowsWithTheMagnitude) {
  EXPECT_DOUBLE_EQ(gpu_vertex_bound(0.0), std::sqrt(3.0) * 0x1p-24 * 5.0);
  EXPECT_GT(gpu_vertex_bound(5000.0), 1000.0 * gpu_vertex_bound(0.0));
}

}  // namespace
}  // namespace gt
