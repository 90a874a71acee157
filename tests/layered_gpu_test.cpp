// The GPU twins of the layered ground's talus collapse, soil creep, vegetation growth and weathering
// (digest 001 §3.10-3.11, §3.15-3.16;
// gpu/erosion/layered/) against reference<float> (reference/erosion/layered/), step for step, on a
// random 24 × 24 layered terrain (l_x = 1 m, l_y = 1.25 m) with a 10 m cliff whose edge is bare
// bedrock, so that talus fragments it: rows of that edge alternate a falling top layer (type 0), a
// hard top layer (type 1) over a falling layer exposed in the cliff face (so the hard one falls), and
// the same with the falling layer buried below the cliff's foot (nothing falls); closed and periodic
// borders, the thesis and seed001_code variants.
//
// Error model, fixed before running: the shaders do the reference<float>'s float operations in its
// order, `precise` (no fused multiply-add); +, −, × are correctly rounded in GLSL 4.50 (§4.7.1) and
// every division goes through gt_div (gpu/shaders/erosion/layered/division.glsl), which rounds to
// nearest by integer long division; min, max, clamp and comparisons are exact; the distances and
// constants are the reference's float casts, made on the host; the random factors are the same
// integer hash. So the state is expected bit for bit: bound 0 on every array, every step. (The one
// exception the model allows, subnormal operands or results, which GLSL may flush to zero, is
// checked absent from the reference's state after every pass.)
// Conversions: fragmented_from is summed in double in column order on both sides from the same
// floats, so it is expected equal. fragmented_into: the reference adds each flux's fragment f as
// double(f)·A; the GPU first sums a column's ≤ 8 fragments in float (error ≤ γ_7 = 7u/(1 − 7u) of
// their sum, u = 2^-24), then adds those in double. Both double sums of N nonnegative terms err by
// ≤ (N + 1)·2^-53 of the total, so |gpu − ref| ≤ (γ_7 + 2(N + 1)·2^-53)·ref.
// Weathering's conversions (§3.16): the GPU writes each column's float amounts and the host adds
// them in double in the reference's order (column, layer, conversion), so they are expected equal.
// Vegetation and weathering run with the variants' vegetation quality (seed001_code: the code's, with
// K_vorg 1.5) and weathering at 50× the code's rates, so that clamps to the source occur.
// Determinism: a second GPU run from the same ground gives the same bits and conversions.
// gt_div itself is checked against the CPU's division on pairs spread over the exponents, and gt_sqrt
// (gpu/shaders/erosion/layered/square_root.glsl) against std::sqrt(float) on normal floats chosen to
// test its rounding.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"
#include "gpu/buffer.hpp"
#include "gpu/erosion/layered/creep.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/talus.hpp"
#include "gpu/erosion/layered/vegetation.hpp"
#include "gpu/erosion/layered/weathering.hpp"
#include "gpu/shader_program.hpp"
#include "reference/erosion/layered/creep.hpp"
#include "reference/erosion/layered/talus.hpp"
#include "reference/erosion/layered/vegetation.hpp"
#include "reference/erosion/layered/weathering.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/same_bits.hpp"

namespace {

using gt::testing::expect_same_bits;

using gt::LayeredConversions;
using gt::LayeredGround;
using gt::LayeredParams;

constexpr int side = 24;
constexpr int cliff_x = 12;  // columns x ≥ cliff_x stand 10 m higher; x = cliff_x is bare bedrock

struct Variant {
  const char* name;
  gt::LayeredBorder border;
  bool seed001_code;  // the code's talus amount and creep denominator, creep without rand
};

LayeredParams params_for(const Variant& variant) {
  LayeredParams params;
  params.border = variant.border;
  params.seed = 7;
  params.weathering_rate = 0.05;
  for (auto& type : params.bedrock_types) type.soil_rate *= 50.0;
  if (variant.seed001_code) {
    params.talus_amount = gt::TalusAmount::seed001_code;
    params.creep_denominator = gt::CreepDenominator::seed001_code;
    params.creep_random = false;
    params.vegetation_quality = gt::VegetationQuality::seed001_code;
    params.vegetation_soil_quality[0] = 1.5;
  }
  return params;
}

// Bedrock of a bare edge column in row y, as the header describes (profile: 3 m of type 0, 2 m of
// type 1, 40 m of type 0).
void set_edge_bedrock(LayeredGround<float>& ground, std::size_t c, int y) {
  if (y % 3 == 0) return;
  ground.bedrock_type[ground.bedrock_index(0, c)] = 1;
  if (y % 3 == 2) ground.bedrock_at(1, c) = 15.0f;
}

// Soil component thicknesses in [0, 0.3) m, about a third of them 0 (so some layers hold no
// organic matter and some are empty).
float random_component(std::mt19937& random) {
  std::uniform_real_distribution<float> share(0.0f, 1.0f);
  const float u = share(random);
  return u < 0.35f ? 0.0f : 0.3f * share(random);
}

LayeredGround<float> random_ground(const LayeredParams& params) {
  std::mt19937 random(2024);
  std::uniform_real_distribution<double> bump(0.0, 2.0);
  gt::Heightmap surface(side, side);
  surface.cell_size_x = 1.0;
  surface.cell_size_y = 1.25;
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) surface.at(x, y) = 0.2 * y + bump(random) + (x >= cliff_x ? 10.0 : 0.0);
  }
  gt::LayeredProfile profile;
  profile.bedrock = {{0, 3.0}, {1, 2.0}, {0, 40.0}};
  auto ground = gt::make_layered_ground<float>(surface, profile, params, 0.0);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const std::size_t c = ground.cell(x, y);
      const bool bare = x == cliff_x;
      for (int layer = 0; layer < gt::soil_layer_count; ++layer) {
        for (int component = 0; component < gt::soil_component_count; ++component) {
          ground.soil_at(layer, component, c) = bare ? 0.0f : random_component(random);
        }
      }
      ground.vegetation[c] = unit(random);
      if (bare) set_edge_bedrock(ground, c, y);
      if (!bare && unit(random) < 0.2f) ground.bedrock_at(0, c) = 0.0f;  // an emptied layer, skipped
    }
  }
  return ground;
}

// The error model's premise: no state value is subnormal.
void expect_no_subnormals(const LayeredGround<float>& ground, const std::string& when) {
  for (const auto& [name, values] : {std::pair{"surface", &ground.surface}, std::pair{"soil", &ground.soil},
                                     std::pair{"bedrock", &ground.bedrock}, std::pair{"vegetation", &ground.vegetation}}) {
    gt::testing::expect_no_subnormals(name, *values, when);
  }
}

void expect_same_ground(const LayeredGround<float>& expected, const LayeredGround<float>& actual,
                        const std::string& when) {
  expect_no_subnormals(expected, when);
  expect_same_bits("surface", expected.surface, actual.surface, when);
  expect_same_bits("soil", expected.soil, actual.soil, when);
  expect_same_bits("bedrock", expected.bedrock, actual.bedrock, when);
  expect_same_bits("bedrock_type", expected.bedrock_type, actual.bedrock_type, when);
  expect_same_bits("vegetation", expected.vegetation, actual.vegetation, when);
}

// The bound of the header's model for fragmented_into after `steps` apply passes.
void expect_conversions(const LayeredConversions& expected, const LayeredConversions& actual, int steps,
                        const std::string& when) {
  EXPECT_EQ(expected.fragmented_from, actual.fragmented_from) << when;
  const double u = std::ldexp(1.0, -24);
  const double gamma7 = 7.0 * u / (1.0 - 7.0 * u);
  const double terms = static_cast<double>(side) * side * gt::layered_neighbour_count * steps;
  const double relative = gamma7 + 2.0 * (terms + 1.0) * std::ldexp(1.0, -53);
  for (std::size_t i = 0; i < expected.fragmented_into.size(); ++i) {
    EXPECT_LE(std::abs(actual.fragmented_into[i] - expected.fragmented_into[i]), relative * expected.fragmented_into[i])
        << when << ": fragments into " << gt::soil_component_name(static_cast<int>(i));
  }
}

// Weathering's counts: equal (see the header).
void expect_weathering_conversions(const LayeredConversions& expected, const LayeredConversions& actual,
                                   const std::string& when) {
  EXPECT_EQ(expected.weathered_from, actual.weathered_from) << when;
  EXPECT_EQ(expected.weathered_into, actual.weathered_into) << when;
  EXPECT_EQ(expected.soil_formed_from, actual.soil_formed_from) << when;
  EXPECT_EQ(expected.soil_formed_into, actual.soil_formed_into) << when;
}

bool moved(const LayeredGround<float>& before, const LayeredGround<float>& after) {
  return before.soil != after.soil || before.surface != after.surface;
}

// Pairs a ≥ 0, b > 0 with normal quotients: random significands over exponents 2^-40 .. 2^40, equal
// significands (the quotient a power of two), b = 1, and a = 0.
std::vector<float> division_pairs() {
  std::mt19937 random(11);
  std::uniform_real_distribution<float> significand(1.0f, 2.0f);
  std::uniform_int_distribution<int> exponent(-40, 40);
  std::vector<float> pairs;
  for (int i = 0; i < 20000; ++i) {
    const float b = std::ldexp(significand(random), exponent(random));
    const float a = i % 10 == 0 ? b * 4.0f : std::ldexp(significand(random), exponent(random));
    pairs.insert(pairs.end(), {a, i % 10 == 1 ? 1.0f : b});
  }
  pairs.insert(pairs.end(), {0.0f, 3.0f, 1.0f, 3.0f, 2.0f, 3.0f, std::nextafter(2.0f, 0.0f), 1.0f});
  return pairs;
}

class LayeredGpuDivision : public gt::testing::GlTest {};

TEST_F(LayeredGpuDivision, GtDivIsTheCpusFloatDivision) {
  const auto pairs = division_pairs();
  const std::size_t count = pairs.size() / 2;
  const auto pair_buffer = gt::StorageBuffer::from(pairs);
  gt::StorageBuffer quotient_buffer(count * sizeof(float));
  pair_buffer.bind(0);
  quotient_buffer.bind(1);
  gt::ComputeProgram::load("erosion/layered/division_probe.comp").dispatch(static_cast<int>(count), 1, 64, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto quotients = quotient_buffer.download<float>(count);
  std::vector<float> expected(count);
  for (std::size_t i = 0; i < count; ++i) expected[i] = pairs[2 * i] / pairs[2 * i + 1];
  expect_same_bits("gt_div", expected, quotients, "division probe");
}

// Positive normal floats whose roots test gt_sqrt's rounding: random bit patterns over the whole
// normal range; exact squares of 12-bit significands (a remainder of 0) and their float neighbours;
// floats nearest the squares of midpoints between adjacent floats (the root just above or below a
// rounding tie: the sticky bit decides) and their neighbours; every power of two (odd and even
// exponents: the two radicand shifts); the smallest and largest normals and their neighbours.
std::vector<float> square_root_values() {
  std::mt19937 random(13);
  std::uniform_int_distribution<std::uint32_t> normal_bits(0x00800000u, 0x7f7fffffu);
  std::uniform_int_distribution<int> twelve_bits(1 << 11, (1 << 12) - 1);
  std::uniform_int_distribution<std::uint32_t> significand(0, 0x7fffffu);
  std::uniform_int_distribution<int> exponent(-60, 60);          // of a root whose square is normal
  std::uniform_int_distribution<int> square_exponent(-74, 51);  // of 2^11 ≤ k < 2^12 in k·2^e: (k·2^e)² normal
  std::vector<float> values;
  const auto with_neighbours = [&](float value) {
    values.insert(values.end(), {std::nextafter(value, 0.0f), value,
                                 std::nextafter(value, std::numeric_limits<float>::infinity())});
  };
  for (int i = 0; i < 200000; ++i) values.push_back(std::bit_cast<float>(normal_bits(random)));
  for (int i = 0; i < 20000; ++i) {
    const float root = std::ldexp(static_cast<float>(twelve_bits(random)), square_exponent(random));
    with_neighbours(root * root);  // exact: 24 significand bits at most
  }
  for (int i = 0; i < 20000; ++i) {
    // The midpoint between root and its successor, squared in double (exactly: 50 bits), rounded to float.
    const auto biased = static_cast<std::uint32_t>(127 + exponent(random));
    const float root = std::bit_cast<float>((biased << 23) | significand(random));
    const double midpoint = 0.5 * (double(root) + double(std::nextafter(root, 2.0f * root)));
    with_neighbours(static_cast<float>(midpoint * midpoint));
  }
  for (int power = -126; power <= 127; ++power) values.push_back(std::ldexp(1.0f, power));
  with_neighbours(std::numeric_limits<float>::max());
  values.pop_back();  // its successor is infinite
  with_neighbours(std::numeric_limits<float>::min());
  values.erase(values.end() - 3);  // its predecessor is subnormal
  return values;
}

class LayeredGpuSquareRoot : public gt::testing::GlTest {};

TEST_F(LayeredGpuSquareRoot, GtSqrtIsTheCpusFloatSquareRoot) {
  const auto values = square_root_values();
  for (float value : values) ASSERT_TRUE(std::isnormal(value) && value > 0.0f) << value;
  const auto value_buffer = gt::StorageBuffer::from(values);
  gt::StorageBuffer root_buffer(values.size() * sizeof(float));
  value_buffer.bind(0);
  root_buffer.bind(1);
  gt::ComputeProgram::load("erosion/layered/square_root_probe.comp")
      .dispatch(static_cast<int>(values.size()), 1, 64, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto roots = root_buffer.download<float>(values.size());
  std::vector<float> expected(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) expected[i] = std::sqrt(values[i]);
  expect_same_bits("gt_sqrt", expected, roots, "square root probe");
}

class LayeredGpu : public gt::testing::GlTestWithParam<Variant> {};

// One process of the layered iteration, as the one-step test runs it: the reference's step and the
// GPU twin's, at step number `step`; `missing_effect` names what the reference's step should have
// done from the test ground and did not (nullptr when it did), so that the comparison is not
// vacuous; `fragments` and `weathers` say which conversions it counts.
struct Process {
  const char* name;
  std::uint32_t step;
  std::function<void(LayeredGround<float>&, const LayeredParams&, std::uint32_t, LayeredConversions&)> reference;
  std::function<void(gt::gpu::LayeredGroundBuffers&, std::uint32_t, LayeredConversions&)> gpu;
  std::function<const char*(const LayeredGround<float>& initial, const LayeredGround<float>& stepped,
                            const LayeredConversions& converted)>
      missing_effect;
  bool fragments;
  bool weathers;
};

std::vector<Process> processes() {
  return {
      {"talus", 3,
       [](auto& ground, const auto& params, std::uint32_t step, auto& converted) {
         gt::reference::talus_step(ground, params, step, converted);
       },
       [](auto& buffers, std::uint32_t step, auto& converted) {
         gt::gpu::layered_talus().step(buffers, step, converted);
       },
       [](const auto& initial, const auto& stepped, const auto& converted) -> const char* {
         if (!moved(initial, stepped)) return "no soil moved";
         if (!(converted.fragmented_from[0] > 0.0)) return "the cliff's bedrock should fragment";
         if (!(converted.fragmented_from[1] > 0.0)) return "a hard layer over an exposed soft one should fall";
         return nullptr;
       },
       true, false},
      {"creep", 5,
       [](auto& ground, const auto& params, std::uint32_t step, auto& converted) {
         gt::reference::creep_step(ground, params, step, converted);
       },
       [](auto& buffers, std::uint32_t step, auto& converted) {
         gt::gpu::layered_creep().step(buffers, step, converted);
       },
       [](const auto& initial, const auto& stepped, const auto&) -> const char* {
         return moved(initial, stepped) ? nullptr : "no soil moved";
       },
       true, false},
      {"vegetation", 6,
       [](auto& ground, const auto& params, std::uint32_t step, auto& converted) {
         gt::reference::vegetation_step(ground, params, step, converted);
       },
       [](auto& buffers, std::uint32_t step, auto& converted) {
         gt::gpu::layered_vegetation().step(buffers, step, converted);
       },
       [](const auto& initial, const auto& stepped, const auto&) -> const char* {
         return initial.vegetation != stepped.vegetation ? nullptr : "no vegetation density changed";
       },
       false, false},
      {"weathering", 2,
       [](auto& ground, const auto& params, std::uint32_t step, auto& converted) {
         gt::reference::weathering_step(ground, params, step, converted);
       },
       [](auto& buffers, std::uint32_t step, auto& converted) {
         gt::gpu::layered_weathering().step(buffers, step, converted);
       },
       [](const auto& initial, const auto& stepped, const auto& converted) -> const char* {
         if (!moved(initial, stepped) && initial.bedrock == stepped.bedrock) return "no soil or bedrock changed";
         if (!(converted.weathered_into[0] > 0.0)) return "no sand weathered into organic matter";
         if (!(converted.soil_formed_from[0] > 0.0)) return "no soft rock became soil";
         return nullptr;
       },
       false, true},
  };
}

// Each process's one step from the same random ground, GPU against reference<float>.
TEST_P(LayeredGpu, OneStepOfEachProcessIsTheFloatReferenceBitForBit) {
  const auto params = params_for(GetParam());
  const auto initial = random_ground(params);
  for (const Process& process : processes()) {
    const std::string when = std::string(process.name) + " step";
    auto reference = initial;
    auto reference_conversions = gt::no_conversions(params.bedrock_types.size());
    process.reference(reference, params, process.step, reference_conversions);
    if (const char* missing = process.missing_effect(initial, reference, reference_conversions)) {
      ADD_FAILURE() << when << " of the reference: " << missing << " (the test ground no longer exercises it)";
      continue;
    }
    gt::gpu::LayeredGroundBuffers buffers(initial, params);
    auto conversions = gt::no_conversions(params.bedrock_types.size());
    process.gpu(buffers, process.step, conversions);
    expect_same_ground(reference, buffers.download(), when);
    if (process.fragments) expect_conversions(reference_conversions, conversions, 1, when);
    if (process.weathers) expect_weathering_conversions(reference_conversions, conversions, when);
  }
}

// 20 iterations of creep, talus, vegetation and weathering (the code's order, §4), compared after
// every pass; then a second GPU run from the same ground repeats the first bit for bit.
TEST_P(LayeredGpu, TwentyStepsOfEveryProcessFollowTheReferenceAndRepeat) {
  const auto params = params_for(GetParam());
  const auto initial = random_ground(params);
  auto reference = initial;
  auto reference_conversions = gt::no_conversions(params.bedrock_types.size());
  gt::gpu::LayeredGroundBuffers buffers(initial, params);
  const auto creep = gt::gpu::layered_creep();
  const auto talus = gt::gpu::layered_talus();
  const auto vegetation = gt::gpu::layered_vegetation();
  const auto weathering = gt::gpu::layered_weathering();
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  const std::uint32_t steps = 20;
  for (std::uint32_t step = 0; step < steps; ++step) {
    const std::string when = "step " + std::to_string(step);
    gt::reference::creep_step(reference, params, step, reference_conversions);
    creep.step(buffers, step, conversions);
    expect_same_ground(reference, buffers.download(), when + " creep");
    gt::reference::talus_step(reference, params, step, reference_conversions);
    talus.step(buffers, step, conversions);
    expect_same_ground(reference, buffers.download(), when + " talus");
    gt::reference::vegetation_step(reference, params, step, reference_conversions);
    vegetation.step(buffers, step, conversions);
    expect_same_ground(reference, buffers.download(), when + " vegetation");
    gt::reference::weathering_step(reference, params, step, reference_conversions);
    weathering.step(buffers, step, conversions);
    expect_same_ground(reference, buffers.download(), when + " weathering");
    expect_conversions(reference_conversions, conversions, 2 * static_cast<int>(step + 1), when);
    expect_weathering_conversions(reference_conversions, conversions, when);
    if (HasFailure()) return;
  }
  EXPECT_GT(reference_conversions.weathered_from[4], 0.0);
  const auto first = buffers.download();
  buffers.upload(initial);
  auto again = gt::no_conversions(params.bedrock_types.size());
  for (std::uint32_t step = 0; step < steps; ++step) {
    creep.step(buffers, step, again);
    talus.step(buffers, step, again);
    vegetation.step(buffers, step, again);
    weathering.step(buffers, step, again);
  }
  expect_same_ground(first, buffers.download(), "second GPU run");
  expect_weathering_conversions(conversions, again, "second GPU run");
  EXPECT_EQ(conversions.fragmented_from, again.fragmented_from);
}

INSTANTIATE_TEST_SUITE_P(Variants, LayeredGpu,
                         ::testing::Values(Variant{"closed_thesis", gt::LayeredBorder::closed, false},
                                           Variant{"periodic_thesis", gt::LayeredBorder::periodic, false},
                                           Variant{"closed_seed001_code", gt::LayeredBorder::closed, true},
                                           Variant{"periodic_seed001_code", gt::LayeredBorder::periodic, true}),
                         [](const ::testing::TestParamInfo<Variant>& info) { return std::string(info.param.name); });

}  // namespace
