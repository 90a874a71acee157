#include "core/params/planet.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

template <class Enum, std::size_t count>
Enum choice_of(const nlohmann::json& resolved, const char* key, const std::pair<const char*, Enum> (&names)[count]) {
  const auto text = resolved.at(key).get<std::string>();
  for (const auto& [name, value] : names) {
    if (text == name) return value;
  }
  throw InputError(fmt::format("{}: unknown value '{}'", key, text));
}

constexpr std::pair<const char*, PlateRule> plate_rules[] = {{"synchronous", PlateRule::synchronous},
                                                             {"legacy", PlateRule::legacy},
                                                             {"legacy_random", PlateRule::legacy_random}};
constexpr std::pair<const char*, PlateCentre> centres[] = {{"mean", PlateCentre::mean},
                                                           {"edge_sum", PlateCentre::edge_sum}};
constexpr std::pair<const char*, PressureFormula> pressures[] = {{"code", PressureFormula::code},
                                                                 {"thesis", PressureFormula::thesis}};
constexpr std::pair<const char*, PlateBases> plate_bases[] = {{"uniform", PlateBases::uniform},
                                                              {"bimodal", PlateBases::bimodal}};
constexpr std::pair<const char*, Smoothing> smoothings[] = {
    {"jacobi", Smoothing::jacobi}, {"legacy", Smoothing::legacy}, {"off", Smoothing::off}};

}  // namespace

const char* plate_rule_name(PlateRule rule) {
  for (const auto& [name, value] : plate_rules) {
    if (value == rule) return name;
  }
  return "?";
}

const char* smoothing_name(Smoothing smoothing) {
  for (const auto& [name, value] : smoothings) {
    if (value == smoothing) return name;
  }
  return "?";
}

PlateRateBounds plate_rate_bounds(const PlanetParams& params) {
  PlateRateBounds bounds;
  bounds.low = static_cast<float>(std::max(0.0, 1.0 - params.expansion_range));
  bounds.high = static_cast<float>(1.0 + params.expansion_range);
  bounds.max_expansions = static_cast<int>(std::floor(bounds.high)) + 1;
  return bounds;
}

const ParamSpecs& planet_param_specs() {
  static const ParamSpecs specs = {
      {"resolution", ParamKind::integer, 50, 1, 300, {}, "count", "R: cells along a cube face's edge; 6R² regions"},
      {"seed", ParamKind::integer, 1, 0, 4294967295.0, {}, "1",
       "counter-RNG seed of every draw (§9.2); also the Perlin permutation's (0 = Perlin's reference table)"},
      {"jitter", ParamKind::real, 1.0, 0.0, 1.0, {}, "1", "j of eq. 5.1: 0 = cell centres, 1 = anywhere in the cell"},
      {"plates", ParamKind::integer, 50, 1, 500, {}, "count", "plateNumber: at most 6R²"},
      {"expansion_range", ParamKind::real, 0.5, 0.0, 5.0, {}, "1",
       "e: plate rates uniform in [max(0, 1 − e), 1 + e] rings per cycle (the code's formula)"},
      {"plate_rule", ParamKind::choice, "synchronous", 0, 0, {"synchronous", "legacy", "legacy_random"}, "",
       "synchronous ring-BFS with the lowest-index rule (both twins), the seed code's sequential first-come fill "
       "(CPU only), or its random-driven variant: one random plate per pick (CPU only)"},
      {"centre", ParamKind::choice, "mean", 0, 0, {"mean", "edge_sum"}, "",
       "plate centre: normalised mean of all members (thesis) or of the edge members (code)"},
      {"elevation_range", ParamKind::real, 0.8, 0.0, 1.0, {}, "1", "e_r: plate base elevations uniform in [−e_r, e_r]"},
      {"plate_bases", ParamKind::choice, "uniform", 0, 0, {"uniform", "bimodal"}, "",
       "plate base elevations uniform in [−e_r, e_r] (the seed), or oceanic plates in [−e_r, −e_r/2] and continental "
       "ones in [0, e_r/4] (Earth-like hypsometry)"},
      {"ocean_share", ParamKind::real, 0.7, 0.0, 1.0, {}, "1", "with bimodal bases: the probability that a plate is oceanic"},
      {"collisions", ParamKind::boolean, true, 0, 0, {}, "", "usePlateCollisions: pressure at plate borders"},
      {"collision_strength", ParamKind::real, 0.5, 0.0, 10.0, {}, "1", "C of eq. 5.3"},
      {"pressure", ParamKind::choice, "code", 0, 0, {"code", "thesis"}, "",
       "pressure formula: the code's (normalised direction, chord velocity) or eq. 5.3's"},
      {"noise", ParamKind::boolean, true, 0, 0, {}, "", "usePerlin: add fBm of improved Perlin noise"},
      {"perlin_frequency", ParamKind::real, 15.0, 0.1, 100.0, {}, "1", "f: noise sampled at f·position"},
      {"perlin_octaves", ParamKind::integer, 1, 1, 10, {}, "count", "o: octaves of normalizedOctaveNoise3D"},
      {"perlin_strength", ParamKind::real, 0.2, 0.0, 10.0, {}, "1", "S: noise amplitude (the code's 0.2; the thesis says 2.0)"},
      {"smoothing", ParamKind::choice, "jacobi", 0, 0, {"jacobi", "legacy", "off"}, "",
       "mean of each region and its neighbours (thesis, both twins), the code's sequential halving blend (CPU only), "
       "or none"},
      {"smooth_only_with_collisions", ParamKind::boolean, false, 0, 0, {}, "",
       "the code's rule: smooth only when collisions are on"},
  };
  return specs;
}

PlanetParams planet_params_from_json(const nlohmann::json& resolved) {
  PlanetParams params;
  params.resolution = resolved.at("resolution").get<int>();
  params.seed = resolved.at("seed").get<std::uint32_t>();
  params.jitter = resolved.at("jitter").get<double>();
  params.plates = resolved.at("plates").get<int>();
  params.expansion_range = resolved.at("expansion_range").get<double>();
  params.plate_rule = choice_of(resolved, "plate_rule", plate_rules);
  params.centre = choice_of(resolved, "centre", centres);
  params.elevation_range = resolved.at("elevation_range").get<double>();
  params.plate_bases = choice_of(resolved, "plate_bases", plate_bases);
  params.ocean_share = resolved.at("ocean_share").get<double>();
  params.collisions = resolved.at("collisions").get<bool>();
  params.collision_strength = resolved.at("collision_strength").get<double>();
  params.pressure = choice_of(resolved, "pressure", pressures);
  params.noise = resolved.at("noise").get<bool>();
  params.perlin_frequency = resolved.at("perlin_frequency").get<double>();
  params.perlin_octaves = resolved.at("perlin_octaves").get<int>();
  params.perlin_strength = resolved.at("perlin_strength").get<double>();
  params.smoothing = choice_of(resolved, "smoothing", smoothings);
  params.smooth_only_with_collisions = resolved.at("smooth_only_with_collisions").get<bool>();
  if (params.plates > params.region_count()) {
    throw InputError(fmt::format("plates = {} exceeds the {} regions of resolution {} (6R²)", params.plates,
                                 params.region_count(), params.resolution));
  }
  return params;
}

}  // namespace gt
