// The shadow-step machinery of the thermal twins (issue 11): the GPU loaded with a mid-run state
// and stepped equals ref<float> stepped from the same state (within the a-priori bound of
// parity_bounds_same_arithmetic, 0 on llvmpipe); a run stepped in pieces equals one in one go on
// both sides; the error model's bounds are positive and finite; the stepped runner's shadow checks
// pass for the real twins and fail for a GPU that is off; the host specs of the first iteration give
// the seeds' worked examples.
#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>
#include <stdexcept>

#include <gtest/gtest.h>

#include "compare/algorithm.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/algorithms/thermal_specs.hpp"
#include "compare/stepped_case.hpp"
#include "core/params.hpp"
#include "core/params/thermal.hpp"
#include "core/rng.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"
#include "tests/support/printers.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using gt::Grid;
using gt::Neighbourhood;

Grid<float> masked_terrain() { return gt::testing::masked_terrain(33, 12, 14, 8); }

gt::ThermalConstants hydra_constants(const Grid<float>& field) {
  gt::ThermalParams params;
  params.talus_angle_deg = 30.0;
  return gt::thermal_constants(params, field.cast<double>());
}

gt::ThermalConstants jako_constants(const Grid<float>& field) {
  gt::ThermalJakoParams params;
  params.talus_angle_deg = 30.0;
  return gt::thermal_jako_constants(params, field.cast<double>());
}

// |a - b| relative to the field's range within the shadow bound for `additions` per cell.
void expect_within_shadow_bound(const Grid<float>& expected, const Grid<float>& measured, double additions) {
  const auto totals = gt::field_totals(expected);
  const double range = totals.high - totals.low;
  const auto bounds = gt::parity_bounds_same_arithmetic(additions, totals.high / range);
  const auto difference = gt::field_difference(expected, measured);
  EXPECT_EQ(difference.nonfinite, 0u);
  EXPECT_LE(difference.max_abs / range, bounds.strict) << bounds.model;
}

class ThermalShadowGpu : public gt::testing::GlTestWithParam<Neighbourhood> {};

// From ref<float>'s state after 7 iterations (odd: an alternating run continues with diagonals),
// one iteration, then three more.
TEST_P(ThermalShadowGpu, SteppedFromAStateMatchesTheFloatReferenceSteppedFromIt) {
  const auto field = masked_terrain();
  const auto constants = hydra_constants(field);
  const int start = 7;
  const auto state = gt::reference::thermal_erosion(field, constants, start, GetParam());
  gt::gpu::ThermalErosion gpu(field.width, field.height, constants, GetParam(), 20);
  gpu.load(state);
  gpu.step(start, 1);
  const auto gpu_one = gpu.result();
  gpu.step(start + 1, 3);
  const auto gpu_four = gpu.result();
  const auto ref_one = gt::reference::thermal_erosion(state, constants, 1, GetParam(), start);
  const auto ref_four = gt::reference::thermal_erosion(ref_one, constants, 3, GetParam(), start + 1);
  EXPECT_GT(gt::field_difference(state, ref_one).max_abs, 0.01) << "the step should move material";
  expect_within_shadow_bound(ref_one, gpu_one, 4.0);
  expect_within_shadow_bound(ref_four, gpu_four, 16.0);
}

// The reference and the GPU run in pieces (5 + 6 iterations) give the bits of one 11-iteration run.
TEST_P(ThermalShadowGpu, SteppingInPiecesEqualsOneRun) {
  const auto field = masked_terrain();
  const auto constants = hydra_constants(field);
  const auto whole = gt::reference::thermal_erosion(field, constants, 11, GetParam());
  const auto first = gt::reference::thermal_erosion(field, constants, 5, GetParam());
  EXPECT_EQ(gt::field_difference(whole, gt::reference::thermal_erosion(first, constants, 6, GetParam(), 5)).differing_bits,
            0u);
  gt::gpu::ThermalErosion gpu(field.width, field.height, constants, GetParam(), 11);
  gpu.load(field);
  gpu.run();
  const auto gpu_whole = gpu.result();
  gpu.load(field);
  gpu.step(0, 5);
  gpu.step(5, 6);
  EXPECT_EQ(gt::field_difference(gpu_whole, gpu.result()).differing_bits, 0u);
}

INSTANTIATE_TEST_SUITE_P(Modes, ThermalShadowGpu,
                         ::testing::Values(Neighbourhood::cardinal, Neighbourhood::diagonal, Neighbourhood::alternating));

class ThermalJakoShadowGpu : public gt::testing::GlTest {};

TEST_F(ThermalJakoShadowGpu, SteppedFromAStateMatchesTheFloatReferenceSteppedFromIt) {
  const auto field = masked_terrain();
  const auto constants = jako_constants(field);
  const auto state = gt::reference::thermal_jako_erosion(field, constants, 6);
  gt::gpu::ThermalJakoErosion gpu(field.width, field.height, constants, 20);
  gpu.load(state);
  gpu.step(1);
  const auto gpu_one = gpu.result();
  gpu.step(3);
  const auto ref_one = gt::reference::thermal_jako_erosion(state, constants, 1);
  EXPECT_GT(gt::field_difference(state, ref_one).max_abs, 0.01);
  expect_within_shadow_bound(ref_one, gpu_one, 16.0);
  expect_within_shadow_bound(gt::reference::thermal_jako_erosion(ref_one, constants, 3), gpu.result(), 64.0);
}

TEST(ThermalErrorModel, ShadowAndLedgerBoundsArePositiveAndFinite) {
  for (const double additions : {4.0, 16.0, 64.0}) {
    const auto bounds = gt::parity_bounds_same_arithmetic(additions, 5.0);
    EXPECT_GT(bounds.strict, 0.0);
    EXPECT_TRUE(std::isfinite(bounds.loose));
    EXPECT_LE(bounds.strict, bounds.loose);
    EXPECT_LT(bounds.loose, 1e-4) << "a shadow bound far below any transfer";
  }
  gt::FieldTotals totals;
  totals.sum_abs = 1000.0;
  totals.low = 0.0;
  totals.high = 10.0;
  totals.cells = 100;
  const auto ledger = gt::moved_ledger_bounds(16.0, totals, 5.0);
  EXPECT_GT(ledger.strict, 0.0);
  EXPECT_LT(ledger.strict, 1e-9);
}

// A thermal case prepared as the driver does.
gt::PreparedTwin prepare(const std::string& algorithm_name, const nlohmann::json& given, const gt::Heightmap& input) {
  const auto& algorithm = gt::find_algorithm(algorithm_name);
  gt::LoadedInput loaded;
  loaded.heights = input;
  return algorithm.prepare(gt::resolve_params(algorithm.name, *algorithm.params, given), loaded);
}

gt::Heightmap centre_peak() {
  gt::Heightmap field(3, 3, 0.0);
  field.at(1, 1) = 1.0;
  return field;
}

// The host specs reproduce the worked examples of datasets/cases/erosion.thermal.json.
TEST(ThermalFirstIterationSpec, GivesTheWorkedExamples) {
  gt::ThermalParams hydra;
  hydra.iterations = 1;
  hydra.talus_angle_deg = std::atan(0.25) * 180.0 / std::numbers::pi;
  hydra.strength = 1.0;
  const auto hydra_after = gt::hydra_first_iteration(centre_peak(), gt::thermal_constants(hydra, centre_peak()),
                                                     Neighbourhood::cardinal);
  EXPECT_NEAR(hydra_after.at(1, 1), 0.625, 1e-12);
  EXPECT_NEAR(hydra_after.at(0, 1), 0.09375, 1e-12);
  EXPECT_EQ(hydra_after.at(0, 0), 0.0);
  gt::ThermalJakoParams jako;
  jako.iterations = 1;
  jako.talus_angle_deg = 35.0;
  jako.rate = 0.5;
  const auto jako_after = gt::jako_first_iteration(centre_peak(), gt::thermal_jako_constants(jako, centre_peak()));
  EXPECT_EQ(jako_after.at(1, 1), 0.75);
  EXPECT_EQ(jako_after.at(0, 0), 0.03125);
  EXPECT_EQ(jako_after.at(1, 0), 0.03125);
}

gt::Heightmap small_cone() {
  gt::Heightmap field(24, 20);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const auto bits = gt::random_u32(7, static_cast<std::uint32_t>(field.index(x, y)), 0, 0);
      field.at(x, y) = std::max(0.0, 20.0 - 2.0 * std::hypot(x - 12.0, y - 10.0)) + 0.3 * gt::uniform01(bits);
    }
  }
  return field;
}

const gt::Check& find_check(const gt::CaseResult& result, const std::string& name) {
  for (const auto& check : result.checks) {
    if (check.name == name) return check;
  }
  throw std::runtime_error("no check " + name);
}

gt::SteppedTwin& stepped(gt::PreparedTwin& prepared) { return std::get<gt::SteppedTwin>(prepared.kind); }

gt::CaseResult run_case(gt::PreparedTwin prepared) {
  gt::RunOptions options;
  options.cpu_reps = 0;
  options.gpu_reps = 0;
  options.gpu_available = true;
  const gt::testing::TemporaryFolder folder("thermal_shadow_test");
  options.report_dir = folder.path();
  gt::CaseResult result;
  result.name = "thermal_shadow_test";
  gt::run_stepped_case(stepped(prepared), nlohmann::json(), options, result);
  prepared.extra_checks(nlohmann::json(), options, result);
  return result;
}

class ThermalSteppedShadow : public gt::testing::GlTest {};

TEST_F(ThermalSteppedShadow, ShadowChecksPassForBothTwins) {
  for (const char* name : {"erosion.thermal", "erosion.thermal_jako"}) {
    SCOPED_TRACE(name);
    const auto result = run_case(prepare(name, {{"iterations", 12}, {"talus_angle", 35.0}}, small_cone()));
    EXPECT_TRUE(result.error.empty()) << result.error;
    for (const char* check : {"parity.shadow.terrain.gpu_vs_float", "parity.shadow.terrain.multi.gpu_vs_float",
                              "mass.moved_first_iteration.cpu", "mass.relative_drift.gpu", "determinism.gpu"}) {
      EXPECT_EQ(find_check(result, check).status, gt::Outcome::pass) << check << ": " << find_check(result, check).detail;
    }
  }
}

// A GPU stepper whose state is off by 1 mm in one cell whenever it is read.
class OffByAMillimetre : public gt::Stepper {
 public:
  explicit OffByAMillimetre(std::unique_ptr<gt::Stepper> gpu) : gpu_(std::move(gpu)) {}
  void set_state(const gt::State& state, int done) override { gpu_->set_state(state, done); }
  void update(int count) override { gpu_->update(count); }
  gt::State get_state() override {
    auto state = gpu_->get_state();
    state.fields[0][5] += 1e-3;
    return state;
  }

 private:
  std::unique_ptr<gt::Stepper> gpu_;
};

TEST_F(ThermalSteppedShadow, ShadowCheckFailsForAGpuThatIsOff) {
  auto prepared = prepare("erosion.thermal", {{"iterations", 12}, {"talus_angle", 35.0}}, small_cone());
  const auto make_gpu = stepped(prepared).make_gpu;
  stepped(prepared).make_gpu = [make_gpu]() -> std::unique_ptr<gt::Stepper> {
    return std::make_unique<OffByAMillimetre>(make_gpu());
  };
  EXPECT_EQ(find_check(run_case(prepared), "parity.shadow.terrain.gpu_vs_float").status, gt::Outcome::fail);
}

TEST(ThermalSteppedTwin, RefusesAStartStateOfAnotherShape) {
  auto prepared = prepare("erosion.thermal", {{"iterations", 2}}, small_cone());
  stepped(prepared).initial.fields.clear();
  gt::CaseResult result;
  EXPECT_THROW(gt::run_stepped_case(stepped(prepared), nlohmann::json(), gt::RunOptions{}, result), std::logic_error);
}

}  // namespace
