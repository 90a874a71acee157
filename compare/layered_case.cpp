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

LayeredProfile profile_from(const LayeredCaseParams& params) {
  const auto shares = soil_shares(params.soil);
  LayeredProfile profile;
  for (std::size_t component = 0; component < shares[0].size(); ++component) {
    profile.topsoil[component] = shares[0][component] * params.topsoil_thickness;
    profile.subsoil[component] = shares[1][component] * params.subsoil_thickness;
  }
  profile.bedrock = {{0, params.soft_rock_thickness}, {1, params.hard_rock_thickness}};
  return profile;
}

}  // namespace

const ParamTable<LayeredCaseParams>& layered_case_param_table() {
  using C = LayeredCaseParams;
  static const ParamTable<C> table = [] {
    ParamTable<C> rows = nested(&C::layered, layered_param_table());
    const ParamTable<C> profile = {
        integer_param("steps", &C::steps, 1, 100000, "count",
                      "iterations of creep, talus, vegetation, weathering (and the water's processes when water is "
                      "given)"),
        choice_param("soil", &C::soil, {"loam", "sand", "scree"}, "",
                     "the initial topsoil's and subsoil's composition"),
        real_param("topsoil_thickness", &C::topsoil_thickness, 0.0, 1e3, "m", "initial topsoil (at most topsoil_max)"),
        real_param("subsoil_thickness", &C::subsoil_thickness, 0.0, 1e4, "m", "initial subsoil"),
        real_param("soft_rock_thickness", &C::soft_rock_thickness, 0.0, 1e5, "m", "bedrock type 0 under the soil"),
        real_param("hard_rock_thickness", &C::hard_rock_thickness, 0.0, 1e6, "m",
                   "bedrock type 1 under the soft rock (never falls)"),
        real_param("vegetation", &C::vegetation, 0.0, 1.0, "1", "initial vegetation density"),
    };
    rows.insert(rows.end(), profile.begin(), profile.end());
    return rows;
  }();
  return table;
}

const ParamSpecs& layered_case_param_specs() {
  static const ParamSpecs specs = param_specs(layered_case_param_table());
  return specs;
}

LayeredSetup layered_setup(const LayeredCaseParams& params, const Heightmap& surface) {
  if (surface.size() == 0) throw InputError("erosion.layered lays its ground on a heightmap: the case needs an input");
  if (std::find(surface.valid.begin(), surface.valid.end(), std::uint8_t{0}) != surface.valid.end()) {
    throw InputError("erosion.layered: the input has no-data cells, which the layered ground cannot hold yet; crop it "
                     "to a window without them");
  }
  LayeredSetup setup;
  setup.params = params.layered;
  setup.soil = params.soil;
  setup.profile = profile_from(params);
  validate_layered_profile(setup.profile, setup.params);
  setup.steps = params.steps;
  setup.vegetation = params.vegetation;
  setup.surface = surface;
  setup.surface.valid.clear();  // every cell valid (a crop of a masked file keeps its all-valid mask)
  // Refuses a bad surface or a grid beyond memory before the run (the double ground is the larger).
  validate_layered_inputs(setup.surface, setup.profile, setup.params, setup.vegetation);
  return setup;
}

LayeredSetup layered_setup(const nlohmann::json& resolved, const Heightmap& surface) {
  return layered_setup(params_from_json(layered_case_param_table(), resolved), surface);
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
