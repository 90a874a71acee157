// The parameters and setup of a layered-ground case (see layered_case.hpp).
#include "compare/layered_case.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

#include "core/errors.hpp"
#include "reference/erosion/layered/iteration.hpp"

namespace gt {
namespace {

using Shares = std::array<double, soil_component_count>;

std::array<Shares, soil_layer_count> soil_shares(const std::string& soil) {
  if (soil == "sand") return {Shares{0, 1, 0, 0, 0}, Shares{0, 1, 0, 0, 0}};
  if (soil == "scree") return {Shares{0, 0.1, 0.3, 0.3, 0.3}, Shares{0, 0.1, 0.3, 0.3, 0.3}};
  return {Shares{0.4, 0.3, 0.15, 0.1, 0.05}, Shares{0.1, 0.35, 0.25, 0.2, 0.1}};
}

LayeredProfile profile_from(const nlohmann::json& resolved) {
  const auto shares = soil_shares(resolved.at("soil").get<std::string>());
  const double topsoil = resolved.at("topsoil_thickness").get<double>();
  const double subsoil = resolved.at("subsoil_thickness").get<double>();
  LayeredProfile profile;
  for (std::size_t component = 0; component < shares[0].size(); ++component) {
    profile.topsoil[component] = shares[0][component] * topsoil;
    profile.subsoil[component] = shares[1][component] * subsoil;
  }
  profile.bedrock = {{0, resolved.at("soft_rock_thickness").get<double>()},
                     {1, resolved.at("hard_rock_thickness").get<double>()}};
  return profile;
}

}  // namespace

const ParamSpecs& layered_case_param_specs() {
  static const ParamSpecs specs = [] {
    ParamSpecs all = layered_param_specs();
    all.push_back({"steps", ParamKind::integer, 200, 1, 100000, {}, "count",
                   "iterations of creep, talus, vegetation, weathering (and the water's processes when water is given)"});
    all.push_back({"soil", ParamKind::choice, "loam", 0, 0, {"loam", "sand", "scree"}, "",
                   "the initial topsoil's and subsoil's composition"});
    all.push_back({"topsoil_thickness", ParamKind::real, 0.5, 0.0, 1e3, {}, "m", "initial topsoil (at most topsoil_max)"});
    all.push_back({"subsoil_thickness", ParamKind::real, 1.5, 0.0, 1e4, {}, "m", "initial subsoil"});
    all.push_back({"soft_rock_thickness", ParamKind::real, 5.0, 0.0, 1e5, {}, "m", "bedrock type 0 under the soil"});
    all.push_back({"hard_rock_thickness", ParamKind::real, 1000.0, 0.0, 1e6, {}, "m",
                   "bedrock type 1 under the soft rock (never falls)"});
    all.push_back({"vegetation", ParamKind::real, 0.0, 0.0, 1.0, {}, "1", "initial vegetation density"});
    return all;
  }();
  return specs;
}

LayeredSetup layered_setup(const nlohmann::json& resolved, const Heightmap& surface) {
  if (surface.size() == 0) throw InputError("erosion.layered lays its ground on a heightmap: the case needs an input");
  if (std::find(surface.valid.begin(), surface.valid.end(), std::uint8_t{0}) != surface.valid.end()) {
    throw InputError("erosion.layered: the input has no-data cells, which the layered ground cannot hold yet; crop it "
                     "to a window without them");
  }
  LayeredSetup setup;
  setup.params = layered_params_from_json(resolved);
  setup.soil = resolved.at("soil").get<std::string>();
  setup.profile = profile_from(resolved);
  validate_layered_profile(setup.profile, setup.params);
  setup.steps = static_cast<int>(resolved.at("steps").get<long long>());
  setup.vegetation = resolved.at("vegetation").get<double>();
  setup.surface = surface;
  setup.surface.valid.clear();  // every cell valid (a crop of a masked file keeps its all-valid mask)
  // Refuses a bad surface or a grid beyond memory before the run (the double ground is the larger).
  validate_layered_inputs(setup.surface, setup.profile, setup.params, setup.vegetation);
  return setup;
}

LayeredOutcome run_layered_reference(const LayeredSetup& setup) {
  LayeredOutcome outcome{make_layered_ground<double>(setup.surface, setup.profile, setup.params, setup.vegetation), {}};
  if (has_water(setup.params)) outcome.water = make_layered_water<double>(outcome.ground.cells(), setup.params.initial_water);
  auto conversions = no_conversions(setup.params.bedrock_types.size());
  for (int step = 0; step < setup.steps; ++step) {
    reference::layered_iteration(outcome.ground, setup.params, static_cast<std::uint32_t>(step), conversions,
                                 outcome.water ? &*outcome.water : nullptr);
  }
  return outcome;
}

}  // namespace gt
