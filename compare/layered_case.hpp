// A case of seed 001's layered ground as the driver states it (compare/algorithms/layered.cpp;
// render.terrain's erode = layered): the parameters of erosion.layered plus the initial profile's,
// and the setup they make on a surface.
//
// Profile parameters (hung from the surface; one profile in every column unless the input's
// "profile" field picks one per column):
//   soil                 the profile: the components' shares (org, sand, gravel, stones, boulders)
//                        of topsoil and subsoil: loam (0.4, 0.3, 0.15, 0.1, 0.05 over 0.1, 0.35,
//                        0.25, 0.2, 0.1), sand (pure sand in both), scree (0, 0.1, 0.3, 0.3, 0.3 in
//                        both), organic (pure organic matter: the thesis's "pure soil"),
//                        sand_over_stones (sand over stones), bare (no soil: bedrock only), and
//                        seed001_code, the code's initial profile with its own thicknesses (topsoil
//                        org 0.9, sand 0.25, gravel 0.1 m; subsoil org 1.25, sand 0.25, gravel 0.5,
//                        stones 0.25 m; 3 m soft rock, 10 m hard rock, then "granite", type 2, as
//                        hard_rock_thickness m in place of the code's 1e6 m, below)
//   soil_1 .. soil_3     the profiles the "profile" field's values 1 .. 3 name (0 is `soil`);
//                        none: not used
//   topsoil_thickness, subsoil_thickness    m; soft_rock_thickness m of bedrock type 0 (the code's
//                        soft rock, tan φ 4, the only one that falls), over hard_rock_thickness m of
//                        type 1 (tan φ 1e7: it never falls; the code makes it 1e6 m, which would
//                        drown the ledger's precision: it only needs to outlast the relief)
//   vegetation           the initial density in [0, 1] on every column (the "vegetation" field
//                        gives one per column instead)
//   steps                iterations (reference/erosion/layered/iteration.hpp)
// Input fields (compare/inputs.hpp; seed 001's spatial inputs): "profile", a whole number 0 .. 3 per
// column naming soil .. soil_3 (a bedrock map is a profile map: each profile brings its bedrock),
// "vegetation", the initial density per column in [0, 1], and "obstacle", a height (m, >= 0) each
// column's surface is raised by (its layers hang from the raised surface, so an obstacle is made
// of the profile its columns take: a profile field names it). Profiles of different bedrock layer
// counts (seed001_code has 3) are padded below with empty granite layers.
// layered_setup(params or resolved, surface, fields) throws InputError for a surface with no-data
// cells (the layered ground holds none; the message names the remedy, a crop), a bad profile,
// parameters, field or surface, a profile field value that is not a whole number naming a profile,
// a negative obstacle, soil_1 .. soil_3 set without a profile field, and a grid whose state does not
// fit in memory (validate_layered_inputs).
// run_layered_reference(setup) runs ref<double> from the setup's start and returns the ground and
// the water (when the setup gives water) after its steps.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/inputs.hpp"
#include "core/grid.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/param_table.hpp"
#include "core/params/layered.hpp"

namespace gt {

struct LayeredSetup {
  LayeredParams params;
  LayeredColumns columns;          // the profiles, the map choosing them, the vegetation
  std::vector<std::string> soils;  // the profiles' names, as columns.profiles
  int steps = 0;
  Heightmap surface;
  int bedrock_layers() const { return static_cast<int>(columns.profiles.front().bedrock.size()); }
};

// A case's parameters: erosion.layered's and the initial profile's (see above).
struct LayeredCaseParams {
  LayeredParams layered;
  int steps = 200;
  std::string soil = "loam";
  std::array<std::string, 3> more_soils{"none", "none", "none"};  // soil_1 .. soil_3
  double topsoil_thickness = 0.5;
  double subsoil_thickness = 1.5;
  double soft_rock_thickness = 5.0;
  double hard_rock_thickness = 1000.0;
  double vegetation = 0.0;
};

// The declarations (core/param_table.hpp: erosion.layered's, then the profile's) and their ParamSpecs.
const ParamTable<LayeredCaseParams>& layered_case_param_table();
const ParamSpecs& layered_case_param_specs();
LayeredSetup layered_setup(const LayeredCaseParams& params, const Heightmap& surface,
                           const std::map<std::string, Heightmap>& fields = {});
// The same from resolve_params(..., layered_case_param_specs(), ...).
LayeredSetup layered_setup(const nlohmann::json& resolved, const Heightmap& surface,
                           const std::map<std::string, Heightmap>& fields = {});

// The input fields a layered case reads (Algorithm::input_fields).
std::vector<InputFieldSpec> layered_input_fields();

struct LayeredOutcome {
  LayeredGround<double> ground;
  std::optional<LayeredWater<double>> water;
};
LayeredOutcome run_layered_reference(const LayeredSetup& setup);

}  // namespace gt
