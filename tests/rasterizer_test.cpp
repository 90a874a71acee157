// The reference rasterizer (reference/render/rasterizer.hpp) against hand-counted coverage and
// analytic values: shared edges drawn once (diagonal, vertical, horizontal; both tie rules), pixel
// centres on edges, the depth test, perspective-correct interpolation and near-plane clipping; and
// seed 000's heightmap from a mesh (reference/render/heightmap_from_mesh.hpp) against the plane
// equation, overlapping surfaces and uncovered texels. CPU only.
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.hpp"
#include "reference/render/heightmap_from_mesh.hpp"
#include "reference/render/rasterizer.hpp"

namespace {

using gt::reference::RasterInput;
using gt::reference::RasterSettings;
using gt::reference::RasterTarget;
using gt::reference::TieRule;

constexpr int side = 8;

// Clip coordinates (w = 1) of window position (x, y) on a side x side target, depth z in NDC.
std::array<double, 4> from_window(double x, double y, double z = 0.0) {
  return {2.0 * x / side - 1.0, 2.0 * y / side - 1.0, z, 1.0};
}

const gt::reference::FragmentShader write_attribute = [](std::span<const double> attributes, std::span<double> colour) {
  colour[0] = attributes[0];
};

RasterInput triangle(std::array<double, 2> a, std::array<double, 2> b, std::array<double, 2> c, double z = 0.0,
                     double value = 1.0) {
  RasterInput input;
  input.clip_positions = {from_window(a[0], a[1], z), from_window(b[0], b[1], z), from_window(c[0], c[1], z)};
  input.attribute_count = 1;
  input.attributes = {value, value, value};
  input.triangles = {{0, 1, 2}};
  return input;
}

// 1 where the triangle covers the pixel, per pixel, row 0 at the bottom.
std::vector<int> coverage(const RasterInput& input, TieRule rule = TieRule::lower_left) {
  RasterTarget target(side, side, 1);
  gt::reference::rasterize(input, write_attribute, target, {.subpixel_bits = 8, .tie_rule = rule});
  std::vector<int> covered(target.depth.size());
  for (std::size_t pixel = 0; pixel < covered.size(); ++pixel) covered[pixel] = target.depth[pixel] < 1.0 ? 1 : 0;
  return covered;
}

std::vector<int> sum(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> total(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) total[k] = a[k] + b[k];
  return total;
}

int at(const std::vector<int>& pixels, int x, int y) { return pixels[std::size_t(y) * side + std::size_t(x)]; }

TEST(Rasterizer, SquareSplitAlongItsDiagonalCoversEachPixelOnce) {
  // Corners on pixel centres: under lower_left the left and bottom sides' pixels belong to the
  // square, the right and top ones do not, so pixels [2, 5] x [2, 5] are covered, each once.
  const auto total = sum(coverage(triangle({2.5, 2.5}, {6.5, 2.5}, {6.5, 6.5})),
                         coverage(triangle({2.5, 2.5}, {6.5, 6.5}, {2.5, 6.5})));
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const bool inside = x >= 2 && x <= 5 && y >= 2 && y <= 5;
      EXPECT_EQ(at(total, x, y), inside ? 1 : 0) << "pixel " << x << ", " << y;
    }
  }
}

TEST(Rasterizer, VerticalSharedEdgeBelongsToTheTriangleOnItsRight) {
  // Diamond split at x = 4.5, an edge through the centres of column 4.
  const auto left = coverage(triangle({4.5, 1.5}, {4.5, 7.5}, {1.5, 4.5}));
  const auto right = coverage(triangle({4.5, 1.5}, {7.5, 4.5}, {4.5, 7.5}));
  const auto total = sum(left, right);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) EXPECT_LE(at(total, x, y), 1) << "pixel " << x << ", " << y;
  }
  for (int y = 2; y <= 6; ++y) {
    EXPECT_EQ(at(right, 4, y), 1) << "row " << y;
    EXPECT_EQ(at(left, 4, y), 0) << "row " << y;
  }
}

TEST(Rasterizer, HorizontalSharedEdgeFollowsTheTieRule) {
  // Diamond split at y = 4.5, an edge through the centres of row 4.
  for (const TieRule rule : {TieRule::lower_left, TieRule::upper_left}) {
    const auto below = coverage(triangle({1.5, 4.5}, {7.5, 4.5}, {4.5, 1.5}), rule);
    const auto above = coverage(triangle({1.5, 4.5}, {4.5, 7.5}, {7.5, 4.5}), rule);
    const auto& owner = rule == TieRule::lower_left ? above : below;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) EXPECT_LE(at(sum(below, above), x, y), 1) << "pixel " << x << ", " << y;
    }
    for (int x = 2; x <= 6; ++x) EXPECT_EQ(at(owner, x, 4), 1) << "column " << x;
  }
}

TEST(Rasterizer, PixelCentresOnEdgesFollowTheRule) {
  // Left edge x = 1.5 and bottom edge y = 1.5 are owned; the hypotenuse x + y = 7 (a right edge)
  // is not: covered are i, j >= 1 with i + j < 6, ten pixels. Both windings give the same.
  for (const auto& input : {triangle({1.5, 1.5}, {5.5, 1.5}, {1.5, 5.5}), triangle({1.5, 1.5}, {1.5, 5.5}, {5.5, 1.5})}) {
    const auto covered = coverage(input);
    int count = 0;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        EXPECT_EQ(at(covered, x, y), (x >= 1 && y >= 1 && x + y < 6) ? 1 : 0) << "pixel " << x << ", " << y;
        count += at(covered, x, y);
      }
    }
    EXPECT_EQ(count, 10);
  }
}

TEST(Rasterizer, DepthTestKeepsTheNearerTriangleInEitherOrder) {
  RasterInput near = triangle({0.0, 0.0}, {8.0, 0.0}, {0.0, 8.0}, -0.3, 2.0);
  RasterInput far = triangle({0.0, 0.0}, {8.0, 0.0}, {0.0, 8.0}, 0.2, 1.0);
  for (const bool near_first : {true, false}) {
    RasterInput both = near_first ? near : far;
    const RasterInput& second = near_first ? far : near;
    both.clip_positions.insert(both.clip_positions.end(), second.clip_positions.begin(), second.clip_positions.end());
    both.attributes.insert(both.attributes.end(), second.attributes.begin(), second.attributes.end());
    both.triangles.push_back({3, 4, 5});
    RasterTarget target(side, side, 1);
    gt::reference::rasterize(both, write_attribute, target);
    EXPECT_EQ(target.colour_at(1, 1, 0), 2.0);
    EXPECT_DOUBLE_EQ(target.depth_at(1, 1), (-0.3 + 1.0) / 2.0);
  }
}

// A perspective camera: 90° field of view, aspect 1, near 1, far 10, looking along -z.
constexpr double near_plane = 1.0, far_plane = 10.0;

std::array<double, 4> perspective(double x, double y, double z) {
  const double a = -(far_plane + near_plane) / (far_plane - near_plane);
  const double b = -2.0 * far_plane * near_plane / (far_plane - near_plane);
  return {x, y, a * z + b, -z};
}

// NDC of the centre of pixel (i, j) on a `pixels`-sided target.
double ndc(int i, int pixels) { return 2.0 * (i + 0.5) / pixels - 1.0; }

TEST(Rasterizer, PerspectiveCorrectAttributeOnASlantedQuad) {
  // The quad x, y ∈ [-1, 1] on the plane z = -2 - x, attribute u = x. The ray through NDC
  // (xn, yn) is t·(xn, yn, -1), meeting the plane at t = 2/(1 - xn): u = 2xn/(1 - xn), and the
  // window depth is that of z = -t.
  const int pixels = 32;
  RasterInput quad;
  quad.attribute_count = 1;
  for (const auto& [x, y] : std::array<std::array<double, 2>, 4>{{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}) {
    quad.clip_positions.push_back(perspective(x, y, -2.0 - x));
    quad.attributes.push_back(x);
  }
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  RasterTarget target(pixels, pixels, 1);
  gt::reference::rasterize(quad, write_attribute, target);
  int covered = 0;
  for (int j = 0; j < pixels; ++j) {
    for (int i = 0; i < pixels; ++i) {
      if (!(target.depth_at(i, j) < 1.0)) continue;
      ++covered;
      const double xn = ndc(i, pixels);
      const double t = 2.0 / (1.0 - xn);
      const auto clip = perspective(0.0, 0.0, -t);
      EXPECT_NEAR(target.colour_at(i, j, 0), 2.0 * xn / (1.0 - xn), 1e-12) << "pixel " << i << ", " << j;
      EXPECT_NEAR(target.depth_at(i, j), 0.5 * (clip[2] / clip[3] + 1.0), 1e-12) << "pixel " << i << ", " << j;
    }
  }
  EXPECT_GT(covered, pixels * pixels / 4);
}

TEST(Rasterizer, NearPlaneClipsAFloorReachingBehindTheCamera) {
  // The floor y = -1 from behind the camera (z = +1) to z = -9, attribute its z. The ray through
  // (xn, yn), yn < 0, meets it at t = -1/yn: z = 1/yn. Only rows below the horizon are drawn.
  const int pixels = 32;
  RasterInput floor;
  floor.attribute_count = 1;
  for (const auto& [x, z] : std::array<std::array<double, 2>, 3>{{{-5, 1}, {5, 1}, {0, -9}}}) {
    floor.clip_positions.push_back(perspective(x, -1.0, z));
    floor.attributes.push_back(z);
  }
  floor.triangles = {{0, 1, 2}};
  RasterTarget target(pixels, pixels, 1);
  gt::reference::rasterize(floor, write_attribute, target);
  int covered = 0;
  for (int j = 0; j < pixels; ++j) {
    for (int i = 0; i < pixels; ++i) {
      if (!(target.depth_at(i, j) < 1.0)) continue;
      ++covered;
      const double yn = ndc(j, pixels);
      ASSERT_LT(yn, 0.0) << "pixel " << i << ", " << j << " above the horizon";
      EXPECT_NEAR(target.colour_at(i, j, 0), 1.0 / yn, 1e-12) << "pixel " << i << ", " << j;
    }
  }
  EXPECT_GT(covered, pixels);
}

gt::Mesh mesh_of(std::vector<std::array<double, 3>> positions, std::vector<std::array<std::uint32_t, 3>> triangles) {
  gt::Mesh mesh;
  mesh.positions = std::move(positions);
  mesh.triangles = std::move(triangles);
  return mesh;
}

TEST(HeightmapFromMesh, TiltedTriangleIsItsPlaneAtTexelCentresAndZeroElsewhere) {
  // z = x/4 + y over the box [0, 4] x [0, 2] x [0, 2]: height 1 - z' = z/2. On a 16 x 16 grid the
  // texel (x, row) has its centre at (x + 0.5)/4, 2 - (row + 0.5)/8; the hypotenuse x/4 + y/2 = 1
  // (a right edge) passes through the centres with x = row, so texels with x < row are covered.
  const auto result = gt::reference::heightmap_from_mesh(mesh_of({{0, 0, 0}, {4, 0, 1}, {0, 2, 2}}, {{0, 1, 2}}), 16, 16);
  EXPECT_DOUBLE_EQ(result.d_xy, 0.5);  // Δy/Δx
  EXPECT_DOUBLE_EQ(result.d_z, 1.0);   // 2Δz/Δx
  EXPECT_DOUBLE_EQ(result.heights.cell_size_x, 0.25);
  EXPECT_DOUBLE_EQ(result.heights.cell_size_y, 0.125);
  for (int row = 0; row < 16; ++row) {
    for (int x = 0; x < 16; ++x) {
      const bool inside = x < row;
      const double wx = (x + 0.5) / 4.0, wy = 2.0 - (row + 0.5) / 8.0;
      EXPECT_EQ(result.covered.at(x, row), inside ? 1 : 0) << "texel " << x << ", " << row;
      EXPECT_NEAR(result.heights.at(x, row), inside ? (wx / 4.0 + wy) / 2.0 : 0.0, 1e-14) << "texel " << x << ", " << row;
    }
  }
}

TEST(HeightmapFromMesh, OverlappingSurfacesKeepTheHighestInEitherOrder) {
  // A square at z = 1 over the whole box, a smaller one at z = 2 above its left half, and an
  // unused vertex at z = 0 that sets the box's bottom: heights 0.5 and 1.
  const std::vector<std::array<double, 3>> positions = {{0, 0, 1}, {4, 0, 1}, {4, 4, 1}, {0, 4, 1}, {0, 0, 2},
                                                        {2, 0, 2}, {2, 4, 2}, {0, 4, 2}, {1, 1, 0}};
  const std::vector<std::array<std::uint32_t, 3>> low = {{0, 1, 2}, {0, 2, 3}}, high = {{4, 5, 6}, {4, 6, 7}};
  for (const bool high_first : {true, false}) {
    auto triangles = high_first ? high : low;
    const auto& second = high_first ? low : high;
    triangles.insert(triangles.end(), second.begin(), second.end());
    const auto result = gt::reference::heightmap_from_mesh(mesh_of(positions, triangles), 8, 8);
    for (int row = 0; row < 8; ++row) {
      for (int x = 0; x < 8; ++x) {
        EXPECT_EQ(result.covered.at(x, row), 1);
        EXPECT_DOUBLE_EQ(result.heights.at(x, row), x < 4 ? 1.0 : 0.5) << "texel " << x << ", " << row;
      }
    }
  }
}

TEST(HeightmapFromMesh, RowZeroIsTheLargestY) {
  // A triangle in the upper-left corner of the box (large y, small x), seen from above.
  const auto result =
      gt::reference::heightmap_from_mesh(mesh_of({{0, 4, 1}, {2, 4, 1}, {0, 2, 1}, {4, 0, 0}}, {{0, 1, 2}}), 8, 8);
  EXPECT_EQ(result.covered.at(0, 0), 1);
  EXPECT_EQ(result.covered.at(0, 7), 0);
  EXPECT_EQ(result.covered.at(7, 0), 0);
}

TEST(HeightmapFromMesh, RefusesMeshesWithNothingToSee) {
  EXPECT_THROW(gt::reference::heightmap_from_mesh(mesh_of({{0, 0, 0}}, {}), 4, 4), gt::InputError);
  EXPECT_THROW(gt::reference::heightmap_from_mesh(mesh_of({{0, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2}}), 4, 4),
               gt::InputError);
}

}  // namespace
