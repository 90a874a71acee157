// Spherical power spectra (compare/descriptors/spherical_spectrum.hpp) of fields whose spectrum is
// known in closed form, the exponent fit, and the nearest-cell sampler of a global grid
// (compare/descriptors/global_relief.hpp) that feeds the Earth's relief to them.
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "compare/descriptors/global_relief.hpp"
#include "compare/descriptors/spherical_spectrum.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

// f = P_2(z) = (3z² − 1)/2 = sqrt(4π/5)·Y_20, so a_20 = sqrt(4π/5) and C_2 = a_20²/5 = 4π/25, every
// other C_l = 0. HEALPix's ring quadrature is not exact even for band-limited fields (a constant's
// C_0 comes out 5e-6 low at nside 8, C_1 1e-5 low: seen once while writing these tests, after 3
// Jacobi iterations); the bound 1e-4 of the power leaves a factor 10 over that and still catches any
// slip of normalisation or sampling (4π, 2l + 1, a wrong axis), each a factor of order 1.
constexpr double quadrature_error = 1e-4;

TEST(SphericalSpectrum, ADegreeTwoZonalFieldHasAllItsPowerAtDegreeTwo) {
  const auto spectrum = angular_power_spectrum(
      [](const std::array<double, 3>& direction) { return 1.5 * direction[2] * direction[2] - 0.5; }, 16, 32);
  ASSERT_EQ(spectrum.size(), 33u);
  const double expected = 4.0 * std::numbers::pi / 25.0;
  EXPECT_NEAR(spectrum[2], expected, quadrature_error * expected);
  for (std::size_t degree = 0; degree < spectrum.size(); ++degree) {
    if (degree != 2) {
      EXPECT_LT(spectrum[degree], quadrature_error * expected) << "degree " << degree;
    }
  }
}

// A constant c: a_00 = c·sqrt(4π), C_0 = 4π·c², nothing else; a rotation moves power only within a
// degree, so z and x (both pure l = 1) have the same C_1 = 4π/9 (z = sqrt(4π/3)·Y_10, C_1 = a²/3).
TEST(SphericalSpectrum, TheMeanIsDegreeZeroAndADirectionOfLDegreeOneHasTheSamePowerWhereverItPoints) {
  const auto constant = angular_power_spectrum([](const std::array<double, 3>&) { return -2.0; }, 8, 16);
  EXPECT_NEAR(constant[0], 4.0 * std::numbers::pi * 4.0, quadrature_error * 16.0 * std::numbers::pi);
  const auto along_z = angular_power_spectrum([](const std::array<double, 3>& d) { return d[2]; }, 8, 16);
  const auto along_x = angular_power_spectrum([](const std::array<double, 3>& d) { return d[0]; }, 8, 16);
  const double expected = 4.0 * std::numbers::pi / 9.0;
  EXPECT_NEAR(along_z[1], expected, quadrature_error * expected);
  EXPECT_NEAR(along_x[1], expected, quadrature_error * expected);
}

TEST(SphericalSpectrum, TheExponentOfAnExactPowerLawIsItsPower) {
  std::vector<double> spectrum(65, 0.0);  // C_0 = 0 lies outside every band
  for (std::size_t degree = 1; degree < spectrum.size(); ++degree) spectrum[degree] = 3.0 * std::pow(double(degree), -2.5);
  EXPECT_NEAR(spectral_exponent(spectrum, 2, 64), 2.5, 1e-12);
  EXPECT_NEAR(spectral_exponent(spectrum, 10, 20), 2.5, 1e-12);
}

TEST(SphericalSpectrum, RefusesWhatItCannotTransformOrFit) {
  const auto zero = [](const std::array<double, 3>&) { return 0.0; };
  EXPECT_THROW(angular_power_spectrum(zero, 8, 24), InputError) << "lmax beyond 3·nside − 1";
  EXPECT_THROW(angular_power_spectrum(zero, 0, 1), InputError);
  EXPECT_THROW(angular_power_spectrum([](const std::array<double, 3>&) { return std::nan(""); }, 4, 8), InputError);
  const std::vector<double> flat(10, 1.0), with_zero{1.0, 1.0, 0.0, 1.0};
  EXPECT_THROW(spectral_exponent(flat, 0, 5), InputError) << "log 0";
  EXPECT_THROW(spectral_exponent(flat, 5, 5), InputError);
  EXPECT_THROW(spectral_exponent(flat, 2, 10), InputError) << "beyond the last degree";
  EXPECT_THROW(spectral_exponent(with_zero, 1, 3), InputError);
}

// ETOPO's layout: rows south first, columns from 20° E on (centres 25, 35, ..., 375), value
// 100·row + column, one no-data cell. Directions: latitude asin(z), longitude atan2(y, x).
TEST(NearestCellSampler, FindsTheNearestCellRoundTheCircleAndGivesNoDataItsStandIn) {
  GlobalGrid grid;
  grid.elevation = Grid<double>(36, 18);
  grid.elevation.valid.assign(grid.elevation.values.size(), 1);
  for (int row = 0; row < 18; ++row) {
    grid.latitudes.push_back(-85.0 + 10.0 * row);
    for (int column = 0; column < 36; ++column) grid.elevation.values[std::size_t(row * 36 + column)] = 100.0 * row + column;
  }
  for (int column = 0; column < 36; ++column) grid.longitudes.push_back(25.0 + 10.0 * column);
  grid.elevation.valid[std::size_t(17 * 36 + 3)] = 0;
  const auto sample = nearest_cell_sampler(grid, -1.0);
  const auto at = [&](double latitude, double longitude) {
    const double phi = latitude * std::numbers::pi / 180.0, lambda = longitude * std::numbers::pi / 180.0;
    return sample({std::cos(phi) * std::cos(lambda), std::cos(phi) * std::sin(lambda), std::sin(phi)});
  };
  EXPECT_EQ(at(1.0, 21.0), 900.0 + 0.0) << "25° E is nearer than 15° E (375°)";
  EXPECT_EQ(at(1.0, 19.0), 900.0 + 35.0) << "15° E, the last column, round the circle";
  EXPECT_EQ(at(-1.0, -170.0), 800.0 + 16.0) << "190° E";
  EXPECT_EQ(at(-89.9, 26.0), 0.0) << "south row first";
  EXPECT_EQ(at(88.0, 44.0), 1700.0 + 2.0);
  EXPECT_EQ(at(88.0, 56.0), -1.0) << "the no-data cell at 55° E gives the stand-in";
}

}  // namespace
}  // namespace gt
