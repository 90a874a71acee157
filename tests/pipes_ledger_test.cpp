// The pipe ledgers against what was asked (compare/checks/pipe_error_model.hpp, issue 11): the
// volume asked for is computed on the host from the parameters and the forcing alone; the twins'
// water added and evaporated meet it within the derived rounding bounds, and a reference with the
// rain halved or the evaporation doubled (the registered mutants) is flagged, although its own
// water balance still closes.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compare/checks/pipe_error_model.hpp"
#include "core/mutant.hpp"
#include "core/params/hydraulic.hpp"
#include "reference/erosion/pipes.hpp"
#include "tests/support/pipe_fields.hpp"

namespace {

using gt::HydraulicForcing;
using gt::HydraulicParams;
using gt::testing::field;
using gt::testing::noise;

// 10 x 8 cells of 2 m x 1 m with 3 no-data cells: 77 valid cells of 2 m².
gt::Grid<double> basin() {
  auto terrain = field(10, 8, 2.0, 1.0, [](int x, int y) { return 1.0 + 0.3 * std::sin(0.6 * x + 0.4 * y) + 0.1 * noise(x, y, 3); });
  terrain.valid.assign(terrain.size(), 1);
  terrain.valid[terrain.index(0, 0)] = terrain.valid[terrain.index(4, 4)] = terrain.valid[terrain.index(9, 7)] = 0;
  return terrain;
}

HydraulicParams rainy_params() {
  HydraulicParams params;
  params.steps = 30;
  params.time_step = 0.5;
  params.rain_rate = 1e-3;
  params.evaporation_rate = 0.05;
  params.gravity = 1.0;  // wave number 0.5·sqrt(2·1.5) < 1
  return params;
}

HydraulicForcing one_source() {
  HydraulicForcing forcing;
  forcing.sources = {{3, 2, 0.2}};
  return forcing;
}

// Runs the reference in Real with the mutant `mutant` active ("" = none) and returns its ledger.
template <class Real>
std::vector<gt::PipeLedgerEntry> ledger_of(const std::string& mutant, const HydraulicForcing& forcing) {
  gt::set_active_mutant(mutant);
  const auto terrain = basin();
  auto state = gt::dry_pipe_state(terrain.cast<Real>());
  for (auto& depth : state.water.values) depth = Real(0.05);
  gt::reference::PipeErosion<Real> erosion(state, gt::pipe_constants(rainy_params(), terrain), forcing);
  erosion.run(rainy_params().steps);
  gt::set_active_mutant("");
  return erosion.ledger();
}

TEST(PipesLedger, AskedVolumeIsRainTimesValidAreaTimesStepPlusSources) {
  const auto terrain = basin();
  const auto constants = gt::pipe_constants(rainy_params(), terrain);
  // 77 valid cells of 2 m², 1e-3 m/s for 0.5 s, and 0.2 m³/s for 0.5 s.
  EXPECT_NEAR(gt::pipe_asked_volume_per_step(constants, one_source(), terrain), 0.5 * (1e-3 * 77 * 2.0 + 0.2), 1e-15);
  HydraulicForcing mapped;
  mapped.rain_map = field(10, 8, 2.0, 1.0, [](int x, int) { return x < 5 ? 2e-3 : 0.0; });
  // The map adds 2e-3 m/s on the cells with x < 5: 40, of which (0, 0) and (4, 4) hold no data.
  const double mapped_cells = 40 - 2;
  EXPECT_NEAR(gt::pipe_asked_volume_per_step(constants, mapped, terrain),
              0.5 * (1e-3 * 77 * 2.0 + 2e-3 * mapped_cells * 2.0), 1e-15);
}

TEST(PipesLedger, TwinsAddWhatWasAskedAndEvaporateAtTheirRate) {
  const auto terrain = basin();
  const auto constants = gt::pipe_constants(rainy_params(), terrain);
  const double asked = gt::pipe_asked_volume_per_step(constants, one_source(), terrain);
  const double share = rainy_params().evaporation_rate * rainy_params().time_step;
  const int steps = rainy_params().steps;
  const auto in_double = ledger_of<double>("", one_source());
  const auto in_float = ledger_of<float>("", one_source());
  EXPECT_LE(gt::pipe_water_added_error(in_double, asked), gt::pipe_water_added_bound(gt::pipe_double_roundoff, steps, 1));
  EXPECT_LE(gt::pipe_water_added_error(in_float, asked), gt::pipe_water_added_bound(gt::pipe_float_roundoff, steps, 1));
  EXPECT_LE(gt::pipe_evaporation_error(in_double, share), gt::pipe_evaporation_bound(gt::pipe_double_roundoff, share));
  EXPECT_LE(gt::pipe_evaporation_error(in_float, share), gt::pipe_evaporation_bound(gt::pipe_float_roundoff, share));
  EXPECT_GT(in_double.back().evaporated, 0.0);
}

TEST(PipesLedger, HalfTheRainIsFlaggedThoughTheBalanceCloses) {
  const auto terrain = basin();
  const double asked = gt::pipe_asked_volume_per_step(gt::pipe_constants(rainy_params(), terrain), one_source(), terrain);
  const auto ledger = ledger_of<double>("erosion.pipe.half_rain", one_source());
  EXPECT_LE(std::abs(gt::water_balance(ledger.back(), ledger.front())), 1e-12 * (ledger.front().water + asked * 30));
  // Half the rain of 30 steps (1.2 m³) missing, against 7.7 m³ held at the start plus 5.3 m³ asked.
  EXPECT_GT(gt::pipe_water_added_error(ledger, asked), 0.05);
  EXPECT_GT(gt::pipe_water_added_error(ledger_of<float>("erosion.pipe.half_rain", one_source()), asked),
            gt::pipe_water_added_bound(gt::pipe_float_roundoff, rainy_params().steps, 1));
}

TEST(PipesLedger, DoubledEvaporationIsFlaggedThoughTheBalanceCloses) {
  const double share = rainy_params().evaporation_rate * rainy_params().time_step;
  const auto ledger = ledger_of<double>("erosion.pipe.double_evaporation", one_source());
  const double handled = ledger.front().water + ledger.back().rain_in + ledger.back().source_in;
  EXPECT_LE(std::abs(gt::water_balance(ledger.back(), ledger.front())), 1e-12 * handled);
  // Evaporating 2K instead of K moves the ratio by about K = 0.025.
  EXPECT_GT(gt::pipe_evaporation_error(ledger, share), 0.5 * share);
}

TEST(PipesLedger, BoundsGrowWithStepsAndSources) {
  const double u = gt::pipe_float_roundoff;
  EXPECT_NEAR(gt::pipe_water_added_bound(u, 100, 0), 104 * u, 1e-3 * 104 * u);
  EXPECT_NEAR(gt::pipe_water_added_bound(u, 100, 2), 304 * u, 1e-3 * 304 * u);
  EXPECT_NEAR(gt::pipe_evaporation_bound(u, 0.01), 3 * u, 1e-2 * 3 * u);
}

}  // namespace
