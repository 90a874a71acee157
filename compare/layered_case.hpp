// A case of seed 001's layered ground as the driver states it (compare/algorithms/layered.cpp;
// render.terrain's erode = layered): the parameters of erosion.layered plus the initial profile's,
// and the setup they make on a surface.
//
// Profile parameters (the same profile in every column, hung from the surface):
//   soil                 the components' shares (org, sand, gravel, stones, boulders) of topsoil and
//                        subsoil: loam (0.4, 0.3, 0.15, 0.1, 0.05 over 0.1, 0.35, 0.25, 0.2, 0.1),
//                        sand (pure sand in both), scree (0, 0.1, 0.3, 0.3, 0.3 in both)
//   topsoil_thickness, subsoil_thickness    m; soft_rock_thickness m of bedrock type 0 (the code's
//                        soft rock, tan φ 4, the only one that falls), over hard_rock_thickness m of
//                        type 1 (tan φ 1e7: it never falls; the code makes it 1e6 m, which would
//                        drown the ledger's precision: it only needs to outlast the relief)
//   vegetation           the initial density in [0, 1] on every column
//   steps                iterations (reference/erosion/layered/iteration.hpp)
// layered_setup(params or resolved, surface) throws InputError for a surface with no-data cells (the layered
// ground holds none; the message names the remedy, a crop), a bad profile, parameters or surface,
// and a grid whose state does not fit in memory (validate_layered_inputs).
// run_layered_reference(setup) runs ref<double> from the setup's start and returns the ground and
// the water (when the setup gives water) after its steps.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/grid.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/param_table.hpp"
#include "core/params/layered.hpp"

namespace gt {

struct LayeredSetup {
  LayeredParams params;
  LayeredProfile profile;
  std::string soil;  // loam, sand, scree
  int steps = 0;
  double vegetation = 0.0;
  Heightmap surface;
};

// A case's parameters: erosion.layered's and the initial profile's (see above).
struct LayeredCaseParams {
  LayeredParams layered;
  int steps = 200;
  std::string soil = "loam";
  double topsoil_thickness = 0.5;
  double subsoil_thickness = 1.5;
  double soft_rock_thickness = 5.0;
  double hard_rock_thickness = 1000.0;
  double vegetation = 0.0;
};

// The declarations (core/param_table.hpp: erosion.layered's, then the profile's) and their ParamSpecs.
const ParamTable<LayeredCaseParams>& layered_case_param_table();
const ParamSpecs& layered_case_param_specs();
LayeredSetup layered_setup(const LayeredCaseParams& params, const Heightmap& surface);
// The same from resolve_params(..., layered_case_param_specs(), ...).
LayeredSetup layered_setup(const nlohmann::json& resolved, const Heightmap& surface);

struct LayeredOutcome {
  LayeredGround<double> ground;
  std::optional<LayeredWater<double>> water;
};
LayeredOutcome run_layered_reference(const LayeredSetup& setup);

}  // namespace gt
