// Properties of the water on seed 001's layered ground, CPU reference (core/layered/layered_water,
// reference/erosion/layered/{water,force_erosion,dissolution,wetness}): a still lake stays still,
// water runs downhill and spreads symmetrically, the river's source and sinks, worked numbers of the
// capacity (eq. 2.1-2.2, 3.5) and of erosion through thin layers (eq. 3.10 with transparency),
// dissolution that settles back when the water leaves, wetness (eq. 3.12) and the flood death, and
// the ledger of every material (ground + water + sunk) over rain and river runs.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"
#include "reference/erosion/layered/column.hpp"
#include "reference/erosion/layered/diffusion.hpp"
#include "reference/erosion/layered/dissolution.hpp"
#include "reference/erosion/layered/force_erosion.hpp"
#include "reference/erosion/layered/impact_erosion.hpp"
#include "reference/erosion/layered/iteration.hpp"
#include "reference/erosion/layered/material_masks.hpp"
#include "reference/erosion/layered/vegetation.hpp"
#include "reference/erosion/layered/water.hpp"
#include "reference/erosion/layered/wetness.hpp"

namespace {

using gt::LayeredGround;
using gt::LayeredParams;
using gt::LayeredProfile;
using gt::LayeredWater;
namespace ref = gt::reference;

constexpr int org = 0;
constexpr int sand = 1;

LayeredProfile loam_profile() {
  LayeredProfile profile;
  profile.topsoil = {0.3, 0.4, 0.2, 0.1, 0.0};
  profile.subsoil = {0.2, 0.8, 0.5, 0.3, 0.2};
  profile.bedrock = {{0, 3.0}, {1, 10.0}};
  return profile;
}

gt::Heightmap cone(int side, double peak, double cell_size) {
  gt::Heightmap surface(side, side, 0.0);
  surface.cell_size_x = surface.cell_size_y = cell_size;
  const double middle = 0.5 * (side - 1);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double distance = std::hypot(x - middle, y - middle) / middle;
      surface.at(x, y) = 100.0 + peak * std::max(0.0, 1.0 - distance);
    }
  }
  return surface;
}

// Total of each component in ground and water, plus what sank, minus what conversions made, m³:
// constant over a run when the ledger closes.
template <class Real>
std::array<double, 5> ledger_balance(const LayeredGround<Real>& ground, const LayeredWater<Real>& water,
                                     const gt::LayeredConversions& conversions, std::size_t types) {
  const auto in_ground = gt::layered_ledger(ground, types);
  const auto in_water = gt::layered_water_ledger(water, ground.cell_size_x * ground.cell_size_y);
  std::array<double, 5> balance{};
  for (int i = 0; i < 5; ++i) {
    const auto k = static_cast<std::size_t>(i);
    balance[k] = in_ground.components[k] + in_water.carried[k] + conversions.sunk[k] -
                 (conversions.converted_into(i) - conversions.converted_from(i));
  }
  return balance;
}

TEST(LayeredWater, AStillLakeStaysStill) {
  // A flat ground under 1 m of water: every level difference is 0, so no flux may start, and the
  // water strength (|v| = 0) erodes nothing; any sign or neighbour error moves water.
  LayeredParams params;
  params.initial_water = 1.0;
  params.regolith_depth = 0.0;
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(8, 6, 50.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), params.initial_water);
  const auto start = ground;
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  for (int step = 0; step < 20; ++step) {
    ref::water_flow(ground, water, params);
    ref::force_erosion_step(ground, water, params, conversions);
  }
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    EXPECT_EQ(water.water[c], 1.0) << "cell " << c;
    for (int k = 0; k < gt::water_pipe_count; ++k) EXPECT_EQ(water.flux_at(k, c), 0.0);
  }
  EXPECT_EQ(ground.soil, start.soil);
}

TEST(LayeredWater, AColumnOfWaterSpreadsSymmetricallyAndKeepsItsVolume) {
  // 1 m of water on the middle of a flat 9 × 9 ground spreads to its 4 neighbours alike: the
  // result is mirror-symmetric in x and y (a pipe mix-up breaks it) and the volume is kept to
  // rounding (9·9 cells, a few roundings each: 1e-12 of the volume).
  LayeredParams params;
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(9, 9, 10.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.0);
  water.water[ground.cell(4, 4)] = 1.0;
  for (int step = 0; step < 15; ++step) ref::water_flow(ground, water, params);
  double total = 0.0;
  for (int y = 0; y < 9; ++y) {
    for (int x = 0; x < 9; ++x) {
      const double depth = water.water[ground.cell(x, y)];
      total += depth;
      EXPECT_NEAR(depth, water.water[ground.cell(8 - x, y)], 1e-12) << x << "," << y;
      EXPECT_NEAR(depth, water.water[ground.cell(x, 8 - y)], 1e-12) << x << "," << y;
      EXPECT_NEAR(depth, water.water[ground.cell(y, x)], 1e-12) << x << "," << y;
    }
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_LT(water.water[ground.cell(4, 4)], 0.5);
  EXPECT_GT(water.water[ground.cell(3, 4)], 0.0);
}

TEST(LayeredWater, WaterRunsDownhillOnly) {
  // On a ramp falling in +x with a thin film, the first step's flux points down the ramp only.
  LayeredParams params;
  gt::Heightmap ramp(6, 4, 0.0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 6; ++x) ramp.at(x, y) = 20.0 - x;
  }
  auto ground = gt::make_layered_ground<double>(ramp, loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.1);
  ref::water_flow(ground, water, params);
  const std::size_t c = ground.cell(2, 1);
  EXPECT_GT(water.flux_at(1, c), 0.0);  // R, downhill
  EXPECT_EQ(water.flux_at(0, c), 0.0);  // L, uphill
  EXPECT_EQ(water.flux_at(2, c), 0.0);  // T, level
  EXPECT_EQ(water.flux_at(3, c), 0.0);  // B, level
  // Step 6: no column sends more than it holds.
  for (std::size_t cell = 0; cell < ground.cells(); ++cell) EXPECT_GE(water.water[cell], 0.0);
}

TEST(LayeredWater, TheRiverHoldsItsSourceAndItsSinksEmpty) {
  LayeredParams params;
  params.river = true;
  params.river_depth = 2.0;
  auto ground = gt::make_layered_ground<double>(cone(32, 5.0, 1.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.2);
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  const double area = 1.0;
  const double start = gt::layered_water_ledger(water, area).water;
  for (int step = 0; step < 10; ++step) {
    ref::water_sources(ground, water, params, static_cast<std::uint32_t>(step), conversions);
    EXPECT_EQ(water.water[gt::river_source_cell(32, 32)], 2.0);
    for (int x = 0; x < 32; ++x) EXPECT_EQ(water.water[ground.cell(x, 30)], 0.0);
    ref::water_flow(ground, water, params);
  }
  EXPECT_EQ(gt::river_source_cell(32, 32), ground.cell(16, 2));
  EXPECT_FALSE(gt::river_sink_row(29, 32));
  EXPECT_TRUE(gt::river_sink_row(30, 32));
  EXPECT_GT(conversions.water_sunk, 0.0);
  const double end = gt::layered_water_ledger(water, area).water;
  EXPECT_NEAR(end - start, conversions.water_added - conversions.water_sunk, 1e-12 * (start + conversions.water_added));
}

// Seed 001's Fig. 5.5 adds and removes water by hand: rain on the first rain_steps iterations, and
// the code's "Drain water" at the start of iteration drain_step, which empties every column of its
// water and what it carries, booked as sunk; the ledger closes across both.
TEST(LayeredWater, RainFallsOnItsStepsAndTheDrainEmptiesEveryColumn) {
  LayeredParams params;
  params.rain_rate = 0.01;
  params.rain_steps = 3;
  params.drain_step = 5;
  auto ground = gt::make_layered_ground<double>(cone(16, 5.0, 1.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.2);
  for (std::size_t c = 0; c < ground.cells(); ++c) water.carried_at(0, c) = 0.01;
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  const double area = 1.0;
  const double start = gt::layered_water_ledger(water, area).water;
  const double rain = params.time_step * params.rain_rate;
  for (std::uint32_t step = 0; step < 8; ++step) {
    const double before = water.water[0];
    ref::water_sources(ground, water, params, step, conversions);
    if (step == 5) {
      for (std::size_t c = 0; c < ground.cells(); ++c) {
        EXPECT_EQ(water.water[c], 0.0);
        EXPECT_EQ(water.carried_at(0, c), 0.0);
      }
    } else {
      EXPECT_EQ(water.water[0], step < 3 ? before + rain : before) << step;
    }
  }
  EXPECT_NEAR(conversions.water_added, 3.0 * rain * area * static_cast<double>(ground.cells()), 1e-12);
  EXPECT_NEAR(conversions.water_sunk, start + conversions.water_added, 1e-12 * start);
  EXPECT_NEAR(conversions.sunk[static_cast<std::size_t>(gt::carried_component(0))],
              0.01 * area * static_cast<double>(ground.cells()), 1e-12);
  EXPECT_EQ(gt::layered_water_ledger(water, area).water, 0.0);
}

TEST(LayeredForceErosion, WaterStrengthIsTheWorkedNumber) {
  // 3 × 3 ground, l = 1, falling 1 m per cell in +x. The middle holds w = w_prev = 0.5 m, sends
  // 0.2 m³/s right and receives 0.1 m³/s from the left: F_x = ½((0.1 − 0) + (0.2 − 0)) = 0.15,
  // v = 0.15/(1·0.5) = 0.3 m/s. Thesis slope: g_x = (9 − 11)/2 = −1, sin φ = sqrt(1/2); l(w) = 1
  // (w > K_w = 0.45); x = 0.25·0.70711·0.3 = 0.0530330. The code's un-halved slope: g_x = −2,
  // sin φ = sqrt(4/5), x = 0.0670820. With veg 1: x/(1 + 0.2).
  LayeredParams params;
  gt::Heightmap ramp(3, 3, 0.0);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 3; ++x) ramp.at(x, y) = 11.0 - x;
  }
  auto ground = gt::make_layered_ground<double>(ramp, loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.5);
  water.flux_at(1, ground.cell(1, 1)) = 0.2;
  water.flux_at(1, ground.cell(0, 1)) = 0.1;
  EXPECT_NEAR(ref::water_strength(ground, ground.surface, water, params, 1, 1), 0.25 * std::sqrt(0.5) * 0.3, 1e-15);
  params.slope_form = gt::SlopeForm::seed001_code;
  EXPECT_NEAR(ref::water_strength(ground, ground.surface, water, params, 1, 1), 0.25 * std::sqrt(0.8) * 0.3, 1e-15);
  ground.vegetation[ground.cell(1, 1)] = 1.0;
  EXPECT_NEAR(ref::water_strength(ground, ground.surface, water, params, 1, 1), 0.25 * std::sqrt(0.8) * 0.3 / 1.2,
              1e-15);
  // Shallow water: l(w) = w/K_w.
  water.water[ground.cell(1, 1)] = 0.09;
  water.previous_water[ground.cell(1, 1)] = 0.09;
  ground.vegetation[ground.cell(1, 1)] = 0.0;
  EXPECT_NEAR(ref::water_strength(ground, ground.surface, water, params, 1, 1),
              0.25 * std::sqrt(0.8) * (0.15 / 0.09) * (0.09 / 0.45), 1e-14);
  // Dry: nothing.
  water.water[ground.cell(1, 1)] = 0.0;
  EXPECT_EQ(ref::water_strength(ground, ground.surface, water, params, 1, 1), 0.0);
}

TEST(LayeredForceErosion, BreakdownFormsAreEquation3_5AndTheCodes) {
  // A_11 = 0.08, B_11 = 0.1 (eq. 3.8-3.9) at x = 0.3: thesis 0.08·(0.3 − 0.1) = 0.016; the code
  // 0.08·0.3 − 0.1 < 0, so 0. Below the threshold both are 0.
  EXPECT_NEAR(ref::breakdown(gt::BreakdownForm::thesis, 0.08, 0.1, 0.3), 0.016, 1e-17);
  EXPECT_EQ(ref::breakdown(gt::BreakdownForm::seed001_code, 0.08, 0.1, 0.3), 0.0);
  EXPECT_NEAR(ref::breakdown(gt::BreakdownForm::seed001_code, 0.08, 0.01, 0.3), 0.014, 1e-17);
  EXPECT_EQ(ref::breakdown(gt::BreakdownForm::thesis, 0.08, 0.1, 0.05), 0.0);
}

TEST(LayeredForceErosion, ErosionReachesThroughAThinLayer) {
  // Topsoil: 0.05 m of organic matter; subsoil: 1 m org + 1 m sand. A request of 0.2 m of org:
  // the topsoil gives min(0.2·max(0.1, 1), 0.05) = 0.05; the rest (0.2 − 0.05) passes at
  // K_p = 1 − 0.05/0.1 = 0.5, so 0.075 reaches the subsoil, which gives 0.075·max(0.1, ½) = 0.0375.
  LayeredParams params;
  LayeredProfile profile = loam_profile();
  profile.topsoil = {0.05, 0.0, 0.0, 0.0, 0.0};
  profile.subsoil = {1.0, 1.0, 0.0, 0.0, 0.0};
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), profile, params);
  // Transparency to the bedrock: 0.5 through the topsoil, 0 through the 2 m subsoil.
  EXPECT_EQ(ref::soil_transparency(ground, 0, params), 0.0);
  EXPECT_NEAR(ref::erode_component(ground, 0, org, 0.2, params), 0.0875, 1e-15);
  EXPECT_EQ(ground.soil_at(0, org, 0), 0.0);
  EXPECT_NEAR(ground.soil_at(1, org, 0), 1.0 - 0.0375, 1e-15);
  EXPECT_NEAR(ground.surface[0], 10.0 - 0.0875, 1e-14);
  // A thick topsoil lets nothing through.
  auto thick = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), loam_profile(), params);
  EXPECT_NEAR(ref::erode_component(thick, 0, org, 5.0, params), 0.3, 1e-15);  // min(5·0.3, 0.3)
  EXPECT_EQ(thick.soil_at(1, org, 0), 0.2);
}

TEST(LayeredForceErosion, ShareFormsAreEquation3_10AndTheCodes) {
  // Topsoil 0.02 org + 0.03 sand (V = 0.05), request 0.05 of sand, share max(0.1, 0.6) = 0.6:
  // thesis min(0.05·0.6, 0.03) = 0.03; the code min(0.03, 0.05)·0.6 = 0.018. Thick subsoil below.
  LayeredParams params;
  LayeredProfile profile = loam_profile();
  profile.topsoil = {0.02, 0.03, 0.0, 0.0, 0.0};
  auto thesis = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), profile, params);
  params.share_form = gt::ShareForm::seed001_code;
  auto code = thesis;
  // What passes below: (0.05 − 0.03)·(1 − 0.05/0.1) = 0.01, and the 2.0 m subsoil (0.8 sand,
  // share 0.4) gives min(0.8, 0.01)·0.4 = 0.004 (code) or min(0.01·0.4, 0.8) = 0.004 (thesis).
  EXPECT_NEAR(ref::erode_component(code, 0, sand, 0.05, params), 0.018 + 0.004, 1e-15);
  params.share_form = gt::ShareForm::thesis;
  const double taken = ref::erode_component(thesis, 0, sand, 0.05, params);
  EXPECT_NEAR(taken, 0.03 + 0.004, 1e-15);
}

TEST(LayeredDissolution, RegolithGrowsToItsDepthAndSettlesWhenTheWaterLeaves) {
  // Still water 1 m deep over loam: the regolith grows toward K_r = 0.01 m and never beyond; when
  // the water is gone (r_max = 0) all of it settles back (K_rd = 1), and every component's volume
  // is back to rounding (1e-15 of the column).
  LayeredParams params;
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(1, 1.0);
  const auto start = gt::layered_ledger(ground, params.bedrock_types.size());
  double last = 0.0;
  for (int step = 0; step < 200; ++step) {
    ref::dissolution_step(ground, water, params);
    const double regolith = water.carried_at(gt::regolith_kind(org), 0) + water.carried_at(gt::regolith_kind(sand), 0);
    EXPECT_LE(regolith, 0.01 * (1 + 1e-12));
    EXPECT_GE(regolith, last);
    last = regolith;
  }
  EXPECT_GT(last, 0.009);
  EXPECT_GT(water.carried_at(gt::regolith_kind(org), 0), 0.0);
  water.water[0] = 0.0;
  ref::dissolution_step(ground, water, params);
  EXPECT_EQ(water.carried_at(gt::regolith_kind(org), 0), 0.0);
  EXPECT_EQ(water.carried_at(gt::regolith_kind(sand), 0), 0.0);
  const auto end = gt::layered_ledger(ground, params.bedrock_types.size());
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(end.components[i], start.components[i], 1e-14) << i;
  EXPECT_NEAR(ground.surface[0], 10.0, 1e-14);
}

// The carried amounts of kind `kind` over a row of `width` columns.
std::vector<double> carried_row(const LayeredWater<double>& water, int kind, int width) {
  std::vector<double> row;
  for (int x = 0; x < width; ++x) row.push_back(water.carried_at(kind, static_cast<std::size_t>(x)));
  return row;
}

TEST(LayeredDiffusion, UniformWeightsAreTheThesisBlurAndKeepTheSum) {
  // §3.8 by hand: 1 m of suspended sand in the middle of a 3 × 3 ground, σ = 0.1: the middle keeps
  // 1 − 4σ = 0.6, each edge neighbour gets 0.1, the corners nothing; the sum stays 1 (one rounding
  // of each product and sum: 1e-15). A border column of a closed grid sends to its 2 or 3
  // neighbours only. The regolith diffuses only with regolith_diffusion.
  LayeredParams params;
  params.sediment_diffusion = 0.1;
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(3, 3, 10.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.0);
  water.carried_at(gt::suspended_kind(sand), ground.cell(1, 1)) = 1.0;
  water.carried_at(gt::regolith_kind(org), ground.cell(0, 0)) = 1.0;
  params.regolith_diffusion = false;
  ref::diffusion_step(ground, water, params);
  const int kind = gt::suspended_kind(sand);
  EXPECT_NEAR(water.carried_at(kind, ground.cell(1, 1)), 0.6, 1e-15);
  for (auto [x, y] : {std::pair{0, 1}, std::pair{2, 1}, std::pair{1, 0}, std::pair{1, 2}}) {
    EXPECT_NEAR(water.carried_at(kind, ground.cell(x, y)), 0.1, 1e-16) << x << "," << y;
  }
  for (auto [x, y] : {std::pair{0, 0}, std::pair{2, 0}, std::pair{0, 2}, std::pair{2, 2}}) {
    EXPECT_EQ(water.carried_at(kind, ground.cell(x, y)), 0.0) << x << "," << y;
  }
  EXPECT_EQ(water.carried_at(gt::regolith_kind(org), ground.cell(0, 0)), 1.0);
  params.regolith_diffusion = true;
  ref::diffusion_step(ground, water, params);
  EXPECT_NEAR(water.carried_at(gt::regolith_kind(org), ground.cell(0, 0)), 0.8, 1e-15);  // corner: 2 neighbours
  EXPECT_NEAR(water.carried_at(gt::regolith_kind(org), ground.cell(1, 0)), 0.1, 1e-16);
  double total = 0.0;
  for (std::size_t c = 0; c < ground.cells(); ++c) total += water.carried_at(kind, c);
  EXPECT_NEAR(total, 1.0, 1e-15);
  // σ = 0 switches the step off.
  params.sediment_diffusion = 0.0;
  const auto before = water.carried;
  ref::diffusion_step(ground, water, params);
  EXPECT_EQ(water.carried, before);
}

TEST(LayeredDiffusion, TheCodesWeightsFollowTheWaterAndSendNothingToADryColumn) {
  // The code's weights on a row of 3 with water 0, 1, 0.5 m: the middle's base is 1 + ½·0 + ½·0.5
  // = 1.25, so it sends 0.25/1.25 = 0.2 to the right and nothing to the dry left; the right's base
  // is 0.5 + ½·1 = 1, it sends 0.5 back. Sand 0, 1, 1 becomes 0, 1 − 0.2 + 0.5 = 1.3, 1 − 0.5 + 0.2 = 0.7.
  LayeredParams params;
  params.diffusion_weighting = gt::DiffusionWeighting::water;
  auto ground = gt::make_layered_ground<double>(gt::Heightmap(3, 1, 10.0), loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.0);
  water.water = {0.0, 1.0, 0.5};
  const int kind = gt::suspended_kind(sand);
  water.carried_at(kind, 1) = 1.0;
  water.carried_at(kind, 2) = 1.0;
  ref::diffusion_step(ground, water, params);
  const auto row = carried_row(water, kind, 3);
  EXPECT_EQ(row[0], 0.0);
  EXPECT_NEAR(row[1], 1.3, 1e-15);
  EXPECT_NEAR(row[2], 0.7, 1e-15);
}

TEST(LayeredDiffusion, ADryColumnKeepsWhatTheBlurBroughtItThroughTheFlow) {
  // The thesis's uniform blur brings sediment to a dry column. Its outflow is scaled to the 0 m³ it
  // holds, so it sends nothing: the flow must leave what it carries there (a column drained of its
  // water sends everything with it, but a dry one has nothing to send it with).
  LayeredParams params;
  gt::Heightmap step_down(3, 1, 10.0);
  step_down.at(0, 0) = 12.0;  // the dry column stands above its wet neighbours: its pipes open
  auto ground = gt::make_layered_ground<double>(step_down, loam_profile(), params);
  auto water = gt::make_layered_water<double>(ground.cells(), 0.0);
  water.water = {0.0, 0.2, 0.2};
  const int kind = gt::suspended_kind(sand);
  water.carried_at(kind, 0) = 0.05;
  const auto start = gt::layered_water_ledger(water, 1.0);
  ref::water_flow(ground, water, params);
  EXPECT_EQ(water.flux_at(1, 0), 0.0);  // its head opened the pipe; step 6 scaled it to the 0 m³ held
  EXPECT_EQ(water.carried_at(kind, 0), 0.05);
  const auto end = gt::layered_water_ledger(water, 1.0);
  EXPECT_NEAR(end.carried[sand], start.carried[sand], 1e-16);
}

TEST(LayeredWetness, GrowsUnderWaterDriesAndFloodsKillVegetation) {
  LayeredParams params;  // Δt 0.2, K_dry 0.5, flood above 1.0
  auto water = gt::make_layered_water<double>(2, 0.0);
  water.water[0] = 0.5;
  water.wetness[1] = 0.8;
  ref::wetness_step(water, params);
  EXPECT_NEAR(water.wetness[0], 0.1, 1e-16);                       // 0 + 0.2·0.5
  EXPECT_NEAR(water.wetness[1], 0.8 * std::pow(0.5, 0.2), 1e-15);  // dry: × K_dry^Δt
  // Flood death: a vegetated column wetter than the threshold loses its cover; the same column
  // without water grows.
  gt::Heightmap flat(2, 1, 10.0);
  auto ground = gt::make_layered_ground<double>(flat, loam_profile(), params, 0.5);
  water.wetness = {1.5, 0.5};
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  auto dry = ground;
  ref::vegetation_step(ground, params, 0, conversions, &water);
  ref::vegetation_step(dry, params, 0, conversions);
  EXPECT_EQ(ground.vegetation[0], 0.0);
  EXPECT_GT(ground.vegetation[1], 0.0);
  EXPECT_GT(dry.vegetation[0], 0.0);
}

template <class Real>
void expect_ledger_closes(LayeredParams params, double tolerance) {
  auto ground = gt::make_layered_ground<Real>(cone(24, 8.0, 2.0), loam_profile(), params, 0.3);
  auto water = gt::make_layered_water<Real>(ground.cells(), params.initial_water);
  const std::size_t types = params.bedrock_types.size();
  auto conversions = gt::no_conversions(types);
  const auto start = ledger_balance(ground, water, conversions, types);
  const auto bedrock_start = gt::layered_ledger(ground, types).bedrock;
  const double water_start = gt::layered_water_ledger(water, 4.0).water;
  for (std::uint32_t step = 0; step < 150; ++step) ref::layered_iteration(ground, params, step, conversions, &water);
  gt::check_layered_ground(ground, params);
  gt::check_layered_water(water, ground.cells());
  const auto end = ledger_balance(ground, water, conversions, types);
  const double total = gt::layered_ledger(ground, types).total();
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(end[i], start[i], tolerance * total) << gt::soil_component_name(int(i));
  const auto bedrock_end = gt::layered_ledger(ground, types).bedrock;
  for (std::size_t t = 0; t < types; ++t) {
    EXPECT_NEAR(bedrock_end[t] - bedrock_start[t], -conversions.bedrock_converted(t), tolerance * total) << t;
  }
  const double water_end = gt::layered_water_ledger(water, 4.0).water;
  EXPECT_NEAR(water_end - water_start, conversions.water_added - conversions.water_sunk,
              tolerance * (water_start + conversions.water_added));
  // Something happened: water moved material.
  double carried = 0.0;
  for (Real amount : water.carried) carried += static_cast<double>(amount);
  EXPECT_GT(carried, 0.0);
}

// Ledger bound: 150 iterations of some 60 roundings per column each, in double, relative to the
// total: 150·60·2^-53 ≈ 1e-12. The water ledger the same.
TEST(LayeredWaterLedger, RainOnAConeClosesPerMaterial) {
  LayeredParams params;
  params.rain_rate = 0.01;
  params.initial_water = 0.05;
  expect_ledger_closes<double>(params, 1e-12);
}

TEST(LayeredWaterLedger, TheRiverClosesWithWhatSinks) {
  LayeredParams params;
  params.river = true;
  params.border = gt::LayeredBorder::periodic;
  params.breakdown_form = gt::BreakdownForm::seed001_code;
  params.share_form = gt::ShareForm::seed001_code;
  params.slope_form = gt::SlopeForm::seed001_code;
  params.velocity_depth_floor = 0.05;
  expect_ledger_closes<double>(params, 1e-12);
}

}  // namespace

namespace {

TEST(LayeredMaterialMasks, ThinLayersShowWhatLiesBelow) {
  // K_pmin = 0.1 m. Topsoil 0.02 m of org (K_p = 0.8), subsoil 0.03 m of sand (K_p = 0.7), soft
  // rock below: org 1 − 0.8 = 0.2, sand 0.8·(1 − 0.7) = 0.24, soft rock 0.8·0.7 = 0.56.
  LayeredParams params;
  LayeredProfile profile;
  profile.topsoil = {0.02, 0.0, 0.0, 0.0, 0.0};
  profile.subsoil = {0.0, 0.03, 0.0, 0.0, 0.0};
  profile.bedrock = {{0, 3.0}, {1, 10.0}};
  const auto ground = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), profile, params);
  const auto masks = ref::material_masks(ground, params, 0);
  ASSERT_EQ(masks.size(), 5u + params.bedrock_types.size());
  EXPECT_NEAR(masks[0], 0.2, 1e-15);
  EXPECT_NEAR(masks[1], 0.24, 1e-15);
  EXPECT_NEAR(masks[5], 0.56, 1e-15);
  EXPECT_EQ(masks[6], 0.0);
  // A thick loam topsoil hides everything below it: its own composition, summing to 1.
  const auto thick = gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), loam_profile(), params);
  const auto loam = ref::material_masks(thick, params, 0);
  EXPECT_NEAR(loam[0], 0.3, 1e-15);
  EXPECT_NEAR(loam[2], 0.2, 1e-15);
  EXPECT_EQ(loam[5], 0.0);
  double sum = 0.0;
  for (double mask : loam) sum += mask;
  EXPECT_NEAR(sum, 1.0, 1e-15);
  // Bare rock of type 1 shows only itself.
  profile.topsoil = {};
  profile.subsoil = {};
  profile.bedrock = {{0, 0.0}, {1, 10.0}};
  const auto bare = ref::material_masks(gt::make_layered_ground<double>(gt::Heightmap(1, 1, 10.0), profile, params), params, 0);
  EXPECT_EQ(bare[6], 1.0);
  EXPECT_EQ(bare[5], 0.0);
}

}  // namespace

namespace {

// A 3 × 1 strip: column 0 (surface 9 m) holds water flowing toward column 1 (surface 10 m: 0.5 m
// topsoil 0.2 org + 0.2 sand + 0.1 gravel over 1.5 m subsoil 0.3 org + 0.6 sand + 0.3 gravel +
// 0.3 stones); column 2 is dry. F_R of column 0 = 2 m³/s, so its net flux F_x = ½·2 = 1 and, at
// w = w̄ = `depth`, v = 1/(1·depth) toward column 1.
struct ImpactStrip {
  LayeredParams params;
  LayeredGround<double> ground;
  LayeredWater<double> water = gt::make_layered_water<double>(3, 0.0);
};

ImpactStrip impact_strip(double depth) {
  ImpactStrip strip;
  strip.params.breakdown_slopes = {};  // only the organic request: a worked number by hand
  LayeredProfile profile;
  profile.topsoil = {0.2, 0.2, 0.1, 0.0, 0.0};
  profile.subsoil = {0.3, 0.6, 0.3, 0.3, 0.0};
  profile.bedrock = {{0, 3.0}, {1, 10.0}};
  gt::Heightmap surface(3, 1, 10.0);
  surface.at(0, 0) = 9.0;
  strip.ground = gt::make_layered_ground<double>(surface, profile, strip.params);
  strip.water.water[0] = strip.water.previous_water[0] = depth;
  strip.water.flux_at(1, 0) = 2.0;
  return strip;
}

TEST(LayeredImpactErosion, WaterHittingABankErodesWhatItTouchesIntoItsOwnSediment) {
  // Water 2 m deep (top 11 m): v = 0.5 m/s; it touches the whole topsoil (10 → 9.5 m, A = 0.5 m²)
  // and the subsoil from 9.5 down to its own bed at 9 m (A = 0.5 m²). S = K_i·v·A·Δt/(l_x·l_y) =
  // 0.25·0.5·0.5·0.2 = 0.0125 m in each; the organic request K_e·0.12·S = 7.5e-4 m takes
  // 7.5e-4·max(0.1, 0.2/0.5) = 3e-4 from the topsoil and 7.5e-4·max(0.1, 0.3/1.5) = 1.5e-4 from
  // the subsoil, which land in column 0's suspended organic matter, not in column 1's water.
  auto strip = impact_strip(2.0);
  auto conversions = gt::no_conversions(strip.params.bedrock_types.size());
  ref::impact_erosion_step(strip.ground, strip.water, strip.params, conversions);
  EXPECT_NEAR(strip.water.carried_at(gt::suspended_kind(org), 0), 3e-4 + 1.5e-4, 1e-17);
  EXPECT_EQ(strip.water.carried_at(gt::suspended_kind(org), 1), 0.0);
  EXPECT_NEAR(strip.ground.soil_at(0, org, 1), 0.2 - 3e-4, 1e-16);
  EXPECT_NEAR(strip.ground.soil_at(1, org, 1), 0.3 - 1.5e-4, 1e-16);
  EXPECT_NEAR(strip.ground.surface[1], 10.0 - 4.5e-4, 1e-14);
  EXPECT_EQ(strip.ground.surface[0], 9.0);  // the water's own bed is force erosion's
  EXPECT_EQ(strip.ground.surface[2], 10.0);
}

TEST(LayeredImpactErosion, OnlyTheLayersBelowTheWaterSurfaceAndOnlyWaterMovingTowardThem) {
  // Water 0.2 m deep (top 9.2 m) reaches only the subsoil between 9 and 9.2 m: v = 1/0.2 = 5 m/s,
  // A = 0.2 m², S = 0.25·5·0.2·0.2 = 0.05 m, organic 0.5·0.12·0.05·0.2 = 6e-4 from the subsoil.
  auto strip = impact_strip(0.2);
  auto conversions = gt::no_conversions(strip.params.bedrock_types.size());
  ref::impact_erosion_step(strip.ground, strip.water, strip.params, conversions);
  EXPECT_EQ(strip.ground.soil_at(0, org, 1), 0.2);
  EXPECT_NEAR(strip.ground.soil_at(1, org, 1), 0.3 - 6e-4, 1e-16);
  // Water flowing away (F_L instead of F_R) hits nothing.
  auto away = impact_strip(2.0);
  away.water.flux_at(1, 0) = 0.0;
  away.water.flux_at(0, 0) = 2.0;
  const auto before = away.ground.soil;
  ref::impact_erosion_step(away.ground, away.water, away.params, conversions);
  EXPECT_EQ(away.ground.soil, before);
}

}  // namespace
