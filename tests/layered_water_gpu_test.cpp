// The GPU twins of the water on the layered ground (digest 001 §3.3-3.5, §3.12-3.15, §3.19;
// gpu/erosion/layered/{water,force_erosion,impact_erosion,water_buffers,iteration}) against
// reference<float> (reference/erosion/layered/{water,force_erosion,impact_erosion,dissolution,
// wetness,iteration}), pass for pass and
// over whole iterations, on a random 20 × 16 layered terrain (l_x = 1 m, l_y = 1.25 m) tilted
// toward +y, with random soils and vegetation and puddles of random depth; variants: the thesis's
// forms with closed borders and rain, and the seed code's (slope, breakdown and share forms, the w̄
// floor) with periodic borders and the river.
//
// Error model, fixed before running (as tests/layered_gpu_test.cpp's): the shaders repeat the
// reference<float>'s float operations in its order, `precise`; divisions through gt_div and square
// roots through gt_sqrt, both rounded to nearest like the CPU's; constants are the host's float
// casts of the reference's doubles. So ground and water are expected bit for bit after every pass
// (bound 0), given no subnormal value, checked absent from the reference's state. Conversions: the
// GPU writes each column's float amounts and the host adds them in double in the reference's order,
// so they are expected equal too.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"
#include "gpu/erosion/layered/force_erosion.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/impact_erosion.hpp"
#include "gpu/erosion/layered/iteration.hpp"
#include "gpu/erosion/layered/water.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"
#include "reference/erosion/layered/diffusion.hpp"
#include "reference/erosion/layered/dissolution.hpp"
#include "reference/erosion/layered/force_erosion.hpp"
#include "reference/erosion/layered/impact_erosion.hpp"
#include "reference/erosion/layered/iteration.hpp"
#include "reference/erosion/layered/water.hpp"
#include "reference/erosion/layered/wetness.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/same_bits.hpp"

namespace {

using gt::testing::expect_no_subnormals;
using gt::testing::expect_same_bits;

using gt::LayeredConversions;
using gt::LayeredGround;
using gt::LayeredParams;
using gt::LayeredWater;

constexpr int width = 20;
constexpr int height = 16;

struct Variant {
  const char* name;
  bool seed001_code;  // the code's forms, periodic borders, the river; else the thesis's, closed, rain
};

LayeredParams params_for(const Variant& variant) {
  LayeredParams params;
  params.seed = 5;
  params.erosion_strength = 2.0;  // strong water, so that every size and the bedrock erode
  params.regolith_depth = 0.05;
  if (variant.seed001_code) {
    params.border = gt::LayeredBorder::periodic;
    params.river = true;
    params.slope_form = gt::SlopeForm::seed001_code;
    params.breakdown_form = gt::BreakdownForm::seed001_code;
    params.share_form = gt::ShareForm::seed001_code;
    params.velocity_depth_floor = 0.05;
    params.erosion_rate = 0.1;
    params.diffusion_weighting = gt::DiffusionWeighting::water;
    params.regolith_diffusion = false;
  } else {
    params.rain_rate = 0.02;
  }
  return params;
}

LayeredGround<float> random_ground(const LayeredParams& params) {
  std::mt19937 random(77);
  std::uniform_real_distribution<double> bump(0.0, 1.5);
  gt::Heightmap surface(width, height);
  surface.cell_size_x = 1.0;
  surface.cell_size_y = 1.25;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) surface.at(x, y) = 30.0 - 0.6 * y + bump(random);
  }
  gt::LayeredProfile profile;
  profile.bedrock = {{0, 3.0}, {1, 40.0}};
  auto ground = gt::make_layered_ground<float>(surface, profile, params, 0.0);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    const bool bare = unit(random) < 0.1f;  // bedrock at the surface: force erosion breaks it
    const bool thin = unit(random) < 0.3f;  // a topsoil thinner than K_pmin: erosion reaches below
    for (int layer = 0; layer < gt::soil_layer_count; ++layer) {
      for (int component = 0; component < gt::soil_component_count; ++component) {
        const float scale = layer == 0 && thin ? 0.015f : 0.3f;
        ground.soil_at(layer, component, c) = bare ? 0.0f : scale * unit(random);
      }
    }
    ground.vegetation[c] = unit(random) < 0.5f ? 0.0f : unit(random);
  }
  return ground;
}

LayeredWater<float> random_water(std::size_t cells) {
  std::mt19937 random(78);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  auto water = gt::make_layered_water<float>(cells, 0.0);
  for (std::size_t c = 0; c < cells; ++c) {
    water.water[c] = unit(random) < 0.25f ? 0.0f : 0.5f * unit(random);
    water.previous_water[c] = water.water[c];
    water.wetness[c] = 2.0f * unit(random);  // some above the flood threshold 1
    for (int kind = 0; kind < gt::carried_kind_count; ++kind) water.carried_at(kind, c) = 0.01f * unit(random);
  }
  return water;
}

void expect_same_state(const LayeredGround<float>& ground, const LayeredWater<float>& water,
                       const gt::gpu::LayeredGroundBuffers& ground_buffers,
                       const gt::gpu::LayeredWaterBuffers& water_buffers, const std::string& when) {
  for (const auto& [name, values] :
       {std::pair{"surface", &ground.surface}, std::pair{"soil", &ground.soil}, std::pair{"bedrock", &ground.bedrock},
        std::pair{"vegetation", &ground.vegetation}, std::pair{"water", &water.water},
        std::pair{"flux", &water.water_flux}, std::pair{"carried", &water.carried},
        std::pair{"wetness", &water.wetness}}) {
    expect_no_subnormals(name, *values, when);
  }
  const auto gpu_ground = ground_buffers.download();
  const auto gpu_water = water_buffers.download();
  expect_same_bits("surface", ground.surface, gpu_ground.surface, when);
  expect_same_bits("soil", ground.soil, gpu_ground.soil, when);
  expect_same_bits("bedrock", ground.bedrock, gpu_ground.bedrock, when);
  expect_same_bits("vegetation", ground.vegetation, gpu_ground.vegetation, when);
  expect_same_bits("water", water.water, gpu_water.water, when);
  expect_same_bits("previous water", water.previous_water, gpu_water.previous_water, when);
  expect_same_bits("flux", water.water_flux, gpu_water.water_flux, when);
  expect_same_bits("carried", water.carried, gpu_water.carried, when);
  expect_same_bits("wetness", water.wetness, gpu_water.wetness, when);
}

void expect_same_conversions(const LayeredConversions& expected, const LayeredConversions& actual,
                             const std::string& when) {
  EXPECT_EQ(expected.broken_from, actual.broken_from) << when;
  EXPECT_EQ(expected.broken_into, actual.broken_into) << when;
  EXPECT_EQ(expected.bedrock_eroded_from, actual.bedrock_eroded_from) << when;
  EXPECT_EQ(expected.bedrock_eroded_into, actual.bedrock_eroded_into) << when;
  EXPECT_EQ(expected.sunk, actual.sunk) << when;
  EXPECT_EQ(expected.water_added, actual.water_added) << when;
  EXPECT_EQ(expected.water_sunk, actual.water_sunk) << when;
}

class LayeredWaterGpu : public gt::testing::GlTestWithParam<Variant> {};

TEST_P(LayeredWaterGpu, EveryWaterPassIsTheFloatReferenceBitForBit) {
  const LayeredParams params = params_for(GetParam());
  auto ground = random_ground(params);
  auto water = random_water(ground.cells());
  gt::gpu::LayeredGroundBuffers ground_buffers(ground, params);
  gt::gpu::LayeredWaterBuffers water_buffers(ground_buffers, water);
  const gt::gpu::LayeredWaterFlow flow;
  const gt::gpu::LayeredForceErosion force_erosion;
  const gt::gpu::LayeredImpactErosion impact;
  const gt::gpu::LayeredWaterPass dissolution("erosion/layered/dissolution.comp");
  const gt::gpu::LayeredWaterPass diffusion("erosion/layered/diffusion.comp");
  const gt::gpu::LayeredWaterPass wetness("erosion/layered/wetness.comp");
  auto expected = gt::no_conversions(params.bedrock_types.size());
  auto actual = gt::no_conversions(params.bedrock_types.size());

  gt::reference::water_sources(ground, water, params, 0, expected);
  flow.sources(ground_buffers, water_buffers, 0, actual);
  expect_same_state(ground, water, ground_buffers, water_buffers, "sources");
  expect_same_conversions(expected, actual, "sources");
  EXPECT_GT(expected.water_added, 0.0);

  const auto before_flow = water;
  gt::reference::water_flow(ground, water, params);
  flow.flow(ground_buffers, water_buffers, 0);
  expect_same_state(ground, water, ground_buffers, water_buffers, "flow");
  EXPECT_NE(before_flow.water, water.water) << "no water moved";

  const auto before_erosion = ground;
  gt::reference::force_erosion_step(ground, water, params, expected);
  force_erosion.step(ground_buffers, water_buffers, 0, actual);
  expect_same_state(ground, water, ground_buffers, water_buffers, "force erosion");
  expect_same_conversions(expected, actual, "force erosion");
  EXPECT_NE(before_erosion.soil, ground.soil) << "force erosion moved nothing";
  EXPECT_GT(expected.broken_into[1], 0.0) << "no fragment broke down";
  EXPECT_GT(expected.bedrock_eroded_from[0], 0.0) << "no bedrock eroded";

  const auto before_impact = ground.soil;
  auto impact_expected = expected;
  gt::reference::impact_erosion_step(ground, water, params, expected);
  impact.step(ground_buffers, water_buffers, 0, actual);
  expect_same_state(ground, water, ground_buffers, water_buffers, "impact erosion");
  expect_same_conversions(expected, actual, "impact erosion");
  EXPECT_NE(before_impact, ground.soil) << "impact erosion moved nothing";
  // The code's max(a·x − b, 0) breaks nothing at these strengths; the thesis's a·(x − b) does.
  if (!GetParam().seed001_code) {
    EXPECT_GT(expected.broken_into[1], impact_expected.broken_into[1]) << "impact erosion broke no fragment";
  }

  const auto before_dissolution = water.carried;
  gt::reference::dissolution_step(ground, water, params);
  dissolution.step(ground_buffers, water_buffers, 0);
  expect_same_state(ground, water, ground_buffers, water_buffers, "dissolution");
  EXPECT_NE(before_dissolution, water.carried) << "no regolith moved";

  const auto before_diffusion = water.carried;
  gt::reference::diffusion_step(ground, water, params);
  water_buffers.snapshot();
  diffusion.step(ground_buffers, water_buffers, 0);
  expect_same_state(ground, water, ground_buffers, water_buffers, "diffusion");
  EXPECT_NE(before_diffusion, water.carried) << "no sediment diffused";

  gt::reference::wetness_step(water, params);
  wetness.step(ground_buffers, water_buffers, 0);
  expect_same_state(ground, water, ground_buffers, water_buffers, "wetness");
}

TEST_P(LayeredWaterGpu, WholeIterationsFollowTheReferenceAndRepeat) {
  const LayeredParams params = params_for(GetParam());
  const auto start_ground = random_ground(params);
  const auto start_water = random_water(start_ground.cells());
  auto ground = start_ground;
  auto water = start_water;
  const gt::gpu::LayeredIteration iteration(true);
  gt::gpu::LayeredGroundBuffers ground_buffers(ground, params);
  gt::gpu::LayeredWaterBuffers water_buffers(ground_buffers, water);
  auto expected = gt::no_conversions(params.bedrock_types.size());
  auto actual = gt::no_conversions(params.bedrock_types.size());
  constexpr std::uint32_t steps = 100;
  for (std::uint32_t step = 0; step < steps; ++step) {
    gt::reference::layered_iteration(ground, params, step, expected, &water);
    iteration.step(ground_buffers, step, actual, &water_buffers);
    expect_same_state(ground, water, ground_buffers, water_buffers, "iteration " + std::to_string(step));
    if (HasFailure()) return;
  }
  expect_same_conversions(expected, actual, "after the iterations");
  EXPECT_EQ(expected.weathered_into, actual.weathered_into);
  EXPECT_EQ(expected.fragmented_from, actual.fragmented_from);
  // Determinism: the same start on fresh buffers gives the same bits.
  gt::gpu::LayeredGroundBuffers again_ground(start_ground, params);
  gt::gpu::LayeredWaterBuffers again_water(again_ground, start_water);
  auto again = gt::no_conversions(params.bedrock_types.size());
  for (std::uint32_t step = 0; step < steps; ++step) iteration.step(again_ground, step, again, &again_water);
  expect_same_state(ground, water, again_ground, again_water, "rerun");
  // Flooded columns lost their vegetation: the flood rule ran.
  bool flooded = false;
  for (std::size_t c = 0; c < ground.cells(); ++c) flooded |= water.wetness[c] > 1.0f && ground.vegetation[c] == 0.0f;
  EXPECT_TRUE(flooded);
}

// The water schedule: at iteration 2, past rain_steps = 2 and at drain_step = 2, the drain empties
// every column (the river's source then refills, with the river), no rain falls, and the GPU books
// the same sunk amounts as ref<float>; at iteration 1 rain still falls on both.
TEST_P(LayeredWaterGpu, TheDrainAndTheRainsLastStepAreTheFloatReferenceBitForBit) {
  LayeredParams params = params_for(GetParam());
  params.rain_steps = 2;
  params.drain_step = 2;
  auto ground = random_ground(params);
  auto water = random_water(ground.cells());
  gt::gpu::LayeredGroundBuffers ground_buffers(ground, params);
  gt::gpu::LayeredWaterBuffers water_buffers(ground_buffers, water);
  const gt::gpu::LayeredWaterFlow flow;
  auto expected = gt::no_conversions(params.bedrock_types.size());
  auto actual = gt::no_conversions(params.bedrock_types.size());
  for (std::uint32_t step : {1u, 2u}) {
    gt::reference::water_sources(ground, water, params, step, expected);
    flow.sources(ground_buffers, water_buffers, step, actual);
    expect_same_state(ground, water, ground_buffers, water_buffers, "sources at step " + std::to_string(step));
    expect_same_conversions(expected, actual, "sources at step " + std::to_string(step));
  }
  EXPECT_GT(expected.water_sunk, 0.0);
  std::size_t wet = 0;
  for (float depth : water.water) wet += depth > 0.0f ? 1 : 0;
  EXPECT_LE(wet, 1u) << "the drain leaves at most the river's source wet";
}

TEST_P(LayeredWaterGpu, RefusesWaterOfAnotherSizeAndAMissingWaterBuffer) {
  const LayeredParams params = params_for(GetParam());
  const auto ground = random_ground(params);
  gt::gpu::LayeredGroundBuffers ground_buffers(ground, params);
  EXPECT_THROW(gt::gpu::LayeredWaterBuffers(ground_buffers, gt::make_layered_water<float>(ground.cells() - 1, 0.0)),
               gt::InputError);
  const gt::gpu::LayeredIteration iteration(true);
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  EXPECT_THROW(iteration.step(ground_buffers, 0, conversions), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Variants, LayeredWaterGpu,
                         ::testing::Values(Variant{"thesis_closed_rain", false}, Variant{"code_periodic_river", true}),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
