// The cube-sphere surface of seed 002 (core/planet/cube_sphere.hpp) against the digest's worked
// numbers and the round trips and neighbour invariants of its §9.5.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/planet/cube_sphere.hpp"

namespace gt {
namespace {

// Local coordinates survive a round trip through the sphere up to a few roundings of numbers of
// magnitude 1: tan, atan, the normalisation and the division by the largest component, each within
// an ulp or two of double, amplified at most by the inverse warp's slope (tan θ / θ: 1.36 for the
// optimised warp, 4/π for eq. 3.4's, 1 for none): 1e-13 is some 450 ulp.
constexpr double round_trip_tolerance = 1e-13;

// The three warps of the planet's `warp` parameter.
const CubeWarp warps[] = {CubeWarp{}, CubeWarp{std::atan(1.0)}, no_warp};

TEST(CubeSphere, WarpAndUnwarpAreInversesThatFixTheCentreAndTheEdges) {
  for (const CubeWarp cube_warp : warps) {
    EXPECT_EQ(warp(0.0, cube_warp), 0.0);
    EXPECT_NEAR(warp(1.0, cube_warp), 1.0, 1e-15);
    EXPECT_NEAR(warp(-1.0, cube_warp), -1.0, 1e-15);
    for (double t = -1.0; t <= 1.0; t += 0.125) EXPECT_NEAR(unwarp(warp(t, cube_warp), cube_warp), t, 1e-15) << t;
  }
  EXPECT_NEAR(std::tan(warp_angle), 1.1822866855, 1e-10) << "the code's hard-coded tan θ";
  // Eq. 3.4: tan(πt/4) moves a third of the way along a face's half to tan(π/12) = 2 − √3.
  EXPECT_NEAR(warp(1.0 / 3.0, CubeWarp{std::atan(1.0)}), 2.0 - std::sqrt(3.0), 1e-15);
  EXPECT_EQ(warp(0.3, no_warp), 0.3);
  EXPECT_EQ(unwarp(0.3, no_warp), 0.3);
}

TEST(CubeSphere, FacesHaveTheCodesNormalsAndAxes) {
  // (face, normal at the centre, direction of +a) from the digest's table (§3.4).
  const struct {
    CubeFace face;
    Vec3 normal;
    Vec3 plus_a;
    Vec3 plus_b;
  } faces[] = {{CubeFace::front, {0, 0, 1}, {1, 0, 0}, {0, -1, 0}},  {CubeFace::right, {1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
               {CubeFace::back, {0, 0, -1}, {-1, 0, 0}, {0, -1, 0}}, {CubeFace::left, {-1, 0, 0}, {0, 0, 1}, {0, -1, 0}},
               {CubeFace::north, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}},  {CubeFace::south, {0, -1, 0}, {1, 0, 0}, {0, 0, -1}}};
  for (const auto& expected : faces) {
    EXPECT_EQ(sphere_position({expected.face, 0.5, 0.5}), expected.normal);
    const Vec3 centre = cube_point({expected.face, 0.5, 0.5});
    EXPECT_EQ(cube_point({expected.face, 1.0, 0.5}) - centre, expected.plus_a);
    EXPECT_EQ(cube_point({expected.face, 0.5, 1.0}) - centre, expected.plus_b);
  }
}

// §3.4: "front a = 1 + e/2 -> (1, y, 1 - e) -> right-face local (e - 1, y, 1) -> a' = e/2", b kept.
TEST(CubeSphere, WrapFoldsAcrossAnEdgeAsTheDigestChecked) {
  const double e = 0.25;
  const auto wrapped = wrap({CubeFace::front, 1.0 + e / 2.0, 0.3});
  ASSERT_TRUE(wrapped);
  EXPECT_EQ(wrapped->face, CubeFace::right);
  EXPECT_DOUBLE_EQ(wrapped->a, e / 2.0);
  EXPECT_DOUBLE_EQ(wrapped->b, 0.3);
  EXPECT_FALSE(wrap({CubeFace::front, 1.1, -0.1})) << "over a corner";
  const auto inside = wrap({CubeFace::south, 0.2, 0.7});
  ASSERT_TRUE(inside);
  EXPECT_EQ(inside->face, CubeFace::south);
  EXPECT_EQ(inside->a, 0.2);
}

// §9.5: across each of the 24 directed edges and back: the fold is an isometry, so stepping over an
// edge by s and returning by s along the new face's inward direction gives the start back.
TEST(CubeSphere, WrapAcrossAll24DirectedEdgesReturns) {
  const double step = 0.1;
  std::set<std::pair<int, int>> crossings;
  for (int face = 0; face < cube_face_count; ++face) {
    for (const auto& [da, db] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}}) {
      const LocalPosition start{static_cast<CubeFace>(face), 0.5 + da * (0.5 - step / 2), 0.5 + db * (0.5 - step / 2)};
      const auto across = wrap({start.face, start.a + da * step, start.b + db * step});
      ASSERT_TRUE(across);
      EXPECT_NE(across->face, start.face);
      crossings.insert({face, static_cast<int>(across->face)});
      // Distances on the cube are kept: the new point is step / 2 inside the new face.
      const Vec3 on_cube = cube_point(*across);
      const Vec3 edge_point = cube_point({start.face, start.a + da * step / 2, start.b + db * step / 2});
      EXPECT_NEAR(length(on_cube - edge_point), step, 1e-12) << "a step of 0.1 in a is 0.2 on the cube, half each side";
      // Stepping back by the same amount along the new face's coordinate that meets the edge returns.
      LocalPosition back = *across;
      const auto step_back = [&](double& coordinate) {
        if (std::abs(coordinate - step / 2) < 1e-12) coordinate -= step;
        if (std::abs(coordinate - (1 - step / 2)) < 1e-12) coordinate += step;
      };
      step_back(back.a);
      step_back(back.b);
      const auto returned = wrap(back);
      ASSERT_TRUE(returned);
      EXPECT_EQ(returned->face, start.face);
      EXPECT_NEAR(returned->a, start.a, 1e-12);
      EXPECT_NEAR(returned->b, start.b, 1e-12);
    }
  }
  EXPECT_EQ(crossings.size(), 24u) << "each face meets four different faces";
}

TEST(CubeSphere, LocalPositionsSurviveTheSphereRoundTrip) {
  std::mt19937_64 random(20260514);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const CubeWarp cube_warp : warps) {
    for (int sample = 0; sample < 6000; ++sample) {
      const LocalPosition local{static_cast<CubeFace>(sample % cube_face_count), unit(random), unit(random)};
      const Vec3 position = sphere_position(local, cube_warp);
      EXPECT_NEAR(length(position), 1.0, 1e-15);
      const LocalPosition back = local_position_of(position, cube_warp);
      ASSERT_EQ(back.face, local.face) << local.a << ", " << local.b;
      EXPECT_NEAR(back.a, local.a, round_trip_tolerance);
      EXPECT_NEAR(back.b, local.b, round_trip_tolerance);
    }
  }
}

TEST(CubeSphere, RegionsRoundTripThroughTheirCellCentres) {
  const CubeSphere sphere(7);
  ASSERT_EQ(sphere.region_count(), 6u * 49u);
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    for (const auto& [offset_a, offset_b] : {std::pair{0.5, 0.5}, {0.1, 0.9}, {0.99, 0.01}}) {
      const LocalPosition local = sphere.local_position(region, offset_a, offset_b);
      EXPECT_EQ(sphere.region_at(local), region);
      EXPECT_EQ(sphere.region_at(local_position_of(sphere_position(local))), region);
    }
  }
  EXPECT_EQ(sphere.local_position(7 * 7 + 7 * 2 + 3).face, CubeFace::right) << "face-major, then rows";
  EXPECT_EQ(sphere.region_at({CubeFace::north, 1.0, 1.0}), 4u * 49u + 48u) << "a coordinate of 1 is cell R - 1";
}

// The symmetric relation, without the cell itself or repeats.
void expect_symmetric_neighbours(const CubeSphere& sphere) {
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    const RegionNeighbours& around = sphere.neighbours(region);
    std::set<std::int32_t> distinct(around.begin(), around.end());
    distinct.erase(invalid_region);
    const auto valid = std::count_if(around.begin(), around.end(), [](std::int32_t n) { return n != invalid_region; });
    EXPECT_EQ(distinct.size(), static_cast<std::size_t>(valid)) << "region " << region;
    EXPECT_FALSE(distinct.contains(static_cast<std::int32_t>(region)));
    for (const std::int32_t neighbour : distinct) {
      const RegionNeighbours& back = sphere.neighbours(static_cast<std::size_t>(neighbour));
      EXPECT_NE(std::find(back.begin(), back.end(), static_cast<std::int32_t>(region)), back.end())
          << region << " -> " << neighbour << " but not back (R = " << sphere.resolution() << ")";
    }
  }
}

TEST(CubeSphere, CornerCellsHaveSevenNeighboursAndTheRelationIsSymmetric) {
  for (const int resolution : {2, 3, 6}) {
    const CubeSphere sphere(resolution);
    std::size_t corner_cells = 0;
    for (std::size_t region = 0; region < sphere.region_count(); ++region) {
      const RegionNeighbours& around = sphere.neighbours(region);
      const auto missing = std::count(around.begin(), around.end(), invalid_region);
      EXPECT_LE(missing, 1) << "region " << region;
      corner_cells += missing == 1 ? 1 : 0;
    }
    EXPECT_EQ(corner_cells, 24u) << "4 corners on each of 6 faces, R = " << resolution;
    expect_symmetric_neighbours(sphere);
  }
}

// R = 1: each face is one cell, its four edge neighbours the four adjacent faces, every diagonal
// over a corner.
TEST(CubeSphere, OneCellPerFaceSeesTheFourAdjacentFaces) {
  const CubeSphere sphere(1);
  for (std::size_t region = 0; region < 6; ++region) {
    const RegionNeighbours& around = sphere.neighbours(region);
    EXPECT_EQ(std::count(around.begin(), around.end(), invalid_region), 4);
    const std::int32_t opposite = static_cast<std::int32_t>(region < 4 ? (region + 2) % 4 : 9 - region);
    EXPECT_EQ(std::count(around.begin(), around.end(), opposite), 0) << "region " << region;
  }
  expect_symmetric_neighbours(sphere);
}

TEST(CubeSphere, RefusesResolutionsOutsideItsRange) {
  EXPECT_THROW(CubeSphere(0), InputError);
  EXPECT_THROW(CubeSphere(max_cube_sphere_resolution + 1), InputError);
  EXPECT_THROW(local_position_of({0.0, 0.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace gt
