// Properties of the thermal-erosion references (reference/erosion/thermal*.cpp) that hold
// whatever the GPU does: the seed's worked example, conservation, borders and masks, odd
// iteration counts, rest states, and the talus formula of eq. 4.10.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "compare/checks/field.hpp"
#include "core/params/thermal.hpp"
#include "core/rng.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"
#include "tests/support/printers.hpp"

namespace {

using gt::Grid;
using gt::Neighbourhood;
using gt::ThermalConstants;

ThermalConstants unit_constants(double talus_slope, double request_factor) {
  ThermalConstants constants;
  constants.talus_slope = talus_slope;
  constants.length_x = constants.length_y = 1.0;
  constants.length_diagonal = std::sqrt(2.0);
  constants.request_factor = request_factor;
  return constants;
}

// Rough terrain: 0..height_scale uniform noise plus a slope, on 1 m cells.
Grid<double> rough_field(int width, int height, double height_scale, std::uint32_t seed) {
  Grid<double> field(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto bits = gt::random_u32(seed, static_cast<std::uint32_t>(field.index(x, y)), 0, 0);
      field.at(x, y) = 500.0 + 0.3 * x + height_scale * gt::uniform01(bits);
    }
  }
  return field;
}

double largest_excess(const Grid<double>& field, double talus_slope) {
  double excess = 0.0;
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x + 1 < field.width; ++x) {
      excess = std::max(excess, std::abs(field.at(x + 1, y) - field.at(x, y)) - talus_slope);
    }
  }
  return excess;
}

TEST(ThermalReference, ReproducesTheSeedsThreeByThreeExample) {
  Grid<double> field(3, 3, 0.0);
  field.at(1, 1) = 1.0;
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.25, 0.5), 1, Neighbourhood::cardinal);
  EXPECT_EQ(eroded.at(1, 1), 0.625);
  for (auto [x, y] : {std::pair{0, 1}, {2, 1}, {1, 0}, {1, 2}}) EXPECT_EQ(eroded.at(x, y), 0.09375);
  for (auto [x, y] : {std::pair{0, 0}, {2, 0}, {0, 2}, {2, 2}}) EXPECT_EQ(eroded.at(x, y), 0.0);
  EXPECT_EQ(gt::field_totals(eroded).sum, 1.0);
}

TEST(ThermalReference, FloatReferenceGivesTheSameExample) {
  Grid<float> field(3, 3, 0.0f);
  field.at(1, 1) = 1.0f;
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.25, 0.5), 1, Neighbourhood::cardinal);
  EXPECT_EQ(eroded.at(1, 1), 0.625f);
  EXPECT_EQ(eroded.at(0, 1), 0.09375f);
}

TEST(ThermalReference, TalusOfEquation4_10) {
  EXPECT_DOUBLE_EQ(gt::talus_threshold_eq_4_10(45.0, 512, 1.0), 0.001953125);
  // The digest's dimensional check: eq. 4.10 is twice as steep as tan α / (width·d_z/2).
  EXPECT_NEAR(gt::talus_threshold_eq_4_10(30.0, 100, 2.0), std::tan(std::numbers::pi / 6) / 200.0, 1e-15);
}

class ThermalNeighbourhoods : public ::testing::TestWithParam<Neighbourhood> {};

TEST_P(ThermalNeighbourhoods, ConservesMaterialInDouble) {
  const auto field = rough_field(41, 29, 30.0, 5);
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.5, 0.5), 60, GetParam());
  // 240 additions per cell, each rounding by at most 2^-53 relative: worst case 240·2^-53 ≈ 2.7e-14.
  EXPECT_LE(gt::relative_mass_drift(field, eroded), 240 * 0x1p-53);
  EXPECT_GT(gt::field_difference(field, eroded).max_abs, 1.0) << "the field should have changed";
}

TEST_P(ThermalNeighbourhoods, OddIterationCountsReturnTheLastState) {
  const auto field = rough_field(23, 17, 10.0, 9);
  const auto constants = unit_constants(0.5, 0.5);
  const auto three = gt::reference::thermal_erosion(field, constants, 3, GetParam());
  const auto two = gt::reference::thermal_erosion(field, constants, 2, GetParam());
  // Iteration index 2 is even: alternating runs it with the cardinal pipes.
  const auto third_pipes = GetParam() == Neighbourhood::diagonal ? Neighbourhood::diagonal : Neighbourhood::cardinal;
  const auto two_then_one = gt::reference::thermal_erosion(two, constants, 1, third_pipes);
  EXPECT_EQ(gt::field_difference(three, two_then_one).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(three, two).max_abs, 0.0);
}

TEST_P(ThermalNeighbourhoods, MaskedCellsNeitherGiveNorReceive) {
  auto field = rough_field(20, 20, 40.0, 11);
  field.valid.assign(field.size(), 1);
  for (int y = 5; y < 12; ++y) {
    for (int x = 6; x < 9; ++x) {
      field.valid[field.index(x, y)] = 0;
      field.at(x, y) = (x + y) % 2 == 0 ? -1000.0 : 5000.0;  // would pull or push hard if it took part
    }
  }
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.3, 0.5), 20, GetParam());
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (!field.is_valid(i)) {
      EXPECT_EQ(eroded.values[i], field.values[i]);
    }
  }
  EXPECT_LE(gt::relative_mass_drift(field, eroded), 80 * 0x1p-53);
  const auto totals = gt::field_totals(eroded);
  EXPECT_GT(totals.low, 400.0) << "no valid cell may move towards a masked one";
  EXPECT_LT(totals.high, 600.0);
}

TEST_P(ThermalNeighbourhoods, NoFlowAcrossTheBorder) {
  // A single tall column in the corner: material can only go inwards; the total stays.
  Grid<double> field(8, 8, 0.0);
  field.at(0, 0) = 10.0;
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.5, 0.5), 30, GetParam());
  EXPECT_NEAR(gt::field_totals(eroded).sum, 10.0, 1e-13);
  EXPECT_LT(eroded.at(0, 0), 10.0);
}

TEST_P(ThermalNeighbourhoods, SlopesWithinTheTalusStayAtRest) {
  Grid<double> field(16, 12);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) field.at(x, y) = 0.2 * x + 0.1 * y;
  }
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(0.5, 0.5), 10, GetParam());
  EXPECT_EQ(gt::field_difference(field, eroded).differing_bits, 0u);
}

INSTANTIATE_TEST_SUITE_P(Modes, ThermalNeighbourhoods,
                         ::testing::Values(Neighbourhood::cardinal, Neighbourhood::diagonal, Neighbourhood::alternating));

TEST(ThermalReference, CardinalErosionApproachesTheTalusSlope) {
  const auto field = rough_field(24, 24, 40.0, 13);
  const double talus = 0.5;
  const auto eroded = gt::reference::thermal_erosion(field, unit_constants(talus, 1.0), 400, Neighbourhood::cardinal);
  EXPECT_LT(largest_excess(eroded, talus), 0.05 * largest_excess(field, talus));
}

TEST(ThermalJakoReference, ConservesMaterialAndRespectsTheMask) {
  auto field = rough_field(30, 22, 30.0, 17);
  field.valid.assign(field.size(), 1);
  field.valid[field.index(10, 10)] = 0;
  field.at(10, 10) = -1e4;
  const auto eroded = gt::reference::thermal_jako_erosion(field, unit_constants(0.5, 0.5), 50);
  // 16 additions per cell and iteration: worst case 800·2^-53.
  EXPECT_LE(gt::relative_mass_drift(field, eroded), 800 * 0x1p-53);
  EXPECT_EQ(eroded.at(10, 10), -1e4);
  EXPECT_GT(gt::field_totals(eroded).low, 400.0);
}

TEST(ThermalJakoReference, MovesHalfTheDropTimesTheRate) {
  // Eq. 2.32 with one lower neighbour: ΔS = rate·H/2 leaves the top cell and arrives below.
  Grid<double> field(2, 1, 0.0);
  field.at(0, 0) = 4.0;
  const auto eroded = gt::reference::thermal_jako_erosion(field, unit_constants(1.0, 0.5), 1);
  EXPECT_DOUBLE_EQ(eroded.at(0, 0), 3.0);
  EXPECT_DOUBLE_EQ(eroded.at(1, 0), 1.0);
}

TEST(ThermalJakoReference, SplitsInProportionToHeightDifferences) {
  // Eq. 2.34 with differences: drops 3 and 1 to the two lower neighbours -> shares 3/4 and 1/4.
  Grid<double> field(3, 1, 0.0);
  field.at(0, 0) = 1.0;
  field.at(1, 0) = 4.0;
  field.at(2, 0) = 3.0;
  auto constants = unit_constants(0.5, 1.0);
  const auto eroded = gt::reference::thermal_jako_erosion(field, constants, 1);
  // The middle cell sends rate·H/2 = 1.5: 1.125 to the left, 0.375 to the right; the outer cells
  // have no lower neighbour and send nothing.
  EXPECT_DOUBLE_EQ(eroded.at(1, 0), 2.5);
  EXPECT_DOUBLE_EQ(eroded.at(0, 0), 2.125);
  EXPECT_DOUBLE_EQ(eroded.at(2, 0), 3.375);
}

TEST(ThermalJakoReference, TheHardnessMapScalesTheMoveAndSteepensTheTalusBelowAHardNeighbour) {
  // Eqs. 2.32-2.33 by hand on a row 0, 1, 0 with C_i = 0, C_a = 0.5, rate 0.5 and R = 2, 1, 0: the
  // left neighbour's threshold is (0.5·2 + 0)·1 = 1, not exceeded by its drop of 1, so only the
  // right one (threshold 0) takes part; the middle moves rate·R·H/2 = 0.5·1·1/2 = 0.25 to it. With
  // R = 0 in the middle nothing moves at all.
  Grid<double> field(3, 1, 0.0);
  field.at(1, 0) = 1.0;
  auto constants = unit_constants(0.0, 0.5);
  constants.hardness_talus = 0.5;
  constants.hardness = {2.0, 1.0, 0.0};
  const auto eroded = gt::reference::thermal_jako_erosion(field, constants, 1);
  EXPECT_EQ(eroded.at(0, 0), 0.0);
  EXPECT_EQ(eroded.at(1, 0), 0.75);
  EXPECT_EQ(eroded.at(2, 0), 0.25);
  constants.hardness = {2.0, 0.0, 0.0};
  EXPECT_EQ(gt::reference::thermal_jako_erosion(field, constants, 1).values, field.values);
}

}  // namespace
