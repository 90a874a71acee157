// Simplex noise references (reference/noise/simplex.cpp) against seed 004 and against the theory,
// and the GLSL twin (gpu/shaders/noise/simplex.glsl) compiling with constants equal to the C++
// float constants. GPU parity is tested with the GPU sampling kernel, not here.
//
// Error models (u = unit roundoff: 2^-24 in float, 2^-53 in double; n = dimension; r2 = kernel
// radius²; S = scale; |g| = longest gradient vector, sqrt(2) for grad3, sqrt(3) for grad4; F, G the
// skew and unskew factors). One corner contributes c(d) = t⁴ (g·d), t = r2 - |d|², q = |d|² < r2:
//   |∇c|     <= |g| t³ (8q + t) = |g| (r2 - q)³ (r2 + 7q) <= |g| (432/343) r2⁴  (largest at q = r2/7)
//   ‖∇²c‖    <= |g| sqrt(q) (48 t² q + 24 t³)             <= 72 |g| sqrt(r2) r2³
//   |∂³_e c| <= |g| (192 t q² + 288 t² q + 24 t³)         <= |g| r2³ (4·192/27 + 4·288/27 + 24)
// and at most n + 1 corners (those of one simplex) contribute, so the field's bounds are these
// times S (n + 1). Every vertex is at distance² >= 0.5 from the facet opposite it, so with r2 = 0.5
// a vertex contributes nothing outside its simplices: the field is Σ over all lattice vertices of
// max(t, 0)⁴ (g·d), three times continuously differentiable. With r2 = 0.6 a vertex still reaches
// t <= r2 - 0.5 across the facet, where it is dropped: the field jumps there by at most
// J = 2 S |g| sqrt(r2) (r2 - 0.5)⁴ (one vertex dropped, one added) - the digest's §2.2.5 caveat.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/gl_test.hpp"

#include "core/noise/permutation.hpp"
#include "core/rng.hpp"
#include "gpu/shader_program.hpp"
#include "reference/noise/simplex.hpp"

namespace {

namespace ref = gt::reference;

using Point = std::array<double, 4>;

constexpr double float_unit = 0x1p-24;
constexpr double double_unit = 0x1p-53;

const gt::Permutation& perlin = gt::perlin_permutation();

// One noise function with what its error model needs.
struct Variant {
  const char* name;
  int dimension;
  float kernel_radius_squared;  // as the GPU receives it; the double runs use the same value
  double scale;
  double gradient_length;
  const ref::SimplexLattice& lattice;
};

const Variant simplex2{"simplex2", 2, 0.5f, 70.0, std::sqrt(2.0), ref::simplex_lattice2};
const Variant simplex3_corrected{"simplex3 r2 0.5", 3, 0.5f, 32.0, std::sqrt(2.0), ref::simplex_lattice3};
const Variant simplex3_seed{"simplex3 r2 0.6", 3, 0.6f, 32.0, std::sqrt(2.0), ref::simplex_lattice3};
const Variant simplex4_corrected{"simplex4 r2 0.5", 4, 0.5f, 27.0, std::sqrt(3.0), ref::simplex_lattice4};
const Variant simplex4_seed{"simplex4 r2 0.6", 4, 0.6f, 27.0, std::sqrt(3.0), ref::simplex_lattice4};
const std::array<const Variant*, 5> all_variants{&simplex2, &simplex3_corrected, &simplex3_seed, &simplex4_corrected,
                                                 &simplex4_seed};

template <class Real>
Real evaluate(const Variant& variant, const std::array<Real, 4>& p, const gt::Permutation& perm = perlin) {
  const auto r2 = static_cast<Real>(variant.kernel_radius_squared);
  switch (variant.dimension) {
    case 2: return ref::simplex2(perm, p[0], p[1]);
    case 3: return ref::simplex3(perm, p[0], p[1], p[2], r2);
    default: return ref::simplex4(perm, p[0], p[1], p[2], p[3], r2);
  }
}

// {value, derivatives...} in 2-D or 3-D, padded with zeros.
std::array<double, 4> evaluate_gradient(const Variant& variant, const Point& p) {
  if (variant.dimension == 2) {
    const auto gradient = ref::simplex2_gradient(perlin, p[0], p[1]);
    return {gradient[0], gradient[1], gradient[2], 0.0};
  }
  return ref::simplex3_gradient(perlin, p[0], p[1], p[2], static_cast<double>(variant.kernel_radius_squared));
}

double corners(const Variant& variant) { return variant.scale * (variant.dimension + 1) * variant.gradient_length; }

double gradient_bound(const Variant& variant) {
  return corners(variant) * (432.0 / 343.0) * std::pow(variant.kernel_radius_squared, 4);
}

double hessian_bound(const Variant& variant) {
  const double r2 = variant.kernel_radius_squared;
  return corners(variant) * 72.0 * std::sqrt(r2) * r2 * r2 * r2;
}

double third_derivative_bound(const Variant& variant) {
  const double r2 = variant.kernel_radius_squared;
  return corners(variant) * (4.0 * 192.0 / 27.0 + 4.0 * 288.0 / 27.0 + 24.0) * r2 * r2 * r2;
}

double jump_bound(const Variant& variant) {
  const double r2 = variant.kernel_radius_squared;
  return 2.0 * variant.scale * variant.gradient_length * std::sqrt(r2) * std::pow(std::max(r2 - 0.5, 0.0), 4);
}

// Rounding of the corner terms for exact offsets: t loses (n + 1) r2 u (n squares, n
// subtractions), g·d loses (n - 1) sqrt(n r2) u (n - 1 additions), t², t⁴ and t⁴ (g·d) round once
// each, and the n + 1 corner sums and the scaling once more:
// S (n + 1) sqrt(r2) r2⁴ ((5n + 9) |g| + (n - 1) sqrt(n)) u + u.
double evaluation_error(const Variant& variant, double unit) {
  const double n = variant.dimension;
  const double r2 = variant.kernel_radius_squared;
  const double per_corner = (5.0 * n + 9.0) * variant.gradient_length + (n - 1.0) * std::sqrt(n);
  return (variant.scale * (n + 1.0) * std::sqrt(r2) * std::pow(r2, 4) * per_corner + 1.0) * unit;
}

// Rounding of the cell offset d0 = p - (i - T), T = (Σ i)·G, for |p_a| <= R: |T| <= n G (R (1 + n F)
// + 1); T is off by 2u|T| (G and the product), i - T and p - X0 round once each (|X0| <= R + 1,
// |d0| <= 1). The same error reaches every corner.
double shared_offset_error(const Variant& variant, double largest, double unit) {
  const double n = variant.dimension;
  const double unskew_sum = n * variant.lattice.corner_unskew[1] * (largest * (1.0 + n * variant.lattice.skew) + 1.0);
  return (2.0 * unskew_sum + largest + 2.0) * unit;
}

// Each corner then rounds d0 - step and + m·G, and m·G itself is rounded: below 5u.
double corner_offset_error(double unit) { return 5.0 * unit; }

// How far the simplex choice is from changing: the skewed coordinates p_a + s against integers
// (the floor) and the differences of their fractional parts, which equal d0_a - d0_b (the ranks).
double face_margin(const Variant& variant, const Point& p) {
  double sum = 0.0;
  for (int axis = 0; axis < variant.dimension; ++axis) sum += p[axis];
  const double skew = sum * variant.lattice.skew;
  std::array<double, 4> fraction{};
  double margin = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < variant.dimension; ++axis) {
    fraction[axis] = (p[axis] + skew) - std::floor(p[axis] + skew);
    margin = std::min({margin, fraction[axis], 1.0 - fraction[axis]});
  }
  for (int first = 0; first < variant.dimension; ++first) {
    for (int second = first + 1; second < variant.dimension; ++second) {
      margin = std::min(margin, std::abs(fraction[first] - fraction[second]));
    }
  }
  return margin;
}

// How wrong the float twin can be about those decisions: p_a + s is off by the rounding of the
// sum (partial sums up to kR), of the product with F and of the addition; d0_a - d0_b by twice the
// offset error.
double decision_error(const Variant& variant, double largest, double unit) {
  const double n = variant.dimension;
  const double skew = variant.lattice.skew;
  const double skewed = largest * (skew * (n * (n + 1.0) / 2.0 - 1.0) + 3.0 * n * skew + 1.0) * unit;
  return std::max(skewed, 2.0 * shared_offset_error(variant, largest, unit));
}

double largest_coordinate(const Variant& variant, const Point& p) {
  double largest = 1.0;
  for (int axis = 0; axis < variant.dimension; ++axis) largest = std::max(largest, std::abs(p[axis]));
  return largest;
}

// Uniform in [-range, range): a float with 24 random bits, or a double with 48.
float random_float(std::uint32_t seed, std::uint32_t sample, std::uint32_t axis, float range) {
  return (2.0f * gt::uniform01(gt::random_u32(seed, sample, axis, 0)) - 1.0f) * range;
}

double random_double(std::uint32_t seed, std::uint32_t sample, std::uint32_t axis, double range) {
  const double fine = gt::uniform01(gt::random_u32(seed, sample, axis, 0)) +
                      0x1p-24 * gt::uniform01(gt::random_u32(seed, sample, axis, 1));
  return (2.0 * fine - 1.0) * range;
}

// ---- seed 004 ----

struct ListingLine {
  int y;
  int z;
  const char* printed;
  bool rendered;
};

// Figure 3.2 of the thesis (x = 9; the line for y = 6, z = 0 is cut off in the figure).
constexpr ListingLine figure_3_2[] = {
    {6, 1, "-0.107878", false}, {6, 2, "0.107878", true},   {6, 3, "0.000000", true},   {6, 4, "0.000000", true},
    {6, 5, "-0.867978", false}, {6, 6, "0.000000", true},   {6, 7, "0.000000", true},   {6, 8, "0.652221", true},
    {6, 9, "0.000000", true},   {7, 0, "0.000000", true},   {7, 1, "-0.652221", false}, {7, 2, "0.000000", true},
    {7, 3, "0.000000", true},   {7, 4, "0.000000", true},   {7, 5, "0.000000", true},   {7, 6, "-0.867978", false},
    {7, 7, "-0.000000", false}, {7, 8, "0.000000", true},   {7, 9, "0.760100", true},   {8, 0, "0.760100", true},
    {8, 1, "0.000000", true},   {8, 2, "0.000000", true},   {8, 3, "0.000000", true},   {8, 4, "0.000000", true},
    {8, 5, "0.000000", true},   {8, 6, "-0.867978", false}, {8, 7, "0.000000", true},   {8, 8, "0.000000", true},
    {8, 9, "-0.652221", false}, {9, 0, "0.000000", true},   {9, 1, "0.000000", true},   {9, 2, "0.000000", true},
    {9, 3, "0.000000", true},   {9, 4, "0.107878", true},   {9, 5, "0.107878", true},   {9, 6, "0.000000", true},
    {9, 7, "0.760100", true},   {9, 8, "0.000000", true},   {9, 9, "0.000000", true},
};

std::string printed_as_in_the_thesis(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%f", value);
  return text;
}

template <class Real>
int points_drawn(const gt::Permutation& perm) {
  int drawn = 0;
  for (int x = 0; x < 10; ++x) {
    for (int y = 0; y < 10; ++y) {
      for (int z = 0; z < 10; ++z) {
        const Real value = ref::simplex3<Real>(perm, Real(x), Real(y), Real(z), Real(0.6));
        drawn += value >= Real(0) ? 1 : 0;
      }
    }
  }
  return drawn;
}

TEST(SimplexSeed004, ReproducesTheFigure32DebugListing) {
  for (const ListingLine& line : figure_3_2) {
    const double value = ref::simplex3<double>(perlin, 9.0, line.y, line.z, 0.6);
    EXPECT_EQ(printed_as_in_the_thesis(value), line.printed) << "y = " << line.y << ", z = " << line.z;
    EXPECT_EQ(value >= 0.0, line.rendered) << "y = " << line.y << ", z = " << line.z;
  }
}

TEST(SimplexSeed004, DrawsTheThesisTotalOf740LatticePoints) {
  EXPECT_EQ(points_drawn<double>(perlin), 740);
  // Half the lattice values are 0 up to rounding, so their signs are rounding noise: the float
  // twin (and the digest's float32 emulation) draws 747. Lattice sampling is no agreement test.
  EXPECT_EQ(points_drawn<float>(perlin), 747);
}

struct TestVector {
  Point p;
  double value;  // printed to 6 decimals
};

// Digest 004 §2.2.6 (raw_noise_3d, kernel 0.6), the last one the thesis's ÷10 wrapper at world (-7, 4, 22).
const TestVector digest_vectors[] = {
    {{0.1, 0.2, 0.3}, 0.635890},     {{1.5, -2.25, 3.75}, -0.569405}, {{-0.3, 0.7, -1.1}, 0.435948},
    {{12.34, 5.67, -8.9}, 0.103462}, {{3.2, 1.1, 0.05}, -0.079717},   {{0.9, 0.6, 0.2}, -0.290695},
    {{0.5, 0.5, 0.5}, 0.0},          {{-7.0 / 10.0, 4.0 / 10.0, 22.0 / 10.0}, 0.118083},
};

// A value printed to 6 decimals is within 5e-7 of the exact one. The independent transcription
// below computes F and G with sqrt at run time as the sources do (1 ulp off the constants here),
// which moves its values by up to 3.2e-14.
constexpr double printed_tolerance = 5e-7 + 1e-13;

TEST(SimplexSeed004, MatchesTheDigestsTestVectors) {
  for (const TestVector& vector : digest_vectors) {
    EXPECT_NEAR(ref::simplex3<double>(perlin, vector.p[0], vector.p[1], vector.p[2], 0.6), vector.value,
                printed_tolerance)
        << vector.p[0] << ", " << vector.p[1] << ", " << vector.p[2];
  }
}

// From a separate Python transcription of Eshelman's raw_noise_2d/3d/4d (Gustavson's 3-D if/else
// chain and 4-D lookup table, not the rank counting used here) with a true floor.
TEST(Simplex, MatchesAnIndependentTranscription) {
  const TestVector vectors2[] = {{{0.1, 0.2}, -0.294108},  {{1.5, -2.25}, 0.512478}, {{-0.3, 0.7}, 0.341408},
                                 {{12.34, 5.67}, -0.828862}, {{3.2, 1.1}, 0.310595},  {{0.9, 0.6}, 0.078364}};
  const TestVector vectors3_corrected[] = {{{0.1, 0.2, 0.3}, 0.204807},     {{1.5, -2.25, 3.75}, -0.253255},
                                          {{-0.3, 0.7, -1.1}, 0.148077},    {{12.34, 5.67, -8.9}, 0.032854},
                                          {{3.2, 1.1, 0.05}, -0.000050},    {{0.9, 0.6, 0.2}, -0.072150}};
  const TestVector vectors4_seed[] = {{{0.1, 0.2, 0.3, 0.4}, 0.227630},     {{1.5, -2.25, 3.75, -0.5}, 0.386441},
                                      {{-0.3, 0.7, -1.1, 2.9}, -0.119538},  {{12.34, 5.67, -8.9, 4.2}, -0.190908},
                                      {{3.2, 1.1, 0.05, -7.7}, 0.110589},   {{0.9, 0.6, 0.2, 0.1}, 0.035248}};
  const TestVector vectors4_corrected[] = {{{0.1, 0.2, 0.3, 0.4}, 0.048459},    {{1.5, -2.25, 3.75, -0.5}, 0.134756},
                                          {{-0.3, 0.7, -1.1, 2.9}, -0.036551}, {{12.34, 5.67, -8.9, 4.2}, -0.038200},
                                          {{3.2, 1.1, 0.05, -7.7}, 0.049259},  {{0.9, 0.6, 0.2, 0.1}, 0.006993}};
  for (const auto& v : vectors2) EXPECT_NEAR(ref::simplex2(perlin, v.p[0], v.p[1]), v.value, printed_tolerance);
  for (const auto& v : vectors3_corrected) {
    EXPECT_NEAR(ref::simplex3(perlin, v.p[0], v.p[1], v.p[2], 0.5), v.value, printed_tolerance);
  }
  for (const auto& v : vectors4_seed) {
    EXPECT_NEAR(ref::simplex4(perlin, v.p[0], v.p[1], v.p[2], v.p[3], 0.6), v.value, printed_tolerance);
  }
  for (const auto& v : vectors4_corrected) {
    EXPECT_NEAR(ref::simplex4(perlin, v.p[0], v.p[1], v.p[2], v.p[3], 0.5), v.value, printed_tolerance);
  }
}

// ---- precision ----

// The float twin against double on the same float inputs, |p_a| <= 64. To first order the error is
// ∇f·Δ with Δ the offset error: the shared part δ_s (same for all corners) costs at most
// |∇f(p)|₁ δ_s (in 4-D, with no analytic gradient, sqrt(n) L δ_s), the per-corner part δ_c at most
// L sqrt(n) δ_c, the second order ½ H n (δ_s + δ_c)², plus the rounding of the corner terms. Where
// p is closer to a simplex face than the float's decision error, float and double can choose
// different simplices: with r2 = 0.5 that changes the value by O(δ⁴) only (the field is a sum over
// all vertices), with r2 = 0.6 it can jump by J. Measured over 2·10⁶ samples: the worst error is
// 0.42 of its bound in 2-D, 0.22 in 3-D, 0.03 in 4-D (global L); with r2 = 0.6, 4 samples took
// the neighbouring simplex and needed J (errors up to 2.9e-3), none with r2 = 0.5.
TEST(Simplex, FloatTwinFollowsDoubleWithinTheRoundingModel) {
  constexpr int samples = 20000;
  constexpr float range = 64.0f;
  for (const Variant* variant : all_variants) {
    const double lipschitz = gradient_bound(*variant);
    const double n = variant->dimension;
    double worst_share = 0.0;
    for (int sample = 0; sample < samples; ++sample) {
      std::array<float, 4> input{};
      Point p{};
      for (int axis = 0; axis < 4; ++axis) {
        input[axis] = random_float(11, sample, axis, range);
        p[axis] = input[axis];
      }
      const double largest = largest_coordinate(*variant, p);
      double slope = std::sqrt(n) * lipschitz;
      if (variant->dimension <= 3) {
        const auto gradient = evaluate_gradient(*variant, p);
        slope = std::abs(gradient[1]) + std::abs(gradient[2]) + std::abs(gradient[3]);
      }
      const double shared = shared_offset_error(*variant, largest, float_unit);
      const double per_corner = corner_offset_error(float_unit);
      double bound = slope * shared + lipschitz * std::sqrt(n) * per_corner +
                     0.5 * hessian_bound(*variant) * n * (shared + per_corner) * (shared + per_corner) +
                     evaluation_error(*variant, float_unit);
      if (face_margin(*variant, p) <= decision_error(*variant, largest, float_unit)) bound += jump_bound(*variant);
      const double error =
          std::abs(static_cast<double>(evaluate<float>(*variant, input)) - evaluate<double>(*variant, p));
      worst_share = std::max(worst_share, error / bound);
      ASSERT_LE(error, bound) << variant->name << " at " << p[0] << ", " << p[1] << ", " << p[2] << ", " << p[3];
    }
    RecordProperty(std::string(variant->name) + " worst error / bound", std::to_string(worst_share));
  }
}

// ---- the analytic gradient ----

// Central differences (f(p + h e) - f(p - h e)) / 2h differ from ∂f/∂e by h²/6 |∂³_e f| <= h²/6 M3
// where f is C³ along the segment, plus the rounding of the two values over 2h and the rounding of
// the analytic gradient. r2 = 0.5 (and 2-D) is C³ everywhere; with r2 = 0.6 only points whose
// stencil stays inside one simplex count: moving p by h along an axis moves p_a + s by at most
// h (1 + F) and f_a - f_b by at most h, so a face margin above 2h keeps it inside.
TEST(Simplex, AnalyticGradientMatchesCentralDifferences) {
  constexpr int samples = 3000;
  constexpr double range = 64.0;
  constexpr double h = 1e-4;
  for (const Variant* variant : {&simplex2, &simplex3_corrected, &simplex3_seed}) {
    const double n = variant->dimension;
    const bool continuous = variant->kernel_radius_squared <= 0.5f;
    int tested = 0;
    for (std::uint32_t sample = 0; sample < samples; ++sample) {
      Point p{};
      for (int axis = 0; axis < variant->dimension; ++axis) p[axis] = random_double(13, sample, axis, range);
      if (!continuous && face_margin(*variant, p) <= 2.0 * h) continue;
      ++tested;
      const double largest = largest_coordinate(*variant, p) + h;
      const double position_error = shared_offset_error(*variant, largest, double_unit) + largest * double_unit;
      const double value_rounding =
          gradient_bound(*variant) * std::sqrt(n) * position_error + evaluation_error(*variant, double_unit);
      // Offset errors reach the gradient through the Hessian; its terms, at most 1.8 times the value
      // terms in size (|∇c| over |c| bound), take a few more roundings each: 8 times the value's.
      const double gradient_rounding =
          hessian_bound(*variant) * std::sqrt(n) * shared_offset_error(*variant, largest, double_unit) +
          8.0 * evaluation_error(*variant, double_unit);
      const auto gradient = evaluate_gradient(*variant, p);
      EXPECT_EQ(gradient[0], evaluate<double>(*variant, p));
      for (int axis = 0; axis < variant->dimension; ++axis) {
        Point forward = p;
        Point backward = p;
        forward[axis] += h;
        backward[axis] -= h;
        const double step = forward[axis] - backward[axis];
        const double difference = (evaluate<double>(*variant, forward) - evaluate<double>(*variant, backward)) / step;
        const double bound =
            step * step / 24.0 * third_derivative_bound(*variant) + 2.0 * value_rounding / step + gradient_rounding;
        ASSERT_NEAR(gradient[axis + 1], difference, bound) << variant->name << " axis " << axis << " at " << p[0]
                                                            << ", " << p[1] << ", " << p[2];
      }
    }
    EXPECT_GE(tested, samples * 9 / 10) << variant->name;
  }
}

// ---- the field ----

// Values stay in [-1, 1], and the mean is 0: each vertex's term t⁴ (g·d) is odd in d and its
// support (a ball, cut to the vertex's simplices with r2 = 0.6, a point-symmetric star) is
// symmetric, so it integrates to 0 over a period. Model: points iid uniform in [-2^28, 2^28)^n,
// i.e. over whole periods (period 256 cells, diameter under 256 n) up to a boundary share below
// n² 256 / 2^28 < 2e-5; the sample mean is then normal with standard deviation σ/sqrt(N): accept
// 5 σ̂/sqrt(N) + 2e-5.
TEST(Simplex, StaysInsideTheUnitIntervalAroundAMeanOfZero) {
  constexpr int samples = 100000;
  const gt::Permutation seeded = gt::seeded_permutation(7);
  for (const gt::Permutation* perm : {&perlin, &seeded}) {
    for (const Variant* variant : all_variants) {
      double sum = 0.0;
      double sum_of_squares = 0.0;
      double largest = 0.0;
      for (std::uint32_t sample = 0; sample < samples; ++sample) {
        Point p{};
        for (int axis = 0; axis < variant->dimension; ++axis) {
          const auto whole = static_cast<std::int32_t>(gt::random_u32(17, sample, axis, 0) >> 3) - (1 << 28);
          p[axis] = whole + static_cast<double>(gt::uniform01(gt::random_u32(17, sample, axis, 1)));
        }
        const double value = evaluate<double>(*variant, p, *perm);
        sum += value;
        sum_of_squares += value * value;
        largest = std::max(largest, std::abs(value));
      }
      const double mean = sum / samples;
      const double deviation = std::sqrt(sum_of_squares / samples - mean * mean);
      EXPECT_LE(largest, 1.0) << variant->name;
      EXPECT_GT(largest, 0.3) << variant->name;  // r2 = 0.5 with the seed's scales peaks near 0.43
      EXPECT_LE(std::abs(mean), 5.0 * deviation / std::sqrt(samples) + 2e-5) << variant->name;
    }
  }
}

// On the plane x = y every point has x0 = y0: a face between two simplices. Crossing it along
// (1, -1, 0) by ±ε changes a continuous field by at most L 2 sqrt(2) ε; the seed's kernel jumps.
// At (6.65625, 6.65625, 1.15625), the largest jump found on a 1/32 grid over [0, 8]², it jumps by
// 0.00632 (the bound J is 0.00701).
TEST(Simplex, CorrectedKernelIsContinuousAcrossFacesTheSeedsJumps) {
  constexpr double epsilon = 1e-9;
  const auto across = [&](const Variant& variant, double a, double z) {
    const double r2 = variant.kernel_radius_squared;
    return std::abs(ref::simplex3(perlin, a + epsilon, a - epsilon, z, r2) -
                    ref::simplex3(perlin, a - epsilon, a + epsilon, z, r2));
  };
  const auto continuity_bound = [&](const Variant& variant, double largest) {
    return gradient_bound(variant) * 2.0 * std::sqrt(2.0) * epsilon +
           2.0 * (gradient_bound(variant) * std::sqrt(3.0) * shared_offset_error(variant, largest, double_unit) +
                  evaluation_error(variant, double_unit));
  };
  EXPECT_GT(across(simplex3_seed, 6.65625, 1.15625), 0.006);
  EXPECT_LE(across(simplex3_corrected, 6.65625, 1.15625), continuity_bound(simplex3_corrected, 7.0));
  double largest_jump = 0.0;
  for (std::uint32_t sample = 0; sample < 20000; ++sample) {
    const double a = random_double(19, sample, 0, 64.0);
    const double z = random_double(19, sample, 1, 64.0);
    const double largest = std::max(std::abs(a), std::abs(z)) + 1.0;
    ASSERT_LE(across(simplex3_corrected, a, z), continuity_bound(simplex3_corrected, largest)) << a << ", " << z;
    const double jump = across(simplex3_seed, a, z);
    ASSERT_LE(jump, jump_bound(simplex3_seed) + continuity_bound(simplex3_seed, largest)) << a << ", " << z;
    largest_jump = std::max(largest_jump, jump);
  }
  EXPECT_GT(largest_jump, 1e-3);
}

// ---- permutations ----

TEST(Simplex, SeededPermutations) {
  EXPECT_EQ(gt::seeded_permutation(0), perlin);
  const gt::Permutation seeded = gt::seeded_permutation(7);
  std::array<int, 256> sorted{};
  std::copy(seeded.begin(), seeded.end(), sorted.begin());
  std::sort(sorted.begin(), sorted.end());
  std::array<int, 256> identity{};
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted, identity);
  EXPECT_NE(seeded, perlin);
  for (const TestVector& vector : digest_vectors) {
    const auto& p = vector.p;
    const double with_seed_0 = ref::simplex3(gt::seeded_permutation(0), p[0], p[1], p[2], 0.6);
    EXPECT_EQ(with_seed_0, ref::simplex3(perlin, p[0], p[1], p[2], 0.6));
    const double with_seed_7 = ref::simplex3(seeded, p[0], p[1], p[2], 0.6);
    if (vector.value != 0.0) {
      EXPECT_NE(with_seed_7, with_seed_0) << p[0] << ", " << p[1] << ", " << p[2];
    }
  }
}

// ---- the GLSL twin ----

// The numbers of `const float name = x;` or `const float name[k] = float[k](x, y, ...);` in the
// shader source, each parsed as C++ parses a float literal.
std::vector<float> glsl_constant(const std::string& source, const std::string& name) {
  const auto start = source.find("const float " + name);
  if (start == std::string::npos) return {};
  const std::string declaration = source.substr(start, source.find(';', start) - start);
  std::vector<float> numbers;
  const auto values = declaration.find('(') != std::string::npos ? declaration.find('(') : declaration.find('=');
  const char* cursor = declaration.c_str() + values + 1;
  while (*cursor != '\0') {
    if (*cursor == '.' || (*cursor >= '0' && *cursor <= '9')) {
      char* end = nullptr;
      numbers.push_back(std::strtof(cursor, &end));
      cursor = end;
    } else {
      ++cursor;
    }
  }
  return numbers;
}

TEST(SimplexGlslSource, LiteralsAreTheFloatsOfTheReferenceConstants) {
  std::ifstream file(gt::shader_root() / "noise" / "simplex.glsl");
  ASSERT_TRUE(file) << "cannot read noise/simplex.glsl";
  std::stringstream contents;
  contents << file.rdbuf();
  const std::string source = contents.str();
  const std::array<const ref::SimplexLattice*, 3> lattices{&ref::simplex_lattice2, &ref::simplex_lattice3,
                                                           &ref::simplex_lattice4};
  for (int dimension = 2; dimension <= 4; ++dimension) {
    const auto& lattice = *lattices[dimension - 2];
    const std::string suffix = std::to_string(dimension);
    std::vector<float> corner_unskew;
    for (int corner = 0; corner <= dimension; ++corner) {
      corner_unskew.push_back(static_cast<float>(lattice.corner_unskew[corner]));
    }
    EXPECT_EQ(glsl_constant(source, "GT_SIMPLEX_SKEW" + suffix), std::vector<float>{static_cast<float>(lattice.skew)});
    EXPECT_EQ(glsl_constant(source, "GT_SIMPLEX_CORNER_UNSKEW" + suffix), corner_unskew);
  }
}

class SimplexGlsl : public gt::testing::GlTest {};

TEST_F(SimplexGlsl, Compiles) { EXPECT_NO_THROW(gt::ComputeProgram::load("test/simplex_compile.comp")); }

}  // namespace
