// The Perlin-noise references (improved Perlin 2002, Gustavson's 2004 texture-based noise) and the
// fractal sums: values against independent implementations and hand computations, bounds derived
// from the formulas, and the hazards of the texture noise. The GLSL twins are only compiled here;
// their value parity is checked by the noise-field comparison.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/gl_test.hpp"

#include "core/noise/perlin_texture_table.hpp"
#include "core/noise/permutation.hpp"
#include "core/params/noise_fractal.hpp"
#include "gpu/noise/perlin_texture.hpp"
#include "gpu/shader_program.hpp"
#include "reference/noise/fractal.hpp"
#include "reference/noise/perlin.hpp"
#include "reference/noise/perlin_texture.hpp"

namespace {

using gt::reference::perlin3;
using gt::reference::perlin3_gradient;
using gt::reference::perlin3_texture;

// |improved Perlin| <= 1.5: Σ_c w_c·|g_c·(d − c)| <= Σ_axis e(t_axis), e(t) = (1 − fade t)·t + fade(t)·(1 − t) <= 1/2.
constexpr double perlin_bound = 1.5;
// max over [0,1] of |t − fade(t)|, reached at t = (1 − sqrt(1 − 4/sqrt(30)))/2 ≈ 0.2403.
constexpr double fade_defect_bound = 0.14675;

const gt::Permutation& table() { return gt::perlin_permutation(); }

// Points spread over several cells, negative coordinates included.
std::vector<std::array<double, 3>> sample_points(int count) {
  std::vector<std::array<double, 3>> points;
  for (int i = 0; i < count; ++i) {
    points.push_back({-7.3 + 0.1379 * i, 3.1 - 0.0713 * i, 0.57 + 0.0419 * i});
  }
  return points;
}

// ---- improved Perlin noise ----

TEST(ImprovedPerlin, IsZeroAtLatticePoints) {
  for (int x = -3; x <= 3; ++x) {
    for (int y = -2; y <= 2; ++y) {
      for (int z : {-257, 0, 1, 255, 256}) {
        EXPECT_EQ(perlin3(table(), double(x), double(y), double(z)), 0.0);
        EXPECT_EQ(perlin3(table(), float(x), float(y), float(z)), 0.0f);
      }
    }
  }
}

TEST(ImprovedPerlin, MatchesPerlinsJavaReference) {
  // From a Python port of Perlin's ImprovedNoise.java (2002), double precision, reference table;
  // (3.14, 42, 7) is the value that code is usually quoted with.
  EXPECT_DOUBLE_EQ(perlin3(table(), 3.14, 42.0, 7.0), 0.13691995878400012);
  EXPECT_DOUBLE_EQ(perlin3(table(), 0.5, 0.5, 0.5), -0.25);
  EXPECT_DOUBLE_EQ(perlin3(table(), -1.25, 2.75, 0.125), -0.061031328077660874);
  EXPECT_DOUBLE_EQ(perlin3(table(), 10.3, -7.7, 100.9), -0.19121297591708614);
  EXPECT_DOUBLE_EQ(perlin3(table(), 123.456, -0.001, 77.7), -0.2052679418634029);
}

TEST(ImprovedPerlin, HasPeriod256) {
  // Multiples of 1/32, so that the shifted coordinates are exact and the local ones identical.
  for (int i = 0; i < 50; ++i) {
    const double x = -7.0 + i * 0.40625, y = 3.0 - i * 0.21875, z = 0.5 + i * 0.03125;
    EXPECT_EQ(perlin3(table(), x + 256.0, y - 512.0, z + 256.0), perlin3(table(), x, y, z));
  }
}

TEST(ImprovedPerlin, StaysWithinTheProvenBoundAndUsesItsRange) {
  double largest = 0.0;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      for (int k = 0; k < 40; ++k) {
        const double value = perlin3(table(), 0.113 * i, 0.127 * j, 0.131 * k);
        EXPECT_LE(std::abs(value), perlin_bound);
        largest = std::max(largest, std::abs(value));
      }
    }
  }
  // A local search over many cells finds 1.0 as the maximum; a grid of 64000 points comes close.
  EXPECT_GT(largest, 0.8);
  EXPECT_LE(largest, 1.0);
}

TEST(ImprovedPerlin, GradientValueIsTheNoiseBitForBit) {
  for (const auto& p : sample_points(200)) {
    EXPECT_EQ(perlin3_gradient(table(), p[0], p[1], p[2])[0], perlin3(table(), p[0], p[1], p[2]));
    const auto x = float(p[0]), y = float(p[1]), z = float(p[2]);
    EXPECT_EQ(perlin3_gradient(table(), x, y, z)[0], perlin3(table(), x, y, z));
  }
}

TEST(ImprovedPerlin, GradientMatchesCentralDifferences) {
  // Along an axis the noise is A + fade(t)·D with A, D affine in t, |D| <= 4, |D'| <= 2, so
  // |f'''| <= 60·4 + 3·(10/sqrt 3)·2 < 275 (|fade'''| <= 60, |fade''| <= 10/sqrt 3), and the central
  // difference is off by at most h²/6·275 < 46·h²; rounding adds ~1e-16·1.5/h.
  constexpr double h = 1e-4;
  constexpr double bound = 46.0 * h * h + 1e-10;
  for (const auto& p : sample_points(300)) {
    const auto analytic = perlin3_gradient(table(), p[0], p[1], p[2]);
    for (int axis = 0; axis < 3; ++axis) {
      auto ahead = p, behind = p;
      ahead[axis] += h;
      behind[axis] -= h;
      const double difference = (perlin3(table(), ahead[0], ahead[1], ahead[2]) -
                                 perlin3(table(), behind[0], behind[1], behind[2])) /
                                (2.0 * h);
      EXPECT_NEAR(analytic[1 + axis], difference, bound) << "axis " << axis << " at " << p[0] << ", " << p[1] << ", "
                                                         << p[2];
    }
  }
}

TEST(ImprovedPerlin, GradientAtALatticePointIsTheCornerGradient) {
  // Only the corner at the point contributes, and its gradient has two components ±1 and one 0.
  const auto gradient = perlin3_gradient(table(), 5.0, -2.0, 9.0);
  EXPECT_EQ(gradient[0], 0.0);
  EXPECT_EQ(std::abs(gradient[1]) + std::abs(gradient[2]) + std::abs(gradient[3]), 2.0);
}

TEST(ImprovedPerlin, SeededTablesGiveOtherNoise) {
  const auto seeded = gt::seeded_permutation(7);
  EXPECT_NE(perlin3(seeded, 3.14, 42.0, 7.0), perlin3(table(), 3.14, 42.0, 7.0));
}

// ---- Gustavson's texture-based noise ----

TEST(PerlinTextureTable, HasGustavsonsLayout) {
  const auto rgba = gt::perlin_texture_rgba(table());
  ASSERT_EQ(rgba.size(), 256u * 256u * 4u);
  const auto& perm = table();
  for (int row : {0, 1, 77, 255}) {
    for (int column : {0, 3, 128, 255}) {
      const std::uint8_t* texel = &rgba[(row * 256 + column) * 4];
      const int value = perm[(column + perm[row]) & 255];
      EXPECT_EQ(texel[3], value);
      const auto& gradient = gt::perlin_texture_gradients()[value & 15];
      for (int axis = 0; axis < 3; ++axis) EXPECT_EQ(texel[axis], gradient[axis] * 64 + 64);
    }
  }
  for (std::size_t i = 0; i < rgba.size(); ++i) {
    if (i % 4 != 3) {
      ASSERT_TRUE(rgba[i] == 0 || rgba[i] == 64 || rgba[i] == 128) << "byte " << i;
    }
  }
}

TEST(PerlinTexture, DecodesGradientsInexactly) {
  using gt::reference::perlin_texture_gradient_component;
  EXPECT_EQ(perlin_texture_gradient_component<float>(0), -1.0f);
  EXPECT_EQ(perlin_texture_gradient_component<float>(64), 4.0f * (64.0f / 255.0f) - 1.0f);
  EXPECT_EQ(perlin_texture_gradient_component<float>(128), 4.0f * (128.0f / 255.0f) - 1.0f);
  EXPECT_EQ(perlin_texture_gradient_component<float>(64), 0.003921628f);
  EXPECT_EQ(perlin_texture_gradient_component<float>(128), 1.0078433f);
  // In exact arithmetic the decode is g' = (256·g + 1)/255.
  EXPECT_NEAR(perlin_texture_gradient_component<double>(64), 1.0 / 255.0, 1e-16);
  EXPECT_NEAR(perlin_texture_gradient_component<double>(128), 257.0 / 255.0, 1e-15);
}

// The same lattice sum with the texture's hash and exact integer gradients grad3_16, in double.
// `wrap_alpha_255` applies hazard 2 (an alpha of 255 addresses column 0).
double integer_gradient_noise(const std::array<double, 3>& p, bool wrap_alpha_255) {
  const auto& perm = table();
  std::array<int, 3> lattice{};
  std::array<double, 3> local{}, weight{};
  for (int axis = 0; axis < 3; ++axis) {
    const double lower = std::floor(p[axis]);
    lattice[axis] = static_cast<int>(lower) & 255;
    local[axis] = p[axis] - lower;
    weight[axis] = gt::reference::perlin_fade(local[axis]);
  }
  double sum = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    const std::array<int, 3> c = {corner & 1, (corner >> 1) & 1, (corner >> 2) & 1};
    int alpha = perm[(lattice[0] + c[0] + perm[(lattice[1] + c[1]) & 255]) & 255];
    if (wrap_alpha_255 && alpha == 255) alpha = 0;
    const int hash = perm[(alpha + perm[(lattice[2] + c[2]) & 255]) & 255];
    const auto& g = gt::perlin_texture_gradients()[hash & 15];
    double dot = 0.0, corner_weight = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      dot += g[axis] * (local[axis] - c[axis]);
      corner_weight *= c[axis] == 1 ? weight[axis] : 1.0 - weight[axis];
    }
    sum += corner_weight * dot;
  }
  return sum;
}

TEST(PerlinTexture, IsTheIntegerGradientNoiseScaledPlusABias) {
  // g' = (256·g + 1)/255 makes N_tex = (256/255)·N_int + (1/255)·Σ_axis (t − fade(t)) exactly
  // (Σ_c w_c·(d_c)_axis = t − fade(t)); in double the two sides agree to rounding.
  const auto rgba = gt::perlin_texture_rgba(table());
  for (const auto& p : sample_points(400)) {
    double bias = 0.0;
    for (double coordinate : p) {
      const double t = coordinate - std::floor(coordinate);
      bias += t - gt::reference::perlin_fade(t);
    }
    const double predicted = 256.0 / 255.0 * integer_gradient_noise(p, true) + bias / 255.0;
    EXPECT_NEAR(perlin3_texture(rgba, p[0], p[1], p[2]), predicted, 1e-12);
  }
}

TEST(PerlinTexture, DiffersFromExactGradientsWithinTheDecodeBound) {
  // |N_tex − N_int| = |N_int + Σ(t − fade t)|/255 <= (1.5 + 3·0.14675)/255 < 0.0077.
  const double bound = (perlin_bound + 3.0 * fade_defect_bound) / 255.0;
  const auto rgba = gt::perlin_texture_rgba(table());
  double largest = 0.0;
  for (const auto& p : sample_points(400)) {
    const double difference = std::abs(perlin3_texture(rgba, p[0], p[1], p[2]) - integer_gradient_noise(p, true));
    EXPECT_LE(difference, bound);
    largest = std::max(largest, difference);
  }
  EXPECT_GT(largest, 1e-3) << "the inexact decode should show (the hazard)";
}

TEST(PerlinTexture, HashesAnAlphaOf255AsColumn0) {
  // Find the cell whose corner (0, 0) reads alpha 255 at y = 0: X = perm⁻¹[255] − perm[0].
  const auto& perm = table();
  int column = 0;
  while (perm[(column + perm[0]) & 255] != 255) ++column;
  const auto rgba = gt::perlin_texture_rgba(table());
  double largest_without_wrap = 0.0;
  for (int z = 0; z < 8; ++z) {
    const std::array<double, 3> p = {column + 0.3, 0.4, z + 0.6};
    const double noise = perlin3_texture(rgba, p[0], p[1], p[2]);
    const double bias = (0.3 - gt::reference::perlin_fade(0.3)) + (0.4 - gt::reference::perlin_fade(0.4)) +
                        (0.6 - gt::reference::perlin_fade(0.6));
    EXPECT_NEAR(noise, 256.0 / 255.0 * integer_gradient_noise(p, true) + bias / 255.0, 1e-12);
    largest_without_wrap = std::max(largest_without_wrap, std::abs(noise - integer_gradient_noise(p, false)));
  }
  EXPECT_GT(largest_without_wrap, 0.05);
}

TEST(PerlinTexture, IsZeroAtLatticePointsAndFloatFollowsDouble) {
  const auto rgba = gt::perlin_texture_rgba(table());
  EXPECT_EQ(perlin3_texture(rgba, 4.0, -3.0, 17.0), 0.0);
  EXPECT_EQ(perlin3_texture(rgba, 4.0f, -3.0f, 17.0f), 0.0f);
  // Float-exact inputs: ~40 roundings of values below 2.5 (2^-24 relative each) stay below 1e-5.
  for (const auto& p : sample_points(200)) {
    const auto x = float(p[0]), y = float(p[1]), z = float(p[2]);
    EXPECT_NEAR(perlin3_texture(rgba, x, y, z), perlin3_texture(rgba, double(x), double(y), double(z)), 1e-5);
  }
}

TEST(PerlinTexture, RejectsATableOfTheWrongSize) {
  EXPECT_THROW(perlin3_texture(std::vector<std::uint8_t>(16), 0.5, 0.5, 0.5), std::invalid_argument);
}

// ---- fractal sums ----

gt::FractalParams fractal(double octaves, double lacunarity, double gain, double H, double offset) {
  return {octaves, lacunarity, gain, H, offset};
}

// n(x, y, z) = scale·(x − y): simple enough to sum by hand.
struct AffineBasis {
  double scale;
  double operator()(double x, double y, double) const { return scale * (x - y); }
};

const auto perlin_basis = [](double x, double y, double z) { return perlin3(gt::perlin_permutation(), x, y, z); };

TEST(FractalTerms, DeriveTheConstantsInDouble) {
  const auto terms = gt::fractal_terms<double>(fractal(3.25, 3.0, 0.5, 1.0, 1.0));
  EXPECT_EQ(terms.whole_octaves, 3);
  EXPECT_EQ(terms.remainder, 0.25);
  EXPECT_DOUBLE_EQ(terms.spectral_ratio, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(terms.fbm_normalisation, 1.0 / (1.0 + 0.5 + 0.25 + 0.25 * 0.125));
  EXPECT_THROW(gt::fractal_terms<float>(fractal(0.5, 2.0, 0.5, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(gt::fractal_terms<float>(fractal(33.0, 2.0, 0.5, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(gt::fractal_terms<float>(fractal(3.0, 0.0, 0.5, 1.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(gt::fractal_terms<float>(fractal(3.0, 2.0, -0.5, 1.0, 1.0)), std::invalid_argument);
}

TEST(Fractal, OneOctaveIsTheBasis) {
  const auto terms = gt::fractal_terms<double>(fractal(1.0, 2.0, 0.5, 1.0, 0.8));
  for (const auto& p : sample_points(50)) {
    const double n = perlin_basis(p[0], p[1], p[2]);
    EXPECT_EQ(gt::reference::fbm(perlin_basis, terms, p[0], p[1], p[2]), n);
    EXPECT_EQ(gt::reference::ridged_multifractal(perlin_basis, terms, p[0], p[1], p[2]),
              (0.8 - std::abs(n)) * (0.8 - std::abs(n)));
    EXPECT_EQ(gt::reference::hetero_terrain(perlin_basis, terms, p[0], p[1], p[2]), 0.8 + n);
  }
}

TEST(Fractal, FbmIsSeed002sNormalizedOctaveNoise) {
  // normalizedOctaveNoise3D: Σ_{k<o} 0.5^k·noise(2^k·p) / Σ_{k<o} 0.5^k (digest 002 §4.4.3).
  const auto terms = gt::fractal_terms<double>(fractal(5.0, 2.0, 0.5, 0.0, 0.0));
  for (const auto& p : sample_points(50)) {
    double sum = 0.0, weights = 0.0;
    for (int k = 0; k < 5; ++k) {
      const double frequency = std::ldexp(1.0, k), amplitude = std::ldexp(1.0, -k);
      sum += amplitude * perlin_basis(frequency * p[0], frequency * p[1], frequency * p[2]);
      weights += amplitude;
    }
    EXPECT_NEAR(gt::reference::fbm(perlin_basis, terms, p[0], p[1], p[2]), sum / weights, 1e-15);
  }
}

TEST(Fractal, FbmNormalisationKeepsTheRange) {
  const auto constant = [](double, double, double) { return 1.0; };
  for (double octaves : {1.0, 2.0, 3.5, 8.0, 8.75}) {
    for (double gain : {0.3, 0.5, 0.9}) {
      const auto terms = gt::fractal_terms<double>(fractal(octaves, 2.0, gain, 1.0, 1.0));
      EXPECT_NEAR(gt::reference::fbm(constant, terms, 0.3, 0.2, 0.1), 1.0, 1e-15);
      for (const auto& p : sample_points(40)) {
        EXPECT_LE(std::abs(gt::reference::fbm(perlin_basis, terms, p[0], p[1], p[2])), perlin_bound);
      }
    }
  }
}

TEST(Fractal, HeteroTerrainByHandWithTheDigestsDefaults) {
  // Digest 001 §3.18 defaults: H = 1, lacunarity = 3, offset = 1; basis n = x − y at p = (0.5, 0.25, 0).
  // Octave 0: value = 1 + 0.25 = 5/4. Octave 1: q = (1.5, 0.75), n = 0.75, pwr = 1/3:
  // value += (1.75·1/3)·5/4 = 35/48 → 95/48. Octave 2: q = (4.5, 2.25), n = 2.25, pwr = 1/9:
  // value += (3.25·1/9)·95/48 → 95/48·49/36 = 4655/1728.
  const AffineBasis basis{1.0};
  const auto two = gt::fractal_terms<double>(fractal(2.0, 3.0, 0.5, 1.0, 1.0));
  const auto three = gt::fractal_terms<double>(fractal(3.0, 3.0, 0.5, 1.0, 1.0));
  const auto two_and_a_half = gt::fractal_terms<double>(fractal(2.5, 3.0, 0.5, 1.0, 1.0));
  EXPECT_DOUBLE_EQ(gt::reference::hetero_terrain(basis, two, 0.5, 0.25, 0.0), 95.0 / 48.0);
  EXPECT_DOUBLE_EQ(gt::reference::hetero_terrain(basis, three, 0.5, 0.25, 0.0), 4655.0 / 1728.0);
  EXPECT_DOUBLE_EQ(gt::reference::hetero_terrain(basis, two_and_a_half, 0.5, 0.25, 0.0),
                   95.0 / 48.0 * (1.0 + 0.5 * 13.0 / 36.0));
}

TEST(Fractal, RidgedMultifractalByHand) {
  // n = (x − y)/4 at p = (0.5, 0.25, 0), lacunarity 2, H = 1 (weights 1, 1/2, 1/4), offset 1.
  // Signals (1 − n)²: 0.9375² = 0.87890625, 0.875² = 0.765625, 0.75² = 0.5625.
  // gain 2: weights clamp to 1: 0.87890625 + 0.765625/2 + 0.5625/4 = 1.40234375.
  // gain 1: weights 0.87890625, then 0.765625·0.87890625 = 0.67291259765625:
  //   0.87890625 + 0.67291259765625/2 + 0.5625·0.67291259765625/4 = 1.309990882873535...
  const AffineBasis basis{0.25};
  const auto feedback_2 = gt::fractal_terms<double>(fractal(3.0, 2.0, 2.0, 1.0, 1.0));
  const auto feedback_1 = gt::fractal_terms<double>(fractal(3.7, 2.0, 1.0, 1.0, 1.0));
  EXPECT_EQ(gt::reference::ridged_multifractal(basis, feedback_2, 0.5, 0.25, 0.0), 1.40234375);
  EXPECT_EQ(gt::reference::ridged_multifractal(basis, feedback_1, 0.5, 0.25, 0.0),
            0.87890625 + 0.67291259765625 / 2 + 0.5625 * 0.67291259765625 / 4);
}

TEST(Fractal, FractionalOctavesInterpolateContinuously) {
  const auto at = [](double octaves) { return gt::fractal_terms<double>(fractal(octaves, 3.0, 0.5, 1.0, 1.0)); };
  for (const auto& p : sample_points(40)) {
    // hetero_terrain(2 + r) = hetero_terrain(2) + r·(hetero_terrain(3) − hetero_terrain(2)).
    const double two = gt::reference::hetero_terrain(perlin_basis, at(2.0), p[0], p[1], p[2]);
    const double three = gt::reference::hetero_terrain(perlin_basis, at(3.0), p[0], p[1], p[2]);
    const double almost = gt::reference::hetero_terrain(perlin_basis, at(2.999), p[0], p[1], p[2]);
    EXPECT_NEAR(almost, two + 0.999 * (three - two), 1e-12);
    // fbm(2 + r) = (S + r·a·n)/(W + r·a), a = gain², |d/dr| <= a·(|n|·W + |S|)/W² <= 0.25·3/1.5 = 0.5.
    const double fbm_three = gt::reference::fbm(perlin_basis, at(3.0), p[0], p[1], p[2]);
    const double fbm_almost = gt::reference::fbm(perlin_basis, at(2.999), p[0], p[1], p[2]);
    EXPECT_LE(std::abs(fbm_three - fbm_almost), 0.001 * 0.5);
  }
}

TEST(Fractal, FloatInstantiationFollowsDouble) {
  // The float sum departs mainly through q_k = q_{k−1}·3 rounded per step (relative k·2^-24): with
  // |∂n/∂axis| <= 1 + 1.875·4 + 2 = 10.5 (A' + fade'·D + fade·D'), |p| < 8 and pwr_k = 3^-k, octave k
  // moves the value by <= 10.5·sqrt(3)·k·2^-24·8·3^k·3^-k·7 (|value| < 7) ≈ k·1.1e-4, Σ_{k<=4} ≈ 1.1e-3;
  // the basis's own float error (< 2e-6) and its growth through the product stay far below that.
  const auto terms_d = gt::fractal_terms<double>(fractal(5.0, 3.0, 0.5, 1.0, 1.0));
  const auto terms_f = gt::fractal_terms<float>(fractal(5.0, 3.0, 0.5, 1.0, 1.0));
  const auto perlin_float = [](float x, float y, float z) { return perlin3(gt::perlin_permutation(), x, y, z); };
  for (const auto& p : sample_points(40)) {
    const auto x = float(p[0]), y = float(p[1]), z = float(p[2]);
    EXPECT_NEAR(gt::reference::hetero_terrain(perlin_float, terms_f, x, y, z),
                gt::reference::hetero_terrain(perlin_basis, terms_d, double(x), double(y), double(z)), 1.5e-3);
  }
}

// ---- GLSL ----

class NoiseGlsl : public gt::testing::GlTest {};

TEST_F(NoiseGlsl, PerlinAndFractalCompile) {
  EXPECT_NO_THROW(gt::ComputeProgram::load("test/perlin_fractal_compile.comp"));
}

TEST_F(NoiseGlsl, PerlinTextureHoldsTheTable) {
  const gt::gpu::PerlinTexture texture(table());
  std::vector<std::uint8_t> read_back(256 * 256 * 4);
  glGetTextureImage(texture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(read_back.size()),
                    read_back.data());
  EXPECT_EQ(read_back, gt::perlin_texture_rgba(table()));
  GLint filter = 0, wrap = 0;
  glGetTextureParameteriv(texture.id(), GL_TEXTURE_MIN_FILTER, &filter);
  glGetTextureParameteriv(texture.id(), GL_TEXTURE_WRAP_S, &wrap);
  EXPECT_EQ(filter, GL_NEAREST);
  EXPECT_EQ(wrap, GL_REPEAT);
}

}  // namespace
