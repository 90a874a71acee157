// The cave references (reference/cave/: density, marching tetrahedra, marching cubes, normals;
// seed 004 digest §2.2–2.8) against the digest's checks and against what a cave mesh must be:
//   - the tet case table on affine fields (every code, every Kuhn tet), a plane, one rock corner
//     (with the exact output order the GPU twin must reproduce), one rock sample padded, a sphere;
//   - the digest's triangle counts (3828 on 12³ cells, 60,292 on the 30³ big cube) and why ours
//     differ (the tie rule at the seed lattice's exact zeros);
//   - solid blocks closed and consistently oriented (every directed edge once, its reverse once,
//     checked here on the raw index buffer), open blocks open only on their faces, neighbouring
//     blocks bit-identical on their shared face with matching boundary loops;
//   - float against double: the same topology where the classifications agree, positions within
//     an error model, disagreements only at near-zero samples;
//   - the seed's marching cubes: its table, and the hole on an ambiguous face;
//   - normals: central differences against the analytic gradient within a derived bound, the
//     winding against the gradient.
// Error models are written beside the tests that use them.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/mesh.hpp"
#include "core/errors.hpp"
#include "core/noise/permutation.hpp"
#include "core/params/cave.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_cubes.hpp"
#include "reference/cave/marching_tetrahedra.hpp"
#include "reference/cave/normals.hpp"
#include "reference/noise/simplex.hpp"

namespace {

namespace ref = gt::reference;

using Vec3 = std::array<double, 3>;
using DirectedEdge = std::pair<std::uint32_t, std::uint32_t>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

template <class Real>
Vec3 position(const gt::TriangleMesh<Real>& mesh, std::uint32_t vertex) {
  return {mesh.positions[vertex][0], mesh.positions[vertex][1], mesh.positions[vertex][2]};
}

// (b - a) × (c - a): the triangle's normal by its winding, twice its area long.
template <class Real>
Vec3 triangle_normal(const gt::TriangleMesh<Real>& mesh, const std::array<std::uint32_t, 3>& triangle) {
  const Vec3 a = position(mesh, triangle[0]);
  return cross(sub(position(mesh, triangle[1]), a), sub(position(mesh, triangle[2]), a));
}

template <class Real>
std::map<DirectedEdge, int> directed_edge_counts(const gt::TriangleMesh<Real>& mesh) {
  std::map<DirectedEdge, int> counts;
  for (const auto& triangle : mesh.triangles) {
    for (int corner = 0; corner < 3; ++corner) ++counts[{triangle[corner], triangle[(corner + 1) % 3]}];
  }
  return counts;
}

// Directed edges whose reverse is not in the mesh.
template <class Real>
std::vector<DirectedEdge> boundary_edges(const gt::TriangleMesh<Real>& mesh) {
  const auto counts = directed_edge_counts(mesh);
  std::vector<DirectedEdge> boundary;
  for (const auto& [edge, count] : counts) {
    if (!counts.contains({edge.second, edge.first})) boundary.push_back(edge);
  }
  return boundary;
}

// Closed and consistently oriented: every directed edge exactly once and its reverse exactly once.
template <class Real>
bool closed_and_oriented(const gt::TriangleMesh<Real>& mesh) {
  const auto counts = directed_edge_counts(mesh);
  return std::all_of(counts.begin(), counts.end(), [&counts](const auto& entry) {
    const auto reverse = counts.find({entry.first.second, entry.first.first});
    return entry.second == 1 && reverse != counts.end() && reverse->second == 1;
  });
}

template <class Real>
double signed_volume(const gt::TriangleMesh<Real>& mesh) {
  double volume = 0;
  for (const auto& triangle : mesh.triangles) {
    volume += dot(position(mesh, triangle[0]), cross(position(mesh, triangle[1]), position(mesh, triangle[2]))) / 6;
  }
  return volume;
}

template <class Real>
std::size_t edge_count(const gt::TriangleMesh<Real>& mesh) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (const auto& [edge, count] : directed_edge_counts(mesh)) edges.insert(std::minmax(edge.first, edge.second));
  return edges.size();
}

gt::CaveParams seed_block(std::array<int, 3> origin, int cells, bool solid) {
  gt::CaveParams params;
  params.origin = origin;
  params.size = {cells, cells, cells};
  params.solid = solid;
  return params;
}

std::array<std::int64_t, 3> lattice_origin(const gt::CaveParams& params) {
  return {params.origin[0], params.origin[1], params.origin[2]};
}

template <class Real>
gt::TriangleMesh<Real> cave_mesh(const gt::CaveParams& params) {
  return ref::marching_tetrahedra(ref::cave_density<Real>(params), static_cast<Real>(params.threshold), params.solid,
                                  lattice_origin(params));
}

// A volume sampling f at the integer points 0..n-1 per axis.
template <class Field>
gt::Volume<double> sampled(int n, Field&& field) {
  gt::Volume<double> volume(n, n, n);
  for (int z = 0; z < n; ++z) {
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) volume.at(x, y, z) = field(double(x), double(y), double(z));
    }
  }
  return volume;
}

TEST(LatticeEdgeKey, RoundTripsAtTheEndsOfItsRange) {
  for (std::int64_t coordinate : {gt::lattice_coordinate_min, std::int64_t{-1}, std::int64_t{0}, std::int64_t{12},
                                  gt::lattice_coordinate_max}) {
    for (int direction = 1; direction <= 7; ++direction) {
      const std::array<std::int64_t, 3> point{coordinate, -coordinate / 2, coordinate / 3};
      const gt::LatticeEdge edge = gt::lattice_edge_from_key(gt::lattice_edge_key(point, direction));
      EXPECT_EQ(edge.lower_point, point);
      EXPECT_EQ(edge.direction, direction);
    }
  }
  EXPECT_NE(gt::lattice_edge_key({0, 0, 0}, 1), gt::lattice_edge_key({0, 0, 0}, 2));
  EXPECT_TRUE(gt::lattice_range_fits({-500001, 0, 0}, {514, 1, 1}, true));
  EXPECT_FALSE(gt::lattice_range_fits({gt::lattice_coordinate_min, 0, 0}, {2, 2, 2}, true));
}

TEST(CaveParams, DefaultsResolveToTheSeedsValues) {
  const auto resolved = gt::resolve_params("cave", gt::cave_param_specs(), nlohmann::json::object());
  const gt::CaveParams params = gt::cave_params_from_json(resolved);
  EXPECT_EQ(params.scale, 10.0);
  EXPECT_EQ(params.threshold, 0.0);
  EXPECT_EQ(params.kernel_radius_squared, 0.6);
  EXPECT_EQ(params.seed, 0u);
  EXPECT_EQ(params.size, (std::array<int, 3>{30, 30, 30}));
  EXPECT_EQ(params.origin, (std::array<int, 3>{0, 0, 0}));
  EXPECT_TRUE(params.solid);
  EXPECT_THROW(gt::resolve_params("cave", gt::cave_param_specs(), {{"size_x", 0}}), gt::InputError);
}

// Every code of every Kuhn tet, on the affine field that is -1 at its rock vertices and +1 at its
// air vertices: each triangle's winding normal is along the field's gradient (rock -> air).
TEST(MarchingTetrahedra, CaseTableWindsEveryCodeFromRockIntoAir) {
  for (int tet = 0; tet < 6; ++tet) {
    std::array<Vec3, 4> vertex{};
    for (int v = 0; v < 4; ++v) {
      const auto offset = ref::corner_offset(ref::kuhn_tetrahedra[tet][v]);
      vertex[v] = {double(offset[0]), double(offset[1]), double(offset[2])};
    }
    const Vec3 e1 = sub(vertex[1], vertex[0]);
    const Vec3 e2 = sub(vertex[2], vertex[0]);
    const Vec3 e3 = sub(vertex[3], vertex[0]);
    ASSERT_GT(dot(e1, cross(e2, e3)), 0) << "tet " << tet << " is not positively oriented";
    for (int code = 1; code < 15; ++code) {
      std::array<double, 4> value{};
      for (int v = 0; v < 4; ++v) value[v] = (code >> v) & 1 ? -1.0 : 1.0;
      // Gradient of the affine interpolant: solve [e1 e2 e3]^T g = (value_i - value_0).
      const double det = dot(e1, cross(e2, e3));
      const std::array<double, 3> rhs{value[1] - value[0], value[2] - value[0], value[3] - value[0]};
      Vec3 gradient{};
      const std::array<Vec3, 3> adjugate_rows{cross(e2, e3), cross(e3, e1), cross(e1, e2)};
      for (int i = 0; i < 3; ++i) {
        for (int axis = 0; axis < 3; ++axis) gradient[axis] += rhs[i] * adjugate_rows[i][axis] / det;
      }
      const ref::TetCase& tet_case = ref::tet_case_table[code];
      ASSERT_GT(tet_case.triangle_count, 0);
      for (int t = 0; t < tet_case.triangle_count; ++t) {
        std::array<Vec3, 3> corner{};
        for (int c = 0; c < 3; ++c) {
          const auto& edge = ref::tet_edges[tet_case.triangles[t][c]];
          const double a = value[edge[0]];
          const double b = value[edge[1]];
          ASSERT_NE(a < 0, b < 0) << "code " << code << " uses an edge that does not cross";
          const double along = (0 - a) / (b - a);
          for (int axis = 0; axis < 3; ++axis) {
            corner[c][axis] = vertex[edge[0]][axis] + along * (vertex[edge[1]][axis] - vertex[edge[0]][axis]);
          }
        }
        const Vec3 normal = cross(sub(corner[1], corner[0]), sub(corner[2], corner[0]));
        const double cosine = dot(normal, gradient) / std::sqrt(dot(normal, normal) * dot(gradient, gradient));
        EXPECT_NEAR(cosine, 1.0, 1e-12) << "tet " << tet << " code " << code << " triangle " << t;
      }
    }
  }
}

TEST(MarchingTetrahedra, LinearFieldGivesItsPlaneWoundAlongTheGradient) {
  const Vec3 gradient{0.3, -0.7, 0.45};
  const auto volume = sampled(5, [&](double x, double y, double z) { return dot(gradient, {x, y, z}) - 0.37; });
  const auto mesh = ref::marching_tetrahedra(volume, 0.0, false, {0, 0, 0});
  ASSERT_FALSE(mesh.triangles.empty());
  for (const auto& triangle : mesh.triangles) {
    const Vec3 normal = triangle_normal(mesh, triangle);
    EXPECT_NEAR(dot(normal, gradient) / std::sqrt(dot(normal, normal) * dot(gradient, gradient)), 1.0, 1e-9);
  }
  for (const auto& p : mesh.positions) EXPECT_NEAR(dot(gradient, {p[0], p[1], p[2]}), 0.37, 1e-12);
}

// One rock corner in one cube: every tet has code 1 at corner 0, one triangle (e01, e02, e03)
// each, on the seven edges from corner 0 at t = 0.49 / (0.49 + f(other end)). The order is the
// specification's (marching_tetrahedra.hpp): tets 0..5, vertices numbered at first use, so
// T0 {0,1,3,7} gives (0, 1, 2) on directions 1, 3, 7; T1 {0,5,1,7} (3, 0, 2) with new direction 5;
// T2 {0,3,2,7} (1, 4, 2) with 2; T3 {0,2,6,7} (4, 5, 2) with 6; T4 {0,4,5,7} (6, 3, 2) with 4;
// T5 {0,6,4,7} (5, 6, 2).
TEST(MarchingTetrahedra, SingleCubeAroundOneRockCorner) {
  const auto volume = sampled(2, [](double x, double y, double z) { return x * x + y * y + z * z - 0.49; });
  const auto mesh = ref::marching_tetrahedra(volume, 0.0, false, {0, 0, 0});
  const std::vector<std::array<std::uint32_t, 3>> triangles{{0, 1, 2}, {3, 0, 2}, {1, 4, 2},
                                                             {4, 5, 2}, {6, 3, 2}, {5, 6, 2}};
  EXPECT_EQ(mesh.triangles, triangles);
  ASSERT_EQ(mesh.positions.size(), 7u);
  ASSERT_EQ(mesh.edge_keys.size(), 7u);
  const std::array<int, 7> directions{1, 3, 7, 5, 2, 6, 4};
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[vertex]);
    EXPECT_EQ(edge.lower_point, (std::array<std::int64_t, 3>{0, 0, 0}));
    EXPECT_EQ(edge.direction, directions[vertex]);
    const auto step = ref::corner_offset(edge.direction);
    const double far_value = step[0] + step[1] + step[2] - 0.49;
    const double t = 0.49 / (far_value + 0.49);
    for (int axis = 0; axis < 3; ++axis) EXPECT_DOUBLE_EQ(mesh.positions[vertex][axis], t * step[axis]);
  }
  for (const auto& triangle : mesh.triangles) {
    const Vec3 normal = triangle_normal(mesh, triangle);
    const Vec3 centroid = {(mesh.positions[triangle[0]][0] + mesh.positions[triangle[1]][0] + mesh.positions[triangle[2]][0]) / 3,
                           (mesh.positions[triangle[0]][1] + mesh.positions[triangle[1]][1] + mesh.positions[triangle[2]][1]) / 3,
                           (mesh.positions[triangle[0]][2] + mesh.positions[triangle[1]][2] + mesh.positions[triangle[2]][2]) / 3};
    EXPECT_GT(dot(normal, centroid), 0) << "a triangle faces the rock corner";
  }
  EXPECT_EQ(boundary_edges(mesh).size(), 6u);
  EXPECT_TRUE(closed_and_oriented(ref::marching_tetrahedra(volume, 0.0, true, {0, 0, 0})));
}

// One rock sample, padded: 8 cubes around it; the sample is corner 7 of the first cube (in all six
// tets) ... corner 0 of the last (in all six), and corners 1..6 lie in two tets each: 24 triangles
// on the 14 Kuhn edges at the sample, all at midpoints (every edge reaches the pad), closed.
TEST(MarchingTetrahedra, OneRockSamplePaddedIsAClosedPolyhedron) {
  const gt::Volume<double> volume(1, 1, 1, -1.0);
  const auto mesh = ref::marching_tetrahedra(volume, 0.0, true, {5, 6, 7});
  EXPECT_EQ(mesh.triangles.size(), 24u);
  EXPECT_EQ(mesh.positions.size(), 14u);
  EXPECT_TRUE(closed_and_oriented(mesh));
  EXPECT_GT(signed_volume(mesh), 0.0);
  const gt::LatticeEdge first = gt::lattice_edge_from_key(mesh.edge_keys[0]);
  EXPECT_EQ(first.lower_point, (std::array<std::int64_t, 3>{4, 5, 6}));  // cube (-1,-1,-1), T0 code 8: e03 first
  EXPECT_EQ(first.direction, 7);
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[vertex]);
    const auto step = ref::corner_offset(edge.direction);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(mesh.positions[vertex][axis], double(edge.lower_point[axis]) + 0.5 * step[axis]);
    }
  }
}

TEST(MarchingTetrahedra, SphereIsClosedWithGenusZeroAndItsVolume) {
  const double radius = 2.3;
  const auto volume = sampled(7, [&](double x, double y, double z) {
    return std::sqrt((x - 3) * (x - 3) + (y - 3.1) * (y - 3.1) + (z - 2.9) * (z - 2.9)) - radius;
  });
  const auto mesh = ref::marching_tetrahedra(volume, 0.0, false, {0, 0, 0});
  ASSERT_TRUE(closed_and_oriented(mesh));
  const auto euler = static_cast<long>(mesh.positions.size()) - static_cast<long>(edge_count(mesh)) +
                     static_cast<long>(mesh.triangles.size());
  EXPECT_EQ(euler, 2);
  // The inscribed polyhedron has less volume than the ball; at this resolution within 10 %.
  const double ball = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
  EXPECT_GT(signed_volume(mesh), 0.9 * ball);
  EXPECT_LT(signed_volume(mesh), ball);
}

// Digest §2.6 and §2.7: 3828 triangles on a 12³-cell block and 60,292 on the 30³ big cube. The
// seed's lattice holds many samples that are zero up to rounding (93 exact zeros and 221 with
// |f| < 1e-6 in the big cube: simplex vertices and cancelling corners at multiples of 1/10), so the
// count depends on the tie rule and on the last bits of the coordinates. Ours (rock iff f < 0,
// coordinates times 0.1) gives 3790 and 60,290; the digest's numbers come out exactly with its
// conventions, coordinates divided by 10 (Listing 3.1) and ties counted as rock (f <= 0, the same
// as f < the smallest positive double).
TEST(MarchingTetrahedra, SeedBlockCountsAndTheDigestsConventions) {
  for (const auto& [cells, ours, digest] : {std::tuple{12, 3790u, 3828u}, std::tuple{30, 60290u, 60292u}}) {
    const auto params = seed_block({0, 0, 0}, cells, false);
    EXPECT_EQ(cave_mesh<double>(params).triangles.size(), ours) << cells << " cells";
    const auto divided = sampled(cells + 1, [](double x, double y, double z) {
      return ref::simplex3<double>(gt::perlin_permutation(), x / 10.0, y / 10.0, z / 10.0, 0.6);
    });
    const auto digest_mesh = ref::marching_tetrahedra(divided, std::nextafter(0.0, 1.0), false, {0, 0, 0});
    EXPECT_EQ(digest_mesh.triangles.size(), digest) << cells << " cells";
  }
}

TEST(MarchingTetrahedra, SolidBlockIsClosedAndBoundsPositiveVolume) {
  for (int cells : {12, 30}) {
    const auto params = seed_block({0, 0, 0}, cells, true);
    const auto mesh = cave_mesh<double>(params);
    EXPECT_TRUE(closed_and_oriented(mesh)) << cells << " cells";
    EXPECT_GT(signed_volume(mesh), 0.0);
    EXPECT_TRUE(closed_and_oriented(cave_mesh<float>(params))) << cells << " cells, float";
  }
}

// A sample exactly at the threshold: without the edge margin every crossing edge ending there would
// put its vertex on that lattice point (t = 1), leaving zero-area triangles pinched at one point.
// With t clamped to [δ, 1 - δ] the air bubble around the sample is a small closed polyhedron of
// distinct vertices within δ·√3 of it.
TEST(MarchingTetrahedra, SampleAtTheThresholdDoesNotPinchTheSurface) {
  gt::Volume<double> volume(3, 3, 3, -1.0);
  volume.at(1, 1, 1) = 0.0;  // air (rock iff f < 0), surrounded by rock
  const auto mesh = ref::marching_tetrahedra(volume, 0.0, false, {0, 0, 0});
  ASSERT_FALSE(mesh.triangles.empty());
  EXPECT_TRUE(closed_and_oriented(mesh));
  const double margin = std::ldexp(1.0, -10);  // edge_margin of every edge of this block
  for (const auto& triangle : mesh.triangles) EXPECT_GT(dot(triangle_normal(mesh, triangle), triangle_normal(mesh, triangle)), 0.0);
  std::set<std::array<double, 3>> distinct(mesh.positions.begin(), mesh.positions.end());
  EXPECT_EQ(distinct.size(), mesh.positions.size());
  for (const auto& position : mesh.positions) {
    const Vec3 offset = sub({position[0], position[1], position[2]}, {1.0, 1.0, 1.0});
    EXPECT_LE(std::sqrt(dot(offset, offset)), margin * std::sqrt(3.0) * (1 + 1e-12));
  }
}

// δ is a power of two of at least 2^-10 and at least 4 float ulps of the edge's largest coordinate,
// so that a + δ and a + 1 - δ round to floats distinct from the lattice points.
TEST(MarchingTetrahedra, EdgeMarginGrowsWithTheCoordinates) {
  EXPECT_EQ(gt::edge_margin({0, 0, 0}, 7), std::ldexp(1.0, -10));
  EXPECT_EQ(gt::edge_margin({2046, 0, 0}, 1), std::ldexp(1.0, -10));  // m + 1 = 2048 = 2^11
  EXPECT_EQ(gt::edge_margin({-5001, 1233, 776}, 3), std::ldexp(1.0, -9));
  EXPECT_EQ(gt::edge_margin({0, 0, -524288}, 4), std::ldexp(1.0, -2));
  for (const std::int64_t coordinate : {std::int64_t{0}, std::int64_t{3000}, std::int64_t{-70000}, std::int64_t{524286}}) {
    for (const int direction : {1, 7}) {
      const double margin = gt::edge_margin({coordinate, 0, 0}, direction);
      const auto lower = static_cast<float>(coordinate);
      const auto upper = static_cast<float>(coordinate + 1);
      EXPECT_NE(upper - static_cast<float>(margin), upper) << coordinate;
      EXPECT_NE(lower + static_cast<float>(margin), lower) << coordinate;
    }
  }
}

// The seed's own lattice is full of samples at the threshold up to rounding: CGAL and OpenMesh must
// still find its solid blocks watertight (no zero-area or touching faces), in double and in float.
TEST(MarchingTetrahedra, SeedBlocksAreWatertightForCgalAndOpenMesh) {
  for (int cells : {12, 30}) {
    const auto params = seed_block({0, 0, 0}, cells, true);
    const gt::MeshReport truth = gt::check_mesh(cave_mesh<double>(params));
    EXPECT_TRUE(gt::is_watertight_and_oriented(truth)) << cells << " cells: " << gt::describe(truth);
    const gt::MeshReport single = gt::check_mesh(gt::to_double_mesh(cave_mesh<float>(params)));
    EXPECT_TRUE(gt::is_watertight_and_oriented(single)) << cells << " cells, float: " << gt::describe(single);
  }
}

// In solid mode every crossing to the pad lies at the edge's midpoint, half a unit outside the block.
TEST(MarchingTetrahedra, SolidCapLiesHalfAUnitOutsideTheBlock) {
  const auto params = seed_block({3, -5, 7}, 6, true);
  const auto mesh = cave_mesh<double>(params);
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[vertex]);
    const auto step = ref::corner_offset(edge.direction);
    bool touches_pad = false;
    for (int axis = 0; axis < 3; ++axis) {
      const std::int64_t upper = edge.lower_point[axis] + step[axis];
      touches_pad = touches_pad || edge.lower_point[axis] < params.origin[axis] ||
                    upper > params.origin[axis] + params.size[axis];
    }
    if (!touches_pad) continue;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(mesh.positions[vertex][axis], double(edge.lower_point[axis]) + 0.5 * step[axis]);
    }
  }
}

// Open mode: a boundary edge joins two vertices on edges in the same face of the block, and every
// edge is used once in each direction at most (manifold, consistently oriented).
TEST(MarchingTetrahedra, OpenBlockBoundaryLiesOnTheBlockFaces) {
  const auto params = seed_block({-4, 2, 9}, 12, false);
  const auto mesh = cave_mesh<double>(params);
  const auto boundary = boundary_edges(mesh);
  ASSERT_FALSE(boundary.empty());
  const auto in_face = [](std::uint64_t key, int axis, std::int64_t face) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(key);
    return edge.lower_point[axis] == face && ((edge.direction >> axis) & 1) == 0;
  };
  for (const auto& [a, b] : boundary) {
    bool on_one_face = false;
    for (int axis = 0; axis < 3; ++axis) {
      for (int face : {params.origin[axis], params.origin[axis] + params.size[axis]}) {
        on_one_face = on_one_face || (in_face(mesh.edge_keys[a], axis, face) && in_face(mesh.edge_keys[b], axis, face) &&
                                      mesh.positions[a][axis] == face && mesh.positions[b][axis] == face);
      }
    }
    EXPECT_TRUE(on_one_face) << "boundary edge " << a << "-" << b << " inside the block";
  }
  const auto counts = directed_edge_counts(mesh);
  EXPECT_TRUE(std::all_of(counts.begin(), counts.end(), [](const auto& entry) { return entry.second == 1; }));
}

// Whether the vertex's lattice edge lies in the plane x = plane_x. (Positions cannot tell: in
// float, a vertex at t close to 1 on an edge crossing the plane rounds onto it.)
bool edge_in_plane_x(std::uint64_t key, std::int64_t plane_x) {
  const gt::LatticeEdge edge = gt::lattice_edge_from_key(key);
  return edge.lower_point[0] == plane_x && (edge.direction & 1) == 0;
}

// The vertices on the plane x = plane_x by key, and the boundary edges there as key pairs.
template <class Real>
struct FaceSeam {
  std::map<std::uint64_t, std::array<Real, 3>> positions;
  std::set<std::pair<std::uint64_t, std::uint64_t>> boundary;
};

template <class Real>
FaceSeam<Real> face_seam(const gt::TriangleMesh<Real>& mesh, std::int64_t plane_x) {
  FaceSeam<Real> seam;
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    if (edge_in_plane_x(mesh.edge_keys[vertex], plane_x)) seam.positions[mesh.edge_keys[vertex]] = mesh.positions[vertex];
  }
  for (const auto& [a, b] : boundary_edges(mesh)) {
    if (edge_in_plane_x(mesh.edge_keys[a], plane_x) && edge_in_plane_x(mesh.edge_keys[b], plane_x)) {
      seam.boundary.insert({mesh.edge_keys[a], mesh.edge_keys[b]});
    }
  }
  return seam;
}

// Blocks [0, 12] and [12, 24] along x, open: the same vertices on x = 12, bit for bit, and the
// boundary edges there are each other's reverses (the union is seamless).
template <class Real>
void expect_seamless_neighbours() {
  const auto left = cave_mesh<Real>(seed_block({0, 0, 0}, 12, false));
  const auto right = cave_mesh<Real>(seed_block({12, 0, 0}, 12, false));
  const FaceSeam<Real> left_seam = face_seam(left, 12);
  const FaceSeam<Real> right_seam = face_seam(right, 12);
  ASSERT_FALSE(left_seam.positions.empty());
  ASSERT_EQ(left_seam.positions.size(), right_seam.positions.size());
  for (const auto& [key, left_position] : left_seam.positions) {
    ASSERT_TRUE(right_seam.positions.contains(key));
    const auto& right_position = right_seam.positions.at(key);
    using Bits = std::array<unsigned char, sizeof(Real)>;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(std::bit_cast<Bits>(left_position[axis]), std::bit_cast<Bits>(right_position[axis]));
    }
  }
  ASSERT_FALSE(left_seam.boundary.empty());
  std::set<std::pair<std::uint64_t, std::uint64_t>> right_reversed;
  for (const auto& [a, b] : right_seam.boundary) right_reversed.insert({b, a});
  EXPECT_EQ(left_seam.boundary, right_reversed);
}

TEST(MarchingTetrahedra, NeighbouringBlocksShareTheirFaceBitForBit) {
  expect_seamless_neighbours<double>();
  expect_seamless_neighbours<float>();
}

// The mesh's topology (triangles, vertex order, edge keys) is a function of the rock/air
// classification of the samples alone: where float and double classify every sample alike (each
// sample's float error below its distance to the threshold, true on a generic field away from the
// seed lattice's near-zero samples), the meshes have the same triangles, vertex order and keys.
// Positions then differ by what float makes of t. Error model for the vertex on edge (a, b), with
// E_a, E_b the samples' float errors and u = 2^-24 (t <= 1, each operation rounding once):
//   t = (T - v_a)/(v_b - v_a): |Δt| <= (E_a + t·(E_a + E_b))/|v_b - v_a|·(1 + 4u) + 3u
//   position = a + t·d:        |Δp| <= |Δt| + u·|p|
TEST(MarchingTetrahedra, DoubleAndFloatShareTopologyOnAGenericField) {
  gt::CaveParams params = seed_block({101, -37, 53}, 16, true);
  params.scale = 9.73;
  const auto density = ref::cave_density<double>(params);
  const auto density_float = ref::cave_density<float>(params);
  const auto float_error = [&](int x, int y, int z) {
    return std::abs(density.at(x, y, z) - double(density_float.at(x, y, z)));
  };
  for (std::size_t i = 0; i < density.values.size(); ++i) {
    ASSERT_LT(std::abs(density.values[i] - double(density_float.values[i])), std::abs(density.values[i]))
        << "sample " << i << ": the field is not generic enough for this test";
  }
  const auto mesh = ref::marching_tetrahedra(density, 0.0, true, lattice_origin(params));
  const auto mesh_float = ref::marching_tetrahedra(density_float, 0.0f, true, lattice_origin(params));
  ASSERT_EQ(mesh.triangles, mesh_float.triangles);
  ASSERT_EQ(mesh.edge_keys, mesh_float.edge_keys);
  const double u = 0x1p-24;
  double largest_difference = 0;
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(mesh.edge_keys[vertex]);
    const auto step = ref::corner_offset(edge.direction);
    std::array<int, 3> a{};
    std::array<int, 3> b{};
    bool touches_pad = false;
    for (int axis = 0; axis < 3; ++axis) {
      a[axis] = static_cast<int>(edge.lower_point[axis] - params.origin[axis]);
      b[axis] = a[axis] + step[axis];
      touches_pad = touches_pad || a[axis] < 0 || b[axis] > params.size[axis];
    }
    double t_bound = 0;  // pad vertices sit at exact midpoints
    if (!touches_pad) {
      const double va = density.at(a[0], a[1], a[2]);
      const double vb = density.at(b[0], b[1], b[2]);
      const double ea = float_error(a[0], a[1], a[2]);
      const double eb = float_error(b[0], b[1], b[2]);
      const double t = -va / (vb - va);
      t_bound = (ea + t * (ea + eb)) / std::abs(vb - va) * (1 + 4 * u) + 3 * u;
    }
    for (int axis = 0; axis < 3; ++axis) {
      const double p = mesh.positions[vertex][axis];
      const double difference = std::abs(p - double(mesh_float.positions[vertex][axis]));
      largest_difference = std::max(largest_difference, difference);
      EXPECT_LE(difference, t_bound * step[axis] + u * std::abs(p)) << "vertex " << vertex << " axis " << axis;
    }
  }
  std::printf("generic field 16³: float and double positions differ by at most %.3g\n", largest_difference);
}

// On the seed's own lattice the classifications of float and double differ, but only at samples
// within the float error of 0 (simplex noise at the big cube's 93 exact and 221 near zeros, where
// the 0.6 kernel's jump J = 2·32·sqrt(2)·sqrt(0.6)·0.1⁴ = 0.0070 decides which side a tie falls).
TEST(MarchingTetrahedra, FloatAndDoubleDisagreeOnlyAtNearZeroSamplesOfTheSeedLattice) {
  const auto params = seed_block({0, 0, 0}, 30, false);
  const auto density = ref::cave_density<double>(params);
  const auto density_float = ref::cave_density<float>(params);
  const double jump = 2 * 32 * std::sqrt(2.0) * std::sqrt(0.6) * 1e-4;
  int disagreements = 0;
  for (std::size_t i = 0; i < density.values.size(); ++i) {
    if ((density.values[i] < 0) == (density_float.values[i] < 0.0f)) continue;
    ++disagreements;
    EXPECT_LE(std::abs(density.values[i]), jump + 1e-5) << "sample " << i;
  }
  std::printf("seed lattice 30³: %d samples classified differently by float and double\n", disagreements);
}

TEST(MarchingTetrahedra, MidpointPlacementKeepsTheTopology) {
  const auto params = seed_block({0, 0, 0}, 12, true);
  const auto density = ref::cave_density<double>(params);
  const auto linear = ref::marching_tetrahedra(density, 0.0, true, {0, 0, 0});
  const auto midpoint = ref::marching_tetrahedra(density, 0.0, true, {0, 0, 0}, ref::EdgePlacement::midpoint);
  EXPECT_EQ(linear.triangles, midpoint.triangles);
  EXPECT_EQ(linear.edge_keys, midpoint.edge_keys);
  for (std::size_t vertex = 0; vertex < midpoint.positions.size(); ++vertex) {
    const gt::LatticeEdge edge = gt::lattice_edge_from_key(midpoint.edge_keys[vertex]);
    const auto step = ref::corner_offset(edge.direction);
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_EQ(midpoint.positions[vertex][axis], double(edge.lower_point[axis]) + 0.5 * step[axis]);
    }
  }
}

TEST(MarchingTetrahedra, RefusesNonFiniteSamplesAndBlocksOutsideTheKeyRange) {
  auto volume = sampled(3, [](double x, double, double) { return x - 1.5; });
  EXPECT_THROW(ref::marching_tetrahedra(volume, 0.0, true, {gt::lattice_coordinate_max - 2, 0, 0}), gt::InputError);
  EXPECT_NO_THROW(ref::marching_tetrahedra(volume, 0.0, false, {gt::lattice_coordinate_max - 2, 0, 0}));
  volume.at(1, 2, 0) = std::nan("");
  EXPECT_THROW(ref::marching_tetrahedra(volume, 0.0, false, {0, 0, 0}), gt::InputError);
  EXPECT_THROW(ref::marching_cubes(volume, 0.0, false, {0, 0, 0}), gt::InputError);
}

// Every case of the built table: triangles on crossing edges, wound from rock into air (the
// normal of the midpoint triangle has a positive dot product with Σ air - rock over its edges),
// every base configuration used, complements only where more than four corners are rock.
TEST(MarchingCubes, TableCoversAllCasesWoundFromRockIntoAir) {
  const auto& table = ref::marching_cubes_table();
  std::set<int> bases_used;
  for (unsigned code = 1; code < 255; ++code) {
    const ref::CubeCase& cube_case = table[code];
    ASSERT_FALSE(cube_case.triangles.empty()) << "case " << code;
    EXPECT_LE(cube_case.triangles.size(), 4u);
    bases_used.insert(cube_case.base);
    EXPECT_EQ(cube_case.complemented, std::popcount(code) > 4) << "case " << code;
    for (const auto& triangle : cube_case.triangles) {
      std::array<Vec3, 3> corner{};
      Vec3 outward{};
      for (int c = 0; c < 3; ++c) {
        const auto [lower, upper] = triangle[c];
        const bool lower_rock = (code >> lower) & 1u;
        ASSERT_NE(lower_rock, bool((code >> upper) & 1u)) << "case " << code << " uses an edge that does not cross";
        const auto a = ref::corner_offset(lower);
        const auto b = ref::corner_offset(upper);
        for (int axis = 0; axis < 3; ++axis) {
          corner[c][axis] = (a[axis] + b[axis]) / 2.0;
          outward[axis] += lower_rock ? b[axis] - a[axis] : a[axis] - b[axis];
        }
      }
      const Vec3 normal = cross(sub(corner[1], corner[0]), sub(corner[2], corner[0]));
      EXPECT_GT(dot(normal, outward), 0) << "case " << code;
    }
  }
  EXPECT_EQ(bases_used.size(), 14u);
}

// Two cubes sharing the face x = 1 with rock on its diagonal (1,0,0)-(1,1,1): the left cube has
// only those two rock corners (kept apart), the right one six (complemented: the air kept apart),
// so the face is cut twice differently and the solid mesh has a hole; marching tetrahedra closes it.
TEST(MarchingCubes, AmbiguousFaceLeavesAHoleThatTetrahedraClose) {
  gt::Volume<double> volume(3, 2, 2, 1.0);
  volume.at(1, 0, 0) = -1.0;
  volume.at(1, 1, 1) = -1.0;
  for (int y = 0; y < 2; ++y) {
    for (int z = 0; z < 2; ++z) volume.at(2, y, z) = -1.0;
  }
  const auto cubes = ref::marching_cubes(volume, 0.0, true, {0, 0, 0});
  EXPECT_FALSE(closed_and_oriented(cubes));
  EXPECT_EQ(boundary_edges(cubes).size(), 4u);
  EXPECT_TRUE(closed_and_oriented(ref::marching_tetrahedra(volume, 0.0, true, {0, 0, 0})));
  const auto params = seed_block({0, 0, 0}, 12, true);
  const auto seed_cubes = ref::marching_cubes(ref::cave_density<double>(params), 0.0, true, {0, 0, 0});
  std::printf("marching cubes, seed block 12³ solid: %zu triangles, %zu boundary edges\n",
              seed_cubes.triangles.size(), boundary_edges(seed_cubes).size());
  EXPECT_FALSE(boundary_edges(seed_cubes).empty());
}

// Central differences (h = step/scale = 0.1 noise units) against the analytic gradient.
// Error model, per axis, in noise units (f = 32 Σ t⁴ (g·d) over one simplex's corners): write f as
// the smooth sum F over all lattice vertices within the kernel minus the terms m of vertices
// outside the current simplex (the 0.6 kernel's leftovers, digest §2.2.5). Then
//   |D_h f - ∂f| <= h²/6 · max|∂³F| + max|m|/h + max|∂m|
// with max|∂³F| <= 560, max|m| <= 0.0062 and max|∂m| <= 0.35 (largest over 200,000 random points
// of the cell of Σ over vertices of the largest |term| any of the 12 gradients gives: 515, 0.0056,
// 0.31, plus 10 %). So |e| <= sqrt(3)·(0.93 + 0.062 + 0.35) = 2.33 and the angle between the two
// normals is at most asin(|e| / |∇f|) — a worst case, met where |∇f| is small. Typically the
// third derivative is far below its maximum: the median angle is a few percent (digest §2.8).
TEST(CaveNormals, CentralDifferencesAgreeWithTheGradient) {
  const auto params = seed_block({0, 0, 0}, 30, false);
  const auto mesh = cave_mesh<double>(params);
  const auto differences = ref::central_difference_normals(mesh, params);
  const auto gradients = ref::gradient_normals(mesh, params);
  const auto angles = ref::normal_angles(differences, gradients);
  const double error_bound = std::sqrt(3.0) * (0.01 / 6 * 560 + 0.0062 / 0.1 + 0.35);
  for (std::size_t vertex = 0; vertex < angles.size(); ++vertex) {
    const auto& p = mesh.positions[vertex];
    const auto gradient = ref::simplex3_gradient<double>(gt::perlin_permutation(), p[0] * 0.1, p[1] * 0.1, p[2] * 0.1, 0.6);
    const double length = std::sqrt(gradient[1] * gradient[1] + gradient[2] * gradient[2] + gradient[3] * gradient[3]);
    if (error_bound >= length) continue;
    EXPECT_LE(angles[vertex], std::asin(error_bound / length)) << "vertex " << vertex;
    EXPECT_NEAR(dot({gradients[vertex][0], gradients[vertex][1], gradients[vertex][2]},
                    {gradient[1] / length, gradient[2] / length, gradient[3] / length}), 1.0, 1e-12);
  }
  auto sorted = angles;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double p99 = sorted[sorted.size() * 99 / 100];
  std::printf("normals, big cube: median angle %.4f rad, 99th percentile %.4f, largest %.4f\n", median, p99,
              sorted.back());
  EXPECT_LT(median, 0.05);
}

int rock_samples(const gt::Volume<double>& density) {
  return static_cast<int>(std::count_if(density.values.begin(), density.values.end(), [](double v) { return v < 0; }));
}

// The winding agrees with the gradient normals, the mesh faces the air: the triangles away from
// the cap have normals within 90° of the mean gradient normal of their corners, all but slivers
// (by area to 1e-3: the exceptions, 53 of 3790 here, have next to no area), and the closed solid
// bounds a positive volume close to the number of rock samples (each stands for a unit cube; the
// difference is the surface's discretisation, 0.2 % here, and a reversed winding would negate it).
TEST(CaveNormals, TrianglesFaceAlongTheGradient) {
  const auto params = seed_block({0, 0, 0}, 12, true);
  const auto density = ref::cave_density<double>(params);
  const auto mesh = ref::marching_tetrahedra(density, 0.0, true, {0, 0, 0});
  const auto normals = ref::gradient_normals(mesh, params);
  double total_area = 0;
  double agreeing_area = 0;
  for (const auto& triangle : mesh.triangles) {
    bool on_cap = false;
    Vec3 mean{};
    for (auto vertex : triangle) {
      for (int axis = 0; axis < 3; ++axis) {
        on_cap = on_cap || mesh.positions[vertex][axis] < 0 || mesh.positions[vertex][axis] > 12;
        mean[axis] += normals[vertex][axis];
      }
    }
    if (on_cap) continue;
    const Vec3 normal = triangle_normal(mesh, triangle);
    const double area = std::sqrt(dot(normal, normal)) / 2;
    total_area += area;
    agreeing_area += dot(normal, mean) > 0 ? area : 0;
  }
  EXPECT_GT(agreeing_area, (1 - 1e-3) * total_area);
  const double rock = rock_samples(density);
  EXPECT_NEAR(signed_volume(mesh), rock, 0.02 * rock);
}

}  // namespace
