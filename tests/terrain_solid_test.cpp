// Tests of reference/render/terrain_solid: the solid of a heightmap is closed, manifold,
// consistently and outwardly oriented and free of self-intersections (compare/checks/mesh.hpp:
// CGAL and OpenMesh), its genus counts the holes of the mask, its volume is the exact prism
// volume, its coordinates follow the documented frame, and unusable grids are refused.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compare/checks/mesh.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "reference/render/terrain_solid.hpp"
#include "tests/support/refusal.hpp"

namespace gt {
namespace {

using ::testing::HasSubstr;
using reference::terrain_solid;
using reference::TerrainSolid;
using reference::TerrainSolidOptions;
using testing::refusal;

constexpr double unit_roundoff = 0x1p-53;  // double

// A smooth, non-planar terrain of width x height samples with rectangular cells, so that rows and
// columns, cell sizes and the triangulation's diagonal all matter.
Heightmap wavy(int width, int height, double cell_x = 10.0, double cell_y = 12.5) {
  Heightmap heights(width, height, 0.0);
  heights.cell_size_x = cell_x;
  heights.cell_size_y = cell_y;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) heights.at(i, j) = 100.0 + 30.0 * std::sin(0.7 * i) * std::cos(0.5 * j) + 3.0 * j;
  }
  return heights;
}

Heightmap with_mask(Heightmap heights, const std::vector<std::pair<int, int>>& no_data) {
  heights.valid.assign(heights.size(), 1);
  for (const auto& [i, j] : no_data) heights.valid[heights.index(i, j)] = 0;
  return heights;
}

bool quad_kept(const Heightmap& heights, int i, int j) {
  return heights.is_valid(i, j) && heights.is_valid(i + 1, j) && heights.is_valid(i, j + 1) &&
         heights.is_valid(i + 1, j + 1);
}

// The exact volume between the triangulated surface (diagonal (i, j)-(i+1, j+1), as documented)
// and the base plane, computed from the heightmap: each triangle is a prism of base area
// cx·cy/2 whose height is the mean of its three corners above the base.
double prism_volume(const Heightmap& heights, double base_y, double vertical_scale = 1.0) {
  double volume = 0.0;
  const double half_cell = 0.5 * heights.cell_size_x * heights.cell_size_y;
  for (int j = 0; j + 1 < heights.height; ++j) {
    for (int i = 0; i + 1 < heights.width; ++i) {
      if (!quad_kept(heights, i, j)) continue;
      const double h00 = vertical_scale * heights.at(i, j), h10 = vertical_scale * heights.at(i + 1, j);
      const double h01 = vertical_scale * heights.at(i, j + 1), h11 = vertical_scale * heights.at(i + 1, j + 1);
      volume += half_cell * ((h00 + h11 + h10) / 3.0 - base_y) + half_cell * ((h00 + h01 + h11) / 3.0 - base_y);
    }
  }
  return volume;
}

// Rounding bound of |CGAL's volume - prism_volume| (error model). CGAL sums, over the N faces,
// det(p, q, r)/6 in double (origin (0,0,0), Epick kernel). With every coordinate within R:
// each 2x2 minor is within 2R² and carries at most 4uR² of rounding, each cofactor product at
// most 6uR³, the three-term sum adds 10uR³: 28uR³ per determinant, under 6uR³ per term after the
// division by 6. The running sum's partial sums are within k·R³ after k terms, so the additions
// add at most u·R³·N²/2. The expected value, a sum of N/2 prisms each within 2R³ (area ≤ R², height
// ≤ 2R), adds about as much again. Total: u·R³·N·(6 + N) < u·R³·N·(8 + N).
double volume_bound(const Mesh& mesh) {
  double radius = 0.0;
  for (const auto& p : mesh.positions) {
    for (const double c : p) radius = std::max(radius, std::abs(c));
  }
  const double faces = double(mesh.triangles.size());
  return unit_roundoff * radius * radius * radius * faces * (8.0 + faces);
}

void expect_watertight(const MeshReport& report) {
  EXPECT_TRUE(is_watertight_and_oriented(report)) << describe(report);
  EXPECT_EQ(report.raw.border_edges, 0u);
  EXPECT_EQ(report.raw.non_manifold_edges, 0u);
  EXPECT_EQ(report.raw.misoriented_edges, 0u);
  EXPECT_EQ(report.raw.zero_area_triangles, 0u);
  EXPECT_EQ(report.raw.duplicate_triangles, 0u);
  EXPECT_EQ(report.raw.unreferenced_vertices, 0u);
  EXPECT_TRUE(report.cgal.closed);
  EXPECT_EQ(report.cgal.reversed_faces, 0u);
  EXPECT_EQ(report.cgal.self_intersections, 0u);
  EXPECT_EQ(report.cgal.bounds_volume, true);
  EXPECT_EQ(report.cgal.outward, true);
  EXPECT_EQ(report.openmesh.rejected_faces, 0u);
  EXPECT_TRUE(report.libraries_agree) << report.disagreement;
}

// ---- full grids ----------------------------------------------------------------------------------

TEST(TerrainSolid, FullGridIsAClosedGenusZeroSolid) {
  const Heightmap heights = wavy(7, 5);
  const TerrainSolid solid = terrain_solid(heights);
  // 6 x 4 quads: 48 surface and 48 base triangles; the boundary has 2·(6 + 4) = 20 edges, two
  // wall triangles each; 35 surface and 35 base vertices.
  EXPECT_EQ(solid.kept_quads, 24u);
  EXPECT_EQ(solid.dropped_quads, 0u);
  EXPECT_EQ(solid.surface_triangles, 48u);
  EXPECT_EQ(solid.base_triangles, 48u);
  EXPECT_EQ(solid.skirt_triangles, 40u);
  EXPECT_EQ(solid.mesh.triangles.size(), 136u);
  EXPECT_EQ(solid.mesh.positions.size(), 70u);
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_EQ(report.openmesh.components, 1u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 2);
  EXPECT_EQ(report.openmesh.genus, 0.0);
  EXPECT_EQ(report.cgal.euler_characteristic, 2);
}

TEST(TerrainSolid, VolumeIsTheExactPrismVolume) {
  const Heightmap heights = wavy(9, 6);
  const TerrainSolid solid = terrain_solid(heights);
  const MeshReport report = check_mesh(solid.mesh);
  ASSERT_TRUE(report.cgal.volume.has_value());
  const double expected = prism_volume(heights, solid.base_y);
  const double bound = volume_bound(solid.mesh);
  EXPECT_NEAR(*report.cgal.volume, expected, bound);
  // The bound is tight enough to see one triangle's prism (area cx·cy/2 over at least the base
  // depth) go missing: the test could fail.
  EXPECT_LT(bound, 1e-3 * 0.5 * heights.cell_size_x * heights.cell_size_y * solid.base_depth);
  // The other diagonal would give a different volume on this non-planar terrain.
  double other_diagonal = 0.0;
  const double half_cell = 0.5 * heights.cell_size_x * heights.cell_size_y;
  for (int j = 0; j + 1 < heights.height; ++j) {
    for (int i = 0; i + 1 < heights.width; ++i) {
      const double h00 = heights.at(i, j), h10 = heights.at(i + 1, j), h01 = heights.at(i, j + 1),
                   h11 = heights.at(i + 1, j + 1);
      other_diagonal += half_cell * ((h00 + h01 + h10) / 3.0 - solid.base_y) +
                        half_cell * ((h10 + h01 + h11) / 3.0 - solid.base_y);
    }
  }
  EXPECT_GT(std::abs(other_diagonal - expected), 1e6 * bound);
}

TEST(TerrainSolid, CoordinatesFollowTheDocumentedFrame) {
  Heightmap heights = wavy(5, 4, 2.0, 3.0);
  const TerrainSolid solid = terrain_solid(heights, {.vertical_scale = 2.0});
  const auto [low, high] = valid_range(heights);
  // Automatic depth: max(0.2·(y_max - y_min), 0.02·max(4·2, 3·3)), y = 2·h.
  EXPECT_DOUBLE_EQ(solid.base_depth, std::max(0.2 * (2.0 * high - 2.0 * low), 0.02 * 9.0));
  EXPECT_DOUBLE_EQ(solid.base_y, 2.0 * low - solid.base_depth);
  // Vertex of sample (i, j): x = (i - 2)·2 (east), y = 2·h, z = (j - 1.5)·3 (south); base vertices follow.
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 5; ++i) {
      const auto& top = solid.mesh.positions[std::size_t(j * 5 + i)];
      EXPECT_DOUBLE_EQ(top[0], (i - 2.0) * 2.0);
      EXPECT_DOUBLE_EQ(top[1], 2.0 * heights.at(i, j));
      EXPECT_DOUBLE_EQ(top[2], (j - 1.5) * 3.0);
      const auto& bottom = solid.mesh.positions[std::size_t(20 + j * 5 + i)];
      EXPECT_EQ(bottom[0], top[0]);
      EXPECT_EQ(bottom[1], solid.base_y);
      EXPECT_EQ(bottom[2], top[2]);
    }
  }
  // The first surface triangle faces up (+y) and the first base triangle down.
  const auto normal_y = [&](std::size_t t) {
    const auto& tri = solid.mesh.triangles[t];
    const auto& a = solid.mesh.positions[tri[0]];
    const auto& b = solid.mesh.positions[tri[1]];
    const auto& c = solid.mesh.positions[tri[2]];
    return (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]);
  };
  EXPECT_GT(normal_y(0), 0.0);
  EXPECT_LT(normal_y(solid.surface_triangles), 0.0);

  const TerrainSolid deep = terrain_solid(heights, {.base_depth = 50.0});
  EXPECT_DOUBLE_EQ(deep.base_y, low - 50.0);
  EXPECT_NEAR(*check_mesh(deep.mesh).cgal.volume, prism_volume(heights, deep.base_y), volume_bound(deep.mesh));
}

TEST(TerrainSolid, FlatGridGetsABaseFromItsExtent) {
  Heightmap flat(3, 3, 5.0);
  flat.cell_size_x = flat.cell_size_y = 10.0;
  const TerrainSolid solid = terrain_solid(flat);
  EXPECT_DOUBLE_EQ(solid.base_depth, 0.02 * 20.0);
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_NEAR(*report.cgal.volume, 20.0 * 20.0 * 0.4, volume_bound(solid.mesh));  // a box
}

// ---- masks -----------------------------------------------------------------------------------------

TEST(TerrainSolid, OneNoDataSampleMakesAHoleOfGenusOne) {
  // Sample (4, 3) removes the four quads around it: a 2x2-quad hole with walls facing into it.
  const Heightmap heights = with_mask(wavy(9, 7), {{4, 3}});
  const TerrainSolid solid = terrain_solid(heights);
  EXPECT_EQ(solid.kept_quads, 8u * 6u - 4u);
  EXPECT_EQ(solid.dropped_quads, 0u);
  EXPECT_EQ(solid.skirt_triangles, 2u * (2u * (8u + 6u) + 8u));  // outer boundary and the hole's 8 edges
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_EQ(report.openmesh.components, 1u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 0);
  EXPECT_EQ(report.openmesh.genus, 1.0);
  EXPECT_NEAR(*report.cgal.volume, prism_volume(heights, solid.base_y), volume_bound(solid.mesh));
}

TEST(TerrainSolid, TwoHolesGiveGenusTwoAndACutGivesTwoSolids) {
  const Heightmap two_holes = with_mask(wavy(12, 7), {{3, 3}, {8, 3}});
  const MeshReport holes = check_mesh(terrain_solid(two_holes).mesh);
  expect_watertight(holes);
  EXPECT_EQ(holes.openmesh.components, 1u);
  EXPECT_EQ(holes.openmesh.genus, 2.0);

  // A full column of no data at x = 5 cuts the grid into two solids, each a sphere.
  std::vector<std::pair<int, int>> column;
  for (int j = 0; j < 7; ++j) column.push_back({5, j});
  const Heightmap cut = with_mask(wavy(12, 7), column);
  const TerrainSolid solid = terrain_solid(cut);
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_EQ(report.openmesh.components, 2u);
  EXPECT_EQ(report.openmesh.euler_characteristic, 4);
  EXPECT_EQ(report.openmesh.genus, 0.0);
  EXPECT_NEAR(*report.cgal.volume, prism_volume(cut, solid.base_y), volume_bound(solid.mesh));
}

TEST(TerrainSolid, QuadsMeetingOnlyAtACornerAreSeparated) {
  // No data at (5, 2) and (3, 4): quads (3, 2) and (4, 3) keep four valid corners each but meet only
  // at sample (4, 3), whose other two quads are gone. The later one, (4, 3), is dropped.
  const Heightmap heights = with_mask(wavy(9, 7), {{5, 2}, {3, 4}});
  ASSERT_TRUE(quad_kept(heights, 3, 2));
  ASSERT_TRUE(quad_kept(heights, 4, 3));
  ASSERT_FALSE(quad_kept(heights, 4, 2));
  ASSERT_FALSE(quad_kept(heights, 3, 3));
  const TerrainSolid solid = terrain_solid(heights);
  EXPECT_EQ(solid.dropped_quads, 1u);
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_EQ(report.cgal.non_manifold_vertices, 0u);
  // The dropped quad's two prisms are missing from the volume.
  const double half_cell = 0.5 * heights.cell_size_x * heights.cell_size_y;
  const double h00 = heights.at(4, 3), h10 = heights.at(5, 3), h01 = heights.at(4, 4), h11 = heights.at(5, 4);
  const double dropped = half_cell * ((h00 + h11 + h10) / 3.0 - solid.base_y) +
                         half_cell * ((h00 + h01 + h11) / 3.0 - solid.base_y);
  EXPECT_NEAR(*report.cgal.volume, prism_volume(heights, solid.base_y) - dropped, volume_bound(solid.mesh));
}

TEST(TerrainSolid, LuxembourgWithItsNoDataMaskIsWatertight) {
  const auto file = std::filesystem::path(GT_DATASET_DIR) / "real" / "elev.tif";
  if (!std::filesystem::exists(file)) GTEST_SKIP() << file << " is missing (datasets/fetch.sh fetches it)";
  const Heightmap heights = read_heightmap(file).heights;
  ASSERT_TRUE(heights.has_mask());
  ASSERT_LT(count_valid(heights), heights.size());
  const TerrainSolid solid = terrain_solid(heights);
  const MeshReport report = check_mesh(solid.mesh);
  expect_watertight(report);
  EXPECT_EQ(solid.dropped_quads, 0u);  // the outline has no diagonal pinches
  EXPECT_NEAR(*report.cgal.volume, prism_volume(heights, solid.base_y), volume_bound(solid.mesh));
  EXPECT_EQ(report.openmesh.genus, 0.0) << describe(report);
}

// ---- refusals --------------------------------------------------------------------------------------

TEST(TerrainSolid, RefusesGridsWithNothingToMesh) {
  Heightmap all_masked = wavy(4, 4);
  all_masked.valid.assign(all_masked.size(), 0);
  EXPECT_THAT(refusal([&] { terrain_solid(all_masked); }), HasSubstr("no 2x2 block of valid samples"));
  EXPECT_THAT(refusal([&] { terrain_solid(wavy(1, 8)); }), HasSubstr("no 2x2 block"));
  EXPECT_THAT(refusal([&] { terrain_solid(Heightmap()); }), HasSubstr("no 2x2 block"));
  // Valid samples only on a checkerboard: no quad has four.
  Heightmap checker = wavy(6, 6);
  checker.valid.assign(checker.size(), 0);
  for (int j = 0; j < 6; ++j) {
    for (int i = (j % 2); i < 6; i += 2) checker.valid[checker.index(i, j)] = 1;
  }
  EXPECT_THAT(refusal([&] { terrain_solid(checker); }), HasSubstr("no 2x2 block"));
}

TEST(TerrainSolid, RefusesNonFiniteHeightsAndBadOptions) {
  Heightmap nan = wavy(4, 4);
  nan.at(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(refusal([&] { terrain_solid(nan); }), "(accepted)");
  Heightmap infinite = wavy(4, 4);
  infinite.at(0, 3) = std::numeric_limits<double>::infinity();
  EXPECT_NE(refusal([&] { terrain_solid(infinite); }), "(accepted)");
  // A NaN under the mask is never read: accepted.
  Heightmap masked_nan = with_mask(nan, {{2, 1}});
  EXPECT_EQ(refusal([&] { terrain_solid(masked_nan); }), "(accepted)");

  Heightmap zero_cell = wavy(4, 4);
  zero_cell.cell_size_y = 0.0;
  EXPECT_THAT(refusal([&] { terrain_solid(zero_cell); }), HasSubstr("cell sizes"));
  EXPECT_THAT(refusal([&] { terrain_solid(wavy(4, 4), {.vertical_scale = 0.0}); }), HasSubstr("vertical scale"));
  EXPECT_THAT(refusal([&] { terrain_solid(wavy(4, 4), {.base_depth = -1.0}); }), HasSubstr("base depth"));
  EXPECT_THAT(refusal([&] { terrain_solid(wavy(4, 4), {.base_depth = std::nan("")}); }), HasSubstr("base depth"));
  // A depth that vanishes against large heights (1e-20 below 100) would leave flat walls.
  EXPECT_THAT(refusal([&] { terrain_solid(wavy(4, 4), {.base_depth = 1e-20}); }), HasSubstr("vanishes"));
}

}  // namespace
}  // namespace gt
