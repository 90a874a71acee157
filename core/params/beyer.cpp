#include "core/params/beyer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

BeyerSpeedRule speed_rule_from_name(const std::string& name) {
  for (auto candidate : {BeyerSpeedRule::physical, BeyerSpeedRule::printed}) {
    if (name == beyer_speed_rule_name(candidate)) return candidate;
  }
  throw InputError(fmt::format("unknown speed rule '{}'; known: physical, printed", name));
}

}  // namespace

const char* beyer_speed_rule_name(BeyerSpeedRule rule) {
  switch (rule) {
    case BeyerSpeedRule::physical: return "physical";
    case BeyerSpeedRule::printed: return "printed";
  }
  return "?";
}

int beyer_reach(const BeyerConstants& constants) {
  return constants.lifetime + static_cast<int>(std::ceil(constants.radius)) + 2;
}

// The thesis gives no defaults (§2.7): these are this project's. Ranges keep the kernel meaningful:
// inertia and evaporation below 1 (0.99 at most); "must be positive" is a lower bound of 1e-6.
const ParamSpecs& beyer_param_specs() {
  static const ParamSpecs specs = {
      {"iterations", ParamKind::integer, 10, 0, 1000, {}, "count",
       "outer iterations of Algorithm 7: each releases one droplet per texel in spacing² passes"},
      {"lifetime", ParamKind::integer, 30, 1, 500, {}, "steps", "steps of one droplet (p_maxPath)"},
      {"spacing", ParamKind::integer, 4, 1, 1024, {}, "texel",
       "one droplet per spacing x spacing block and pass; disjoint needs spacing > 2·(lifetime + ceil(radius) + 2)"},
      {"inertia", ParamKind::real, 0.05, 0.0, 0.99, {}, "1",
       "c_i (p_inertia): share of the old direction kept, eq. 2.36"},
      {"capacity_factor", ParamKind::real, 4.0, 1e-6, 1e3, {}, "step/texel",
       "c_c (p_capacity): capacity = c_c·max(-Δh, c_min)·v·w, eq. 2.39"},
      {"min_slope", ParamKind::real, 0.01, 0.0, 1.0, {}, "height",
       "c_min (p_minSlope): the height difference the capacity assumes at least, eq. 2.39"},
      {"deposition", ParamKind::real, 0.3, 0.0, 1.0, {}, "1",
       "c_d (p_deposition): share of the surplus over capacity deposited, eq. 2.40"},
      {"erosion", ParamKind::real, 0.3, 0.0, 1.0, {}, "1",
       "c_e of eq. 2.41 (p_erosion): share of the free capacity eroded"},
      {"gravity", ParamKind::real, 4.0, 0.0, 100.0, {}, "(texel/step)²/height", "c_g (p_gravity), eq. 2.44"},
      {"evaporation", ParamKind::real, 0.01, 0.0, 0.99, {}, "1",
       "c_e of eq. 2.45 (p_evaporation): share of the water lost per step"},
      {"radius", ParamKind::real, 3.0, 1.0, 8.0, {}, "texel", "c_r (p_radius): radius of the erosion brush, eq. 2.42"},
      {"initial_speed", ParamKind::real, 1.0, 0.0, 100.0, {}, "texel/step", "a new droplet's speed v_0"},
      {"initial_water", ParamKind::real, 1.0, 1e-6, 100.0, {}, "1", "a new droplet's water w_0"},
      {"speed_rule", ParamKind::choice, "printed", 0, 0, {"physical", "printed"}, "",
       "eq. 2.44: physical v = sqrt(max(v² - Δh·c_g, 0)) (downhill speeds up), or printed v = "
       "sqrt(max(v² + Δh·c_g, 0))"},
      {"seed", ParamKind::integer, 1, 0, 4294967295.0, {}, "1",
       "of the counter RNG that picks one of 8 compass directions where eq. 2.36 gives the direction 0"},
      {"ordering", ParamKind::choice, "batch", 0, 0, {"race", "disjoint", "batch"}, "",
       "droplets of one pass: race (all at once; compared statistically), disjoint (spacing keeps them "
       "apart; exact), batch (frozen heights and a fixed-point delta; bit-exact at any spacing)"},
      {"normalised", ParamKind::boolean, true, 0, 0, {}, "",
       "seed 000's heights (h - min)/(max - min) in [0, 1], in which min_slope and the capacity are given; off: "
       "the input's heights as they are"},
  };
  return specs;
}

BeyerConstants beyer_constants(const nlohmann::json& resolved, const Heightmap& heights) {
  BeyerConstants constants;
  constants.iterations = resolved.at("iterations").get<int>();
  constants.lifetime = resolved.at("lifetime").get<int>();
  constants.spacing = resolved.at("spacing").get<int>();
  constants.inertia = resolved.at("inertia").get<double>();
  constants.capacity_factor = resolved.at("capacity_factor").get<double>();
  constants.min_slope = resolved.at("min_slope").get<double>();
  constants.deposition = resolved.at("deposition").get<double>();
  constants.erosion = resolved.at("erosion").get<double>();
  constants.gravity = resolved.at("gravity").get<double>();
  constants.evaporation = resolved.at("evaporation").get<double>();
  constants.radius = resolved.at("radius").get<double>();
  constants.initial_speed = resolved.at("initial_speed").get<double>();
  constants.initial_water = resolved.at("initial_water").get<double>();
  constants.speed_rule = speed_rule_from_name(resolved.at("speed_rule").get<std::string>());
  constants.seed = resolved.at("seed").get<std::uint32_t>();
  constants.ordering = droplet_ordering_from_name(resolved.at("ordering").get<std::string>());
  if (constants.ordering == DropletOrdering::disjoint && constants.spacing <= 2 * beyer_reach(constants)) {
    throw InputError(fmt::format(
        "erosion.beyer: ordering `disjoint` needs spacing > 2·(lifetime + ceil(radius) + 2) = {} so that no two "
        "droplets of a pass meet; spacing is {} (use `race` or `batch`, or a spacing of at least {})",
        2 * beyer_reach(constants), constants.spacing, 2 * beyer_reach(constants) + 1));
  }
  const auto [low, high] = valid_range(heights);
  constants.quantum = batch_quantum(low > high ? 0.0 : std::max(std::abs(low), std::abs(high)));
  return constants;
}

}  // namespace gt
