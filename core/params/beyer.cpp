// Parameter table of erosion.beyer and the kernel constants from it (see beyer.hpp).
#include "core/params/beyer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"

namespace gt {
namespace {

constexpr Choice<BeyerSpeedRule> speed_rule_choices[] = {{"physical", BeyerSpeedRule::physical},
                                                         {"printed", BeyerSpeedRule::printed}};

// The kernel's constants but the quantum, which the heights give. The thesis gives no defaults
// (§2.7): these are this project's. Ranges keep the kernel meaningful: inertia and evaporation below
// 1 (0.99 at most); "must be positive" is a lower bound of 1e-6.
ParamTable<BeyerConstants> kernel_rows() {
  using K = BeyerConstants;
  return {
      integer_param("iterations", &K::iterations, 0, 1000, "count",
                    "outer iterations of Algorithm 7: each releases one droplet per texel in spacing² passes"),
      integer_param("lifetime", &K::lifetime, 1, 500, "steps", "steps of one droplet (p_maxPath)"),
      integer_param("spacing", &K::spacing, 1, 1024, "texel",
                    "one droplet per spacing x spacing block and pass; disjoint needs spacing > 2·(lifetime + "
                    "ceil(radius) + 2)"),
      real_param("inertia", &K::inertia, 0.0, 0.99, "1", "c_i (p_inertia): share of the old direction kept, eq. 2.36"),
      real_param("capacity_factor", &K::capacity_factor, 1e-6, 1e3, "step/texel",
                 "c_c (p_capacity): capacity = c_c·max(-Δh, c_min)·v·w, eq. 2.39"),
      real_param("min_slope", &K::min_slope, 0.0, 1.0, "height",
                 "c_min (p_minSlope): the height difference the capacity assumes at least, eq. 2.39"),
      real_param("deposition", &K::deposition, 0.0, 1.0, "1",
                 "c_d (p_deposition): share of the surplus over capacity deposited, eq. 2.40"),
      real_param("erosion", &K::erosion, 0.0, 1.0, "1",
                 "c_e of eq. 2.41 (p_erosion): share of the free capacity eroded"),
      real_param("gravity", &K::gravity, 0.0, 100.0, "(texel/step)²/height", "c_g (p_gravity), eq. 2.44"),
      real_param("evaporation", &K::evaporation, 0.0, 0.99, "1",
                 "c_e of eq. 2.45 (p_evaporation): share of the water lost per step"),
      real_param("radius", &K::radius, 1.0, 8.0, "texel", "c_r (p_radius): radius of the erosion brush, eq. 2.42"),
      real_param("initial_speed", &K::initial_speed, 0.0, 100.0, "texel/step", "a new droplet's speed v_0"),
      real_param("initial_water", &K::initial_water, 1e-6, 100.0, "1", "a new droplet's water w_0"),
      real_param("blur_blend", &K::blur_blend, 0.0, 1.0, "1",
                 "c_b of eq. 2.43: after each outer iteration the heights become c_b·(3x3 box blur) + (1 - c_b)·"
                 "heights, exchanged between neighbours so that the volume is kept; 0 is off"),
      choice_param("speed_rule", &K::speed_rule, speed_rule_choices, "",
                   "eq. 2.44: physical v = sqrt(max(v² - Δh·c_g, 0)) (downhill speeds up), "
                   "or printed v = sqrt(max(v² + Δh·c_g, 0))"),
      integer_param("seed", &K::seed, 0, 4294967295.0, "1",
                    "of the counter RNG that picks one of 8 compass directions where eq. 2.36 gives the direction 0"),
      choice_param("ordering", &K::ordering, droplet_ordering_choices, "",
                   "droplets of one pass: race (all at once; compared statistically), "
                   "disjoint (spacing keeps them apart; exact), batch (frozen heights and a fixed-point delta; "
                   "bit-exact at any spacing)"),
  };
}

}  // namespace

const char* beyer_speed_rule_name(BeyerSpeedRule rule) { return choice_name(speed_rule_choices, rule); }

int beyer_reach(const BeyerConstants& constants) {
  return constants.lifetime + static_cast<int>(std::ceil(constants.radius)) + 2;
}

const ParamTable<BeyerParams>& beyer_param_table() {
  static const ParamTable<BeyerParams> table = [] {
    ParamTable<BeyerParams> rows = nested(&BeyerParams::kernel, kernel_rows());
    rows.push_back(boolean_param("normalised", &BeyerParams::normalised,
                                 "seed 000's heights (h - min)/(max - min) in [0, 1], in which min_slope and the "
                                 "capacity are given; off: the input's heights as they are"));
    return rows;
  }();
  return table;
}

const ParamSpecs& beyer_param_specs() {
  static const ParamSpecs specs = param_specs(beyer_param_table());
  return specs;
}

BeyerParams beyer_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(beyer_param_table(), resolved);
}

BeyerConstants beyer_constants(const nlohmann::json& resolved, const Heightmap& heights) {
  BeyerConstants constants = beyer_params_from_json(resolved).kernel;
  if (constants.ordering == DropletOrdering::disjoint && constants.spacing <= 2 * beyer_reach(constants)) {
    throw InputError(fmt::format(
        "erosion.beyer: ordering `disjoint` needs spacing > 2·(lifetime + ceil(radius) + 2) = {} so that no two "
        "droplets of a pass meet; spacing is {} (use `race` or `batch`, or a spacing of at least {})",
        2 * beyer_reach(constants), constants.spacing, 2 * beyer_reach(constants) + 1));
  }
  // Mutant (both twins read their constants here): erosion.beyer.capacity_doubled takes 2·c_c, a
  // conserving error of the law that only the hand-derived droplet (spec.droplet.*) sees.
  if (mutant_active("erosion.beyer.capacity_doubled")) constants.capacity_factor *= 2.0;
  const auto [low, high] = valid_range(heights);
  constants.quantum = batch_quantum(low > high ? 0.0 : std::max(std::abs(low), std::abs(high)));
  return constants;
}

}  // namespace gt
