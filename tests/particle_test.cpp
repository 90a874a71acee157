// Seed 000's droplet erosion: the reference against hand-derived droplets (a pit; the ramp is
// datasets/cases/erosion.particle.json's spec case), its ledger on a masked terrain
// in every ordering, the parameters' refusals, and the GPU twin against ref<float> (batch bit for
// bit; disjoint, where llvmpipe rounds division and sqrt correctly, too).
#include <cmath>

#include <gtest/gtest.h>

#include "compare/checks/field.hpp"
#include "core/errors.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/particle.hpp"
#include "reference/erosion/particle.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"
#include "tests/support/printers.hpp"

namespace {

using gt::DropletOrdering;
using gt::Grid;
using gt::ParticleConstants;

// Upstream defaults (digest 000 §4.4.1) with a short life and no bilinear spread.
ParticleConstants short_life(int lifetime) {
  ParticleConstants constants;
  constants.lifetime = lifetime;
  constants.interpolate = false;
  constants.quantum = gt::batch_quantum(1.0);
  return constants;
}

// Rows 0 and 2: 0.9 0.8 0.8 0.8 0.9; row 1: 0.9 0.8 0.5 0.8 0.9 — a pit at (2, 1).
Grid<double> pit() {
  Grid<double> field(5, 3, 0.8);
  for (int y = 0; y < 3; ++y) field.at(0, y) = field.at(4, y) = 0.9;
  field.at(2, 1) = 0.5;
  return field;
}

// From (1, 1): v_x = -0.5·(0.8 - 0.9) = 0.05 (rest takes the -x branch), v_y = 0 (level), ×0.8:
// 0.04, capacity 4e-4, erodes 0.25·4e-4 = 1e-4 at (1, 1) and moves to (2, 1). There the pit
// (0.5 below all four neighbours) stops it: capacity 0, it deposits 0.25·1e-4, then 0.25 of the
// 7.5e-5 left, staying put: (2, 1) = 0.5 + 2.5e-5 + 1.875e-5, carried 5.625e-5.
TEST(ParticleReference, APitStopsTheDropletAndTakesItsSediment) {
  Grid<double> field = pit();
  const auto path = gt::reference::run_one_droplet(field, short_life(3), 1, 1);
  ASSERT_EQ(path.positions.size(), 4u);
  EXPECT_DOUBLE_EQ(path.positions[1].first, 2.5);
  EXPECT_DOUBLE_EQ(path.positions[3].first, 2.5) << "the pit stop keeps it at (2, 1)";
  EXPECT_NEAR(field.at(1, 1), 0.7999, 1e-12);
  EXPECT_NEAR(field.at(2, 1), 0.50004375, 1e-12);
  EXPECT_NEAR(path.sediment, 5.625e-5, 1e-12);
}

// The same droplet in float: every operation rounded to float, so within a few float ulps of the
// double droplet (not equal: 0.8 and 0.9 are not float numbers).
TEST(ParticleReference, TheFloatDropletFollowsTheDoubleOne) {
  Grid<double> field = pit();
  Grid<float> field_float = field.cast<float>();
  const auto path = gt::reference::run_one_droplet(field, short_life(3), 1, 1);
  const auto path_float = gt::reference::run_one_droplet(field_float, short_life(3), 1, 1);
  EXPECT_NEAR(path_float.sediment, path.sediment, 1e-9);
  EXPECT_NEAR(field_float.at(2, 1), field.at(2, 1), 1e-7);
}

template <class Real>
double sum_of(const Grid<Real>& field) {
  double sum = 0.0;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field.is_valid(i)) sum += static_cast<double>(field.values[i]);
  }
  return sum;
}

template <class Real>
double ledger_residual(const Grid<Real>& before, const gt::reference::DropletRun<Real>& run) {
  const auto& l = run.ledger;
  return sum_of(run.heights) + l.sediment_at_end + l.sediment_left + l.deposited_outside - sum_of(before) -
         l.eroded_outside - l.clamp_created - l.apply_rounding;
}

ParticleConstants terrain_constants(DropletOrdering ordering, bool interpolate) {
  ParticleConstants constants;
  constants.lifetime = 20;
  constants.spacing = 3;
  constants.interpolate = interpolate;
  constants.ordering = ordering;
  constants.quantum = gt::batch_quantum(1.0);
  return constants;
}

// The masked terrain normalised: droplets meet the no-data blob and the grid's edges, so every
// ledger term carries material. Sum of 851 heights near 0.5: double rounding ~1e-13 absolute.
class ParticleLedger : public ::testing::TestWithParam<std::tuple<DropletOrdering, bool>> {};

TEST_P(ParticleLedger, ClosesInDoubleAndInQuanta) {
  const auto [ordering, interpolate] = GetParam();
  const Grid<double> field = gt::normalise_heights(gt::testing::masked_terrain(3, 20, 10, 12).cast<double>());
  const auto constants = terrain_constants(ordering, interpolate);
  const auto run = gt::reference::particle_erosion(field, constants, 2, ordering);
  EXPECT_GT(run.ledger.eroded, 0.0);
  EXPECT_GT(run.ledger.eroded_outside + run.ledger.deposited_outside, 0.0) << "the blob and edges take part";
  EXPECT_LE(std::abs(ledger_residual(field, run)), 1e-12 * sum_of(field));
  const auto run_float = gt::reference::particle_erosion(field.cast<float>(), constants, 2, ordering);
  if (ordering == DropletOrdering::batch) {
    const auto& l = run_float.ledger;
    EXPECT_EQ(l.applied_quanta + l.sediment_end_quanta + l.deposited_outside_quanta - l.eroded_outside_quanta -
                  l.clamp_created_quanta,
              0);
    EXPECT_LE(std::abs(ledger_residual(field.cast<float>(), run_float)), 1e-12 * sum_of(field));
  }
}

INSTANTIATE_TEST_SUITE_P(Orderings, ParticleLedger,
                         ::testing::Combine(::testing::Values(DropletOrdering::race, DropletOrdering::batch),
                                            ::testing::Bool()));

TEST(ParticleParams, DisjointNeedsTheSpacingThatKeepsDropletsApart) {
  const gt::Heightmap field(8, 8, 1.0);
  auto resolved = gt::resolve_params("erosion.particle", gt::particle_param_specs(),
                                     {{"ordering", "disjoint"}, {"lifetime", 10}, {"spacing", 24}});
  EXPECT_THROW(gt::particle_constants(resolved, field), gt::InputError) << "24 = 2·(10 + 2) lets them touch";
  resolved["spacing"] = 25;
  EXPECT_EQ(gt::particle_constants(resolved, field).spacing, 25);
}

TEST(ParticleParams, StrengthsOfAHalfAndMoreAreRunWithAWarning) {
  const gt::Heightmap field(8, 8, 1.0);
  const auto resolved = gt::resolve_params("erosion.particle", gt::particle_param_specs(), {{"erosion_strength", 0.5}});
  EXPECT_EQ(gt::particle_warnings(gt::particle_constants(resolved, field)).size(), 1u);
  EXPECT_THROW(gt::resolve_params("erosion.particle", gt::particle_param_specs(), {{"lifetime", 0}}), gt::InputError);
  EXPECT_THROW(gt::resolve_params("erosion.particle", gt::particle_param_specs(), {{"max_velocity", 0.0}}),
               gt::InputError);
}

TEST(ParticleParams, TheQuantumIsAPowerOfTwoAtFloatResolution) {
  EXPECT_EQ(gt::batch_quantum(0.0), std::ldexp(1.0, -24));
  EXPECT_EQ(gt::batch_quantum(1.0), std::ldexp(1.0, -24));
  EXPECT_EQ(gt::batch_quantum(1000.0), std::ldexp(1.0, -14));
}

class ParticleGpu : public gt::testing::GlTestWithParam<std::tuple<DropletOrdering, bool>> {};

// Batch: every bit equal to ref<float> and repeatable. Disjoint: the same float operations in the
// same order, and llvmpipe divides and takes square roots correctly: every bit equal too.
TEST_P(ParticleGpu, EqualsTheFloatReferenceBitForBit) {
  const auto [ordering, interpolate] = GetParam();
  const Grid<float> field =
      gt::normalise_heights(gt::testing::masked_terrain(5, 10, 12, 9).cast<double>()).cast<float>();
  auto constants = terrain_constants(ordering, interpolate);
  if (ordering == DropletOrdering::disjoint) {
    constants.lifetime = 6;
    constants.spacing = 17;
  }
  constants.iterations = 2;
  const auto reference = gt::reference::particle_erosion(
      field, constants, 2, ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race);
  gt::gpu::ParticleErosion gpu(field.width, field.height, constants);
  gpu.load(field);
  gpu.run();
  const auto first = gpu.result();
  gpu.load(field);
  gpu.run();
  EXPECT_EQ(gt::field_difference(reference.heights, first).differing_bits, 0u);
  EXPECT_EQ(gt::field_difference(first, gpu.result()).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(field, first).max_abs, 1e-4) << "the terrain should have changed";
}

INSTANTIATE_TEST_SUITE_P(Orderings, ParticleGpu,
                         ::testing::Combine(::testing::Values(DropletOrdering::disjoint, DropletOrdering::batch),
                                            ::testing::Bool()));

}  // namespace
