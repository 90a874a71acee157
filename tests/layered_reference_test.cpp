// Properties of seed 001's layered ground reference (core/layered, reference/erosion/layered): the
// parameter checks, the thesis's reserve-then-deposit example, removal order, fragmentation, the
// per-material ledger over many talus + creep steps, resting piles at their angles of repose, the
// fixed layer count, and the classic stack's growth on the Fig. 3.1 scenario; vegetation growth
// (§3.15) and weathering (§3.16): worked examples by hand, the reach of bedrock → soil, and the
// ledger per material with every conversion counted.
#include <algorithm>
#include <cmath>
#include <limits>
#include <iostream>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"
#include "core/rng.hpp"
#include "reference/erosion/layered/classic_stack.hpp"
#include "reference/erosion/layered/column.hpp"
#include "reference/erosion/layered/creep.hpp"
#include "reference/erosion/layered/iteration.hpp"
#include "reference/erosion/layered/talus.hpp"
#include "reference/erosion/layered/vegetation.hpp"
#include "reference/erosion/layered/weathering.hpp"
#include "tests/support/refusal.hpp"

namespace {

using gt::LayeredGround;
using gt::LayeredParams;
using gt::LayeredProfile;
namespace ref = gt::reference;

constexpr int org = 0;
constexpr int sand = 1;
constexpr int boulders = 4;

gt::Heightmap flat_surface(int width, int height, double level) { return gt::Heightmap(width, height, level); }

LayeredProfile profile_with(std::array<double, 5> topsoil, std::array<double, 5> subsoil, double bedrock) {
  LayeredProfile profile;
  profile.topsoil = topsoil;
  profile.subsoil = subsoil;
  profile.bedrock = {{0, bedrock}, {1, bedrock}};
  return profile;
}

template <class Real>
Real column_thickness(const LayeredGround<Real>& ground, std::size_t c) {
  Real sum = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) sum += ground.bedrock_at(layer, c);
  return sum;
}

// ---------------------------------------------------------------------------------------------
// Parameters

TEST(LayeredParams, DefaultsAreTheThesisAndCodeValues) {
  const LayeredParams params;
  EXPECT_NO_THROW(gt::validate_layered_params(params));
  EXPECT_EQ(params.repose_tan, (std::array<double, 5>{1.25, 0.7, 0.8, 1.0, 1.0}));
  EXPECT_EQ(params.vegetation_repose, 0.2);
  EXPECT_EQ(params.depth_factor, 1.25);
  EXPECT_EQ(params.topsoil_max, 1.5);
  EXPECT_EQ(params.creep_rate, 0.01);
  EXPECT_EQ(params.critical_slope, 1.40);
  EXPECT_EQ(params.creep_denominator_floor, 0.1);
  EXPECT_EQ(params.talus_amount, gt::TalusAmount::thesis);
  EXPECT_EQ(params.creep_denominator, gt::CreepDenominator::singular);
  EXPECT_EQ(params.border, gt::LayeredBorder::closed);
  const auto resolved = gt::resolve_params("erosion.layered", gt::layered_param_specs(), nlohmann::json::object());
  const LayeredParams read = gt::layered_params_from_json(resolved);
  EXPECT_EQ(read.repose_tan, params.repose_tan);
  EXPECT_EQ(read.time_step, params.time_step);
  EXPECT_EQ(read.seed, params.seed);
}

TEST(LayeredParams, RefusesBadValuesWithTheirName) {
  const auto refused = [](auto change, const std::string& named) {
    LayeredParams params;
    change(params);
    try {
      gt::validate_layered_params(params);
      ADD_FAILURE() << "accepted a bad " << named;
    } catch (const gt::InputError& error) {
      EXPECT_NE(std::string(error.what()).find(named), std::string::npos) << error.what();
    }
  };
  refused([](LayeredParams& p) { p.repose_tan[sand] = 0.0; }, "repose_sand");
  refused([](LayeredParams& p) { p.repose_tan[org] = -1.0; }, "repose_org");
  refused([](LayeredParams& p) { p.repose_tan[boulders] = std::numeric_limits<double>::infinity(); }, "repose_boulders");
  refused([](LayeredParams& p) { p.repose_tan[sand] = std::nan(""); }, "repose_sand");
  refused([](LayeredParams& p) { p.time_step = std::nan(""); }, "time_step");
  refused([](LayeredParams& p) { p.topsoil_max = -1.0; }, "topsoil_max");
  refused([](LayeredParams& p) { p.bedrock_types[1].fragments = {0.1, 0.1, 0.1, 0.1}; }, "sum to 0.4");
  refused([](LayeredParams& p) { p.bedrock_types[0].repose_tan = 0.0; }, "bedrock type 0 repose_tan");
  refused([](LayeredParams& p) { p.depth_factor = 2.0; }, "depth_factor");
  EXPECT_THROW(gt::bedrock_types_from_json(nlohmann::json::parse(R"([{"repose_tan": 1, "fragments": [0.5, 0.6, 0, 0]}])")),
               gt::InputError);
}

TEST(LayeredParams, RefusesBadProfiles) {
  const LayeredParams params;
  EXPECT_THROW(gt::validate_layered_profile(profile_with({-0.1, 0, 0, 0, 0}, {}, 5.0), params), gt::InputError);
  EXPECT_THROW(gt::validate_layered_profile(profile_with({}, {}, -5.0), params), gt::InputError);
  EXPECT_THROW(gt::validate_layered_profile(profile_with({1.0, 1.0, 0, 0, 0}, {}, 5.0), params), gt::InputError);
  LayeredProfile unknown_type = profile_with({}, {}, 5.0);
  unknown_type.bedrock[0].type = 7;
  EXPECT_THROW(gt::validate_layered_profile(unknown_type, params), gt::InputError);
  EXPECT_THROW((gt::make_layered_ground<double>(flat_surface(3, 3, 0.0), profile_with({}, {std::nan(""), 0, 0, 0, 0}, 5.0),
                                                params)),
               gt::InputError);
}

// validate_layered_inputs refuses what make_layered_ground refuses, with the same message, and
// makes nothing: the driver checks a case with it before the run.
TEST(LayeredParams, ValidateLayeredInputsRefusesWhatMakeLayeredGroundRefuses) {
  const LayeredParams params;
  const LayeredProfile profile = profile_with({0.5, 0, 0, 0, 0}, {}, 5.0);
  const auto same_columns_refusal = [&](const gt::Heightmap& surface, const gt::LayeredColumns& columns,
                                        const std::string& named) {
    const std::string validated = gt::testing::refusal([&] { gt::validate_layered_inputs(surface, columns, params); });
    const std::string made =
        gt::testing::refusal([&] { (void)gt::make_layered_ground<double>(surface, columns, params); });
    EXPECT_NE(validated.find(named), std::string::npos) << validated;
    EXPECT_EQ(validated, made);
  };
  const auto same_refusal = [&](const gt::Heightmap& surface, const LayeredProfile& with, double vegetation,
                                const std::string& named) {
    same_columns_refusal(surface, gt::LayeredColumns{{with}, {}, {vegetation}}, named);
  };
  EXPECT_NO_THROW(gt::validate_layered_inputs(flat_surface(3, 3, 0.0), gt::LayeredColumns{{profile}, {}, {0.5}}, params));
  same_refusal(flat_surface(3, 3, 0.0), profile_with({}, {}, -5.0), 0.0, "erosion.layered");
  gt::Heightmap masked = flat_surface(3, 3, 0.0);
  masked.valid.assign(9, 1);
  masked.valid[4] = 0;
  same_refusal(masked, profile, 0.0, "no-data");
  gt::Heightmap not_finite = flat_surface(3, 3, 0.0);
  not_finite.values[4] = std::nan("");
  same_refusal(not_finite, profile, 0.0, "layered ground surface");
  gt::Heightmap no_spacing = flat_surface(3, 3, 0.0);
  no_spacing.cell_size_x = 0.0;
  same_refusal(no_spacing, profile, 0.0, "layered ground surface");
  same_refusal(flat_surface(3, 3, 0.0), profile, 1.5, "vegetation 1.5");
  // The spatial inputs: a map of another size, an index without a profile, a vegetation map value
  // outside [0, 1], profiles with different bedrock layer counts.
  LayeredProfile deeper = profile;
  deeper.bedrock.push_back({1, 10.0});
  same_columns_refusal(flat_surface(3, 3, 0.0), {{profile}, std::vector<std::int32_t>(8, 0), {0.0}}, "profile map");
  same_columns_refusal(flat_surface(3, 3, 0.0), {{profile, profile}, {0, 1, 2, 0, 0, 0, 0, 0, 0}, {0.0}},
                       "profile 2 at cell 2");
  same_columns_refusal(flat_surface(3, 3, 0.0), {{profile}, {}, {0, 0, 0, 0, -0.5, 0, 0, 0, 0}}, "vegetation -0.5");
  same_columns_refusal(flat_surface(3, 3, 0.0), {{profile, deeper}, {}, {0.0}}, "same number of bedrock layers");
}

TEST(LayeredGround, EachColumnTakesTheProfileAndVegetationItsMapsName) {
  const LayeredParams params;
  const LayeredProfile loam = profile_with({0.5, 0, 0, 0, 0}, {}, 5.0);
  const LayeredProfile bare = profile_with({}, {}, 7.0);
  const auto ground = gt::make_layered_ground<double>(
      flat_surface(2, 2, 3.0), gt::LayeredColumns{{loam, bare}, {0, 1, 1, 0}, {0.0, 0.25, 0.5, 0.75}}, params);
  for (std::size_t c = 0; c < 4; ++c) {
    const bool is_bare = c == 1 || c == 2;
    EXPECT_EQ(ground.soil_thickness(0, c), is_bare ? 0.0 : 0.5) << c;
    EXPECT_EQ(ground.bedrock_at(0, c), is_bare ? 7.0 : 5.0) << c;
    EXPECT_EQ(ground.vegetation[c], 0.25 * double(c)) << c;
    EXPECT_EQ(ground.surface[c], 3.0) << c;
  }
}

// ---------------------------------------------------------------------------------------------
// Column operations

// The thesis's example (§3.1): a pure organic topsoil at h_max receives h_max of pure rock. Reserve
// first: the whole organic layer moves down (share clamp((h_max + h_max − h_max)/h_max) = 1, taken
// whole, so exactly), then the rock fills the topsoil: pure rock on top, no mixing.
TEST(LayeredColumn, ReserveThenDepositReproducesTheThesisExample) {
  const LayeredParams params;
  const double h_max = params.topsoil_max;
  auto ground = gt::make_layered_ground<double>(flat_surface(1, 1, 10.0), profile_with({h_max, 0, 0, 0, 0}, {}, 5.0),
                                                params);
  ref::deposit_soil(ground, 0, ref::Composition<double>{0, h_max, 0, 0, 0}, h_max);
  EXPECT_EQ(ground.soil_at(0, sand, 0), h_max);
  EXPECT_EQ(ground.soil_at(0, org, 0), 0.0);
  EXPECT_EQ(ground.soil_at(1, org, 0), h_max);
  EXPECT_EQ(ground.soil_at(1, sand, 0), 0.0);
  EXPECT_EQ(ground.surface[0], 10.0 + h_max);
}

// A partial reserve keeps the old mixture's proportions and the deposit stays on top; more than
// h_max arriving at once overfills, and the second organize pushes the excess down.
TEST(LayeredColumn, DepositKeepsTheTopsoilAtMostItsMaximum) {
  const LayeredParams params;
  auto ground = gt::make_layered_ground<double>(flat_surface(1, 1, 0.0),
                                                profile_with({0.6, 0.6, 0, 0, 0}, {0, 0, 1.0, 0, 0}, 5.0), params);
  ref::deposit_soil(ground, 0, ref::Composition<double>{0, 0, 0, 0.6, 0}, 1.5);
  // Reserve moves (1.2 + 0.6 − 1.5)/1.2 = 1/4 of org and sand down.
  EXPECT_NEAR(ground.soil_at(0, org, 0), 0.45, 1e-15);
  EXPECT_NEAR(ground.soil_at(1, org, 0), 0.15, 1e-15);
  EXPECT_EQ(ground.soil_at(0, 3, 0), 0.6);
  ref::deposit_soil(ground, 0, ref::Composition<double>{0, 0, 0, 0, 4.0}, 1.5);
  EXPECT_NEAR(ground.soil_thickness(0, 0), 1.5, 1e-15);
  EXPECT_NEAR(ground.soil_at(0, boulders, 0), 1.5, 1e-15);  // the old topsoil went down whole
  EXPECT_NEAR(ground.soil_thickness(0, 0) + ground.soil_thickness(1, 0), 1.2 + 1.0 + 0.6 + 4.0, 1e-14);
  EXPECT_NEAR(ground.surface[0], 0.6 + 4.0, 1e-15);
}

TEST(LayeredColumn, RemoveSoilTakesTopsoilThenSubsoilThenTheFirstNonEmptyBedrock) {
  const LayeredParams params;
  LayeredProfile profile = profile_with({0.5, 0.5, 0, 0, 0}, {0, 0, 2.0, 0, 0}, 3.0);
  profile.bedrock = {{2, 0.0}, {0, 3.0}, {1, 4.0}};
  auto ground = gt::make_layered_ground<double>(flat_surface(1, 1, 100.0), profile, params);
  auto removed = ref::remove_soil(ground, 0, 0.5);
  EXPECT_EQ(removed.soil[org], 0.25);
  EXPECT_EQ(removed.soil[sand], 0.25);
  EXPECT_EQ(ground.soil_thickness(1, 0), 2.0);
  removed = ref::remove_soil(ground, 0, 1.5);  // 0.5 topsoil + 1.0 subsoil
  EXPECT_EQ(ground.soil_thickness(0, 0), 0.0);
  EXPECT_EQ(ground.soil_at(1, 2, 0), 1.0);
  EXPECT_EQ(removed.bedrock_layer, -1);
  removed = ref::remove_soil(ground, 0, 10.0);  // the subsoil, then bedrock layer 1 only (layer 0 is empty)
  EXPECT_EQ(removed.bedrock_layer, 1);
  EXPECT_EQ(removed.bedrock, 3.0);
  EXPECT_EQ(ground.bedrock_at(1, 0), 0.0);
  EXPECT_EQ(ground.bedrock_at(2, 0), 4.0);
  EXPECT_EQ(ground.surface[0], 100.0 - 0.5 - 1.5 - 1.0 - 3.0);
  EXPECT_EQ(ref::top_nonempty_layer(ground, 0), 2 + 2);
}

TEST(LayeredColumn, FragmentsFollowKRockAndSumToTheRock) {
  const gt::BedrockType type{4.0, {0.1, 0.2, 0.3, 0.4}, 1.0};
  const auto broken = ref::fragments(type, 2.0);
  EXPECT_EQ(broken[org], 0.0);
  EXPECT_NEAR(broken[sand], 0.2, 1e-15);
  EXPECT_NEAR(broken[2], 0.4, 1e-15);
  EXPECT_NEAR(broken[3], 0.6, 1e-15);
  EXPECT_NEAR(broken[boulders], 0.8, 1e-15);
  EXPECT_EQ(ref::composition_total(broken), 2.0);
}

// ---------------------------------------------------------------------------------------------
// Ledger over many steps

// A rough layered terrain: every column its own topsoil/subsoil mixture (0..max), bedrock of types
// 0 and 1, surface noise of ±2 m on 1 m cells (slopes up to ~4, so talus moves everywhere), and a
// few bare type-0 cliffs (tan φ 4) of 12 m, steep enough to fall and fragment.
template <class Real>
LayeredGround<Real> random_terrain(int size, const LayeredParams& params, std::uint32_t seed) {
  auto ground = gt::make_layered_ground<Real>(flat_surface(size, size, 50.0), profile_with({}, {}, 0.0), params);
  auto draw = [seed](std::size_t c, std::uint32_t stream) {
    return static_cast<double>(gt::uniform01(gt::random_u32(seed, static_cast<std::uint32_t>(c), 0, stream)));
  };
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    const bool cliff = draw(c, 20) < 0.05;
    double topsoil = 0.0;
    for (int component = 0; component < 5; ++component) {
      const double share = draw(c, static_cast<std::uint32_t>(component));
      ground.soil_at(0, component, c) = cliff ? Real(0) : static_cast<Real>(0.3 * share);
      ground.soil_at(1, component, c) = cliff ? Real(0) : static_cast<Real>(0.8 * draw(c, 10u + component));
      topsoil += 0.3 * share;
    }
    EXPECT_LE(topsoil, params.topsoil_max);
    ground.bedrock_at(0, c) = static_cast<Real>(2.0 + 3.0 * draw(c, 30));
    ground.bedrock_at(1, c) = static_cast<Real>(20.0);
    ground.surface[c] = static_cast<Real>(50.0 + 4.0 * draw(c, 31) + (cliff ? 12.0 : 0.0));
    ground.vegetation[c] = static_cast<Real>(draw(c, 32));
  }
  return ground;
}

// Every thickness finite and ≥ 0, every topsoil at most its maximum (the last organize leaves the
// topsoil at exactly topsoil_max·(1 ± a few ulp); 1e-6 relative is the check's own allowance).
template <class Real>
void expect_valid(const LayeredGround<Real>& ground, const LayeredParams& params) {
  EXPECT_NO_THROW(gt::check_layered_ground(ground, params));
}

// The ledger's error model. Per step a stored component thickness goes through at most R = 32
// roundings (removal: 2; up to 8 incoming shares and 8 additions: 16; two organizes, each a share
// taken and added below: 8; the deposit's addition: 1; rounded up), each within the unit roundoff u of
// a value no larger than what that cell holds of the material. Summed over cells, one step's drift
// of a material's total is at most R·u·(its total + what moved), so after S steps the relative
// drift is at most S·R·u (with "what moved" bounded by the total, a factor 2). S = 60: double
// 60·32·2·1.1e-16 = 4.3e-13 (inside the issue's 1e-12), float 60·32·2·6.0e-8 = 2.3e-4.
template <class Real>
double ledger_tolerance(int steps) {
  return steps * 32.0 * 2.0 * std::numeric_limits<Real>::epsilon() / 2.0;
}

template <class Real>
void run_ledger_case(gt::LayeredBorder border) {
  LayeredParams params;
  params.border = border;
  params.bedrock_types[0].fragments = {0.1, 0.2, 0.3, 0.4};
  auto ground = random_terrain<Real>(24, params, 7);
  const std::size_t types = params.bedrock_types.size();
  const gt::LayeredLedger initial = gt::layered_ledger(ground, types);
  std::vector<Real> base(ground.cells());
  for (std::size_t c = 0; c < ground.cells(); ++c) base[c] = ground.surface[c] - column_thickness(ground, c);
  const std::size_t soil_size = ground.soil.size();
  const std::size_t bedrock_size = ground.bedrock.size();
  gt::LayeredConversions conversions = gt::no_conversions(types);
  constexpr int steps = 60;
  const double tolerance = ledger_tolerance<Real>(steps);
  for (int step = 0; step < steps; ++step) {
    ref::creep_step(ground, params, static_cast<std::uint32_t>(step), conversions);
    ref::talus_step(ground, params, static_cast<std::uint32_t>(step), conversions);
    expect_valid(ground, params);
  }
  const gt::LayeredLedger final_ledger = gt::layered_ledger(ground, types);
  for (int component = 0; component < 5; ++component) {
    const auto i = static_cast<std::size_t>(component);
    const double expected = initial.components[i] + conversions.fragmented_into[i];
    EXPECT_NEAR(final_ledger.components[i], expected, tolerance * expected) << gt::soil_component_name(component);
  }
  for (std::size_t type = 0; type < types; ++type) {
    const double expected = initial.bedrock[type] - conversions.fragmented_from[type];
    EXPECT_NEAR(final_ledger.bedrock[type], expected, tolerance * initial.bedrock[type]) << "bedrock type " << type;
  }
  // Fragmentation happened (the cliffs fell), only type 0 can fall, and it made no organic matter.
  EXPECT_GT(conversions.fragmented_from[0], 1.0);
  EXPECT_EQ(conversions.fragmented_from[1], 0.0);
  EXPECT_EQ(conversions.fragmented_into[org], 0.0);
  double into = 0.0;
  for (double volume : conversions.fragmented_into) into += volume;
  EXPECT_NEAR(into, conversions.fragmented_from[0], tolerance * conversions.fragmented_from[0]);
  EXPECT_NEAR(final_ledger.total(), initial.total(), tolerance * initial.total());
  // The surface stayed in step with the layers: base = surface − column thickness is unchanged up
  // to one rounding of the surface and of the thickness sum per operation (≤ 32 per step).
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    const double scale = static_cast<double>(ground.surface[c]);
    EXPECT_NEAR(ground.surface[c] - column_thickness(ground, c), base[c], tolerance * scale) << "cell " << c;
  }
  EXPECT_EQ(ground.soil.size(), soil_size);  // the layer count is fixed
  EXPECT_EQ(ground.bedrock.size(), bedrock_size);
}

TEST(LayeredLedger, EveryMaterialIsConservedOverTalusAndCreepDouble) {
  run_ledger_case<double>(gt::LayeredBorder::closed);
}

TEST(LayeredLedger, EveryMaterialIsConservedWithPeriodicBorders) {
  run_ledger_case<double>(gt::LayeredBorder::periodic);
}

TEST(LayeredLedger, EveryMaterialIsConservedInFloatToItsRounding) {
  run_ledger_case<float>(gt::LayeredBorder::closed);
}

TEST(LayeredLedger, CodeVariantsConserveToo) {
  LayeredParams params;
  params.talus_amount = gt::TalusAmount::seed001_code;
  params.creep_denominator = gt::CreepDenominator::seed001_code;
  params.creep_random = false;
  auto ground = random_terrain<double>(16, params, 11);
  const auto initial = gt::layered_ledger(ground, params.bedrock_types.size());
  auto conversions = gt::no_conversions(params.bedrock_types.size());
  for (std::uint32_t step = 0; step < 30; ++step) {
    ref::creep_step(ground, params, step, conversions);
    ref::talus_step(ground, params, step, conversions);
  }
  const auto final_ledger = gt::layered_ledger(ground, params.bedrock_types.size());
  EXPECT_NEAR(final_ledger.total(), initial.total(), ledger_tolerance<double>(30) * initial.total());
  EXPECT_GT(conversions.fragmented_from[0], 0.0);
}

// ---------------------------------------------------------------------------------------------
// Talus and creep behaviour

// A cone of pure `component` (all topsoil: topsoil_max raised to hold it) on flat bedrock, twice as
// steep as its angle of repose, collapses until a step moves nothing. At rest no neighbour pair may
// be steeper than tan φ. The slope is measured from the layers (bedrock top + soil thickness), not
// from the algorithm's surface; the two differ by the surface's rounding, ≤ S·2·u·h per step count S
// (one addition and one subtraction per step, heights h ≤ 40 m), so the bound is
// tan φ + 2·S·2·u·h / l with l = 1 m: about 1e-11 for S ≤ 4000.
// A pile flattened far below its angle would mean a wrong threshold or amount: the steepest pair was
// last moved from a slope ≥ tan φ, and a move shrinks a difference at most by the factor 1 − 4.5·Δt
// (a donor giving Δt·Δh/2 to 8 neighbours as low, the receiver gaining Δt·Δh/2), so the floor checked
// is (1 − 4.5·Δt)·tan φ = 0.1·tan φ at the default Δt = 0.2.
TEST(LayeredTalus, APileOfEachMaterialRestsAtItsAngleOfRepose) {
  for (int component = 0; component < 5; ++component) {
    LayeredParams params;
    params.topsoil_max = 100.0;
    const double repose = params.repose_tan[static_cast<std::size_t>(component)];
    constexpr int size = 41;
    constexpr double radius = 6.0;
    auto ground = gt::make_layered_ground<double>(flat_surface(size, size, 0.0), profile_with({}, {}, 10.0), params);
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const double r = std::hypot(x - size / 2, y - size / 2);
        const double height = std::max(0.0, 2.0 * repose * (radius - r));
        ground.soil_at(0, component, ground.cell(x, y)) = height;
        ground.surface[ground.cell(x, y)] = height;
      }
    }
    const double volume = gt::layered_ledger(ground, 3).components[static_cast<std::size_t>(component)];
    auto conversions = gt::no_conversions(3);
    int steps = 0;
    constexpr int max_steps = 2000;
    for (; steps < max_steps; ++steps) {
      const auto outflows = ref::talus_outflows(ground, params, static_cast<std::uint32_t>(steps));
      const bool moving = std::any_of(outflows.begin(), outflows.end(), [](const auto& amounts) {
        return std::any_of(amounts.begin(), amounts.end(), [](double a) { return a > 0.0; });
      });
      if (!moving) break;
      ref::talus_step(ground, params, static_cast<std::uint32_t>(steps), conversions);
    }
    ASSERT_LT(steps, max_steps) << gt::soil_component_name(component) << " never came to rest";
    double steepest = 0.0;
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        const std::size_t c = ground.cell(x, y);
        const double top = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
        for (int k = 0; k < 8; ++k) {
          const auto n = gt::layered_neighbour(ground, params.border, x, y, k);
          if (!n) continue;
          const double other = ground.soil_thickness(0, *n) + ground.soil_thickness(1, *n);
          steepest = std::max(steepest, (top - other) / gt::layered_neighbour_distance(1.0, 1.0, k));
        }
      }
    }
    const double bound = 2.0 * max_steps * 2.0 * std::numeric_limits<double>::epsilon() / 2.0 * 40.0;
    EXPECT_LE(steepest, repose + bound) << gt::soil_component_name(component);
    EXPECT_GE(steepest, (1.0 - 4.5 * params.time_step) * repose) << gt::soil_component_name(component);
    EXPECT_NEAR(gt::layered_ledger(ground, 3).components[static_cast<std::size_t>(component)], volume, 1e-12 * volume);
    EXPECT_EQ(conversions.fragmented_from[0], 0.0);  // flat bedrock under the pile never falls
  }
}

// Why Δt defaults to 0.2, not the thesis's 0.5: eq. 3.3 is per neighbour, so a peak Δh above its 8
// neighbours gives 8·Δt·Δh/2 and each neighbour gains Δt·Δh/2; the new difference is Δh·(1 − 4.5·Δt)
// (before the availability clamp), negative for Δt > 2/9. At 0.5 the peak drops below its neighbours
// (a checkerboard that never rests: the pile test at 0.5 still moved after 4000 steps); at 0.2 it
// keeps 1 − 0.9 = 0.1 of its difference.
TEST(LayeredTalus, ThePerNeighbourAmountOvershootsAboveTwoNinthsOfASecond) {
  for (double time_step : {0.5, 0.2}) {
    LayeredParams params;
    params.talus_random = false;
    params.time_step = time_step;
    auto ground = gt::make_layered_ground<double>(flat_surface(3, 3, 0.0), profile_with({}, {}, 5.0), params);
    ground.soil_at(0, sand, 4) = 1.0;
    ground.surface[4] = 1.0;  // slope 1 to the sides, 1/√2 = 0.707 ≥ 0.7 to the corners
    auto conversions = gt::no_conversions(3);
    ref::talus_step(ground, params, 0, conversions);
    const double expected = std::max(0.0, 1.0 - 4.0 * time_step) - std::min(time_step / 2.0, 1.0 / 8.0);
    EXPECT_NEAR(ground.surface[4] - ground.surface[1], expected, 1e-15) << "Δt = " << time_step;
  }
}

// A sand peak on the west border: with closed borders nothing crosses it, with periodic borders the
// columns on the east border receive (the three of them: L, TL, BL wrap around).
TEST(LayeredTalus, PeriodicBordersWrapClosedBordersDoNot) {
  for (auto border : {gt::LayeredBorder::closed, gt::LayeredBorder::periodic}) {
    LayeredParams params;
    params.border = border;
    auto ground = gt::make_layered_ground<double>(flat_surface(5, 5, 0.0), profile_with({}, {}, 5.0), params);
    const std::size_t peak = ground.cell(0, 2);
    ground.soil_at(0, sand, peak) = 1.0;
    ground.surface[peak] = 1.0;
    auto conversions = gt::no_conversions(3);
    ref::talus_step(ground, params, 0, conversions);
    const bool wraps = border == gt::LayeredBorder::periodic;
    for (int y : {1, 2, 3}) {
      EXPECT_EQ(ground.surface[ground.cell(4, y)] > 0.0, wraps) << gt::layered_border_name(border) << " y " << y;
      EXPECT_GT(ground.surface[ground.cell(1, y)], 0.0);
    }
  }
}

TEST(LayeredTalus, VegetationSteepensTheReposeAndDepthCompactsTheSubsoil) {
  LayeredParams params;
  auto ground = gt::make_layered_ground<double>(flat_surface(1, 1, 0.0),
                                                profile_with({0, 1.0, 0, 0, 0}, {0, 0, 0, 0, 2.0}, 5.0), params);
  EXPECT_DOUBLE_EQ(ref::soil_repose(ground, params, 0), 0.7);  // min(0.7, 1.25·1.0)
  ground.vegetation[0] = 1.0;
  EXPECT_DOUBLE_EQ(ref::soil_repose(ground, params, 0), 0.7 * 1.2);
  ground.soil_at(0, sand, 0) = 0.0;
  EXPECT_DOUBLE_EQ(ref::soil_repose(ground, params, 0), 1.25 * 1.0 * 1.2);  // only the subsoil is left
}

// Two columns, 1 m apart, with nothing but the talus rule between them: a donor above its repose
// gives Δt·Δh·rand/2 (eq. 3.3), loses its vegetation, and so does the receiver.
TEST(LayeredTalus, MovesEquationThreePointThreeAndClearsVegetation) {
  LayeredParams params;
  params.talus_random = false;
  params.time_step = 0.5;
  auto ground = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile_with({0, 1.0, 0, 0, 0}, {}, 5.0),
                                                params, 0.5);
  ground.soil_at(0, sand, 0) = 1.5;
  ground.surface[0] = 1.5;
  ground.surface[1] = 1.0;  // Δh = 0.5 < 0.7: stable
  auto conversions = gt::no_conversions(3);
  ref::talus_step(ground, params, 0, conversions);
  EXPECT_EQ(ground.surface[0], 1.5);
  EXPECT_EQ(ground.vegetation[0], 0.5);
  ground.surface[1] = 0.5;  // Δh = 1.0 ≥ 0.7·(1 + 0.2·0.5) = 0.77
  ground.soil_at(0, sand, 1) = 0.5;
  ref::talus_step(ground, params, 1, conversions);
  EXPECT_DOUBLE_EQ(ground.surface[0], 1.5 - 0.5 * 1.0 / 2.0);
  EXPECT_DOUBLE_EQ(ground.surface[1], 0.5 + 0.25);
  EXPECT_EQ(ground.vegetation[0], 0.0);
  EXPECT_EQ(ground.vegetation[1], 0.0);
}

TEST(LayeredTalus, OnlyExposedSoftBedrockFallsAndBreaksIntoFragments) {
  LayeredParams params;
  params.talus_random = false;
  LayeredProfile profile = profile_with({}, {}, 0.0);
  profile.bedrock = {{1, 2.0}, {0, 20.0}};  // hard over soft
  auto ground = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile, params);
  ground.surface[0] = 10.0;  // 10 m cliff: slope 10 ≥ 4, but the hard cap does not fall...
  auto conversions = gt::no_conversions(3);
  // ...unless the soft layer below is exposed: its top is at 8 m, above the neighbour's 0 m.
  ref::talus_step(ground, params, 0, conversions);
  // The top (hard) layer moves: Δt·Δh/2 = 1 m asked (Δt = 0.2), of the layer's 2 m; it arrives
  // as fragments by type 1's K_rock (boulders 0.7).
  EXPECT_DOUBLE_EQ(conversions.fragmented_from[1], 0.2 * 10.0 / 2.0);
  EXPECT_DOUBLE_EQ(ground.bedrock_at(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(ground.soil_thickness(0, 1), 1.0);
  EXPECT_DOUBLE_EQ(ground.soil_at(0, boulders, 1), 0.7);
  // The same 10 m cliff with a 12 m hard cap: the soft layer's top (−2 m) is below the neighbour,
  // so only the hard type's tan φ = 1e7 counts, and nothing falls.
  auto buried = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile, params);
  buried.surface[0] = 10.0;
  buried.bedrock_at(0, 0) = 12.0;
  ref::talus_step(buried, params, 0, conversions);
  EXPECT_EQ(buried.surface[0], 10.0);
  EXPECT_EQ(buried.bedrock_at(0, 0), 12.0);
}

// Creep has no threshold, moves only downhill, scales with the organic share, and leaves the
// vegetation alone; a pure rock layer does not creep.
TEST(LayeredCreep, MovesOrganicSoilDownhillAtAnySlope) {
  LayeredParams params;
  params.creep_random = false;
  params.time_step = 0.5;
  auto ground = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile_with({0.5, 0.5, 0, 0, 0}, {}, 5.0),
                                                params, 0.8);
  ground.surface[0] = 0.1;  // slope 0.1, far below every repose
  auto conversions = gt::no_conversions(3);
  ref::creep_step(ground, params, 0, conversions);
  // q = 0.01·0.1/(1 − (0.1/1.4)²); Δ = Δt·(V_org/V)·q/2
  const double q = 0.01 * 0.1 / (1.0 - (0.1 / 1.4) * (0.1 / 1.4));
  EXPECT_NEAR(ground.surface[0], 0.1 - 0.5 * 0.5 * q / 2.0, 1e-16);
  EXPECT_NEAR(ground.surface[1], q * 0.125, 1e-18);
  EXPECT_EQ(ground.vegetation[0], 0.8);
  auto rock = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile_with({0, 1.0, 0, 0, 0}, {}, 5.0), params);
  rock.surface[0] = 1.0;
  ref::creep_step(rock, params, 0, conversions);
  EXPECT_EQ(rock.surface[0], 1.0);
}

// At the critical slope the thesis's law diverges (the whole layer goes), the code's is capped by
// its least denominator 0.1.
TEST(LayeredCreep, TheThesisLawIsSingularAtTheCriticalSlopeTheCodesIsCapped) {
  LayeredParams params;
  params.creep_random = false;
  params.time_step = 0.5;
  auto make = [&params] {
    auto ground = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile_with({1.0, 0, 0, 0, 0}, {}, 5.0), params);
    ground.surface[0] = 1.5;  // slope 1.5 > S_c = 1.4
    return ground;
  };
  auto thesis = make();
  auto conversions = gt::no_conversions(3);
  ref::creep_step(thesis, params, 0, conversions);
  EXPECT_EQ(thesis.soil_thickness(0, 0), 0.0);
  params.creep_denominator = gt::CreepDenominator::seed001_code;
  auto code = make();
  ref::creep_step(code, params, 0, conversions);
  EXPECT_NEAR(code.soil_thickness(0, 0), 1.0 - 0.5 * 0.01 * 1.5 / 0.1 / 2.0, 1e-15);
}

TEST(LayeredTalus, RandomFactorIsKeyedAndInRange) {
  for (std::uint32_t c = 0; c < 100; ++c) {
    const double r = ref::random_factor<double>(true, 1, c, 3, gt::talus_neighbour_stream(2));
    EXPECT_GE(r, 0.9);
    EXPECT_LT(r, 1.0);
    EXPECT_EQ(r, ref::random_factor<double>(true, 1, c, 3, gt::talus_neighbour_stream(2)));
  }
  EXPECT_NE(ref::random_factor<double>(true, 1, 0, 3, 0), ref::random_factor<double>(true, 1, 0, 4, 0));
  EXPECT_EQ(ref::random_factor<double>(false, 1, 0, 3, 0), 1.0);
}

// ---------------------------------------------------------------------------------------------
// Layer count: the classic stack against the fixed model on Fig. 3.1's scenario

// A uniform slope (1.5 per 1 m cell, above both repose slopes) of rock over a base; every step water
// leaves d = 0.05 m of sediment on every column and talus moves a = Δt·Δh/2 = 0.375 m to the lower
// neighbour. Away from the ends (whose disturbance travels one column per step) every column is
// alike, so each gives the slide it receives: a slide of sediment d over a − d of older layers, cut
// inside a layer. The cut leaves one more layer than before in the donor, the received slide is
// stacked whole (it is not homogeneous): at least one net new layer per step in the middle of the
// row. After S = 24 steps on 64 columns the middle holds ≥ 1 + 24 layers; the check asks for S/2
// (cuts that land on a boundary add none). The fixed model on the same scenario keeps its 2 soil
// layers and 2 bedrock layers per column, its arrays unchanged.
TEST(LayeredLayerCount, TheClassicStackGrowsWhileTheFixedModelStaysBounded) {
  constexpr int columns = 64;
  constexpr int steps = 24;
  constexpr double slope = 1.5;
  constexpr double sediment = 0.05;
  constexpr double time_step = 0.5;
  ref::ClassicRow row;
  row.repose_tan = {1.0, 0.6};  // rock, sediment
  for (int i = 0; i < columns; ++i) row.columns.push_back({{0, 100.0 + slope * (columns - i)}, {0, 5.0}});
  std::vector<std::size_t> counts;
  for (int step = 0; step < steps; ++step) {
    for (std::size_t i = 0; i < row.columns.size(); ++i) ref::classic_deposit(row, i, {1, sediment});
    ref::classic_talus_step(row, time_step);
    counts.push_back(ref::classic_max_layers(row));
  }
  EXPECT_GE(counts.back(), static_cast<std::size_t>(steps / 2));

  LayeredParams params;
  params.time_step = time_step;
  params.talus_random = false;
  gt::Heightmap surface(columns, 1);
  for (int i = 0; i < columns; ++i) surface.at(i, 0) = 105.0 + slope * (columns - i);
  auto ground = gt::make_layered_ground<double>(surface, profile_with({}, {0, 0, 5.0, 0, 0}, 100.0), params);
  const std::size_t soil_size = ground.soil.size();
  const std::size_t bedrock_size = ground.bedrock.size();
  auto conversions = gt::no_conversions(3);
  for (int step = 0; step < steps; ++step) {
    for (std::size_t c = 0; c < ground.cells(); ++c) {
      ref::deposit_soil(ground, c, ref::Composition<double>{0, sediment, 0, 0, 0}, params.topsoil_max);
    }
    ref::talus_step(ground, params, static_cast<std::uint32_t>(step), conversions);
  }
  EXPECT_EQ(ground.soil.size(), soil_size);
  EXPECT_EQ(ground.bedrock.size(), bedrock_size);
  EXPECT_EQ(ground.bedrock_layer_count, 2);
  EXPECT_NO_THROW(gt::check_layered_ground(ground, params));
  std::cout << "classic stack max layers per step:";
  for (auto count : counts) std::cout << ' ' << count;
  std::cout << '\n';
}

// ---------------------------------------------------------------------------------------------
// Vegetation growth (§3.15) and weathering (§3.16)

TEST(LayeredParams, VegetationAndWeatheringDefaultsAndRefusals) {
  const LayeredParams params;
  EXPECT_EQ(params.vegetation_quality, gt::VegetationQuality::thesis);
  EXPECT_EQ(params.vegetation_soil_quality, (std::array<double, 5>{1.0, 0.2, 0.0, 0.0, 0.0}));
  EXPECT_EQ(params.weathering_shares, (std::array<double, 4>{1.0, 0.2, 0.3, 0.4}));
  EXPECT_EQ(params.weathering_reach, 4.0);
  EXPECT_EQ(params.bedrock_types[1].soil_rate, 0.0003);
  const auto resolved = gt::resolve_params("erosion.layered", gt::layered_param_specs(),
                                           nlohmann::json{{"vegetation_quality", "seed001_code"},
                                                          {"vegetation_quality_org", 1.5},
                                                          {"weathering_stones", 0.5}});
  const LayeredParams read = gt::layered_params_from_json(resolved);
  EXPECT_EQ(read.vegetation_quality, gt::VegetationQuality::seed001_code);
  EXPECT_EQ(read.vegetation_soil_quality[0], 1.5);
  EXPECT_EQ(read.weathering_shares[3], 0.5);
  EXPECT_EQ(read.root_depth, 0.25);
  LayeredParams bad;
  bad.bedrock_types[0].soil_composition = {0.5, 0.0, 0.0, 0.0, 0.0};
  EXPECT_THROW(gt::validate_layered_params(bad), gt::InputError);
  bad = LayeredParams{};
  bad.weathering_rate = -1.0;
  EXPECT_THROW(gt::validate_layered_params(bad), gt::InputError);
  bad = LayeredParams{};
  bad.root_depth = 0.0;
  EXPECT_THROW(gt::validate_layered_params(bad), gt::InputError);
}

// The worked column: topsoil org 0.1, sand 0.1 (0.2 m); subsoil org 0.05, sand 0.15, gravel 0.3
// (0.5 m); 3 × 3 columns alike, vegetation 0.5 everywhere; the code's constants (K_vorg 1.5,
// K_vrock0 0.2, K_eveg 0.8, K_nveg 0.25, K_veg 1, Δt 0.2, depths 0.25 m and 2.0 m, base 0.2).
LayeredGround<double> worked_ground(const LayeredParams& params) {
  return gt::make_layered_ground<double>(flat_surface(3, 3, 10.0),
                                         profile_with({0.1, 0.1, 0, 0, 0}, {0.05, 0.15, 0.3, 0, 0}, 5.0), params, 0.5);
}

LayeredParams worked_params(gt::VegetationQuality quality) {
  LayeredParams params;
  params.vegetation_quality = quality;
  params.vegetation_soil_quality[0] = 1.5;
  return params;
}

// By hand: the 0.25 m sample takes the whole topsoil and 0.05/0.5 of the subsoil: org 0.1 + 0.005,
// sand 0.1 + 0.015, gravel 0.03 (K 0); q(0.25) = (1.5·0.105 + 0.2·0.115)/0.25 = 0.722. The 2.0 m
// sample takes all 0.7 m: q(2.0) = (1.5·0.15 + 0.2·0.25)/0.7 = 0.275/0.7.
// Thesis: drive = q − 0.8·0.5 + 0.25·(8·0.5) = 1.322 at the centre (8 neighbours);
// seed001_code: q_s = 0.5·0.722 + 0.5·0.275/0.7 − 0.2, nveg = 9·0.5.
// veg' = 0.5 + u·1·0.2·drive with u the column's rand(0, 1). Bound 1e-15: a few roundings of
// numbers ≤ 2.
TEST(LayeredVegetation, WorkedColumnByHand) {
  const std::uint32_t step = 4;
  const std::size_t centre = 4;
  const double u = gt::uniform01(gt::random_u32(1, static_cast<std::uint32_t>(centre), step, gt::vegetation_cell_stream));
  const double shallow = (1.5 * 0.105 + 0.2 * 0.115) / 0.25;
  const double deep = 0.275 / 0.7;
  {
    const auto params = worked_params(gt::VegetationQuality::thesis);
    auto ground = worked_ground(params);
    EXPECT_NEAR(ref::soil_quality(ground, params, centre, 0.25), 0.722, 1e-15);
    EXPECT_NEAR(ref::soil_quality(ground, params, centre, 2.0), deep, 1e-15);
    auto conversions = gt::no_conversions(3);
    ref::vegetation_step(ground, params, step, conversions);
    EXPECT_NEAR(ground.vegetation[centre], 0.5 + u * 0.2 * (shallow - 0.8 * 0.5 + 0.25 * 4.0), 1e-15);
    // A corner has 3 neighbours inside the closed border.
    const double corner_u = gt::uniform01(gt::random_u32(1, 0, step, gt::vegetation_cell_stream));
    EXPECT_NEAR(ground.vegetation[0], 0.5 + corner_u * 0.2 * (shallow - 0.4 + 0.25 * 1.5), 1e-15);
  }
  {
    const auto params = worked_params(gt::VegetationQuality::seed001_code);
    auto ground = worked_ground(params);
    auto conversions = gt::no_conversions(3);
    ref::vegetation_step(ground, params, step, conversions);
    const double quality = 0.5 * shallow + 0.5 * deep - 0.2;
    EXPECT_NEAR(ground.vegetation[centre], 0.5 + u * 0.2 * (quality - 0.4 + 0.25 * 4.5), 1e-15);
  }
}

// No organic matter in either soil layer kills the vegetation (the code's rule); organic matter in
// the subsoil alone keeps it. Growth never leaves [0, 1], and it converts nothing.
TEST(LayeredVegetation, DeathWithoutOrganicMatterClampAndNoMaterial) {
  LayeredParams params;
  params.vegetation_rate = 10.0;  // large steps, to reach the clamps
  auto ground = gt::make_layered_ground<double>(flat_surface(4, 1, 0.0), profile_with({0, 0.3, 0, 0, 0}, {}, 5.0),
                                                params, 1.0);
  ground.soil_at(1, org, 1) = 0.2;   // organic subsoil: lives
  ground.soil_at(0, org, 2) = 1.0;   // rich topsoil: grows to the clamp
  ground.soil_at(0, sand, 3) = 0.0;  // no soil at all: dies
  const auto soil = ground.soil;
  const auto bedrock = ground.bedrock;
  const auto surface = ground.surface;
  auto conversions = gt::no_conversions(3);
  for (std::uint32_t step = 0; step < 20; ++step) {
    ref::vegetation_step(ground, params, step, conversions);
    for (double veg : ground.vegetation) {
      EXPECT_GE(veg, 0.0);
      EXPECT_LE(veg, 1.0);
    }
    EXPECT_EQ(ground.vegetation[0], 0.0);
    EXPECT_EQ(ground.vegetation[3], 0.0);
  }
  EXPECT_GT(ground.vegetation[1], 0.0);
  EXPECT_EQ(ground.vegetation[2], 1.0);
  EXPECT_EQ(ground.soil, soil);
  EXPECT_EQ(ground.bedrock, bedrock);
  EXPECT_EQ(ground.surface, surface);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(conversions.converted_into(i), 0.0);
    EXPECT_EQ(conversions.converted_from(i), 0.0);
  }
}

// The worked column of WorkedColumnByHand, one weathering step (veg 0.5, Δt 0.2, K_conv 0.001:
// K_conv·Δt·veg = 1e-4 m): topsoil sand → org 1e-4 (gravel 0: nothing else); subsoil sand → org
// 1e-4, gravel → sand 0.2e-4 (stones 0: nothing more); the soil (0.7 m) is within the reach, so
// bedrock type 0 gives q = 0.001·0.2·0.5 = 1e-4 m to the subsoil: org 0.2q, stones 0.1q, boulders
// 0.7q. The surface stays. Cell area l_x·l_y = 1 m², so the counts in m³ equal the thicknesses.
// Bound 1e-17: one or two roundings of numbers ≤ 0.3.
TEST(LayeredWeathering, WorkedColumnByHand) {
  const LayeredParams params;
  auto ground = worked_ground(params);
  auto conversions = gt::no_conversions(3);
  const std::size_t c = 4;
  ref::weathering_step(ground, params, 0, conversions);
  const double q = 1e-4;
  EXPECT_NEAR(ground.soil_at(0, org, c), 0.1 + 1e-4, 1e-17);
  EXPECT_NEAR(ground.soil_at(0, sand, c), 0.1 - 1e-4, 1e-17);
  EXPECT_NEAR(ground.soil_at(1, org, c), 0.05 + 1e-4 + 0.2 * q, 1e-17);
  EXPECT_NEAR(ground.soil_at(1, sand, c), 0.15 + 0.2e-4 - 1e-4, 1e-17);
  EXPECT_NEAR(ground.soil_at(1, 2, c), 0.3 - 0.2e-4, 1e-17);
  EXPECT_NEAR(ground.soil_at(1, 3, c), 0.1 * q, 1e-17);
  EXPECT_NEAR(ground.soil_at(1, boulders, c), 0.7 * q, 1e-17);
  EXPECT_NEAR(ground.bedrock_at(0, c), 5.0 - q, 1e-15);
  EXPECT_EQ(ground.bedrock_at(1, c), 5.0);
  EXPECT_EQ(ground.surface[c], 10.0);
  const double cells = 9.0;
  EXPECT_NEAR(conversions.weathered_from[sand], cells * 2e-4, 1e-16);
  EXPECT_NEAR(conversions.weathered_into[org], cells * 2e-4, 1e-16);
  EXPECT_NEAR(conversions.weathered_from[2], cells * 0.2e-4, 1e-17);
  EXPECT_EQ(conversions.weathered_from[boulders], 0.0);
  EXPECT_NEAR(conversions.soil_formed_from[0], cells * q, 1e-16);
  EXPECT_EQ(conversions.soil_formed_from[1], 0.0);
  EXPECT_NEAR(conversions.soil_formed_into[boulders], cells * 0.7 * q, 1e-16);
}

// Each amount is clamped to its source (the code's clamp; the thesis has none): 1e-6 m of boulders
// against 0.4·1e-4 asked leaves exactly 0, never a negative thickness. No vegetation, no weathering.
TEST(LayeredWeathering, ClampsToTheSourceAndNeedsVegetation) {
  LayeredParams params;
  auto ground = gt::make_layered_ground<double>(flat_surface(2, 1, 0.0), profile_with({0, 0, 0, 0, 1e-6}, {}, 5.0),
                                                params, 0.5);
  ground.vegetation[1] = 0.0;
  const auto bare = ground;
  auto conversions = gt::no_conversions(3);
  ref::weathering_step(ground, params, 0, conversions);
  EXPECT_EQ(ground.soil_at(0, boulders, 0), 0.0);
  EXPECT_EQ(ground.soil_at(0, 3, 0), 1e-6);
  EXPECT_EQ(conversions.weathered_from[boulders], 1e-6);
  for (std::size_t i = 0; i < ground.soil.size(); ++i) {
    if (i % 2 == 1) {
      EXPECT_EQ(ground.soil[i], bare.soil[i]) << i;  // column 1 (no vegetation) untouched
    }
  }
  EXPECT_EQ(ground.bedrock_at(0, 1), 5.0);
}

// Bedrock turns into soil only under less soil than the reach (4.0 m, strict), from the top
// non-empty bedrock layer (an emptied layer is skipped), at the type's rate (type 2: none).
TEST(LayeredWeathering, BedrockTurnsIntoSoilOnlyWithinReach) {
  LayeredParams params;
  LayeredProfile profile = profile_with({}, {}, 0.0);
  profile.bedrock = {{0, 0.0}, {1, 5.0}, {0, 5.0}};
  auto ground = gt::make_layered_ground<double>(flat_surface(4, 1, 0.0), profile, params, 1.0);
  const std::array<double, 4> soil{3.9, 4.0, 4.1, 0.0};
  for (int x = 0; x < 4; ++x) ground.soil_at(1, org, static_cast<std::size_t>(x)) = soil[static_cast<std::size_t>(x)];
  ground.bedrock_type[ground.bedrock_index(1, 3)] = 2;  // granite forms no soil
  auto conversions = gt::no_conversions(3);
  ref::weathering_step(ground, params, 0, conversions);
  const double q = 0.0003 * 0.2 * 1.0;  // type 1
  EXPECT_NEAR(ground.bedrock_at(1, 0), 5.0 - q, 1e-15);
  EXPECT_EQ(ground.bedrock_at(1, 1), 5.0);
  EXPECT_EQ(ground.bedrock_at(1, 2), 5.0);
  EXPECT_EQ(ground.bedrock_at(1, 3), 5.0);
  EXPECT_EQ(ground.bedrock_at(2, 0), 5.0);
  EXPECT_NEAR(ground.soil_thickness(1, 0), 3.9 + q, 1e-15);
  EXPECT_NEAR(ground.soil_at(1, boulders, 0), 0.8 * q, 1e-18);
  EXPECT_EQ(conversions.soil_formed_from[0], 0.0);
  EXPECT_NEAR(conversions.soil_formed_from[1], q, 1e-18);
  EXPECT_EQ(conversions.soil_formed_from[2], 0.0);
  // The q-thick slice of rock formed q of soil: the surface is where it was.
  for (double h : ground.surface) EXPECT_EQ(h, 0.0);
}

// The ledger with every process: S = 60 iterations of creep, talus, vegetation and weathering (the
// code's order, §4) on random_terrain, with weathering 50× the code's rate so that every conversion
// is large. For each component, V(end) − V(start) = Σ converted in − Σ converted out, for each
// bedrock type V(end) − V(start) = −(fragmented + formed into soil). Error model: creep and talus's R = 32
// roundings per stored value and step (above), plus weathering's: 2 per component and layer for
// the breakdown ((V + in) − out), 1 for the subsoil's share of the formed soil and 1 for the bedrock:
// R = 36, so the relative drift is at most S·R·2·u (what moved bounded by the total): double
// 60·36·2·1.1e-16 = 4.8e-13, float 2.6e-4. The conversions themselves are counted exactly in
// double from the amounts the column used.
template <class Real>
void run_full_ledger_case(gt::LayeredBorder border, gt::VegetationQuality quality) {
  LayeredParams params;
  params.border = border;
  params.vegetation_quality = quality;
  params.weathering_rate = 0.05;
  for (auto& type : params.bedrock_types) type.soil_rate *= 50.0;
  auto ground = random_terrain<Real>(24, params, 13);
  const std::size_t types = params.bedrock_types.size();
  const gt::LayeredLedger initial = gt::layered_ledger(ground, types);
  gt::LayeredConversions conversions = gt::no_conversions(types);
  constexpr int steps = 60;
  const double tolerance = steps * 36.0 * 2.0 * std::numeric_limits<Real>::epsilon() / 2.0;
  for (int step = 0; step < steps; ++step) {
    const auto s = static_cast<std::uint32_t>(step);
    ref::layered_iteration(ground, params, s, conversions);
    ASSERT_NO_THROW(gt::check_layered_ground(ground, params)) << "step " << step;  // ≥ 0, veg in [0, 1]
  }
  const gt::LayeredLedger final_ledger = gt::layered_ledger(ground, types);
  for (int component = 0; component < 5; ++component) {
    const auto i = static_cast<std::size_t>(component);
    const double expected = initial.components[i] + conversions.converted_into(component) -
                            conversions.converted_from(component);
    const double scale = initial.components[i] + conversions.converted_into(component);
    EXPECT_NEAR(final_ledger.components[i], expected, tolerance * scale) << gt::soil_component_name(component);
  }
  for (std::size_t type = 0; type < types; ++type) {
    EXPECT_NEAR(final_ledger.bedrock[type], initial.bedrock[type] - conversions.bedrock_converted(type),
                tolerance * initial.bedrock[type])
        << "bedrock type " << type;
  }
  EXPECT_NEAR(final_ledger.total(), initial.total(), tolerance * initial.total());
  // Every kind of conversion happened; weathering is the only source of organic matter.
  EXPECT_GT(conversions.weathered_into[org], 0.0);
  EXPECT_GT(conversions.weathered_from[boulders], 0.0);
  EXPECT_GT(conversions.soil_formed_from[0], 0.0);
  EXPECT_GT(conversions.soil_formed_into[org], 0.0);
  EXPECT_EQ(conversions.soil_formed_from[2], 0.0);
  EXPECT_EQ(conversions.fragmented_into[org], 0.0);
}

TEST(LayeredLedger, EveryMaterialWithWeatheringAndVegetationDouble) {
  run_full_ledger_case<double>(gt::LayeredBorder::closed, gt::VegetationQuality::thesis);
}

TEST(LayeredLedger, EveryMaterialWithWeatheringAndVegetationPeriodicCode) {
  run_full_ledger_case<double>(gt::LayeredBorder::periodic, gt::VegetationQuality::seed001_code);
}

TEST(LayeredLedger, EveryMaterialWithWeatheringAndVegetationFloat) {
  run_full_ledger_case<float>(gt::LayeredBorder::closed, gt::VegetationQuality::thesis);
}

}  // namespace
