// The parameters and setup of a layered-ground case (see layered_case.hpp).
#include "compare/layered_case.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "reference/erosion/layered/iteration.hpp"

namespace gt {
namespace {

using Shares = std::array<double, soil_component_count>;

const std::vector<std::string> soil_names = {"loam", "sand", "scree", "organic", "sand_over_stones", "bare",
                                             "seed001_code"};
constexpr std::size_t most_profiles = 4;  // soil, soil_1 .. soil_3
constexpr int granite = 2;                 // the code's third bedrock type

// The topsoil's and subsoil's component shares of a named soil (not seed001_code).
std::array<Shares, soil_layer_count> soil_shares(const std::string& soil) {
  if (soil == "sand") return {Shares{0, 1, 0, 0, 0}, Shares{0, 1, 0, 0, 0}};
  if (soil == "scree") return {Shares{0, 0.1, 0.3, 0.3, 0.3}, Shares{0, 0.1, 0.3, 0.3, 0.3}};
  if (soil == "organic") return {Shares{1, 0, 0, 0, 0}, Shares{1, 0, 0, 0, 0}};
  if (soil == "sand_over_stones") return {Shares{0, 1, 0, 0, 0}, Shares{0, 0, 0, 1, 0}};
  if (soil == "bare") return {Shares{}, Shares{}};
  return {Shares{0.4, 0.3, 0.15, 0.1, 0.05}, Shares{0.1, 0.35, 0.25, 0.2, 0.1}};
}

// Digest 001 §3.18 [code]: every column's initial layers, thicknesses as given (m).
LayeredProfile seed001_code_profile(const LayeredCaseParams& params) {
  LayeredProfile profile;
  profile.topsoil = {0.9, 0.25, 0.1, 0.0, 0.0};
  profile.subsoil = {1.25, 0.25, 0.5, 0.25, 0.0};
  profile.bedrock = {{0, 3.0}, {1, 10.0}, {granite, params.hard_rock_thickness}};
  return profile;
}

LayeredProfile profile_named(const std::string& soil, const LayeredCaseParams& params) {
  if (soil == "seed001_code") return seed001_code_profile(params);
  const auto shares = soil_shares(soil);
  LayeredProfile profile;
  for (std::size_t component = 0; component < shares[0].size(); ++component) {
    profile.topsoil[component] = shares[0][component] * params.topsoil_thickness;
    profile.subsoil[component] = shares[1][component] * params.subsoil_thickness;
  }
  profile.bedrock = {{0, params.soft_rock_thickness}, {1, params.hard_rock_thickness}};
  return profile;
}

// soil, then soil_1 .. soil_3 up to the last one named; a gap is refused.
std::vector<std::string> named_soils(const LayeredCaseParams& params) {
  std::vector<std::string> soils{params.soil};
  std::size_t last = 0;
  for (std::size_t i = 0; i < params.more_soils.size(); ++i) {
    if (params.more_soils[i] != "none") last = i + 1;
  }
  for (std::size_t i = 0; i < last; ++i) {
    if (params.more_soils[i] == "none") {
      throw InputError(fmt::format("erosion.layered: soil_{} is none but soil_{} names a profile: name them in order",
                                   i + 1, last));
    }
    soils.push_back(params.more_soils[i]);
  }
  return soils;
}

// Pads each profile below with empty granite layers to the most bedrock layers among them.
void pad_bedrock(std::vector<LayeredProfile>& profiles) {
  std::size_t most = 0;
  for (const auto& profile : profiles) most = std::max(most, profile.bedrock.size());
  for (auto& profile : profiles) profile.bedrock.resize(most, {granite, 0.0});
}

// The "profile" field as indices into `count` profiles: each value a whole number in [0, count).
std::vector<std::int32_t> profile_map(const Heightmap& field, std::size_t count) {
  std::vector<std::int32_t> indices(field.size());
  for (std::size_t c = 0; c < field.size(); ++c) {
    const double value = field.values[c];
    if (value != std::floor(value) || value < 0.0 || value >= double(count)) {
      throw InputError(fmt::format("erosion.layered: the profile field holds {} at cell ({}, {}); its values name the "
                                   "profiles 0 .. {} (soil{}), whole numbers",
                                   value, c % std::size_t(field.width), c / std::size_t(field.width), count - 1,
                                   count > 1 ? fmt::format(" .. soil_{}", count - 1) : std::string()));
    }
    indices[c] = static_cast<std::int32_t>(value);
  }
  return indices;
}

LayeredColumns columns_from(const LayeredCaseParams& params, const std::vector<std::string>& soils,
                            const std::map<std::string, Heightmap>& fields) {
  LayeredColumns columns;
  for (const auto& soil : soils) columns.profiles.push_back(profile_named(soil, params));
  pad_bedrock(columns.profiles);
  const auto profile = fields.find("profile");
  if (profile != fields.end()) {
    columns.profile_of = profile_map(profile->second, soils.size());
  } else if (soils.size() > 1) {
    throw InputError("erosion.layered: soil_1 names a profile, but no input field 'profile' says which column takes it");
  }
  const auto vegetation = fields.find("vegetation");
  columns.vegetation = vegetation != fields.end() ? vegetation->second.values : std::vector<double>{params.vegetation};
  return columns;
}

// The surface raised by the "obstacle" field (m, each value >= 0): the column's layers hang from
// the raised surface, so an obstacle is made of the profile its columns take.
Heightmap raised_by_obstacles(Heightmap surface, const std::map<std::string, Heightmap>& fields) {
  const auto obstacle = fields.find("obstacle");
  if (obstacle == fields.end()) return surface;
  for (std::size_t c = 0; c < surface.size(); ++c) {
    const double height = obstacle->second.values[c];
    if (!(height >= 0.0)) {
      throw InputError(fmt::format("erosion.layered: the obstacle field holds {} m at cell ({}, {}); an obstacle "
                                   "raises the surface by a height >= 0",
                                   height, c % std::size_t(surface.width), c / std::size_t(surface.width)));
    }
    surface.values[c] += height;
  }
  return surface;
}

}  // namespace

const ParamTable<LayeredCaseParams>& layered_case_param_table() {
  using C = LayeredCaseParams;
  static const ParamTable<C> table = [] {
    ParamTable<C> rows = nested(&C::layered, layered_param_table());
    std::vector<std::string> more_names = soil_names;
    more_names.insert(more_names.begin(), "none");
    ParamTable<C> profile = {
        integer_param("steps", &C::steps, 1, 100000, "count",
                      "iterations of creep, talus, vegetation, weathering (and the water's processes when water is "
                      "given)"),
        choice_param("soil", &C::soil, soil_names, "",
                     "the initial profile (value 0 of the profile field): topsoil's and subsoil's composition, or "
                     "bare rock, or the seed code's whole profile"),
    };
    for (std::size_t i = 0; i < most_profiles - 1; ++i) {
      profile.push_back(choice_param(fmt::format("soil_{}", i + 1), element(&C::more_soils, i), more_names, "",
                                     fmt::format("the profile value {} of the profile input field names", i + 1)));
    }
    const ParamTable<C> thicknesses = {
        real_param("topsoil_thickness", &C::topsoil_thickness, 0.0, 1e3, "m", "initial topsoil (at most topsoil_max)"),
        real_param("subsoil_thickness", &C::subsoil_thickness, 0.0, 1e4, "m", "initial subsoil"),
        real_param("soft_rock_thickness", &C::soft_rock_thickness, 0.0, 1e5, "m", "bedrock type 0 under the soil"),
        real_param("hard_rock_thickness", &C::hard_rock_thickness, 0.0, 1e6, "m",
                   "bedrock type 1 under the soft rock (never falls)"),
        real_param("vegetation", &C::vegetation, 0.0, 1.0, "1",
                   "initial vegetation density (the vegetation input field gives one per column)"),
    };
    rows.insert(rows.end(), profile.begin(), profile.end());
    rows.insert(rows.end(), thicknesses.begin(), thicknesses.end());
    return rows;
  }();
  return table;
}

const ParamSpecs& layered_case_param_specs() {
  static const ParamSpecs specs = param_specs(layered_case_param_table());
  return specs;
}

std::vector<InputFieldSpec> layered_input_fields() {
  return {{"profile", "index",
           "which profile each column starts with: 0 is the soil parameter's, 1 .. 3 soil_1 .. soil_3's (each profile "
           "brings its bedrock)"},
          {"vegetation", "1", "the initial vegetation density of each column, in [0, 1]"},
          {"obstacle", "m",
           "raises each column's surface by this height (>= 0): a block made of the profile its columns take"}};
}

LayeredSetup layered_setup(const LayeredCaseParams& params, const Heightmap& surface,
                           const std::map<std::string, Heightmap>& fields) {
  if (surface.size() == 0) throw InputError("erosion.layered lays its ground on a heightmap: the case needs an input");
  if (std::find(surface.valid.begin(), surface.valid.end(), std::uint8_t{0}) != surface.valid.end()) {
    throw InputError("erosion.layered: the input has no-data cells, which the layered ground cannot hold yet; crop it "
                     "to a window without them");
  }
  LayeredSetup setup;
  setup.params = params.layered;
  setup.soils = named_soils(params);
  setup.columns = columns_from(params, setup.soils, fields);
  setup.steps = params.steps;
  setup.surface = raised_by_obstacles(surface, fields);
  setup.surface.valid.clear();  // every cell valid (a crop of a masked file keeps its all-valid mask)
  // Refuses a bad profile, map, surface or a grid beyond memory before the run (the double ground
  // is the larger).
  validate_layered_inputs(setup.surface, setup.columns, setup.params);
  return setup;
}

LayeredSetup layered_setup(const nlohmann::json& resolved, const Heightmap& surface,
                           const std::map<std::string, Heightmap>& fields) {
  return layered_setup(params_from_json(layered_case_param_table(), resolved), surface, fields);
}

LayeredOutcome run_layered_reference(const LayeredSetup& setup) {
  LayeredOutcome outcome{make_layered_ground<double>(setup.surface, setup.columns, setup.params), {}};
  if (has_water(setup.params)) outcome.water = make_layered_water<double>(outcome.ground.cells(), setup.params.initial_water);
  auto conversions = no_conversions(setup.params.bedrock_types.size());
  for (int step = 0; step < setup.steps; ++step) {
    reference::layered_iteration(outcome.ground, setup.params, static_cast<std::uint32_t>(step), conversions,
                                 outcome.water ? &*outcome.water : nullptr);
  }
  return outcome;
}

}  // namespace gt
