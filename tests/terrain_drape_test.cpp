// The terrain look's colour drape (reference/render/phong.hpp "Colour drape", GL twin in
// gpu/shaders/render/phong_look.glsl): the bilinear lookup gives a texel exactly at its centre, the
// mean of two neighbours halfway between them and the edge texel beyond the edges; the drape
// replaces the ramp but not the rock; a flat ground seen from above shows the texture lit by the
// Phong terms at the expected pixels; the GL twin matches the reference on a draped hill within
// issue 6's acceptance; and refusals of malformed drapes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include "compare/algorithms/render_phong.hpp"
#include "compare/checks/image.hpp"
#include "core/errors.hpp"
#include "gpu/render/phong.hpp"
#include "reference/render/phong.hpp"
#include "reference/render/terrain_solid.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/phong_twins.hpp"

namespace {

using gt::reference::TerrainDrape;
using gt::reference::Vec3;

// A 4×2 drape (powers of two: the texel centres (i + 0.5)/W and the midpoints i/W map to x = i
// and x = i - 0.5 without rounding) with every channel different, over x, z in [-2, 2].
TerrainDrape small_drape() {
  TerrainDrape drape{.width = 4, .height = 2, .rgb = {}, .x_west = -2.0, .x_east = 2.0, .z_north = -2.0, .z_south = 2.0};
  for (int texel = 0; texel < 8; ++texel) {
    drape.rgb.push_back(std::uint8_t(30 * texel));
    drape.rgb.push_back(std::uint8_t(250 - 25 * texel));
    drape.rgb.push_back(std::uint8_t(texel % 2 == 0 ? 200 : 40));
  }
  return drape;
}

Vec3 texel(const TerrainDrape& drape, int column, int row) {
  const std::size_t first = 3 * std::size_t(row * drape.width + column);
  return {drape.rgb[first] / 255.0, drape.rgb[first + 1] / 255.0, drape.rgb[first + 2] / 255.0};
}

TEST(TerrainDrape, TexelCentresGiveTheTexelExactly) {
  const TerrainDrape drape = small_drape();
  for (int row = 0; row < drape.height; ++row) {
    for (int column = 0; column < drape.width; ++column) {
      EXPECT_EQ(gt::reference::drape_colour(drape, (column + 0.5) / 4.0, (row + 0.5) / 2.0), texel(drape, column, row))
          << "texel " << column << ", " << row;
    }
  }
}

TEST(TerrainDrape, HalfwayBetweenTexelsGivesTheirMean) {
  // a + 0.5·(b - a) against (a + b)/2: equal up to one rounding of a channel in [0, 1] (<= 2^-53).
  const TerrainDrape drape = small_drape();
  for (int column = 0; column + 1 < drape.width; ++column) {
    const Vec3 along_u = gt::reference::drape_colour(drape, (column + 1.0) / 4.0, 0.25);
    const Vec3 corner = gt::reference::drape_colour(drape, (column + 1.0) / 4.0, 0.5);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(along_u[c], 0.5 * (texel(drape, column, 0)[c] + texel(drape, column + 1, 0)[c]), 1e-15);
      const double four = texel(drape, column, 0)[c] + texel(drape, column + 1, 0)[c] + texel(drape, column, 1)[c] +
                          texel(drape, column + 1, 1)[c];
      EXPECT_NEAR(corner[c], 0.25 * four, 1e-15) << "between four texels: their mean";
    }
  }
  const Vec3 along_v = gt::reference::drape_colour(drape, 0.125, 0.5);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(along_v[c], 0.5 * (texel(drape, 0, 0)[c] + texel(drape, 0, 1)[c]), 1e-15);
}

TEST(TerrainDrape, ClampsToTheEdgeTexels) {
  // Within half a texel of an edge and beyond it, the edge texel alone (both neighbours clamp to it).
  const TerrainDrape drape = small_drape();
  for (const double u : {-3.0, 0.0, 0.05, 0.125}) EXPECT_EQ(gt::reference::drape_colour(drape, u, 0.25), texel(drape, 0, 0));
  for (const double u : {0.875, 0.95, 1.0, 7.0}) EXPECT_EQ(gt::reference::drape_colour(drape, u, 0.25), texel(drape, 3, 0));
  for (const double v : {-1.0, 0.0, 0.2}) EXPECT_EQ(gt::reference::drape_colour(drape, 0.625, v), texel(drape, 2, 0));
  for (const double v : {0.8, 1.0, 2.0}) EXPECT_EQ(gt::reference::drape_colour(drape, 0.625, v), texel(drape, 2, 1));
}

TEST(TerrainDrape, ReplacesTheRampButNotTheRock) {
  // Placement: x = -2 + 4u (east), z = -2 + 4v (south); texel (2, 1)'s centre is at x = 0.5, z = 1.
  gt::reference::TerrainLook look;
  look.drape = small_drape();
  const Vec3 flat = {0.0, 1.0, 0.0};
  for (const double height : {-5.0, 0.3, 40.0}) {
    EXPECT_EQ(gt::reference::terrain_albedo(look, {0.5, height, 1.0}, flat), texel(*look.drape, 2, 1))
        << "the drape ignores the height";
  }
  const double a = 60.0 * std::numbers::pi / 180.0;  // beyond rock_full = 45°
  EXPECT_EQ(gt::reference::terrain_albedo(look, {0.5, 0.3, 1.0}, {std::sin(a), std::cos(a), 0.0}), look.rock);
}

TEST(TerrainDrape, MalformedDrapesAreRefused) {
  gt::Mesh quad;
  quad.positions = {{-2.0, 0.0, -2.0}, {2.0, 0.0, -2.0}, {2.0, 0.0, 2.0}, {-2.0, 0.0, 2.0}};
  quad.triangles = {{0, 2, 1}, {0, 3, 2}};
  auto scene = gt::reference::phong_scene(quad, gt::reference::orbit_camera(quad, 0.0, 60.0, 40.0, 16, 16));
  scene.look = gt::reference::Look::terrain;  // the default range [0, 1]: the quad is flat
  const auto refused = [&](auto change) {
    auto bad = scene;
    bad.terrain.drape = small_drape();
    change(*bad.terrain.drape);
    EXPECT_THROW(gt::reference::render_phong(bad), gt::InputError);
  };
  refused([](TerrainDrape& d) { d.rgb.pop_back(); });
  refused([](TerrainDrape& d) { d.width = 0; });
  refused([](TerrainDrape& d) { d.x_east = d.x_west; });
  refused([](TerrainDrape& d) { d.z_south = -3.0; });
}

TEST(TerrainDrape, FlatGroundSeenFromAboveShowsTheLitTexture) {
  // The quad y = 0, |x|, |z| <= 2 under the drape, seen straight down from (0, 5, 0) with north (-z)
  // at the top of the picture. At a pixel centre (c + 0.5, r + 0.5) the ray meets the ground at
  //   x = 5·t·a·n_x, z = -5·t·n_y, n_x = 2(c + 0.5)/W - 1, n_y = 1 - 2(r + 0.5)/H, t = tan(fov/2)
  // and the expected colour is phong_lit there with n = +y and the drape's colour as the albedo.
  // Error model: the rasterizer snaps vertices to 1/256 pixel, which moves the interpolated p by
  // about 1/256 of a pixel's footprint (a pixel covers ~0.12 world units here: ~0.0005); the drape
  // changes by less than 1 per texel width (1 unit), the lighting far slower, so the colour moves
  // by < 0.001 and the rounding to 8 bits adds 0.5/255: at most one byte apart.
  gt::Mesh quad;
  quad.positions = {{-2.0, 0.0, -2.0}, {2.0, 0.0, -2.0}, {2.0, 0.0, 2.0}, {-2.0, 0.0, 2.0}};
  quad.triangles = {{0, 2, 1}, {0, 3, 2}};  // facing +y
  const gt::reference::Camera camera{.eye = {0.0, 5.0, 0.0}, .target = {0.0, 0.0, 0.0}, .up = {0.0, 0.0, -1.0},
                                     .fov_y_deg = 60.0, .near = 1.0, .far = 10.0, .width = 64, .height = 48};
  auto scene = gt::reference::phong_scene(quad, camera);
  scene.look = gt::reference::Look::terrain;  // the default height range: the drape ignores it
  scene.terrain.drape = small_drape();
  scene.light_power = 12.5;  // E <= 0.5: nothing clamps
  const auto image = gt::reference::render_phong(scene);
  const double t = std::tan(30.0 * std::numbers::pi / 180.0), aspect = 64.0 / 48.0;
  int checked = 0;
  for (int row = 4; row < 48; row += 5) {
    for (int column = 4; column < 64; column += 5) {
      const double nx = 2.0 * (column + 0.5) / 64.0 - 1.0, ny = 1.0 - 2.0 * (row + 0.5) / 48.0;
      const Vec3 p = {5.0 * t * aspect * nx, 0.0, -5.0 * t * ny};
      if (std::abs(p[0]) > 1.95 || std::abs(p[2]) > 1.95) continue;  // off the quad or at its edge
      const Vec3 albedo = gt::reference::drape_colour(*scene.terrain.drape, (p[0] + 2.0) / 4.0, (p[2] + 2.0) / 4.0);
      const Vec3 expected = gt::reference::phong_lit(p, {0.0, 1.0, 0.0}, camera.eye, albedo, scene.light_power);
      for (int c = 0; c < 3; ++c) {
        const int byte = image.rgb[3 * std::size_t(row * 64 + column) + std::size_t(c)];
        EXPECT_NEAR(byte, 255.0 * expected[c], 1.0) << "pixel " << column << ", " << row << ", channel " << c;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 40) << "enough pixels on the quad";
  // North-west texel (0, 0) at the top left, south-east texel (3, 1) at the bottom right: the
  // picture is neither flipped nor mirrored (their red channels are 0 and 210).
  const auto red_at = [&](double x, double z) {
    const int column = int(std::floor((x / (5.0 * t * aspect) + 1.0) * 32.0));
    const int row = int(std::floor((1.0 + z / (5.0 * t)) * 24.0));
    return int(image.rgb[3 * std::size_t(row * 64 + column)]);
  };
  EXPECT_LT(red_at(-1.8, -1.8), 20);
  EXPECT_GT(red_at(1.8, 1.8), 60);
}

class TerrainDrapeGpu : public gt::testing::GlTest {};


// A 64×48 drape of smooth colour bands with a sharper diagonal stripe, so that both slow and fast
// texel changes are seen.
TerrainDrape banded_drape(double x_west, double x_east, double z_north, double z_south) {
  TerrainDrape drape{.width = 64, .height = 48, .rgb = {}, .x_west = x_west, .x_east = x_east, .z_north = z_north,
                     .z_south = z_south};
  for (int row = 0; row < drape.height; ++row) {
    for (int column = 0; column < drape.width; ++column) {
      const bool stripe = (column + row) % 16 < 3;
      drape.rgb.push_back(std::uint8_t(stripe ? 240 : 4 * column));
      drape.rgb.push_back(std::uint8_t(stripe ? 230 : 60 + 4 * row));
      drape.rgb.push_back(std::uint8_t(stripe ? 40 : 255 - 3 * column));
    }
  }
  return drape;
}

TEST_F(TerrainDrapeGpu, DrapedHillMatchesTheReference) {
  // Error model as for the undraped terrain look (tests/phong_test.cpp): the GPU's float u, v and
  // blend are within ~1e-5 of the reference's; a texel step of at most 240/255 across a texel
  // (~1/64 of the extent, several pixels here) turns that into far less than one 8-bit step, so
  // channels differ by at most one step except where another triangle is seen (silhouettes).
  gt::Heightmap heights(33, 25, 0.0);
  for (int j = 0; j < heights.height; ++j) {
    for (int i = 0; i < heights.width; ++i) {
      const double x = i - 16.0, z = j - 12.0;
      heights.at(i, j) = 10.0 * std::exp(-(x * x + z * z) / 50.0) + 0.1 * z;
    }
  }
  const gt::reference::TerrainSolid solid = gt::reference::terrain_solid(heights);
  auto scene = gt::reference::phong_scene(solid.mesh, gt::reference::orbit_camera(solid.mesh, 35.0, 30.0, 37.0, 160, 120),
                                          gt::reference::Look::terrain);
  scene.terrain.drape = banded_drape(-16.0, 16.0, -12.0, 12.0);
  const auto twins = gt::testing::render_twins(scene);
  gt::testing::expect_twins_agree(twins);
  const auto& cpu = twins.cpu;
  // And the drape shows: the undraped look gives a different picture.
  auto undraped = scene;
  undraped.terrain.drape.reset();
  EXPECT_NE(gt::reference::render_phong(undraped).rgb, cpu.rgb);
}

}  // namespace
