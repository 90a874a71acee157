// Beyer's droplet erosion (seed 000 §2.7): the reference against eq. 2.42's weights of Fig. 2.10
// and hand-derived droplets (a step down a tilted plane, a step uphill without sediment, the
// compass fallback on a flat), its ledger on a masked terrain in every ordering (and the mutants of
// both twins it must catch), eq. 2.43's blend with a blurred map (the box blur, the volume, the
// quanta), the parameters' refusals, and the GPU twin against ref<float> (batch bit for bit;
// disjoint, where llvmpipe rounds division and sqrt correctly, too), with and without the blend.
#include <cmath>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "compare/checks/field.hpp"
#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/params/beyer.hpp"
#include "core/params/thermal.hpp"
#include "core/rng.hpp"
#include "gpu/erosion/beyer.hpp"
#include "reference/erosion/beyer.hpp"
#include "reference/erosion/blur_blend.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"
#include "tests/support/printers.hpp"

namespace {

using gt::BeyerConstants;
using gt::BeyerSpeedRule;
using gt::DropletOrdering;
using gt::Grid;

// Fig. 2.10: c_r = 1.5 with the droplet on a sample (the digest's "cell centre"): w = 1.5 there,
// 0.5 at the 4 edge neighbours, 1.5 - √2 at the 4 corners, Σ = 3.5 + 4·(1.5 - √2) = 3.8431;
// normalised 0.3903 / 0.1301 / 0.0223 (digest 000 §3.7, verified there).
TEST(BeyerReference, BrushWeightsAreThoseOfFigure2_10) {
  const Grid<double> field(11, 9, 0.5);
  const Grid<double> weights = gt::reference::beyer_brush_weights(field, 5.0, 4.0, 1.5);
  EXPECT_NEAR(weights.at(5, 4), 0.3903, 5e-5);
  for (const auto& [x, y] : {std::pair{4, 4}, {6, 4}, {5, 3}, {5, 5}}) EXPECT_NEAR(weights.at(x, y), 0.1301, 5e-5);
  for (const auto& [x, y] : {std::pair{4, 3}, {6, 3}, {4, 5}, {6, 5}}) EXPECT_NEAR(weights.at(x, y), 0.0223, 5e-5);
  double sum = 0.0;
  for (const double w : weights.values) sum += w;
  EXPECT_NEAR(sum, 1.0, 1e-15) << "nothing beyond the 3x3 square";
  const Grid<double> weights_float = gt::reference::beyer_brush_weights(field.cast<float>(), 5.0f, 4.0f, 1.5f);
  EXPECT_NEAR(weights_float.at(5, 4), 0.3903, 5e-5);
  EXPECT_NEAR(weights_float.at(4, 3), 0.0223, 5e-5);
}

// In a corner of the grid the brush keeps the 4 samples it has and renormalises over them:
// (1.5, 0.5, 0.5, 1.5 - √2) / (4 - √2).
TEST(BeyerReference, TheBrushRenormalisesOverTheSamplesOnTheMap) {
  Grid<double> field(6, 6, 0.5);
  field.valid.assign(field.size(), 1);
  field.valid[field.index(2, 0)] = 0;
  const Grid<double> weights = gt::reference::beyer_brush_weights(field, 0.0, 0.0, 1.5);
  const double sum = 4.0 - std::sqrt(2.0);
  EXPECT_NEAR(weights.at(0, 0), 1.5 / sum, 1e-15);
  EXPECT_NEAR(weights.at(1, 0), 0.5 / sum, 1e-15);
  EXPECT_NEAR(weights.at(1, 1), (1.5 - std::sqrt(2.0)) / sum, 1e-15);
  const Grid<double> masked = gt::reference::beyer_brush_weights(field, 2.0, 1.0, 1.5);
  EXPECT_EQ(masked.at(2, 0), 0.0) << "a masked sample takes no share";
}

// Defaults (c_i 0.05, c_c 4, c_min 0.01, c_g 4, c_evap 0.01) with a short life and a small brush.
BeyerConstants single_step(double erosion) {
  BeyerConstants constants;
  constants.lifetime = 1;
  constants.radius = 1.0;
  constants.erosion = erosion;
  constants.speed_rule = BeyerSpeedRule::physical;  // the derivations below start from it
  return constants;
}

// h = 0.1·x. From (5.5, 3.5): cell (5, 3), u = v = 0.5, h_old = 0.55, g = (0.1, 0); dir =
// -0.95·g normalised = (-1, 0); p_new = (4.5, 3.5), h_new = 0.45, dh = -0.1. Capacity 4·0.1·1·1 =
// 0.4; erosion min(0.2·0.4, 0.1) = 0.08 with the brush of radius 1 at (5.5, 3.5): the 4 samples of
// the cell, all at √0.5, 0.02 each. Speed sqrt(1 + 0.1·4) (physical) or sqrt(1 - 0.4) (printed);
// water 0.99.
TEST(BeyerReference, ADropletStepsDownATiltedPlane) {
  Grid<double> field(12, 8);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) field.at(x, y) = 0.1 * x;
  }
  Grid<double> eroded = field;
  const auto path = gt::reference::beyer_one_droplet(eroded, single_step(0.2), 5.5, 3.5, 0);
  ASSERT_EQ(path.positions.size(), 2u);
  EXPECT_EQ(path.positions[1], std::make_pair(4.5, 3.5));
  EXPECT_FALSE(path.left);
  EXPECT_NEAR(path.sediment, 0.08, 1e-15);
  EXPECT_NEAR(path.speed, std::sqrt(1.4), 1e-15);
  EXPECT_NEAR(path.water, 0.99, 1e-15);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const bool brushed = (x == 5 || x == 6) && (y == 3 || y == 4);
      EXPECT_NEAR(eroded.at(x, y), field.at(x, y) - (brushed ? 0.02 : 0.0), 1e-15) << x << ", " << y;
    }
  }
  // Eq. 2.41's bound: c_e = 0.3 wants 0.12 but the droplet only descended 0.1.
  Grid<double> bounded = field;
  EXPECT_NEAR(gt::reference::beyer_one_droplet(bounded, single_step(0.3), 5.5, 3.5, 0).sediment, 0.1, 1e-15);
  auto printed = single_step(0.2);
  printed.speed_rule = BeyerSpeedRule::printed;
  Grid<double> printed_field = field;
  EXPECT_NEAR(gt::reference::beyer_one_droplet(printed_field, printed, 5.5, 3.5, 0).speed, std::sqrt(0.6), 1e-15);
}

// Rows 0.3 0.3 0.3 0.3 0.3 0 0.9 0.9. From (4.5, 1.5): h_old = 0.15, g = (-0.3, 0), dir = (1, 0);
// at (5.5, 1.5) h_new = 0.45: uphill by 0.3 with no sediment, so it deposits min(0.3, 0) = 0.
// Physical speed sqrt(max(1 - 0.3·4, 0)) = 0; printed sqrt(1 + 1.2).
TEST(BeyerReference, AnUphillStepDepositsAtMostTheSediment) {
  Grid<double> field(8, 4, 0.3);
  for (int y = 0; y < field.height; ++y) {
    field.at(5, y) = 0.0;
    field.at(6, y) = field.at(7, y) = 0.9;
  }
  Grid<double> after = field;
  const auto path = gt::reference::beyer_one_droplet(after, single_step(0.3), 4.5, 1.5, 0);
  EXPECT_EQ(path.positions.back(), std::make_pair(5.5, 1.5));
  EXPECT_EQ(path.sediment, 0.0);
  EXPECT_EQ(path.speed, 0.0) << "the radicand 1 - 1.2 is clamped";
  EXPECT_EQ(gt::field_difference(field, after).differing_bits, 0u);
  auto printed = single_step(0.3);
  printed.speed_rule = BeyerSpeedRule::printed;
  EXPECT_NEAR(gt::reference::beyer_one_droplet(after, printed, 4.5, 1.5, 0).speed, std::sqrt(2.2), 1e-15);
}

// On a flat the turn gives direction 0: the droplet takes compass direction
// random_u32(seed, droplet, 0, 0) % 8, and with dh = 0 erodes nothing.
TEST(BeyerReference, AZeroDirectionTakesACompassDirection) {
  const double s = 0.70710678118654752;
  const double compass[8][2] = {{1, 0}, {s, s}, {0, 1}, {-s, s}, {-1, 0}, {-s, -s}, {0, -1}, {s, -s}};
  auto constants = single_step(0.3);
  constants.seed = 77;
  const Grid<double> field(9, 9, 0.5);
  for (std::uint32_t droplet = 0; droplet < 16; ++droplet) {
    Grid<double> after = field;
    const auto path = gt::reference::beyer_one_droplet(after, constants, 4.5, 4.5, droplet);
    const auto pick = gt::random_u32(77, droplet, 0, 0) % 8;
    ASSERT_EQ(path.positions.size(), 2u);
    EXPECT_EQ(path.positions[1], std::make_pair(4.5 + compass[pick][0], 4.5 + compass[pick][1])) << droplet;
    EXPECT_EQ(gt::field_difference(field, after).differing_bits, 0u);
  }
}

// A droplet on the last column has no cell on the map: it does nothing and counts as left.
TEST(BeyerReference, ADropletStartingOffTheMapLeavesAtOnce) {
  Grid<double> field(6, 6, 0.5);
  const auto path = gt::reference::beyer_one_droplet(field, single_step(0.3), 5.5, 2.5, 0);
  EXPECT_TRUE(path.left);
  EXPECT_EQ(path.positions.size(), 1u);
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

long long quanta_residual(const gt::reference::DropletLedger& l) {
  return l.applied_quanta + l.sediment_end_quanta + l.deposited_outside_quanta - l.eroded_outside_quanta -
         l.clamp_created_quanta;
}

BeyerConstants terrain_constants(DropletOrdering ordering) {
  BeyerConstants constants;
  constants.lifetime = 20;
  constants.spacing = 3;
  constants.radius = 2.0;
  constants.ordering = ordering;
  constants.quantum = gt::batch_quantum(1.0);
  constants.speed_rule = BeyerSpeedRule::physical;
  return constants;
}

Grid<double> normalised_terrain() {
  return gt::normalise_heights(gt::testing::masked_terrain(3, 20, 10, 12).cast<double>());
}

// The masked terrain normalised: droplets meet the no-data blob and the grid's edges, erode,
// deposit and leave. Sum of 851 heights near 0.5: double rounding ~1e-13 absolute.
class BeyerLedger : public ::testing::TestWithParam<DropletOrdering> {};

TEST_P(BeyerLedger, ClosesInDoubleAndInQuanta) {
  const DropletOrdering ordering = GetParam();
  const Grid<double> field = normalised_terrain();
  const auto constants = terrain_constants(ordering);
  const auto run = gt::reference::beyer_erosion(field, constants, 2, ordering);
  EXPECT_GT(run.ledger.eroded, 0.0);
  EXPECT_GT(run.ledger.deposited, 0.0);
  EXPECT_GT(run.ledger.droplets_left, 0);
  EXPECT_GT(run.ledger.sediment_at_end + run.ledger.sediment_left, 0.0);
  EXPECT_EQ(run.ledger.eroded_outside + run.ledger.deposited_outside + run.ledger.clamp_created, 0.0);
  EXPECT_LE(std::abs(ledger_residual(field, run)), 1e-12 * sum_of(field));
  if (ordering == DropletOrdering::batch) {
    EXPECT_EQ(quanta_residual(run.ledger), 0);
    const auto run_float = gt::reference::beyer_erosion(field.cast<float>(), constants, 2, ordering);
    EXPECT_EQ(quanta_residual(run_float.ledger), 0);
    EXPECT_LE(std::abs(ledger_residual(field.cast<float>(), run_float)), 1e-12 * sum_of(field));
  }
}

INSTANTIATE_TEST_SUITE_P(Orderings, BeyerLedger, ::testing::Values(DropletOrdering::race, DropletOrdering::batch));

class ActiveMutant {
 public:
  explicit ActiveMutant(const std::string& name) { gt::set_active_mutant(name); }
  ~ActiveMutant() { gt::set_active_mutant(""); }
  ActiveMutant(const ActiveMutant&) = delete;
  ActiveMutant& operator=(const ActiveMutant&) = delete;
};

// The mutants of both twins destroy (sediment not taken up) or create (uphill deposits of dh, the
// droplet's sediment clamped at 0) material: the ledger no longer closes, by far more than rounding.
class BeyerLedgerMutants : public ::testing::TestWithParam<std::tuple<std::string, DropletOrdering>> {};

TEST_P(BeyerLedgerMutants, AreCaughtByTheLedger) {
  const auto [mutant, ordering] = GetParam();
  const Grid<double> field = normalised_terrain();
  const ActiveMutant active(mutant);
  auto constants = terrain_constants(ordering);
  constants.lifetime = 8;  // batch: droplets that never fill up dig without bound; keep the delta in range
  const auto run = gt::reference::beyer_erosion(field, constants, 1, ordering);
  EXPECT_GT(std::abs(ledger_residual(field, run)), 1e-6 * sum_of(field));
  if (ordering == DropletOrdering::batch) {
    EXPECT_NE(quanta_residual(run.ledger), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    BothTwins, BeyerLedgerMutants,
    ::testing::Combine(::testing::Values("erosion.beyer.sediment_not_taken_on_erosion",
                                         "erosion.beyer.uphill_deposit_unbounded"),
                       ::testing::Values(DropletOrdering::race, DropletOrdering::batch)));

// The batch delta holds what the GPU's int32 counter holds, 2^31 - 1 quanta a cell and pass, and
// refuses one more as a run that left the twins' range (RunawayRun: the case becomes inconclusive),
// not as a failure of either twin.
TEST(BatchDelta, HoldsTheCounterRangeAndRefusesBeyondItAsARunaway) {
  const double quantum = gt::batch_quantum(1.0);  // 2^-24
  gt::reference::DropletLedger ledger;
  gt::Grid<float> heights(2, 1, 0.0);
  gt::reference::BatchDelta<float> delta(heights.size(), static_cast<float>(quantum), "erosion.beyer");
  delta.add(0, 2147483647LL);
  delta.add(1, -2147483647LL);
  delta.apply(heights, ledger);
  EXPECT_FLOAT_EQ(heights.values[0], 128.0f);
  EXPECT_FLOAT_EQ(heights.values[1], -128.0f);
  delta.add(1, -2147483648LL);
  EXPECT_THROW(delta.apply(heights, ledger), gt::RunawayRun);
}

// The apply pass's rounding, which the batch ledger books as measured, stays within one rounding
// of float(delta) and one of the sum per cell — over deltas beyond 2^24 quanta, where float(delta)
// itself rounds — and a change applied 2^-10 too large in both twins does not.
TEST(BatchDelta, TheApplyRoundingStaysWithinItsBoundAndAScaledApplyDoesNot) {
  const auto apply_random_deltas = [] {
    const double quantum = gt::batch_quantum(100.0);
    gt::Grid<float> heights(64, 64, 0.0f);
    gt::reference::BatchDelta<float> delta(heights.size(), static_cast<float>(quantum), "erosion.beyer");
    for (std::size_t i = 0; i < heights.size(); ++i) {
      const auto cell = static_cast<std::uint32_t>(i);
      heights.values[i] = 100.0f * gt::uniform01(gt::random_u32(7, cell, 0, 0));
      const double share = 2.0 * gt::uniform01(gt::random_u32(7, cell, 0, 1)) - 1.0;
      delta.add(i, static_cast<long long>(share * 2.0e9));
    }
    gt::reference::DropletLedger ledger;
    delta.apply(heights, ledger);
    return ledger;
  };
  const auto honest = apply_random_deltas();
  EXPECT_GT(std::abs(honest.apply_rounding), 0.0) << "the deltas beyond 2^24 round";
  EXPECT_LE(std::abs(honest.apply_rounding), honest.apply_rounding_bound);
  const ActiveMutant scaled("erosion.beyer.apply_scaled");
  const auto mutated = apply_random_deltas();
  EXPECT_GT(std::abs(mutated.apply_rounding), mutated.apply_rounding_bound);
}

// ---- eq. 2.43: the blend with a blurred map --------------------------------------------------------

// The 3x3 box blur of the grid extended by mirroring each cell into its missing neighbours (the
// border's decision): c_b·blurred + (1 - c_b)·h, written from eq. 2.43 directly in double.
double blended_by_eq_2_43(const Grid<double>& heights, int x, int y, double blend) {
  double sum = 0.0;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const bool open = heights.inside(x + dx, y + dy) && heights.is_valid(x + dx, y + dy);
      sum += open ? heights.at(x + dx, y + dy) : heights.at(x, y);
    }
  }
  return blend * (sum / 9.0) + (1.0 - blend) * heights.at(x, y);
}

// On the masked terrain (37x23, heights 500-540 m, a no-data blob): every open cell is eq. 2.43 with
// the box blur and the mirror border, to the few roundings either form takes at 540 m (10 u·540 ≈
// 1.2e-12); no-data cells keep their heights.
TEST(BlurBlend, IsEq2_43WithABoxBlurAndAMirrorBorder) {
  const Grid<double> before = gt::testing::masked_terrain(5, 10, 8, 9).cast<double>();
  Grid<double> blended = before;
  gt::reference::blur_blend(blended, 0.4, "erosion.beyer");
  const double tolerance = 10.0 * 0x1p-53 * 540.0;
  int open = 0;
  for (int y = 0; y < before.height; ++y) {
    for (int x = 0; x < before.width; ++x) {
      if (!before.is_valid(x, y)) {
        EXPECT_EQ(blended.at(x, y), before.at(x, y));
        continue;
      }
      ++open;
      EXPECT_NEAR(blended.at(x, y), blended_by_eq_2_43(before, x, y, 0.4), tolerance) << x << ", " << y;
    }
  }
  EXPECT_GT(gt::field_difference(before, blended).max_abs, 1.0) << "the relief of 40 m should have been smoothed";
  EXPECT_GT(open, 800);
}

// The exchanges cancel in pairs: in double the volume moves by the sums' roundings only (18 per
// cell of at most u·540: 1e-10 over 850 cells), in float by those of float (18·850·u_float·540 ≈
// 0.5, the model's worst case; it lands far below); the box blur renormalised at the border
// (the mutant) loses metres of volume over the terrain's edge.
TEST(BlurBlend, KeepsTheVolumeWhereARenormalisedBlurDoesNot) {
  const Grid<float> before = gt::testing::masked_terrain(5, 10, 8, 9);
  const double cells = static_cast<double>(before.size());
  Grid<double> in_double = before.cast<double>();
  gt::reference::blur_blend(in_double, 0.5, "erosion.beyer");
  EXPECT_LE(std::abs(sum_of(in_double) - sum_of(before)), 18.0 * cells * 0x1p-53 * 540.0);
  Grid<float> in_float = before;
  gt::reference::blur_blend(in_float, 0.5, "erosion.beyer");
  EXPECT_LE(std::abs(sum_of(in_float) - sum_of(before)), 18.0 * cells * 0x1p-24 * 540.0);
  const ActiveMutant renormalised("erosion.beyer.blur_renormalised_at_border");
  Grid<double> mutated = before.cast<double>();
  gt::reference::blur_blend(mutated, 0.5, "erosion.beyer");
  EXPECT_GT(std::abs(sum_of(mutated) - sum_of(before)), 1.0);
}

// Batch: each exchange's count of quanta is exactly minus its pair's, so the applied quanta sum to
// 0 (the ledger's identity), and the result lies within the quanta's rounding (half a quantum per
// exchange, 8 a cell, and the apply's) of the blend in float.
TEST(BlurBlend, InQuantaThePairsCancelExactly) {
  const Grid<float> before = gt::testing::masked_terrain(5, 10, 8, 9);
  const double quantum = gt::batch_quantum(540.0);
  gt::reference::BatchDelta<float> delta(before.size(), static_cast<float>(quantum), "erosion.beyer");
  gt::reference::blur_blend_quanta(before, 0.5, static_cast<float>(1.0 / quantum), delta, "erosion.beyer");
  Grid<float> in_quanta = before;
  gt::reference::DropletLedger ledger;
  delta.apply(in_quanta, ledger);
  EXPECT_EQ(ledger.applied_quanta, 0);
  EXPECT_GT(ledger.largest_cell_delta_quanta, 1000);
  Grid<float> in_place = before;
  gt::reference::blur_blend(in_place, 0.5, "erosion.beyer");
  EXPECT_LE(gt::field_difference(in_place, in_quanta).max_abs, 4.0 * quantum + 4.0 * 0x1p-24 * 540.0);
}

class BlurBlendGpu : public gt::testing::GlTestWithParam<DropletOrdering> {};

// Beyer's droplets with c_b 0.5 after each of two iterations, on the GPU against ref<float>: every
// bit equal in batch (the blend's quanta through one more apply) and in disjoint (the blend in place,
// the same float operations in the same order); the blend changes the result.
TEST_P(BlurBlendGpu, EqualsTheFloatReferenceBitForBit) {
  const DropletOrdering ordering = GetParam();
  const Grid<float> field = normalised_terrain().cast<float>();
  auto constants = terrain_constants(ordering);
  if (ordering == DropletOrdering::disjoint) {
    constants.lifetime = 6;
    constants.spacing = 21;  // > 2·(6 + 2 + 2)
  }
  constants.iterations = 2;
  constants.blur_blend = 0.5;
  const DropletOrdering reference_ordering =
      ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race;
  const auto reference = gt::reference::beyer_erosion(field, constants, 2, reference_ordering);
  gt::gpu::BeyerErosion gpu(field.width, field.height, constants);
  gpu.load(field);
  gpu.run();
  EXPECT_EQ(gt::field_difference(reference.heights, gpu.result()).differing_bits, 0u);
  auto unblended = constants;
  unblended.blur_blend = 0.0;
  const auto without = gt::reference::beyer_erosion(field, unblended, 2, reference_ordering);
  EXPECT_GT(gt::field_difference(without.heights, reference.heights).max_abs, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Orderings, BlurBlendGpu, ::testing::Values(DropletOrdering::disjoint, DropletOrdering::batch));

TEST(BeyerParams, DisjointNeedsTheSpacingThatKeepsDropletsApart) {
  const gt::Heightmap field(8, 8, 1.0);
  auto resolved = gt::resolve_params("erosion.beyer", gt::beyer_param_specs(),
                                     {{"ordering", "disjoint"}, {"lifetime", 10}, {"radius", 2.5}, {"spacing", 30}});
  EXPECT_THROW(gt::beyer_constants(resolved, field), gt::InputError) << "30 = 2·(10 + ceil(2.5) + 2) lets them touch";
  resolved["spacing"] = 31;
  EXPECT_EQ(gt::beyer_constants(resolved, field).spacing, 31);
}

TEST(BeyerParams, DefaultsAndChoicesReachTheConstants) {
  const gt::Heightmap field(8, 8, 1.0);
  const auto defaults = gt::beyer_constants(gt::resolve_params("erosion.beyer", gt::beyer_param_specs(), {}), field);
  EXPECT_EQ(defaults.ordering, DropletOrdering::batch);
  EXPECT_EQ(defaults.speed_rule, BeyerSpeedRule::printed);
  EXPECT_EQ(defaults.quantum, gt::batch_quantum(1.0));
  EXPECT_EQ(gt::beyer_reach(defaults), 30 + 3 + 2);
  const auto chosen = gt::beyer_constants(
      gt::resolve_params("erosion.beyer", gt::beyer_param_specs(), {{"speed_rule", "physical"}, {"seed", 4294967295.0}}),
      field);
  EXPECT_EQ(chosen.speed_rule, BeyerSpeedRule::physical);
  EXPECT_EQ(chosen.seed, 4294967295u);
  EXPECT_THROW(gt::resolve_params("erosion.beyer", gt::beyer_param_specs(), {{"inertia", 1.0}}), gt::InputError);
  EXPECT_THROW(gt::resolve_params("erosion.beyer", gt::beyer_param_specs(), {{"radius", 0.5}}), gt::InputError);
  EXPECT_THROW(gt::resolve_params("erosion.beyer", gt::beyer_param_specs(), {{"speed_rule", "sideways"}}),
               gt::InputError);
}

// A plateau at 0.5 with a bowl 0.4 deep and 7 samples wide: droplets on the plateau start with
// direction 0 and take a compass direction from the RNG, so the result depends on every droplet's
// number, which the GPU must count as the reference does.
Grid<float> plateau_with_bowl() {
  Grid<float> field(37, 23, 0.5f);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const double distance = std::hypot(x - 18.0, y - 11.0);
      field.at(x, y) = static_cast<float>(0.5 - 0.4 * std::max(0.0, 1.0 - distance / 7.0));
    }
  }
  return field;
}

class BeyerGpu : public gt::testing::GlTestWithParam<std::tuple<DropletOrdering, BeyerSpeedRule>> {};

// Batch: every bit equal to ref<float> and repeatable. Disjoint: the same float operations in the
// same order, and llvmpipe divides and takes square roots correctly: every bit equal too.
TEST_P(BeyerGpu, EqualsTheFloatReferenceBitForBit) {
  const auto [ordering, speed_rule] = GetParam();
  const Grid<float> field = normalised_terrain().cast<float>();
  auto constants = terrain_constants(ordering);
  constants.speed_rule = speed_rule;
  if (ordering == DropletOrdering::disjoint) {
    constants.lifetime = 6;
    constants.spacing = 21;  // > 2·(6 + 2 + 2)
  }
  constants.iterations = 2;
  const auto reference = gt::reference::beyer_erosion(
      field, constants, 2, ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race);
  gt::gpu::BeyerErosion gpu(field.width, field.height, constants);
  gpu.load(field);
  gpu.run();
  const auto first = gpu.result();
  gpu.load(field);
  gpu.run();
  EXPECT_EQ(gt::field_difference(reference.heights, first).differing_bits, 0u);
  EXPECT_EQ(gt::field_difference(first, gpu.result()).differing_bits, 0u);
  EXPECT_GT(gt::field_difference(field, first).max_abs, 1e-4) << "the terrain should have changed";
}

INSTANTIATE_TEST_SUITE_P(Orderings, BeyerGpu,
                         ::testing::Combine(::testing::Values(DropletOrdering::disjoint, DropletOrdering::batch),
                                            ::testing::Values(BeyerSpeedRule::physical, BeyerSpeedRule::printed)));

class BeyerGpuRandom : public gt::testing::GlTest {};

// The random compass directions on the plateau (they matter: another seed gives other heights),
// numbered on across step() calls: load, step(1), step(1) equals the reference's two iterations
// bit for bit.
TEST_F(BeyerGpuRandom, CompassDirectionsAreNumberedAsTheReferenceNumbersThem) {
  const Grid<float> field = plateau_with_bowl();
  auto constants = terrain_constants(DropletOrdering::batch);
  constants.spacing = 5;  // at spacing 3 the bowl's converging droplets, blind to each other, dig without bound
  constants.seed = 12345;
  const auto reference = gt::reference::beyer_erosion(field, constants, 2, DropletOrdering::batch);
  auto reseeded = constants;
  reseeded.seed = 54321;
  const auto other = gt::reference::beyer_erosion(field, reseeded, 2, DropletOrdering::batch);
  EXPECT_GT(gt::field_difference(reference.heights, other.heights).differing_bits, 0u);
  gt::gpu::BeyerErosion gpu(field.width, field.height, constants);
  gpu.load(field);
  gpu.step(1);
  gpu.step(1);
  EXPECT_EQ(gt::field_difference(reference.heights, gpu.result()).differing_bits, 0u);
}

// A state resumed after one iteration numbers its droplets from there (the stepper protocol's
// set_state(state, 1)): the reference from iteration 1 ends where two iterations in one go end,
// bit for bit. The number matters (on the plateau an iteration numbered 1 draws other directions
// than one numbered 0), and the GPU loaded with one iteration behind its heights draws as the
// reference does.
TEST_F(BeyerGpuRandom, AStateResumedMidRunDrawsWhatTheWholeRunDraws) {
  const Grid<float> field = plateau_with_bowl();
  auto constants = terrain_constants(DropletOrdering::batch);
  constants.spacing = 5;
  constants.seed = 12345;
  const auto whole = gt::reference::beyer_erosion(field, constants, 2, DropletOrdering::batch);
  const auto first = gt::reference::beyer_erosion(field, constants, 1, DropletOrdering::batch);
  const auto resumed = gt::reference::beyer_erosion(first.heights, constants, 1, DropletOrdering::batch, 1);
  EXPECT_EQ(gt::field_difference(whole.heights, resumed.heights).differing_bits, 0u);
  const auto numbered_1 = gt::reference::beyer_erosion(field, constants, 1, DropletOrdering::batch, 1);
  EXPECT_GT(gt::field_difference(first.heights, numbered_1.heights).differing_bits, 0u);
  gt::gpu::BeyerErosion gpu(field.width, field.height, constants);
  gpu.load(field, 1);
  gpu.step(1);
  EXPECT_EQ(gt::field_difference(numbered_1.heights, gpu.result()).differing_bits, 0u);
  gpu.load(first.heights, 1);
  gpu.step(1);
  EXPECT_EQ(gt::field_difference(whole.heights, gpu.result()).differing_bits, 0u);
}

}  // namespace
