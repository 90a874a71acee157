// Beneš's dissolution erosion (reference/erosion/dissolution.cpp, gpu/erosion/dissolution.cpp):
// eq. 2.9's pair rule on the reference in double, what the model conserves on a masked terrain, the
// masked cells left alone, and the GPU twin against ref<float> (one step from a wet state, within the
// rounding-interval bound of that step) on a grid whose sides are not multiples of the 16x16 work
// groups, with two runs giving the same bits.
#include <cmath>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "core/params/dissolution.hpp"
#include "core/rounding_interval.hpp"
#include "core/sum.hpp"
#include "gpu/erosion/dissolution.hpp"
#include "reference/erosion/dissolution.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"

namespace {

using gt::DissolutionState;
using gt::Grid;

template <class Real>
DissolutionState<Real> dry_state(const Grid<Real>& terrain) {
  Grid<Real> zero = terrain;
  std::fill(zero.values.begin(), zero.values.end(), Real(0));
  return {terrain, zero, zero, zero};
}

// The 2x1 pair of the thesis's example: terrain 0 | `high`, no water yet.
DissolutionState<double> pair(double high) {
  Grid<double> terrain(2, 1, 0.0);
  terrain.at(1, 0) = high;
  return dry_state(terrain);
}

gt::DissolutionConstants rain_only(double rain) {
  gt::DissolutionParams params;
  params.rain = rain;
  params.evaporation = 0.0;
  params.evaporation_threshold = 0.0;
  params.saturation = 0.0;
  return gt::dissolution_constants(params);
}

TEST(Dissolution, ThePairLevelsItsSurfacesByEquation2_9) {
  // After rain 1: b = 1, w = 1 against b' = 0, w' = 1; ŵ = 0.5, so 0.5 moves and both surfaces are 1.5.
  const auto level = gt::reference::dissolution_erosion(pair(1.0), rain_only(1.0), 1);
  EXPECT_EQ(level.water.at(1, 0), 0.5);
  EXPECT_EQ(level.water.at(0, 0), 1.5);
  // b = 3: ŵ = −0.5 < 0, all the water moves.
  const auto all_down = gt::reference::dissolution_erosion(pair(3.0), rain_only(1.0), 1);
  EXPECT_EQ(all_down.water.at(1, 0), 0.0);
  EXPECT_EQ(all_down.water.at(0, 0), 2.0);
}

double total(const Grid<double>& a, const Grid<double>& b) {
  gt::CompensatedSum sum;
  for (std::size_t cell = 0; cell < a.size(); ++cell) {
    if (a.is_valid(cell)) sum.add(a.values[cell] + b.values[cell]);
  }
  return sum.value();
}

TEST(Dissolution, ConservesMaterialAndBooksEveryDropOfWaterOnAMaskedTerrain) {
  const Grid<double> terrain = gt::testing::masked_terrain(3, 18, 11, 12).cast<double>();
  gt::DissolutionParams params;
  params.rain = 0.05;
  params.saturation = 0.2;
  params.deposition_rate = 0.5;
  const int iterations = 40;
  const auto start = dry_state(terrain);
  const auto end = gt::reference::dissolution_erosion(start, gt::dissolution_constants(params), iterations);
  std::size_t valid = 0;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) valid += terrain.is_valid(cell) ? 1 : 0;
  const double rained = iterations * params.rain * static_cast<double>(valid);
  // Worst case of the additions' rounding in double (35 a cell and iteration on at most twice the
  // water, 35 on twice Σ(|b| + s)): far below these, which a lost share of any cell's water exceeds.
  EXPECT_NEAR(total(end.water, end.evaporated), rained, 1e-9 * rained);
  EXPECT_NEAR(total(end.terrain, end.dissolved), total(terrain, start.dissolved), 1e-12 * 520.0 * valid);
  double moved = 0.0;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) {
      EXPECT_EQ(end.terrain.values[cell], terrain.values[cell]);
      EXPECT_EQ(end.water.values[cell], 0.0);
      continue;
    }
    moved = std::max(moved, std::abs(end.terrain.values[cell] - terrain.values[cell]));
    // A cell that gives all its water keeps the rounding of its eight subtractions: at most 8u of a
    // depth under 2 m (40 iterations of 5 cm, less what evaporates).
    EXPECT_GE(end.water.values[cell], -8.0 * 0x1p-53 * 2.0);
  }
  EXPECT_GT(moved, 1e-3) << "the terrain should have dissolved somewhere";
}

class DissolutionGpu : public gt::testing::GlTest {};

TEST_F(DissolutionGpu, StepsAsTheFloatReferenceWithinItsRoundingIntervalAndRepeats) {
  const Grid<float> terrain = gt::testing::masked_terrain(7, 9, 14, 10);
  gt::DissolutionParams params;
  params.rain = 0.05;
  params.saturation = 0.1;
  const auto constants = gt::dissolution_constants(params);
  // A wet state with dissolved material everywhere, from ref<float>.
  const auto wet = gt::reference::dissolution_erosion(dry_state(terrain), constants, 12);
  gt::gpu::DissolutionErosion gpu(terrain.width, terrain.height, constants);
  gpu.load(wet);
  gpu.step(1);
  const auto stepped = gpu.result();
  const auto reference = gt::reference::dissolution_erosion(wet, constants, 1);
  // The same step in rounding-interval arithmetic holds ref<float>'s and any float implementation
  // of the same operations (GLSL's 2.5-ulp division included): within twice its width.
  const auto to_interval = [](const Grid<float>& grid) {
    Grid<gt::RoundingInterval> interval(grid.width, grid.height);
    interval.valid = grid.valid;
    for (std::size_t cell = 0; cell < grid.size(); ++cell) interval.values[cell] = gt::RoundingInterval::exact(grid.values[cell]);
    return interval;
  };
  const auto bounds = gt::reference::dissolution_erosion(
      DissolutionState<gt::RoundingInterval>{to_interval(wet.terrain), to_interval(wet.water), to_interval(wet.dissolved),
                                             to_interval(wet.evaporated)},
      constants, 1);
  for (const auto& [gpu_field, reference_field, bound] :
       {std::tuple{&stepped.terrain, &reference.terrain, &bounds.terrain},
        std::tuple{&stepped.water, &reference.water, &bounds.water},
        std::tuple{&stepped.dissolved, &reference.dissolved, &bounds.dissolved},
        std::tuple{&stepped.evaporated, &reference.evaporated, &bounds.evaporated}}) {
    for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
      if (!terrain.is_valid(cell)) continue;
      ASSERT_LE(std::abs(double(gpu_field->values[cell]) - reference_field->values[cell]),
                2.0 * bound->values[cell].width())
          << "cell " << cell;
    }
  }
  EXPECT_GT(wet.dissolved.values[terrain.index(30, 5)], 0.0f) << "the state should be wet and dissolving";
}

TEST_F(DissolutionGpu, TwoRunsGiveTheSameBitsSteppedInPiecesOrInOneGo) {
  const Grid<float> terrain = gt::testing::masked_terrain(7, 9, 14, 10);
  gt::DissolutionParams params;
  params.rain = 0.05;
  const auto constants = gt::dissolution_constants(params);
  const auto start = dry_state(terrain);
  gt::gpu::DissolutionErosion gpu(terrain.width, terrain.height, constants);
  gpu.load(start);
  gpu.step(25);
  const auto whole = gpu.result();
  gpu.load(start);
  gpu.step(10);
  gpu.step(15);
  const auto pieces = gpu.result();
  for (const auto& [first, second] : {std::pair{&whole.terrain, &pieces.terrain}, std::pair{&whole.water, &pieces.water},
                                      std::pair{&whole.dissolved, &pieces.dissolved},
                                      std::pair{&whole.evaporated, &pieces.evaporated}}) {
    for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
      if (!terrain.is_valid(cell)) continue;
      ASSERT_EQ(first->values[cell], second->values[cell]) << "cell " << cell;
    }
  }
}

}  // namespace
