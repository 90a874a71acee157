// Seed 004's cave look (reference/render/cave_look.hpp; GPU twin gpu/shaders/render/phong_look.glsl
// through gpu/render/phong.hpp): the colour strip and its lookup, the solid texture's
// height-dependent frequency (the fix of the seed's 2 + y/100), the moss tint, the bump's analytic
// gradient against finite differences, the cave scene's camera checks, and the GL twin against the
// reference on a camera inside the seed's cave.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include "compare/algorithms/render_phong.hpp"
#include "compare/checks/image.hpp"
#include "core/errors.hpp"
#include "core/noise/perlin_texture_table.hpp"
#include "gpu/render/phong.hpp"
#include "reference/cave/density.hpp"
#include "reference/noise/perlin_texture.hpp"
#include "reference/render/cave_look.hpp"
#include "reference/render/phong.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/phong_twins.hpp"

namespace {

using gt::reference::CaveLook;
using gt::reference::Vec3;

// The Gustavson texture noise the look's colour uses, at p·frequency, as the reference evaluates it.
double texture_noise(const Vec3& p, double frequency) {
  static const auto rgba = gt::perlin_texture_rgba(gt::perlin_permutation());
  return gt::reference::perlin3_texture<double>(rgba, p[0] * frequency, p[1] * frequency, p[2] * frequency);
}

TEST(ColourStrip, SeedStripHas256EightBitEntriesInsideTheUnitCube) {
  const auto strip = gt::reference::seed_colour_strip();
  ASSERT_EQ(strip.size(), 256u);
  for (const auto& entry : strip) {
    for (const double channel : entry) {
      EXPECT_GE(channel, 0.0);
      EXPECT_LE(channel, 1.0);
      EXPECT_EQ(255.0 * channel, std::round(255.0 * channel)) << "an 8-bit value k/255";
    }
  }
  // Entry 0 sits 1/512 past the first stop (0.20, 0.16, 0.13): within one 8-bit step of it.
  EXPECT_NEAR(strip[0][0], 0.20, 1.0 / 255.0);
  EXPECT_NEAR(strip[255][2], 0.76, 1.0 / 255.0);
}

TEST(ColourStrip, LookupAtEntryCentresGivesTheEntriesExactly) {
  // s = (i + 0.5)/256 gives x = 256·s - 0.5 = i exactly (powers of two), so f = 0.
  const auto strip = gt::reference::seed_colour_strip();
  for (int i = 0; i < 256; ++i) {
    const Vec3 colour = gt::reference::strip_colour(strip, (i + 0.5) / 256.0);
    EXPECT_EQ(colour, strip[std::size_t(i)]) << "entry " << i;
  }
}

TEST(ColourStrip, LookupBlendsLinearlyAndClampsToTheEdges) {
  const auto strip = gt::reference::seed_colour_strip();
  // Halfway between the centres of entries i and i + 1: their mean (one rounding of a + 0.5·(b - a)).
  for (int i = 0; i < 255; ++i) {
    const Vec3 colour = gt::reference::strip_colour(strip, (i + 1.0) / 256.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(colour[c], 0.5 * (strip[std::size_t(i)][c] + strip[std::size_t(i) + 1][c]), 1e-16);
    }
  }
  // GL_CLAMP_TO_EDGE: below the first centre and above the last, the end entries.
  EXPECT_EQ(gt::reference::strip_colour(strip, 0.0), strip.front());
  EXPECT_EQ(gt::reference::strip_colour(strip, -3.0), strip.front());
  EXPECT_EQ(gt::reference::strip_colour(strip, 1.0), strip.back());
  EXPECT_EQ(gt::reference::strip_colour(strip, 7.0), strip.back());
}

TEST(CaveShade, LatticePointsOfTheTextureGiveTheStripMiddle) {
  // With one frequency (rate 0), p·f0 on the noise lattice: the noise is exactly 0 (every corner
  // term and fade vanish), shade 0.5, colour halfway between entries 127 and 128.
  CaveLook look;
  look.colour_octaves_per_unit = 0.0;
  const Vec3 p = {0.5, 1.5, -2.0};  // ·2 = (1, 3, -4)
  EXPECT_EQ(gt::reference::cave_shade(look, p), 0.5);
  const Vec3 colour = gt::reference::cave_albedo(look, p, {0.0, -1.0, 0.0});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(colour[c], 0.5 * (look.colour_strip[127][c] + look.colour_strip[128][c]), 1e-16);
}

TEST(CaveShade, OneFrequencyIsTheSeedsShadeFormula) {
  // rate 0: shade = 0.5 + 0.5·noise(p·f0) exactly (t = 0: (1·N_0 + 0·N_1)/sqrt(1) = N_0).
  CaveLook look;
  look.colour_octaves_per_unit = 0.0;
  for (const Vec3& p : {Vec3{0.13, -2.71, 5.9}, Vec3{-11.3, 4.44, 0.07}, Vec3{30.01, -17.5, -8.25}}) {
    EXPECT_EQ(gt::reference::cave_shade(look, p), 0.5 + 0.5 * texture_noise(p, 2.0));
  }
}

TEST(CaveShade, TextureIsFinerLowerDownAndNeverLosesItsFrequency) {
  // The seed's scaleFactor = 2 + y/100 is coarser lower down (against the thesis's intent), 0 at
  // y = -200 and negative below. The fix: f(y) = f0·2^((y0 - y)·rate). With rate = 1/128 (exact),
  // y = -128 lies exactly on the next octave (t = 0): the noise at 2·f0; y = 128 at f0/2; y = -384
  // at 8·f0, where the seed's frequency would be -1.84.
  CaveLook look;
  look.colour_octaves_per_unit = 1.0 / 128.0;
  const double x = 0.37, z = -1.91;
  EXPECT_EQ(gt::reference::cave_shade(look, {x, -128.0, z}), 0.5 + 0.5 * texture_noise({x, -128.0, z}, 4.0));
  EXPECT_EQ(gt::reference::cave_shade(look, {x, 128.0, z}), 0.5 + 0.5 * texture_noise({x, 128.0, z}, 1.0));
  EXPECT_EQ(gt::reference::cave_shade(look, {x, -384.0, z}), 0.5 + 0.5 * texture_noise({x, -384.0, z}, 16.0));
  // Between octaves: the normalised cross-fade, here t = 0.25 at y = -32.
  const Vec3 p = {x, -32.0, z};
  const double t = 0.25, expected = ((1 - t) * texture_noise(p, 2.0) + t * texture_noise(p, 4.0)) /
                                    std::sqrt((1 - t) * (1 - t) + t * t);
  EXPECT_NEAR(gt::reference::cave_shade(look, p), 0.5 + 0.5 * expected, 1e-15);
}

TEST(CaveShade, FrequencyIsClampedToTheOctaveLimit) {
  // y is unbounded in an endless cave: L is clamped to ±colour_octave_limit (4: between f0/16 and
  // 16·f0), so far below y0 the texture is the noise at 2·16 = 32 cells per unit, far above at 1/8.
  const CaveLook look;  // rate 1/(200 ln 2): the limit is reached 555 units from y0
  for (const double y : {-10000.0, -600.0}) {
    const Vec3 p = {0.37, y, -1.91};
    EXPECT_EQ(gt::reference::cave_shade(look, p), 0.5 + 0.5 * texture_noise(p, 32.0)) << "y = " << y;
  }
  for (const double y : {10000.0, 600.0}) {
    const Vec3 p = {0.37, y, -1.91};
    EXPECT_EQ(gt::reference::cave_shade(look, p), 0.5 + 0.5 * texture_noise(p, 0.125)) << "y = " << y;
  }
}

TEST(CaveShade, ContinuousAcrossOctaveBoundaries) {
  // At an octave boundary the cross-fade hands over from (N_k at t -> 1) to (N_{k+1} at t = 0): the
  // same value. Error model: |∂shade/∂y| <= 0.5·(|∂N/∂y| + |dt/dy|·(|N_k| + |N_k+1|)·2) with
  // |∇N| below 3 per noise cell (texture Perlin noise; the fade's slope is at most 1.875), i.e.
  // <= 0.5·(3·f + 4·rate) <= 13 per world unit at f = 8; a step of 1e-9 moves the shade by < 2e-8.
  CaveLook look;
  look.colour_octaves_per_unit = 1.0 / 128.0;
  for (const double boundary : {-128.0, 0.0, 128.0, -256.0}) {
    for (const Vec3& base : {Vec3{0.37, 0.0, -1.91}, Vec3{-5.2, 0.0, 3.3}, Vec3{12.75, 0.0, 0.6}}) {
      const double below = gt::reference::cave_shade(look, {base[0], boundary - 1e-9, base[2]});
      const double above = gt::reference::cave_shade(look, {base[0], boundary + 1e-9, base[2]});
      EXPECT_NEAR(below, above, 2e-8) << "boundary y = " << boundary;
    }
  }
}

TEST(CaveMoss, OnlyUpwardNormalsGetGreen) {
  CaveLook look;  // the seed's moss: n_y/40
  const Vec3 p = {1.3, -0.7, 2.9};
  const Vec3 strip = gt::reference::strip_colour(look.colour_strip, gt::reference::cave_shade(look, p));
  for (const Vec3& down : {Vec3{0.0, -1.0, 0.0}, Vec3{1.0, 0.0, 0.0}, Vec3{0.6, -0.8, 0.0}}) {
    EXPECT_EQ(gt::reference::cave_albedo(look, p, down), strip) << "no moss where n_y <= 0";
  }
  const Vec3 up = {0.0, 0.6, 0.8};
  const Vec3 mossy = gt::reference::cave_albedo(look, p, up);
  EXPECT_EQ(mossy[0], strip[0]);
  EXPECT_EQ(mossy[2], strip[2]);
  EXPECT_EQ(mossy[1], strip[1] + look.moss * 0.6);
  EXPECT_GT(mossy[1], strip[1]);
  // A floor facing straight up gets the whole tint, 1/40 = 0.025 (about 6 of 255 steps).
  EXPECT_NEAR(gt::reference::cave_albedo(look, p, {0.0, 1.0, 0.0})[1] - strip[1], 0.025, 1e-16);
}

TEST(CaveBump, AnalyticGradientMatchesFiniteDifferences) {
  // Central differences of b = a·P(s·p) with step h: error h²/6·|b'''| + ε·|b|/h. With a = 0.04,
  // s = 4, |P'''| below 10³ per noise cell³ (fade''' = 360t² - 360t + 60 is at most 60, times the
  // corner terms), |b'''| <= a·s³·10³ ≈ 2.6·10³, so h = 1e-5 gives < 5e-8 + 4e-13; bound 1e-7.
  const CaveLook look;
  for (const Vec3& p : {Vec3{0.13, -2.71, 5.9}, Vec3{-11.3, 4.44, 0.07}, Vec3{3.01, -1.5, -8.25},
                        Vec3{0.26, 0.51, 0.77}}) {
    const Vec3 gradient = gt::reference::cave_bump_gradient(look, p);
    const double h = 1e-5;
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 plus = p, minus = p;
      plus[axis] += h;
      minus[axis] -= h;
      const double difference =
          (gt::reference::cave_bump_height(look, plus) - gt::reference::cave_bump_height(look, minus)) / (2.0 * h);
      EXPECT_NEAR(gradient[axis], difference, 1e-7) << "axis " << axis;
    }
  }
}

TEST(CaveBump, PerturbedNormalIsUnitAndLeansAgainstTheSurfaceGradient) {
  const CaveLook look;
  const Vec3 p = {0.13, -2.71, 5.9};
  const Vec3 n = {0.0, 0.6, 0.8};
  const Vec3 bumped = gt::reference::cave_bumped_normal(look, p, n);
  EXPECT_NEAR(bumped[0] * bumped[0] + bumped[1] * bumped[1] + bumped[2] * bumped[2], 1.0, 1e-15);
  // n' ∝ n - (g - (g·n)n): parallel to it (cross product zero) and on the same side as n.
  const Vec3 g = gt::reference::cave_bump_gradient(look, p);
  const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
  const Vec3 m = {n[0] - (g[0] - along * n[0]), n[1] - (g[1] - along * n[1]), n[2] - (g[2] - along * n[2])};
  EXPECT_NEAR(bumped[1] * m[2] - bumped[2] * m[1], 0.0, 1e-15);
  EXPECT_NEAR(bumped[2] * m[0] - bumped[0] * m[2], 0.0, 1e-15);
  EXPECT_NEAR(bumped[0] * m[1] - bumped[1] * m[0], 0.0, 1e-15);
  EXPECT_GT(bumped[0] * n[0] + bumped[1] * n[1] + bumped[2] * n[2], 0.0);
  EXPECT_NE(bumped, n) << "the default bump perturbs the normal";
  // Zero amplitude: the normal exactly as it came.
  CaveLook flat = look;
  flat.bump_amplitude = 0.0;
  EXPECT_EQ(gt::reference::cave_bumped_normal(flat, p, n), n);
}

// The render.cave.tunnel.start camera, in a smaller block around its view (28x28x32 cells).
gt::CaveParams tunnel_block() {
  gt::CaveParams block;
  block.origin = {-12, -18, -24};
  block.size = {28, 28, 32};
  return block;
}

gt::reference::Camera tunnel_camera(int width, int height) {
  return {.eye = {2.0, -6.0, -18.0}, .target = {2.0, -3.41, -8.34}, .up = {0.0, 1.0, 0.0}, .fov_y_deg = 60.0,
          .near = 0.1, .far = 200.0, .width = width, .height = height};
}

TEST(CaveScene, RefusesAnEyeInRockOrOutsideTheBlock) {
  const CaveLook look;
  const gt::CaveParams block = tunnel_block();
  gt::reference::Camera outside = tunnel_camera(64, 48);
  outside.eye = {2.0, -6.0, -30.0};
  outside.target = {2.0, -6.0, -20.0};
  EXPECT_THROW(gt::reference::cave_scene(block, outside, look, 25.0), gt::InputError);
  // The first point of the line x = 2, y = -6 (quarter steps along z) where the seed's density is
  // negative, i.e. rock.
  const gt::Permutation& perm = gt::perlin_permutation();
  double z = -18.0;
  while (gt::reference::cave_density_at<double>(perm, block, 2.0, -6.0, z) >= 0.0 && z < 7.0) z += 0.25;
  ASSERT_LT(z, 7.0) << "the line crosses rock inside the block";
  gt::reference::Camera in_rock = tunnel_camera(64, 48);
  in_rock.eye = {2.0, -6.0, z};
  in_rock.target = {2.0, -6.0, z + 5.0};
  EXPECT_THROW(gt::reference::cave_scene(block, in_rock, look, 25.0), gt::InputError);
  EXPECT_THROW(gt::reference::cave_scene(block, tunnel_camera(64, 48), look, 0.0), gt::InputError)
      << "the light must have power";
}

TEST(CaveScene, TunnelCameraSeesWallsNotTheVoid) {
  const auto scene = gt::reference::cave_scene(tunnel_block(), tunnel_camera(96, 72), CaveLook{}, 25.0);
  EXPECT_EQ(scene.look, gt::reference::Look::cave);
  const auto image = gt::reference::render_phong(scene);
  EXPECT_GE(double(image.covered_pixels), 0.95 * 96 * 72);
}

class CaveLookGpu : public gt::testing::GlTest {};


TEST_F(CaveLookGpu, TunnelMatchesTheReference) {
  // Error model: the GPU evaluates the same formulas in float from float positions; its
  // perspective-correct position is within a few float ulps of the reference's (|p| < 40: ~1e-5),
  // and the look amplifies that by at most the strip's slope (<= 4/255 per entry, 256 entries per
  // unit shade) times the noise's (<= 3·f per world unit at f <= 2.3) for the colour and a·s²·|∇²P|
  // (<= 0.64·10) for the bump normal: ~1e-4 at worst, below half an 8-bit step. So a channel
  // differs by at most one step (where the exact value lies next to a rounding boundary), except
  // where a different triangle is seen (silhouettes, depth ties): the 3×3-tolerant comparison at
  // 1.5/255 must pass everywhere but a few edge pixels, well inside issue 6's acceptance
  // (PSNR >= 40 dB, <= 0.5 % beyond 4/255 after the edge tolerance).
  const auto scene = gt::reference::cave_scene(tunnel_block(), tunnel_camera(128, 96), CaveLook{}, 25.0);
  gt::testing::expect_twins_agree(gt::testing::render_twins(scene));
}

TEST_F(CaveLookGpu, CrossFadeAndClampMatchTheReference) {
  // The same camera with the texture's frequency changing fast with height (rate 1/8 per unit:
  // L runs from -1.25 to 2.25 over the block's y in [-18, 10]) and clamped at ±1.5 octaves: the
  // cross-fade between octaves, its boundaries and the clamp on both twins. Error model as above
  // (the noise's slope grows with f <= 2·2^2.5 ≈ 11: still ~1e-4 at worst).
  CaveLook look;
  look.colour_octaves_per_unit = 0.125;
  look.colour_octave_limit = 1.5;
  const auto scene = gt::reference::cave_scene(tunnel_block(), tunnel_camera(128, 96), look, 25.0);
  gt::testing::expect_twins_agree(gt::testing::render_twins(scene));
}

TEST_F(CaveLookGpu, ZeroBumpFlatStripAndNoMossIsThePlainProgramExactly) {
  // The cave program with every look term neutral (strip = the albedo everywhere: a + f·0 = a; moss
  // 0: g + 0 = g; bump 0: n untouched) runs the plain program's arithmetic: identical bytes.
  auto scene = gt::reference::cave_scene(tunnel_block(), tunnel_camera(96, 72), CaveLook{}, 25.0);
  scene.cave.colour_strip.assign(256, scene.albedo);
  scene.cave.moss = 0.0;
  scene.cave.bump_amplitude = 0.0;
  const gt::gpu::PhongRenderer cave(gt::phong_draw(scene));
  cave.run();
  scene.look = gt::reference::Look::plain;
  const gt::gpu::PhongRenderer plain(gt::phong_draw(scene));
  plain.run();
  EXPECT_EQ(cave.image().rgb, plain.image().rgb);
}

}  // namespace
