// The flow map of seed 000 (§4.7): eq. 4.13's contrast mapping against the digest's values, hand-
// derived maps on a ramp and around a pit (with the plug pass), the batch rule against the
// sequential one where they agree, and the GPU twin against ref<float> bit for bit.
#include <cmath>
#include <cstddef>

#include <gtest/gtest.h>

#include "compare/checks/field.hpp"
#include "core/errors.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/flow_map.hpp"
#include "reference/erosion/flow_map.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"

namespace {

using gt::DropletOrdering;
using gt::FlowConstants;
using gt::Grid;

// The upstream motion defaults, a short life, the concentration at the droplet's texel.
FlowConstants short_flow(int lifetime, DropletOrdering ordering) {
  FlowConstants flow;
  flow.spacing = 2;
  flow.lifetime = lifetime;
  flow.factor = 0.2;
  flow.interpolate = false;
  flow.ordering = ordering;
  flow.batch_powers = gt::flow_batch_powers(flow.factor);
  return flow;
}

// F after n visits of factor f: 1 - (1 - f)^n (eq. 4.12 from F = 0).
double after_visits(int visits, double factor) { return 1.0 - std::pow(1.0 - factor, visits); }

// Eq. 4.13's values as the digest prints them (5 significant digits): within half their last digit.
TEST(FlowMapParams, TheContrastMappingGivesTheDigestsValues) {
  EXPECT_NEAR(gt::flow_contrast_factor(0.0), 0.2, 1e-15);
  EXPECT_NEAR(gt::flow_contrast_factor(0.5), 0.0073398, 5e-8);
  EXPECT_NEAR(gt::flow_contrast_factor(1.0), 0.00026937, 5e-9);
}

// The batch powers: (1 - f)^(2^i / 1024), so 10 set bits above bit 0 make (1 - f)^1.
TEST(FlowMapParams, TheBatchPowersAreTheFactorsBinaryRoots) {
  const auto powers = gt::flow_batch_powers(0.2);
  EXPECT_NEAR(powers[10], 0.8, 1e-15);
  EXPECT_NEAR(powers[11], 0.64, 1e-15);
  EXPECT_NEAR(powers[9] * powers[9], 0.8, 1e-15);
}

// A 6x3 ramp h = 0.8 - 0.05·x, level along y. Row 1 and row 2: droplet 0 leaves across x = 0 after
// one visit (the grid's outside reads 0); droplet k >= 1 starts at rest, takes the -x branch
// (drop h_k - h_(k-1) = -0.05, v_x = +0.025) and visits k, k+1, k+2 within its 3 steps (those
// inside). Row 0: the outside below pulls every droplet across y = 0 after one visit. Visits per
// texel: row 0 all 1; rows 1, 2: 1 1 2 3 3 3. No texel stays 0, so the plug pass fills none.
Grid<double> ramp() {
  Grid<double> field(6, 3, 0.0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) field.at(x, y) = 0.8 - 0.05 * x;
  }
  return field;
}

class FlowMapOrdering : public ::testing::TestWithParam<DropletOrdering> {};

// Sequential and batch agree here: every visit weighs 1, and both give 1 - (1 - f)^n (batch through
// 10 set bits per visit: within a few double roundings, 1e-14).
TEST_P(FlowMapOrdering, TheRampIsVisitedAsDerivedByHand) {
  const auto run = gt::reference::flow_map(ramp(), short_flow(3, GetParam()));
  const int visits[6] = {1, 1, 2, 3, 3, 3};
  for (int x = 0; x < 6; ++x) {
    EXPECT_NEAR(run.concentration.at(x, 0), after_visits(1, 0.2), 1e-14) << "x " << x;
    EXPECT_NEAR(run.concentration.at(x, 1), after_visits(visits[x], 0.2), 1e-14) << "x " << x;
    EXPECT_NEAR(run.concentration.at(x, 2), after_visits(visits[x], 0.2), 1e-14) << "x " << x;
  }
  EXPECT_EQ(run.plugged, 0u);
  EXPECT_EQ(run.droplets, 2u * 3u * 2u * 2u);  // spacing 2: 4 passes of 3 x 2 droplets
}

INSTANTIATE_TEST_SUITE_P(Orderings, FlowMapOrdering,
                         ::testing::Values(DropletOrdering::race, DropletOrdering::batch));

// A 3x3 plateau of 1 with a pit of 0.5 at the centre. The centre's droplet is in a pit and stops
// before leaving anything; (2, 1) and (1, 2) roll into the pit and stop there; (2, 2) has level
// neighbours behind it on both axes (from rest the -x and -y ones) and never moves; the others are
// pulled off the grid by its outside after one visit. Before the plug pass (1, 1) and (2, 2) are 0;
// it fills (1, 1) with the mean of 4 visited neighbours, F1, and (2, 2) with (F1 + F1 + 0 + 0) / 4.
TEST(FlowMapReference, ThePlugPassFillsTheTexelsNoDropletLeftAnythingOn) {
  Grid<double> field(3, 3, 1.0);
  field.at(1, 1) = 0.5;
  const auto run = gt::reference::flow_map(field, short_flow(4, DropletOrdering::race));
  const double once = after_visits(1, 0.2);
  for (const auto& [x, y] : {std::pair{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}, {0, 2}, {1, 2}}) {
    EXPECT_NEAR(run.concentration.at(x, y), once, 1e-15) << x << ", " << y;
  }
  EXPECT_NEAR(run.concentration.at(1, 1), once, 1e-15);
  EXPECT_NEAR(run.concentration.at(2, 2), once / 2, 1e-15);
  EXPECT_EQ(run.plugged, 2u);
}

// Masked texels read 0, take no flow and stay 0 after the plug pass.
TEST(FlowMapReference, MaskedTexelsStayEmpty) {
  const Grid<float> field = gt::testing::masked_terrain(3, 8, 9, 12);
  FlowConstants flow = short_flow(10, DropletOrdering::race);
  flow.interpolate = true;
  const auto run = gt::reference::flow_map(field, flow);
  std::size_t masked = 0;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field.is_valid(i)) continue;
    ++masked;
    EXPECT_EQ(run.concentration.values[i], 0.0f);
  }
  EXPECT_GT(masked, 0u);
}

TEST(FlowMapParams, DisjointNeedsTheFlowSpacingThatKeepsDropletsApart) {
  gt::ParticleConstants erosion;
  erosion.lifetime = 10;
  erosion.ordering = DropletOrdering::disjoint;
  // flow_constants reads resolve_params' output: every parameter, the unnamed ones at their defaults.
  const auto resolved_with = [](const nlohmann::json& given) {
    return gt::resolve_params("erosion.particle", gt::particle_param_specs(), given);
  };
  nlohmann::json resolved = resolved_with(
      {{"flow_map", true}, {"flow_spacing", 24}, {"flow_contrast", 0.5}, {"interpolate_flow", true}});
  EXPECT_THROW(gt::flow_constants(resolved, erosion), gt::InputError);
  resolved["flow_spacing"] = 25;
  EXPECT_EQ(gt::flow_constants(resolved, erosion)->spacing, 25);
  resolved["flow_map"] = false;
  EXPECT_FALSE(gt::flow_constants(resolved, erosion).has_value());
}

class FlowMapGpu : public gt::testing::GlTestWithParam<std::tuple<DropletOrdering, bool>> {};

// Batch: integer counts, every bit equal to ref<float>. Disjoint: no two droplets of a pass touch a
// common texel and the operations are the reference's, in its order (llvmpipe divides and takes
// square roots correctly): every bit equal too.
TEST_P(FlowMapGpu, EqualsTheFloatReferenceBitForBit) {
  const auto [ordering, interpolate] = GetParam();
  const Grid<float> field =
      gt::normalise_heights(gt::testing::masked_terrain(5, 10, 12, 9).cast<double>()).cast<float>();
  FlowConstants flow = short_flow(6, ordering);
  flow.factor = gt::flow_contrast_factor(0.3);
  flow.batch_powers = gt::flow_batch_powers(flow.factor);
  flow.interpolate = interpolate;
  flow.spacing = ordering == DropletOrdering::disjoint ? 17 : 3;
  FlowConstants twinned = flow;
  twinned.ordering = gt::reference_ordering(ordering);
  const auto reference = gt::reference::flow_map(field, twinned);
  gt::gpu::FlowMap gpu(field.width, field.height, flow);
  gpu.load(field);
  gpu.run();
  const Grid<float> result = gpu.result();
  EXPECT_EQ(gt::field_difference(reference.concentration, result).differing_bits, 0u);
  EXPECT_GT(gt::field_totals(result.cast<double>()).high, 0.1) << "the map should show paths";
}

INSTANTIATE_TEST_SUITE_P(Orderings, FlowMapGpu,
                         ::testing::Combine(::testing::Values(DropletOrdering::disjoint, DropletOrdering::batch),
                                            ::testing::Bool()));

}  // namespace
