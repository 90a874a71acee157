// The host spec of one pipe step (compare/algorithms/pipe_spec.hpp) and spec.step.*
// (compare/checks/pipe_spec_check.hpp): the spec against a step worked by hand, its own water and
// material balance, and the check on an anisotropic grid with no-data cells, a source and both
// borders: ref<double> passes it, and the both-twins bugs that conserve water and material (the
// registered mutants) fail it, which no ledger can.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/algorithms/pipe_spec.hpp"
#include "compare/checks/pipe_spec_check.hpp"
#include "compare/inputs.hpp"
#include "core/mutant.hpp"
#include "core/params/hydraulic.hpp"
#include "reference/erosion/pipes.hpp"
#include "tests/support/pipe_fields.hpp"

namespace {

using gt::HydraulicForcing;
using gt::HydraulicParams;
using gt::PipeState;
using gt::testing::field;
using gt::testing::noise;

// Two 1 m cells: the left 1 m high with 0.2 m of water, the right at 0 m and dry.
PipeState<double> two_cells() {
  auto state = gt::dry_pipe_state(field(2, 1, 1.0, 1.0, [](int x, int) { return x == 0 ? 1.0 : 0.0; }));
  state.water.at(0, 0) = 0.2;
  return state;
}

HydraulicParams hand_params() {
  HydraulicParams params;
  params.time_step = 0.1;
  params.gravity = 10.0;
  params.capacity = 0.1;
  params.dissolving_rate = 0.5;  // k_s = 0.05 per step
  return params;
}

// Worked by hand from eqs. 2.10-2.23 (Δt = 0.1 s, g = 10 m/s², A = l² = 1 m², K_c = 0.1 s):
//   f_R(left) = Δt·A·g·Δh/l = 0.1·1·10·1.2 = 1.2 m³/s; K = min(1, 0.2·1/(1.2·0.1)) = 1
//   d_B = 0.2 − 0.1·1.2 = 0.08 (left), 0.12 (right)
//   u = ½·1.2/(1·d̄): d̄ = 0.14 (left), 0.06 (right)
//   sin α = 1/√2 (one-sided slopes of −1), C = K_c·sin α·|u|; the bed erodes by k_s·C
//   the left cell's water moved 1.2·0.1/0.2 = 0.6 of itself, and that share of its sediment.
TEST(PipeSpec, OneStepWorkedByHand) {
  const PipeState<double> next = gt::pipe_spec_step(two_cells(), hand_params(), {});
  const double sine = 1.0 / std::sqrt(2.0);
  const double u_left = 0.6 / 0.14, u_right = 0.6 / 0.06;
  const double eroded_left = 0.05 * 0.1 * sine * u_left, eroded_right = 0.05 * 0.1 * sine * u_right;
  constexpr double tolerance = 1e-14;  // a few roundings of values near 1
  EXPECT_NEAR(next.outflow[0][1], 1.2, tolerance);  // pipe R of the left cell
  EXPECT_EQ(next.outflow[1][0], 0.0);               // nothing flows uphill
  EXPECT_NEAR(next.water.at(0, 0), 0.08, tolerance);
  EXPECT_NEAR(next.water.at(1, 0), 0.12, tolerance);
  EXPECT_NEAR(next.velocity_x.at(0, 0), u_left, tolerance);
  EXPECT_NEAR(next.velocity_x.at(1, 0), u_right, tolerance);
  EXPECT_NEAR(next.terrain.at(0, 0), 1.0 - eroded_left, tolerance);
  EXPECT_NEAR(next.terrain.at(1, 0), -eroded_right, tolerance);
  EXPECT_NEAR(next.sediment.at(0, 0), 0.4 * eroded_left, tolerance);
  EXPECT_NEAR(next.sediment.at(1, 0), eroded_right + 0.6 * eroded_left, tolerance);
}

// 12 x 9 cells of 2 m x 1 m, noisy and sloped, with 3 no-data cells.
gt::Grid<double> basin() {
  auto terrain = field(12, 9, 2.0, 1.0, [](int x, int y) {
    return 2.0 + 0.15 * x - 0.05 * y + 0.3 * std::sin(0.6 * x + 0.4 * y) + 0.1 * noise(x, y, 5);
  });
  terrain.valid.assign(terrain.size(), 1);
  terrain.valid[terrain.index(0, 0)] = terrain.valid[terrain.index(5, 4)] = terrain.valid[terrain.index(11, 8)] = 0;
  return terrain;
}

HydraulicParams basin_params(gt::PipeBoundary boundary) {
  HydraulicParams params;
  params.time_step = 0.2;
  params.gravity = 2.0;  // wave number below 1 on 2 m x 1 m cells
  params.rain_rate = 2e-3;
  params.evaporation_rate = 0.1;
  params.capacity = 0.05;
  params.dissolving_rate = 1.5;  // K_s ≠ K_d, so exchanging them shows
  params.deposition_rate = 0.5;
  params.depth_ramp = 0.05;
  params.boundary = boundary;
  return params;
}

HydraulicForcing basin_forcing() {
  HydraulicForcing forcing;
  forcing.sources = {{3, 6, 0.3}};
  return forcing;
}

// Seed 001's variant on top: regolith, sediment diffusion by `weighting`, the code's raw tilt.
HydraulicParams seed001_params(gt::PipeBoundary boundary, gt::DiffusionWeighting weighting) {
  HydraulicParams params = basin_params(boundary);
  params.regolith_depth = 0.01;
  params.regolith_dissolving_rate = 2.0;
  params.regolith_deposition_rate = 3.0;
  params.sediment_diffusion = 0.1;
  params.diffusion_weighting = weighting;
  params.tilt_differences = gt::TiltDifferences::seed001_code;
  return params;
}

// The spec.step checks of the seventh step, with `mutant` active ("" = none) in the twins' constants.
std::vector<gt::Check> spec_checks(const std::string& mutant, const HydraulicParams& params) {
  gt::set_active_mutant(mutant);
  const auto terrain = basin();
  const auto constants = gt::pipe_constants(params, terrain);
  auto start = gt::dry_pipe_state(terrain);
  for (auto& depth : start.water.values) depth = 0.02;
  gt::reference::PipeErosion<double> truth(start, constants, basin_forcing());
  truth.run(6);
  auto checks = gt::pipe_spec_checks(truth.state(), constants, params, basin_forcing(), 7);
  gt::set_active_mutant("");
  return checks;
}

const gt::Check& named(const std::vector<gt::Check>& checks, const std::string& name) {
  for (const auto& check : checks) {
    if (check.name == name) return check;
  }
  throw std::runtime_error("no check " + name);
}

void expect_all_pass(const std::vector<gt::Check>& checks, std::size_t count) {
  ASSERT_EQ(checks.size(), count);
  for (const auto& check : checks) {
    EXPECT_EQ(check.status, gt::Outcome::pass) << check.name << " = " << check.value << ": " << check.detail;
    ASSERT_TRUE(check.threshold.has_value()) << check.name;
    EXPECT_GT(*check.threshold, 0.0) << check.name;  // a bound from the model, not a tolerance of 0
  }
}

TEST(PipeSpec, ReferenceStepPassesOnBothBordersAndSeed001sVariant) {
  for (const auto boundary : {gt::PipeBoundary::closed, gt::PipeBoundary::open}) {
    expect_all_pass(spec_checks("", basin_params(boundary)), 6);
    for (const auto weighting : {gt::DiffusionWeighting::uniform, gt::DiffusionWeighting::water}) {
      expect_all_pass(spec_checks("", seed001_params(boundary, weighting)), 7);
    }
    // 8 pipes (anisotropic cells: the diagonals' shares along x and y differ) and Mei's
    // semi-Lagrangian transport or MacCormack's correction of it, each alone and together.
    for (const int pipes : {4, 8}) {
      for (const auto transport : {gt::SedimentTransport::flux, gt::SedimentTransport::semi_lagrangian,
                                   gt::SedimentTransport::maccormack}) {
        HydraulicParams params = basin_params(boundary);
        params.pipe_count = pipes;
        params.transport = transport;
        expect_all_pass(spec_checks("", params), 6);
        // Jákó & Tóth's combined step after it, at a talus (10°) the basin's flanks exceed.
        params.thermal_step = true;
        params.thermal_talus_angle = 10.0;
        params.thermal_rate = 0.3;
        expect_all_pass(spec_checks("", params), 6);
      }
    }
  }
}

// Šťava's three layers on the basin, thin enough that the water empties the top ones within the
// six steps, under Algorithm 1 as meant and as printed (the basin's start sediment lets the printed
// condition act); without eq. 2.29 (a bug of both twins that conserves material) the layers fail.
HydraulicParams layered_params(gt::LayerErosion condition) {
  HydraulicParams params = basin_params(gt::PipeBoundary::open);
  params.layers = 3;
  params.layer_capacity = {0.1, 0.2, 0.4};
  params.layer_erosion = condition;
  return params;
}

std::vector<gt::Check> layered_spec_checks(const std::string& mutant, gt::LayerErosion condition) {
  gt::set_active_mutant(mutant);
  const auto params = layered_params(condition);
  const auto terrain = basin();
  const auto constants = gt::pipe_constants(params, terrain);
  auto start = gt::dry_pipe_state(terrain, 3);
  for (auto& depth : start.water.values) depth = 0.02;
  for (auto& suspended : start.sediment.values) suspended = 0.002;
  for (std::size_t k = 0; k < 3; ++k) {
    for (std::size_t cell = 0; cell < terrain.size(); ++cell) start.layers[k].values[cell] = 0.02 * (1.0 + double(k)) * noise(int(cell), 0, 31);
  }
  gt::reference::PipeErosion<double> truth(start, constants, basin_forcing());
  truth.run(6);
  auto checks = gt::pipe_spec_checks(truth.state(), constants, params, basin_forcing(), 7);
  gt::set_active_mutant("");
  return checks;
}

TEST(PipeSpec, LayeredStepPassesAsMeantAndAsPrintedAndFailsWithoutEquation229) {
  expect_all_pass(layered_spec_checks("", gt::LayerErosion::capacity_above_sediment), 9);
  // As printed the walk stops at the top layer unless the sediment exceeds its capacity and empties
  // it: the buried layers are left as they were, exactly (a bound of 0 there).
  const auto printed = layered_spec_checks("", gt::LayerErosion::as_printed);
  ASSERT_EQ(printed.size(), 9u);
  for (const auto& check : printed) EXPECT_EQ(check.status, gt::Outcome::pass) << check.name << ": " << check.detail;
  EXPECT_GT(*named(printed, "spec.step.layer_3.cpu").threshold, 0.0);
  const auto checks = layered_spec_checks("erosion.pipe.layers_above_ignored", gt::LayerErosion::capacity_above_sediment);
  EXPECT_EQ(named(checks, "spec.step.layer_1.cpu").status, gt::Outcome::fail);
  EXPECT_EQ(named(checks, "spec.step.terrain.cpu").status, gt::Outcome::fail);
  EXPECT_EQ(named(checks, "spec.step.water.cpu").status, gt::Outcome::pass);
}

// MacCormack on the Jacksboro DEM (74 m x 92 m cells, 0.1 m of water, Δt = 1 s): by step 11 cells
// drain at the K cap, one cell a step, where the displacement lands an ulp either side of a whole
// cell in ref<double> and in the spec. A limiter over the four corners the backtrace read switched
// corners there and the two differed by 0.6 m; the limiter over the 3×3 neighbourhood does not
// depend on the displacement, and the honest step passes.
TEST(PipeSpec, MacCormackOnARealDemPassesWhereDisplacementsMeetWholeCells) {
  const auto terrain = gt::load_input({{"file", "real/jacksboro_fault_dem.npz"}}, nullptr, GT_DATASET_DIR).heights;
  HydraulicParams params;
  params.time_step = 1.0;
  params.capacity = 0.1;
  params.transport = gt::SedimentTransport::maccormack;
  const auto constants = gt::pipe_constants(params, terrain);
  auto start = gt::dry_pipe_state(terrain);
  for (auto& depth : start.water.values) depth = 0.1;
  gt::reference::PipeErosion<double> truth(start, constants, {});
  truth.run(10);
  expect_all_pass(gt::pipe_spec_checks(truth.state(), constants, params, {}, 11), 6);
}

TEST(PipeSpec, ConservingBugsOfBothTwinsFail) {
  for (const char* mutant : {"erosion.pipe.capacity_doubled", "erosion.pipe.rates_swapped", "erosion.pipe.tilt_unhalved",
                             "erosion.pipe.capacity_off_above_bound"}) {
    for (const auto boundary : {gt::PipeBoundary::closed, gt::PipeBoundary::open}) {
      const auto checks = spec_checks(mutant, basin_params(boundary));
      EXPECT_EQ(named(checks, "spec.step.terrain.cpu").status, gt::Outcome::fail) << mutant;
      EXPECT_EQ(named(checks, "spec.step.sediment.cpu").status, gt::Outcome::fail) << mutant;
      EXPECT_EQ(named(checks, "spec.step.water.cpu").status, gt::Outcome::pass) << mutant;  // the water is untouched
    }
  }
  const auto open = basin_params(gt::PipeBoundary::open);
  EXPECT_EQ(named(spec_checks("erosion.pipe.gravity_in_cgs", open), "spec.step.outflow.cpu").status, gt::Outcome::fail);
  EXPECT_EQ(named(spec_checks("erosion.pipe.half_rain", open), "spec.step.water.cpu").status, gt::Outcome::fail);
  // MacCormack's correction subtracted in both twins: only the transported fields move.
  HydraulicParams maccormack = open;
  maccormack.transport = gt::SedimentTransport::maccormack;
  const auto negated = spec_checks("erosion.pipe.maccormack_correction_negated", maccormack);
  EXPECT_EQ(named(negated, "spec.step.sediment.cpu").status, gt::Outcome::fail);
  EXPECT_EQ(named(negated, "spec.step.water.cpu").status, gt::Outcome::pass);
  // In seed 001's variant, where the code's raw tilt takes no span, the rates still show.
  const auto variant = seed001_params(gt::PipeBoundary::closed, gt::DiffusionWeighting::water);
  EXPECT_EQ(named(spec_checks("erosion.pipe.rates_swapped", variant), "spec.step.terrain.cpu").status, gt::Outcome::fail);
}

// The spec's own balance with closed borders: material b + s is only moved, and the water after the
// step is what was there plus rain and the source, less the evaporated share.
TEST(PipeSpec, ClosedBordersBalance) {
  const auto params = basin_params(gt::PipeBoundary::closed);
  auto start = gt::dry_pipe_state(basin());
  for (auto& depth : start.water.values) depth = 0.02;
  const auto next = gt::pipe_spec_step(start, params, basin_forcing());
  double material_before = 0.0, material_after = 0.0, water_before = 0.0, water_after = 0.0, valid = 0.0;
  for (std::size_t cell = 0; cell < start.terrain.size(); ++cell) {
    if (!start.terrain.is_valid(cell)) continue;
    valid += 1.0;
    material_before += start.terrain.values[cell] + start.sediment.values[cell];
    material_after += next.terrain.values[cell] + next.sediment.values[cell];
    water_before += start.water.values[cell];
    water_after += next.water.values[cell];
  }
  const double cell_area = 2.0;
  const double added = valid * params.rain_rate * params.time_step + 0.3 * params.time_step / cell_area;
  const double kept = 1.0 - params.evaporation_rate * params.time_step;
  // Roundings: about ten per cell on sums of 105 values near 2 m (material) and 0.02 m (water).
  EXPECT_NEAR(material_after, material_before, 1e-12);
  EXPECT_NEAR(water_after, (water_before + added) * kept, 1e-14);
}

}  // namespace
