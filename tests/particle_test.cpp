// Seed 000's droplet erosion: the reference against hand-derived droplets (a pit; the ramp is
// datasets/cases/erosion.particle.json's spec case), its ledger on a masked terrain
// in every ordering, the parameters' refusals, and the GPU twin against ref<float> (batch bit for
// bit; disjoint, where llvmpipe rounds division and sqrt correctly, too). Colour transport (§4.5):
// a hand-derived droplet, the batch ordering's weighted mean, no colour created in sequential and
// batch ordering, and the GPU's colour and side maps against ref<float> bit for bit.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "compare/checks/field.hpp"
#include "core/errors.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "core/rng.hpp"
#include "gpu/erosion/particle.hpp"
#include "reference/erosion/particle.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/masked_terrain.hpp"
#include "tests/support/printers.hpp"

namespace {

using gt::DropletOrdering;
using gt::Grid;
using gt::ParticleConstants;
using gt::reference::ColourMap;

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

// A colour per texel from the counter RNG: channel ch uniform in [low[ch], low[ch] + span[ch]).
template <class Real>
ColourMap<Real> random_colour(int width, int height, std::uint32_t seed, std::array<float, 4> low,
                              std::array<float, 4> span) {
  ColourMap<Real> colour(width, height);
  for (std::size_t i = 0; i < colour.size(); ++i) {
    for (int ch = 0; ch < 4; ++ch) {
      const float u = gt::uniform01(gt::random_u32(seed, static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(ch), 0));
      colour.values[i][ch] = static_cast<Real>(low[ch] + span[ch] * u);
    }
  }
  return colour;
}

// Rows 0 and 1: 0.9 0.8 0.78 0.8 0.85 0.9 (a dip at x = 2, a rise beyond); row 2: a wall of 0.9.
// Colour (0.1·x, 0.1·y, 0.5, 1).
Grid<double> dip() {
  const double row[6] = {0.9, 0.8, 0.78, 0.8, 0.85, 0.9};
  Grid<double> field(6, 3, 0.9);
  for (int x = 0; x < 6; ++x) field.at(x, 0) = field.at(x, 1) = row[x];
  return field;
}

ColourMap<double> dip_colour() {
  ColourMap<double> colour(6, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) colour.at(x, y) = {0.1 * x, 0.1 * y, 0.5, 1.0};
  }
  return colour;
}

// Upstream defaults (f_col 0.2), no interpolation, 4 steps from (1, 1); the droplet starts with
// col = C(1, 1) = (0.1, 0.1, 0.5, 1).
//   step 0 at (1, 1): v_x = -0.5·(0.8 - 0.9) = 0.05, ×0.8 = 0.04, capacity 4e-4: erodes 0.25·4e-4 = 1e-4
//     ((1, 1) = 0.7999) and picks up 0.2·C(1, 1) + 0.8·col = col; moves to (2, 1).
//   step 1 at (2, 1): v_x = 0.04 + 0.5·(0.78 - 0.8) = 0.03, ×0.8 = 0.024, capacity 2.4e-4 > 1e-4 but
//     (2, 1) is no higher than its lowest neighbour (0.78 above it): nothing; moves to (3, 1).
//   step 2 at (3, 1): v_x = 0.024 + 0.5·(0.8 - 0.85) = -0.001, ×0.8 = -0.0008, capacity 8e-6 < 1e-4:
//     deposits 0.25·9.2e-5 = 2.3e-5 ((3, 1) = 0.800023, sediment 7.7e-5) and the colour
//     C(3, 1) = 0.8·(0.3, 0.1, 0.5, 1) + 0.2·col = (0.26, 0.1, 0.5, 1); moves back to (2, 1).
//   step 3 at (2, 1): from v_x < 0 the -x side: v_x = -0.0008 - 0.5·(0.78 - 0.7999) = 0.00915, ×0.8
//     = 0.00732, capacity 7.32e-5 < 7.7e-5: deposits 0.25·3.8e-6 = 9.5e-7 ((2, 1) = 0.78000095,
//     sediment 7.605e-5) and C(2, 1) = 0.8·(0.2, 0.1, 0.5, 1) + 0.2·col = (0.18, 0.1, 0.5, 1).
// Every other texel keeps its colour.
TEST(ParticleReference, ADropletCarriesColourToTheTwoTexelsItDepositsOn) {
  Grid<double> field = dip();
  ColourMap<double> colour = dip_colour();
  const ColourMap<double> before = colour;
  auto constants = short_life(4);
  constants.interpolate_colour = false;
  const auto path = gt::reference::run_one_droplet(field, constants, 1, 1, &colour);
  ASSERT_EQ(path.positions.size(), 5u);
  EXPECT_DOUBLE_EQ(path.positions[3].first, 2.5) << "the rise sends it back";
  EXPECT_NEAR(field.at(1, 1), 0.7999, 1e-12);
  EXPECT_NEAR(field.at(3, 1), 0.800023, 1e-12);
  EXPECT_NEAR(field.at(2, 1), 0.78000095, 1e-12);
  EXPECT_NEAR(path.sediment, 7.605e-5, 1e-12);
  const std::array<double, 4> at_3{0.26, 0.1, 0.5, 1.0}, at_2{0.18, 0.1, 0.5, 1.0};
  for (int ch = 0; ch < 4; ++ch) {
    EXPECT_NEAR(colour.at(3, 1)[ch], at_3[ch], 1e-12) << "channel " << ch;
    EXPECT_NEAR(colour.at(2, 1)[ch], at_2[ch], 1e-12) << "channel " << ch;
  }
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 6; ++x) {
      if (y == 1 && (x == 2 || x == 3)) continue;
      EXPECT_EQ(colour.at(x, y), before.at(x, y)) << "texel " << x << ", " << y;
    }
  }
}

// Batch: a cell starting at 0.5 that receives col 1 and col 0 with weight 0.2 each ends at
// (0.5 + 0.2·1 + 0.2·0) / (1 + 0.4) = 0.5, and the same bits whichever deposit comes first.
TEST(ParticleReference, TheBatchColourIsTheWeightedMeanInAnyOrder) {
  using Delta = gt::reference::ColourDelta<double>;
  ColourMap<double> first(1, 1, {0.5, 0.5, 0.5, 0.5}), second = first;
  Delta a(1, "test"), b(1, "test");
  a.add(0, 0.2, {1.0, 0.0, 0.25, 3.0});
  a.add(0, 0.2, {0.0, 1.0, 0.75, -1.0});
  b.add(0, 0.2, {0.0, 1.0, 0.75, -1.0});
  b.add(0, 0.2, {1.0, 0.0, 0.25, 3.0});
  a.apply(first);
  b.apply(second);
  EXPECT_EQ(first.values[0], second.values[0]);
  // 0.2 is 209715.2 units of 2^-20, rounded to 209715: the weights are those quanta.
  const double w = 209715.0 / 1048576.0;
  EXPECT_NEAR(first.values[0][0], (0.5 + w) / (1 + 2 * w), 1e-7);
  EXPECT_NEAR(first.values[0][0], 0.5, 1e-6);
  EXPECT_NEAR(first.values[0][3], (0.5 + 2 * w * 1.0) / (1 + 2 * w), 1e-6);
  ColourMap<double> untouched(1, 1, {0.3, 0.3, 0.3, 0.3});
  a.apply(untouched);
  EXPECT_EQ(untouched.values[0][0], 0.3) << "apply() cleared the sums";
}

// A terrain falling towards +x and +y (1 - 0.01·(x + y), with 0.002 of noise) and the masked
// terrain's no-data blob: droplets keep positive velocities (at x or y = 0 the outside, reading 0,
// is more than drop_max below), so they stay at x, y >= 0.5 where colorize4's weights are in [0, 1]
// (nearer the low edges the truncated corner gives weights outside it and colour may overshoot,
// as upstream).
Grid<double> tilted_terrain() {
  Grid<double> field = gt::testing::masked_terrain(9, 20, 10, 12).cast<double>();
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const double noise = (field.at(x, y) - 500.0) / 40.0;
      field.at(x, y) = 1.0 - 0.01 * (x + y) + 0.002 * noise;
    }
  }
  return field;
}

// Each channel's range over the valid texels, widened to 0: masked and off-grid texels read
// (0, 0, 0, 0), the colour of droplets that start there or pick colour up there.
template <class Real>
std::array<std::pair<double, double>, 4> channel_ranges(const ColourMap<Real>& colour, const Grid<double>& mask) {
  std::array<std::pair<double, double>, 4> ranges;
  ranges.fill({0.0, 0.0});
  for (std::size_t i = 0; i < colour.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    for (int ch = 0; ch < 4; ++ch) {
      ranges[ch].first = std::min(ranges[ch].first, static_cast<double>(colour.values[i][ch]));
      ranges[ch].second = std::max(ranges[ch].second, static_cast<double>(colour.values[i][ch]));
    }
  }
  return ranges;
}

template <class Real>
void expect_no_colour_created(DropletOrdering ordering, bool interpolate_colour, double tolerance) {
  const Grid<Real> field = tilted_terrain().cast<Real>();
  const ColourMap<Real> colour = random_colour<Real>(field.width, field.height, 21, {0.2f, -1.0f, 0.5f, 0.0f},
                                                     {0.6f, 3.0f, 0.0f, 1.0f});
  auto constants = terrain_constants(ordering, true);
  constants.interpolate_colour = interpolate_colour;
  const auto run = gt::reference::particle_erosion(field, constants, 2, ordering, &colour);
  ASSERT_EQ(run.colour.size(), colour.size());
  const Grid<double> mask = field.template cast<double>();
  const auto ranges = channel_ranges(colour, mask);
  double outside = 0.0, changed = 0.0;
  for (std::size_t i = 0; i < colour.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    for (int ch = 0; ch < 4; ++ch) {
      const double value = run.colour.values[i][ch];
      outside = std::max({outside, ranges[ch].first - value, value - ranges[ch].second});
      changed = std::max(changed, std::abs(value - static_cast<double>(colour.values[i][ch])));
    }
  }
  EXPECT_LE(outside, tolerance) << "colour left its channel's range";
  EXPECT_GT(changed, 1e-3) << "the droplets should have moved colour";
}

class ParticleColourRange : public ::testing::TestWithParam<std::tuple<DropletOrdering, bool>> {};

// Sequential: every write is a convex blend (weights in [0, 1]), off by its roundings only (double
// 1e-12, float 1e-5 over up to 2 channels' magnitude). Batch: a weighted mean whose terms are rounded
// to 2^-20 each, about 1e-6 per deposit into a cell and pass: 1e-4 leaves room for ~100.
TEST_P(ParticleColourRange, NoColourIsCreated) {
  const auto [ordering, interpolate_colour] = GetParam();
  const bool batch = ordering == DropletOrdering::batch;
  expect_no_colour_created<double>(ordering, interpolate_colour, batch ? 1e-4 : 1e-12);
  expect_no_colour_created<float>(ordering, interpolate_colour, batch ? 1e-4 : 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Orderings, ParticleColourRange,
                         ::testing::Combine(::testing::Values(DropletOrdering::race, DropletOrdering::batch),
                                            ::testing::Bool()));

TEST(ParticleReference, WithoutColourNothingElseChanges) {
  const Grid<double> field = gt::normalise_heights(gt::testing::masked_terrain(3, 20, 10, 12).cast<double>());
  for (const auto ordering : {DropletOrdering::race, DropletOrdering::batch}) {
    const auto constants = terrain_constants(ordering, true);
    const ColourMap<double> colour = random_colour<double>(field.width, field.height, 5, {0, 0, 0, 0}, {1, 1, 1, 1});
    const auto plain = gt::reference::particle_erosion(field, constants, 2, ordering);
    const auto coloured = gt::reference::particle_erosion(field, constants, 2, ordering, &colour);
    EXPECT_TRUE(plain.colour.values.empty());
    EXPECT_EQ(plain.heights.values, coloured.heights.values);
    EXPECT_EQ(plain.eroded_at_droplet.values, coloured.eroded_at_droplet.values);
    EXPECT_EQ(plain.deposited_at_droplet.values, coloured.deposited_at_droplet.values);
  }
}

// Texels whose colours differ in any bit.
std::size_t differing_colours(const ColourMap<float>& a, const ColourMap<float>& b) {
  if (a.values.size() != b.values.size()) return std::numeric_limits<std::size_t>::max();
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    for (int ch = 0; ch < 4; ++ch) {
      if (std::bit_cast<std::uint32_t>(a.values[i][ch]) != std::bit_cast<std::uint32_t>(b.values[i][ch])) {
        ++differing;
        break;
      }
    }
  }
  return differing;
}

// Colour transport: 0 none, 1 interpolated (colorize4), 2 at the droplet's texel.
class ParticleGpuColour : public gt::testing::GlTestWithParam<std::tuple<DropletOrdering, int>> {};

// Heights, both side maps and (when transported) the colour, every bit equal to ref<float>: batch
// by construction, disjoint as the heights (llvmpipe rounds division and sqrt correctly).
TEST_P(ParticleGpuColour, SideMapsAndColourEqualTheFloatReferenceBitForBit) {
  const auto [ordering, transport] = GetParam();
  const Grid<float> field =
      gt::normalise_heights(gt::testing::masked_terrain(5, 10, 12, 9).cast<double>()).cast<float>();
  const ColourMap<float> colour =
      random_colour<float>(field.width, field.height, 8, {0.0f, -0.5f, 0.25f, 1.0f}, {1.0f, 2.0f, 0.5f, 0.0f});
  auto constants = terrain_constants(ordering, true);
  if (ordering == DropletOrdering::disjoint) {
    constants.lifetime = 6;
    constants.spacing = 17;
  }
  constants.iterations = 2;
  constants.interpolate_colour = transport == 1;
  const auto reference = gt::reference::particle_erosion(
      field, constants, 2, ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race,
      transport != 0 ? &colour : nullptr);
  gt::gpu::ParticleErosion gpu(field.width, field.height, constants, transport != 0);
  gpu.load(field);
  if (transport != 0) gpu.load_colour(colour);
  gpu.run();
  EXPECT_EQ(gt::field_difference(reference.heights, gpu.result()).differing_bits, 0u);
  const Grid<float> eroded = gpu.eroded_at_droplet(), deposited = gpu.deposited_at_droplet();
  EXPECT_EQ(gt::field_difference(reference.eroded_at_droplet.cast<float>(), eroded).differing_bits, 0u);
  EXPECT_EQ(gt::field_difference(reference.deposited_at_droplet.cast<float>(), deposited).differing_bits, 0u);
  EXPECT_EQ(gt::field_difference(reference.eroded_at_droplet, eroded).max_abs, 0.0) << "the maps are float sums";
  EXPECT_GT(gt::field_totals(eroded).high, 0.0);
  EXPECT_GT(gt::field_totals(deposited).high, 0.0);
  if (transport != 0) {
    const ColourMap<float> moved = gpu.colour_result();
    EXPECT_EQ(differing_colours(reference.colour, moved), 0u);
    EXPECT_GT(differing_colours(colour, moved), 10u) << "the droplets should have moved colour";
    gpu.load(field);
    EXPECT_THROW(gpu.run(), std::logic_error) << "load() asks for the colour again";
  } else {
    EXPECT_THROW(gpu.load_colour(colour), std::logic_error);
  }
}

INSTANTIATE_TEST_SUITE_P(Orderings, ParticleGpuColour,
                         ::testing::Combine(::testing::Values(DropletOrdering::disjoint, DropletOrdering::batch),
                                            ::testing::Values(0, 1, 2)));

}  // namespace
