// The GPU twins of thermal erosion against ref<float>: same float operations in the same order,
// so they agree within parity_bounds_same_arithmetic (0 on llvmpipe, which divides correctly);
// grids whose sides are not multiples of the 16x16 work groups, masks, every neighbourhood, odd
// iteration counts; and two runs give the same bits.
#include <gtest/gtest.h>

#include "compare/algorithm.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/inputs.hpp"
#include "compare/stepped_case.hpp"
#include "compare/steppers/height.hpp"
#include "core/errors.hpp"
#include "core/params.hpp"
#include "core/params/thermal.hpp"
#include "core/rng.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"
#include "tests/support/masked_terrain.hpp"
#include "tests/support/printers.hpp"
#include "tests/support/gl_test.hpp"

namespace {

using gt::Grid;
using gt::Neighbourhood;

Grid<float> masked_terrain() { return gt::testing::masked_terrain(21, 20, 8, 10); }

gt::ThermalConstants constants_for(const Grid<float>& field) {
  gt::ThermalParams params;
  params.talus_angle_deg = 30.0;
  return gt::thermal_constants(params, field.cast<double>());
}

double range_of(const Grid<float>& field) {
  const auto totals = gt::field_totals(field);
  return totals.high - totals.low;
}

void expect_same_arithmetic(const Grid<float>& reference, const Grid<float>& gpu, double additions, double range) {
  const auto bounds = gt::parity_bounds_same_arithmetic(additions, 540.0 / range);
  const auto difference = gt::field_difference(reference, gpu);
  EXPECT_EQ(difference.nonfinite, 0u);
  EXPECT_LE(difference.max_abs / range, bounds.strict) << bounds.model;
}

class ThermalGpu : public gt::testing::GlTestWithParam<Neighbourhood> {};

TEST_P(ThermalGpu, MatchesTheFloatReferenceAndRepeats) {
  const auto field = masked_terrain();
  const auto constants = constants_for(field);
  const int iterations = 37;
  gt::gpu::ThermalErosion gpu(field.width, field.height, constants, GetParam(), iterations);
  gpu.load(field);
  gpu.run();
  const auto first = gpu.result();
  gpu.load(field);
  gpu.run();
  const auto second = gpu.result();
  const auto reference = gt::reference::thermal_erosion(field, constants, iterations, GetParam());
  expect_same_arithmetic(reference, first, 4.0 * iterations, range_of(field));
  EXPECT_EQ(gt::field_difference(first, second).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(field, first).max_abs, 0.1f) << "the terrain should have changed";
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (!field.is_valid(i)) {
      EXPECT_EQ(first.values[i], field.values[i]);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, ThermalGpu,
                         ::testing::Values(Neighbourhood::cardinal, Neighbourhood::diagonal, Neighbourhood::alternating));

class ThermalJakoGpu : public gt::testing::GlTest {};

TEST_F(ThermalJakoGpu, MatchesTheFloatReferenceAndRepeats) {
  const auto field = masked_terrain();
  gt::ThermalJakoParams params;
  params.talus_angle_deg = 30.0;
  const auto constants = gt::thermal_jako_constants(params, field.cast<double>());
  const int iterations = 25;
  gt::gpu::ThermalJakoErosion gpu(field.width, field.height, constants, iterations);
  gpu.load(field);
  gpu.run();
  const auto first = gpu.result();
  gpu.load(field);
  gpu.run();
  const auto reference = gt::reference::thermal_jako_erosion(field, constants, iterations);
  expect_same_arithmetic(reference, first, 16.0 * iterations, range_of(field));
  EXPECT_EQ(gt::field_difference(first, gpu.result()).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(field, first).max_abs, 0.1f);
}

TEST_F(ThermalJakoGpu, FollowsTheReferenceUnderAHardnessMap) {
  // R varies cell by cell (0 .. 1.5), so each pipe's threshold depends on which neighbour it leads
  // to: a GPU reading another pipe's threshold or ignoring R departs from ref<float>.
  const auto field = masked_terrain();
  gt::ThermalJakoParams params;
  params.talus_angle_deg = 20.0;
  params.hardness_talus = 0.4;
  auto constants = gt::thermal_jako_constants(params, field.cast<double>());
  constants.hardness.resize(field.size());
  for (std::size_t c = 0; c < field.size(); ++c) constants.hardness[c] = 0.25 * double((c * 5) % 7);
  const int iterations = 25;
  gt::gpu::ThermalJakoErosion gpu(field.width, field.height, constants, iterations);
  gpu.load(field);
  gpu.run();
  const auto reference = gt::reference::thermal_jako_erosion(field, constants, iterations);
  expect_same_arithmetic(reference, gpu.result(), 16.0 * iterations, range_of(field));
  const auto uniform = gt::reference::thermal_jako_erosion(field, gt::thermal_jako_constants(params, field.cast<double>()),
                                                           iterations);
  EXPECT_GT(gt::field_difference(reference, uniform).max_abs, 0.1f) << "the hardness map should change the result";
}

TEST_F(ThermalJakoGpu, SetHardnessReplacesTheMap) {
  const auto field = masked_terrain();
  gt::ThermalJakoParams params;
  params.talus_angle_deg = 20.0;
  params.hardness_talus = 0.4;
  const auto uniform = gt::thermal_jako_constants(params, field.cast<double>());
  auto mapped = uniform;
  mapped.hardness.resize(field.size());
  for (std::size_t c = 0; c < field.size(); ++c) mapped.hardness[c] = 0.25 * double((c * 3) % 7);
  const int iterations = 12;
  gt::gpu::ThermalJakoErosion gpu(field.width, field.height, uniform, iterations);
  gpu.set_hardness(mapped.hardness);
  gpu.load(field);
  gpu.run();
  const auto reference = gt::reference::thermal_jako_erosion(field, mapped, iterations);
  EXPECT_EQ(gt::field_difference(reference, gpu.result()).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(reference, gt::reference::thermal_jako_erosion(field, uniform, iterations)).max_abs,
            0.1f)
      << "the map should change the result";
}

// The harness's steppers (and so an outside caller of the references through the BMI) take R from
// the state they load, not from the case they were prepared for: loaded with another map, ref<float>
// and the GPU give that map's terrain, bit for bit alike; a map outside eq. 2.32's range is refused.
TEST_F(ThermalJakoGpu, TheSteppersReadTheHardnessTheStateLoads) {
  const gt::Algorithm& algorithm = gt::find_algorithm("erosion.thermal_jako");
  gt::LoadedInput input;
  input.heights = masked_terrain().cast<double>();
  const nlohmann::json params = {{"iterations", 8}, {"talus_angle", 20.0}, {"hardness_talus", 0.4}, {"rate", 0.5}};
  const auto prepared = algorithm.prepare(gt::resolve_params(algorithm.name, *algorithm.params, params), input);
  const auto& twin = std::get<gt::SteppedTwin>(prepared.kind);
  ASSERT_EQ(twin.fields.size(), 2u);
  ASSERT_EQ(twin.fields[1].name, "hardness");
  gt::State loaded = twin.initial;
  for (std::size_t c = 0; c < loaded.fields[1].size(); ++c) loaded.fields[1][c] = 0.5 * double((c * 3) % 5);
  gt::ThermalJakoParams jako;
  jako.talus_angle_deg = 20.0;
  jako.hardness_talus = 0.4;
  jako.rate = 0.5;
  auto constants = gt::thermal_jako_constants(jako, input.heights);
  constants.hardness = loaded.fields[1];
  for (std::size_t c = 0; c < constants.hardness.size(); ++c) {
    if (!input.heights.is_valid(c)) constants.hardness[c] = 1.0;  // no-data cells: R = 1
  }
  const auto expected = gt::reference::thermal_jako_erosion(masked_terrain(), constants, 8);
  for (const auto& make : {twin.reference_float, twin.make_gpu}) {
    auto stepper = make();
    stepper->set_state(loaded, 0);
    stepper->update(8);
    const gt::State after = stepper->get_state();
    EXPECT_EQ(after.fields[1], loaded.fields[1]) << "R handed back as loaded";
    EXPECT_EQ(gt::field_difference(gt::heights_of<float>(after), expected).differing_bits, 0u);
    gt::State negative = loaded;
    negative.fields[1][input.heights.index(10, 10)] = -0.5;
    EXPECT_THROW(stepper->set_state(negative, 0), gt::InputError);
  }
}

class ThermalGpuSpec : public gt::testing::GlTest {};

TEST_F(ThermalGpuSpec, ReproducesTheSeedsThreeByThreeExample) {
  Grid<float> field(3, 3, 0.0f);
  field.at(1, 1) = 1.0f;
  gt::ThermalConstants constants;
  constants.talus_slope = 0.25;
  constants.length_diagonal = std::sqrt(2.0);
  constants.request_factor = 0.5;
  gt::gpu::ThermalErosion gpu(3, 3, constants, Neighbourhood::cardinal, 1);
  gpu.load(field);
  gpu.run();
  const auto eroded = gpu.result();
  EXPECT_EQ(eroded.at(1, 1), 0.625f);
  EXPECT_EQ(eroded.at(1, 0), 0.09375f);
  EXPECT_EQ(eroded.at(0, 0), 0.0f);
}

}  // namespace
