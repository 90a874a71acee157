// The radially averaged power spectrum and its slope β (compare/descriptors/power_spectrum.hpp):
// β of synthesised fractional Brownian surfaces within a bound derived below, a sinusoid's peak at
// its frequency with unequal cell sizes, Parseval, refusals and no-data cells.
#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <random>
#include <type_traits>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compare/descriptors/power_spectrum.hpp"
#include "tests/support/refusal.hpp"

namespace {

using gt::testing::refusal;
using ::testing::HasSubstr;

struct Geometry {
  int width;
  int height;
  double dx;
  double dy;
};

gt::Heightmap flat_grid(const Geometry& geometry) {
  gt::Heightmap grid(geometry.width, geometry.height, 0.0);
  grid.cell_size_x = geometry.dx;
  grid.cell_size_y = geometry.dy;
  return grid;
}

struct PlanDestroy {
  void operator()(fftw_plan plan) const { fftw_destroy_plan(plan); }
};

// Signed DFT index of position `index` along an axis of n samples, in (-n/2, n/2].
int signed_index(int index, int n) { return 2 * index <= n ? index : index - n; }

// Makes the half spectrum Hermitian where r2c stores both twins: columns 0 and (even widths) the
// Nyquist column hold k and -k in rows j and height - j; self-twinned coefficients must be real.
void make_hermitian(std::vector<std::complex<double>>& half, int width, int height) {
  const int half_width = width / 2 + 1;
  for (int i : {0, width / 2}) {
    if (i == width / 2 && width % 2 != 0) continue;
    for (int j = 0; j < height; ++j) {
      auto& z = half[static_cast<std::size_t>(j) * half_width + i];
      const int twin = (height - j) % height;
      if (twin == j) z = std::abs(z) * (z.real() < 0.0 ? -1.0 : 1.0);
      if (twin < j) z = std::conj(half[static_cast<std::size_t>(twin) * half_width + i]);
    }
  }
}

// A fractional Brownian surface: every DFT coefficient has amplitude |f|^(-β/2) (f in cycles per
// metre, the mean 0) and a uniformly random phase, transformed back by FFTW's c2r.
gt::Heightmap fractal_surface(const Geometry& geometry, double beta, std::uint64_t seed) {
  const int half_width = geometry.width / 2 + 1;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::vector<std::complex<double>> half(static_cast<std::size_t>(geometry.height) * half_width);
  for (int j = 0; j < geometry.height; ++j) {
    const double frequency_y = signed_index(j, geometry.height) / (geometry.height * geometry.dy);
    for (int i = 0; i < half_width; ++i) {
      const double frequency = std::hypot(i / (geometry.width * geometry.dx), frequency_y);
      const double amplitude = frequency > 0.0 ? std::pow(frequency, -beta / 2.0) : 0.0;
      half[static_cast<std::size_t>(j) * half_width + i] = std::polar(amplitude, phase(random));
    }
  }
  make_hermitian(half, geometry.width, geometry.height);
  gt::Heightmap surface = flat_grid(geometry);
  const std::unique_ptr<std::remove_pointer_t<fftw_plan>, PlanDestroy> plan(
      fftw_plan_dft_c2r_2d(geometry.height, geometry.width, reinterpret_cast<fftw_complex*>(half.data()),
                           surface.values.data(), FFTW_ESTIMATE));
  fftw_execute(plan.get());
  return surface;
}

// Tolerance of the recovered β, derived before any run (the numbers come from the formulas below
// evaluated on the three grids' bin layouts: 14 to 17 bins inside the default band, the lowest
// holding 12 to 20 coefficients). The synthesis gives every coefficient exactly S ∝ f^-β on a
// periodic surface, so neither edge leakage nor random amplitudes add error. What remains:
//  (a) Window smoothing. The windowed periodogram is S convolved with |Ŵ|², a kernel whose per-axis
//      variance is σ_w² = 3.58/π² ≈ 0.36 coefficients² (continuous elliptical Hann:
//      (N/2π)²·∫|∂w/∂x|² / ∫w²). To second order ln S̃ - ln S = ½σ_w²·∇²S/S = σ_w²·β²/(2k²), k in
//      coefficients (the 2-D Laplacian of k^-β is β²·k^(-β-2)). It lifts the lowest bins, so β reads
//      high: the least-squares slope of this term over the band's bins is +0.0044·β² (0.039 at
//      β = 3); doubled for the higher orders that matter at k = 4 (in 1-D the exact (1/6, 2/3, 1/6)
//      smoothing of k^-3 at k = 4 lifts ln S by 0.137 against the second-order 0.118): ≤ +0.009·β².
//  (b) Few coefficients a bin. The window mixes about 9 neighbouring coefficients of random phase,
//      so each windowed |Z|² fluctuates (relative variance 1 - Σc⁴/(Σc²)² = 0.75 for Hann's
//      (¼, ½, ¼)² kernel; taken as 1) and neighbours are correlated (Σρ² = 1.94² ≈ 3.8 over the
//      kernel's lags). A bin of n coefficients (n/2 independent twins) then has relative variance
//      v ≤ 2·3.8/n = 7.6/n, and the log of its mean reads low by v/2 (Jensen), most in the lowest
//      bins: the least-squares slope of -v/2 over the bins is -0.110 to -0.127 in β.
//  (c) Detrending subtracts w·plane, whose spectrum sits in the lowest 2 to 3 coefficients and falls
//      as k^-3.5 beyond: under 1e-3 of S at k = 4, under 0.005 in β.
//  (d) A bin's power is the mean of S over its coefficients, its frequency their geometric mean; for
//      f^-β over 1/20 decade they differ by ≤ β²·var(ln f)/2 ≤ 0.005 in ln S, nearly equally in
//      every bin: under 0.005 in β.
// So the bias lies in [-0.14, +0.01 + 0.009·β²]. Random part: σ_β² = Σ(x_b - x̄)²·v_b / (Σ(x_b - x̄)²)²
// with x_b = ln f_b gives σ_β ≤ 0.25 for one surface (the lowest bins dominate); the mean of
// R = 64 surfaces has σ ≤ 0.031, of which 3σ = 0.094 is allowed. Bounds on the mean of R:
// β - 0.234 ≤ mean ≤ β + 0.104 + 0.009·β².
constexpr int realisations = 64;
constexpr double random_allowance = 0.094;
constexpr double bias_low = 0.14;

double bias_high(double beta) { return 0.01 + 0.009 * beta * beta; }

double mean_recovered_beta(const Geometry& geometry, double beta) {
  double sum = 0.0;
  for (int seed = 0; seed < realisations; ++seed) {
    const gt::Heightmap surface = fractal_surface(geometry, beta, 1000 * static_cast<std::uint64_t>(beta * 10) + seed);
    const auto [low, high] = gt::default_spectral_band(surface);
    const auto slope = gt::spectral_slope(gt::radial_power_spectrum(surface), low, high);
    if (!slope) {
      ADD_FAILURE() << "no slope for seed " << seed;
      return std::numeric_limits<double>::quiet_NaN();
    }
    sum += slope->beta;
  }
  return sum / realisations;
}

void expect_recovered_slopes(const Geometry& geometry) {
  for (double beta : {1.5, 2.0, 2.5, 3.0}) {
    SCOPED_TRACE(::testing::Message() << "beta " << beta);
    const double mean = mean_recovered_beta(geometry, beta);
    EXPECT_GE(mean, beta - bias_low - random_allowance);
    EXPECT_LE(mean, beta + bias_high(beta) + random_allowance);
  }
}

TEST(Spectrum, RecoversTheSlopeOfSynthesisedFractalSurfaces) { expect_recovered_slopes({256, 256, 1.0, 1.0}); }

TEST(Spectrum, RecoversTheSlopeWithUnequalCellSizes) { expect_recovered_slopes({256, 256, 1.0, 1.5}); }

TEST(Spectrum, RecoversTheSlopeOnANonSquareGrid) { expect_recovered_slopes({256, 192, 1.0, 1.0}); }

int bin_index(double frequency) {
  return static_cast<int>(std::floor(gt::spectrum_bins_per_decade * std::log10(frequency)));
}

// Σ_bins power·coefficients·Δfx·Δfy: the variance the spectrum holds.
double integrated_power(const gt::RadialSpectrum& spectrum, const gt::Heightmap& grid) {
  const double coefficient_area = 1.0 / (grid.width * grid.cell_size_x) / (grid.height * grid.cell_size_y);
  double total = 0.0;
  for (std::size_t i = 0; i < spectrum.power.size(); ++i) total += spectrum.power[i] * spectrum.coefficients[i];
  return total * coefficient_area;
}

// z = A·sin(2π(mx·x/Nx - my·y/Ny)) with whole cycles along both axes: mean and least-squares plane
// are exactly 0, so detrending leaves it whole. Its frequency is hypot(mx/(Nx·dx), my/(Ny·dy)); the
// minus sign puts its stored coefficient at a negative y index (row Ny - my of the half spectrum).
TEST(Spectrum, PutsASinusoidInTheBinOfItsFrequency) {
  const Geometry geometry{256, 256, 2.0, 3.0};
  const int cycles_x = 24, cycles_y = 54;
  const double amplitude = 3.0;
  gt::Heightmap wave = flat_grid(geometry);
  for (int y = 0; y < geometry.height; ++y) {
    for (int x = 0; x < geometry.width; ++x) {
      const double phase = 2.0 * std::numbers::pi *
                            (cycles_x * x / double(geometry.width) - cycles_y * y / double(geometry.height));
      wave.at(x, y) = amplitude * std::sin(phase);
    }
  }
  const double length_x = geometry.width * geometry.dx, length_y = geometry.height * geometry.dy;
  const double frequency = std::hypot(cycles_x / length_x, cycles_y / length_y);
  // Chosen mid-bin (0.54 of the way), and cell sizes swapped would move it two bins: the check tells
  // dx from dy.
  const double swapped = std::hypot(cycles_x / (geometry.width * geometry.dy), cycles_y / (geometry.height * geometry.dx));
  ASSERT_NE(bin_index(frequency), bin_index(swapped));

  const gt::RadialSpectrum spectrum = gt::radial_power_spectrum(wave);
  const auto peak = static_cast<std::size_t>(
      std::max_element(spectrum.power.begin(), spectrum.power.end()) - spectrum.power.begin());
  // Every coefficient but the zero-frequency one, none beyond the corner of the Nyquist rectangle.
  EXPECT_EQ(std::accumulate(spectrum.coefficients.begin(), spectrum.coefficients.end(), 0),
            geometry.width * geometry.height - 1);
  EXPECT_LE(spectrum.frequency_per_m.back(), std::hypot(0.5 / geometry.dx, 0.5 / geometry.dy));
  EXPECT_EQ(bin_index(spectrum.frequency_per_m[peak]), bin_index(frequency));
  EXPECT_NEAR(std::log10(spectrum.frequency_per_m[peak] / frequency), 0.0, 1.0 / gt::spectrum_bins_per_decade);
  // The window's normalisation keeps the variance A²/2 up to Σw²·cos(2·phase)/Σw², the transform of
  // the smooth w² at twice the wave's frequency (over 100 coefficients out): far below 1e-3.
  EXPECT_NEAR(integrated_power(spectrum, wave), amplitude * amplitude / 2.0, 1e-3 * amplitude * amplitude / 2.0);
}

// 2.5 cycles of a cosine across the grid: its periodic extension jumps at the edges, which without a
// window leaks power falling only as f^-2 (amplitude ∝ 1/k for a jump). The elliptical Hann window
// vanishes with its slope at the ellipse, so the tapered field is smooth and its leakage falls at
// least as k^-6; 25 coefficients and more from the wave that is a factor of 25^4 ≈ 4e5 below the
// plain leakage. Asserted: the windowed power above 25 cycles is under 1e-2 of the plain one.
TEST(Spectrum, WindowSuppressesLeakageFromTheEdges) {
  gt::Heightmap wave = flat_grid({128, 128, 1.0, 1.0});
  for (int y = 0; y < wave.height; ++y) {
    for (int x = 0; x < wave.width; ++x) wave.at(x, y) = std::cos(2.0 * std::numbers::pi * 2.5 * x / 128.0);
  }
  const auto power_above = [](const gt::RadialSpectrum& spectrum, double frequency) {
    double total = 0.0;
    for (std::size_t i = 0; i < spectrum.power.size(); ++i) {
      if (spectrum.frequency_per_m[i] > frequency) total += spectrum.power[i] * spectrum.coefficients[i];
    }
    return total;
  };
  const double windowed = power_above(gt::radial_power_spectrum(wave), 25.0 / 128.0);
  const double plain = power_above(gt::radial_power_spectrum(wave, {.hann_window = false}), 25.0 / 128.0);
  EXPECT_LT(windowed, 1e-2 * plain);
}

// White noise made point-symmetric about the grid's centre (z(x, y) = z(Nx-1-x, Ny-1-y)): its
// least-squares plane is flat, so the detrended heights are the heights less their mean.
gt::Heightmap symmetric_noise(const Geometry& geometry, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(5.0, 2.0);
  gt::Heightmap grid = flat_grid(geometry);
  for (double& value : grid.values) value = noise(random);
  gt::Heightmap symmetric = grid;
  for (int y = 0; y < geometry.height; ++y) {
    for (int x = 0; x < geometry.width; ++x) {
      symmetric.at(x, y) = grid.at(x, y) + grid.at(geometry.width - 1 - x, geometry.height - 1 - y);
    }
  }
  return symmetric;
}

double valid_variance(const gt::Heightmap& grid) {
  double sum = 0.0, sum_squares = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!grid.is_valid(i)) continue;
    sum += grid.values[i];
    ++count;
  }
  const double mean = sum / static_cast<double>(count);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.is_valid(i)) sum_squares += (grid.values[i] - mean) * (grid.values[i] - mean);
  }
  return sum_squares / static_cast<double>(count);
}

// Parseval holds exactly for the un-windowed periodogram: only rounding (about 1e-15 a term, 1e-12
// over the few thousand) separates the two sides.
TEST(Spectrum, SumsToTheVarianceWithoutTheWindow) {
  const Geometry geometry{64, 48, 0.5, 2.0};
  gt::Heightmap noise = symmetric_noise(geometry, 7);
  const gt::SpectrumOptions plain{.hann_window = false};
  EXPECT_NEAR(integrated_power(gt::radial_power_spectrum(noise, plain), noise), valid_variance(noise),
              1e-10 * valid_variance(noise));

  // A point-symmetric mask keeps the plane flat; the spectrum then sums to the valid cells' variance.
  noise.valid.assign(noise.size(), 1);
  for (int x = 10; x < 30; ++x) {
    noise.valid[noise.index(x, 5)] = 0;
    noise.valid[noise.index(geometry.width - 1 - x, geometry.height - 1 - 5)] = 0;
  }
  const gt::RadialSpectrum masked = gt::radial_power_spectrum(noise, plain);
  EXPECT_EQ(masked.masked_cells, 40u);
  EXPECT_NEAR(integrated_power(masked, noise), valid_variance(noise), 1e-10 * valid_variance(noise));
}

TEST(Spectrum, RefusesAPlane) {
  gt::Heightmap plane = flat_grid({40, 30, 2.0, 0.5});
  for (int y = 0; y < plane.height; ++y) {
    for (int x = 0; x < plane.width; ++x) plane.at(x, y) = 1200.0 + 0.3 * x * 2.0 - 0.2 * y * 0.5;
  }
  EXPECT_THAT(refusal([&] { gt::radial_power_spectrum(plane); }), HasSubstr("a plane has no spectrum"));
}

TEST(Spectrum, RefusesSmallGridsAndMasksThatLeaveNothingToMeasure) {
  EXPECT_THAT(refusal([] { gt::radial_power_spectrum(symmetric_noise({15, 64, 1.0, 1.0}, 1)); }),
              HasSubstr("too small for a spectrum: the grid is 15x64 cells"));
  gt::Heightmap one_row = symmetric_noise({32, 32, 1.0, 1.0}, 2);
  one_row.valid.assign(one_row.size(), 0);
  for (int x = 0; x < one_row.width; ++x) one_row.valid[one_row.index(x, 5)] = 1;
  EXPECT_THAT(refusal([&] { gt::radial_power_spectrum(one_row); }), HasSubstr("lie on one line"));
  // The four corners (random heights, off any one plane) fix a plane but lie outside the ellipse
  // inscribed in the grid (ρ = 1.33 there).
  gt::Heightmap corners = one_row;
  corners.valid.assign(corners.size(), 0);
  for (int y : {0, 31}) {
    for (int x : {0, 31}) corners.valid[corners.index(x, y)] = 1;
  }
  EXPECT_THAT(refusal([&] { gt::radial_power_spectrum(corners); }), HasSubstr("outside the elliptical window"));
}

// No-data cells are counted and their stored values never read: NaN or 1e300 there changes nothing.
TEST(Spectrum, CountsAndIgnoresNoDataCells) {
  gt::Heightmap surface = fractal_surface({64, 64, 1.0, 1.0}, 2.0, 3);
  surface.valid.assign(surface.size(), 1);
  for (int i = 0; i < 37; ++i) surface.valid[static_cast<std::size_t>(i) * 97 % surface.size()] = 0;
  const gt::RadialSpectrum reference = gt::radial_power_spectrum(surface);
  EXPECT_EQ(reference.masked_cells, 37u);
  for (double stored : {std::numeric_limits<double>::quiet_NaN(), 1e300}) {
    gt::Heightmap altered = surface;
    for (std::size_t i = 0; i < altered.size(); ++i) {
      if (!altered.is_valid(i)) altered.values[i] = stored;
    }
    const gt::RadialSpectrum spectrum = gt::radial_power_spectrum(altered);
    EXPECT_EQ(spectrum.power, reference.power);
    EXPECT_EQ(spectrum.masked_cells, 37u);
  }
}

TEST(Spectrum, DefaultBandAndTooFewBins) {
  const auto [low, high] = gt::default_spectral_band(flat_grid({256, 192, 2.0, 3.0}));
  EXPECT_DOUBLE_EQ(low, 4.0 / 512.0);  // 4 cycles across the shorter side, 256 x 2 m
  EXPECT_DOUBLE_EQ(high, 1.0 / 24.0);  // wavelengths of 8 of the coarser 3 m cells
  const gt::Heightmap small = symmetric_noise({32, 32, 1.0, 1.0}, 4);
  const auto [small_low, small_high] = gt::default_spectral_band(small);
  EXPECT_GE(small_low, small_high);  // 4 cycles across 32 cells is the quarter-Nyquist wavelength of 8 cells
  const gt::RadialSpectrum spectrum = gt::radial_power_spectrum(small);
  EXPECT_FALSE(gt::spectral_slope(spectrum, small_low, small_high));
  EXPECT_FALSE(gt::spectral_slope(spectrum, 0.1, 0.1));
  EXPECT_TRUE(gt::spectral_slope(spectrum, 0.0, 1.0));
}

}  // namespace
