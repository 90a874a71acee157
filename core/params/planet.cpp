// Parameter table of planet.earth_like and the plate rate bounds (see planet.hpp).
#include "core/params/planet.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"

namespace gt {
namespace {

constexpr Choice<PlateRule> plate_rule_choices[] = {{"synchronous", PlateRule::synchronous},
                                                    {"legacy", PlateRule::legacy},
                                                    {"legacy_random", PlateRule::legacy_random}};
constexpr Choice<PlateCentre> centre_choices[] = {{"mean", PlateCentre::mean}, {"edge_sum", PlateCentre::edge_sum}};
constexpr Choice<PressureFormula> pressure_choices[] = {{"code", PressureFormula::code},
                                                        {"thesis", PressureFormula::thesis}};
constexpr Choice<RateFormula> rate_formula_choices[] = {{"code", RateFormula::code}, {"thesis", RateFormula::thesis}};
constexpr Choice<PlateBases> plate_bases_choices[] = {{"uniform", PlateBases::uniform},
                                                      {"bimodal", PlateBases::bimodal}};
constexpr Choice<Smoothing> smoothing_choices[] = {
    {"jacobi", Smoothing::jacobi}, {"legacy", Smoothing::legacy}, {"off", Smoothing::off}};
constexpr Choice<PlanetWarp> warp_choices[] = {
    {"none", PlanetWarp::none}, {"tangent", PlanetWarp::tangent}, {"optimised", PlanetWarp::optimised}};

}  // namespace

CubeWarp cube_warp(PlanetWarp warp) {
  switch (warp) {
    case PlanetWarp::none: return no_warp;
    // Mutant planet.cube_sphere.tangent_eighth_turn (both twins share this): θ = π/8 for eq. 3.4's π/4.
    case PlanetWarp::tangent: return {std::atan(1.0) * (mutant_active("planet.cube_sphere.tangent_eighth_turn") ? 0.5 : 1.0)};
    case PlanetWarp::optimised: break;
  }
  return {warp_angle};
}

const char* planet_warp_name(PlanetWarp warp) { return choice_name(warp_choices, warp); }

const char* plate_rule_name(PlateRule rule) { return choice_name(plate_rule_choices, rule); }

const char* smoothing_name(Smoothing smoothing) { return choice_name(smoothing_choices, smoothing); }

PlateRateBounds plate_rate_bounds(const PlanetParams& params) {
  PlateRateBounds bounds;
  const double e = params.expansion_range;
  // Mutant planet.plates.thesis_rate_as_code (both twins take their bounds here): the thesis's
  // formula asked, the code's upper bound 1 + e used for e > 1.
  const bool thesis_above_one = params.rate_formula == RateFormula::thesis && e > 1.0;
  const bool code_high = !thesis_above_one || mutant_active("planet.plates.thesis_rate_as_code");
  bounds.low = static_cast<float>(std::max(0.0, 1.0 - e));
  bounds.high = static_cast<float>(code_high ? 1.0 + e : e);
  bounds.max_expansions = static_cast<int>(std::floor(bounds.high)) + 1;
  return bounds;
}

const ParamTable<PlanetParams>& planet_param_table() {
  using P = PlanetParams;
  static const ParamTable<P> table = {
      integer_param("resolution", &P::resolution, 1, 300, "count", "R: cells along a cube face's edge; 6R² regions"),
      integer_param("seed", &P::seed, 0, 4294967295.0, "1",
                    "counter-RNG seed of every draw (§9.2); also the Perlin permutation's (0 = Perlin's reference "
                    "table)"),
      real_param("jitter", &P::jitter, 0.0, 1.0, "1", "j of eq. 5.1: 0 = cell centres, 1 = anywhere in the cell"),
      choice_param("warp", &P::warp, warp_choices, "",
                   "cube-to-sphere warp: none (the identity), tangent (eq. 3.4, tan(πt/4)) or optimised (eq. 3.5, "
                   "θ = 0.868734829276)"),
      integer_param("plates", &P::plates, 1, 500, "count", "plateNumber: at most 6R²"),
      real_param("expansion_range", &P::expansion_range, 0.0, 5.0, "1",
                 "e: plate rates uniform in [max(0, 1 − e), 1 + e] rings per cycle (the code's formula)"),
      choice_param("rate_formula", &P::rate_formula, rate_formula_choices, "",
                   "plate rates: the code's U[max(0, 1 − e), 1 + e], or the thesis's U[1 − e, 1 + e] for e < 1 and "
                   "U[0, e] for e > 1 (undefined at e = 1)"),
      choice_param("plate_rule", &P::plate_rule, plate_rule_choices, "",
                   "synchronous ring-BFS with the lowest-index rule (both twins), "
                   "the seed code's sequential first-come fill (CPU only), or its random-driven variant: one random "
                   "plate per pick (CPU only)"),
      choice_param("centre", &P::centre, centre_choices, "",
                   "plate centre: normalised mean of all members (thesis) or of the edge members (code)"),
      real_param("elevation_range", &P::elevation_range, 0.0, 1.0, "1",
                 "e_r: plate base elevations uniform in [−e_r, e_r]"),
      choice_param("plate_bases", &P::plate_bases, plate_bases_choices, "",
                   "plate base elevations uniform in [−e_r, e_r] (the seed), or oceanic plates in [−e_r, "
                   "−e_r/2] and continental ones in [0, e_r/4] (Earth-like hypsometry)"),
      real_param("ocean_share", &P::ocean_share, 0.0, 1.0, "1",
                 "with bimodal bases: the probability that a plate is oceanic"),
      boolean_param("collisions", &P::collisions, "usePlateCollisions: pressure at plate borders"),
      real_param("collision_strength", &P::collision_strength, 0.0, 10.0, "1", "C of eq. 5.3"),
      choice_param("pressure", &P::pressure, pressure_choices, "",
                   "pressure formula: the code's (normalised direction, chord velocity) or eq. 5.3's"),
      boolean_param("noise", &P::noise, "usePerlin: add fBm of improved Perlin noise"),
      real_param("perlin_frequency", &P::perlin_frequency, 0.1, 100.0, "1", "f: noise sampled at f·position"),
      integer_param("perlin_octaves", &P::perlin_octaves, 1, 10, "count", "o: octaves of normalizedOctaveNoise3D"),
      real_param("perlin_strength", &P::perlin_strength, 0.0, 10.0, "1",
                 "S: noise amplitude (the code's 0.2; the thesis says 2.0)"),
      choice_param("smoothing", &P::smoothing, smoothing_choices, "",
                   "mean of each region and its neighbours (thesis, both twins), "
                   "the code's sequential halving blend (CPU only), or none"),
      boolean_param("smooth_only_with_collisions", &P::smooth_only_with_collisions,
                    "the code's rule: smooth only when collisions are on"),
  };
  return table;
}

const ParamSpecs& planet_param_specs() {
  static const ParamSpecs specs = param_specs(planet_param_table());
  return specs;
}

PlanetParams planet_params_from_json(const nlohmann::json& resolved) {
  const PlanetParams params = params_from_json(planet_param_table(), resolved);
  if (params.rate_formula == RateFormula::thesis && params.expansion_range == 1.0) {
    throw InputError("rate_formula = thesis is undefined at expansion_range = 1 (the thesis gives [1 − e, 1 + e] below "
                     "1 and [0, e] above it, and nothing at 1): choose another e, or rate_formula = code");
  }
  if (params.plates > params.region_count()) {
    throw InputError(fmt::format("plates = {} exceeds the {} regions of resolution {} (6R²)", params.plates,
                                 params.region_count(), params.resolution));
  }
  return params;
}

}  // namespace gt
