// The driver's view of the two thermal-erosion models: parameters to constants, the three
// versions (ref<double>, ref<float>, GPU) and the error model's count of rounded additions.
#include <cmath>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/checks/threshold.hpp"
#include "core/errors.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"

namespace gt {
namespace {

// The GPU object lives as long as the runner's closures.
template <class Gpu>
GpuFieldRunner field_runner(std::shared_ptr<Gpu> gpu) {
  return {[gpu](const Grid<float>& heights) { gpu->load(heights); }, [gpu] { gpu->run(); },
          [gpu] { return gpu->result(); }};
}

// Spec vector of eq. 4.10 when a case asks for it: {"talus_eq_4_10": {"angle", "width",
// "vertical_aspect", "value"}}; exact in double up to the rounding of tan (a few ulp).
void add_talus_spec(const nlohmann::json& expect, const RunOptions&, CaseResult& result) {
  if (!expect.is_object() || !expect.contains("talus_eq_4_10")) return;
  const auto& vector = expect["talus_eq_4_10"];
  const double value = talus_threshold_eq_4_10(vector.at("angle"), vector.at("width"), vector.at("vertical_aspect"));
  const double expected = vector.at("value");
  result.checks.push_back(bounded_check("spec.talus_eq_4_10", std::abs(value - expected), 4e-16 * std::abs(expected),
                                        std::nullopt, "T_α = tan(α)/(width·d_z); tolerance: a few ulp of tan in double"));
}

void require_heightmap(const Heightmap& input, const char* algorithm) {
  if (input.size() == 0) throw InputError(fmt::format("{} erodes a heightmap: the case needs an input", algorithm));
}

PreparedTwin prepare_thermal(const nlohmann::json& resolved, const Heightmap& input) {
  require_heightmap(input, "erosion.thermal");
  const ThermalParams params = thermal_params_from_json(resolved);
  PreparedTwin prepared;
  prepared.input = params.normalised ? normalise_heights(input) : input;
  const ThermalConstants constants = thermal_constants(params, input);
  FieldTwin& twin = prepared.twin;
  twin.reference_double = [=](const Grid<double>& field) {
    return reference::thermal_erosion(field, constants, params.iterations, params.neighbourhood);
  };
  twin.reference_float = [=](const Grid<float>& field) {
    return reference::thermal_erosion(field, constants, params.iterations, params.neighbourhood);
  };
  twin.make_gpu = [=, width = input.width, height = input.height] {
    return field_runner(std::make_shared<gpu::ThermalErosion>(width, height, constants, params.neighbourhood,
                                                              params.iterations));
  };
  twin.additions_per_cell = 4.0 * params.iterations;  // one per pipe and iteration (Algorithm 11)
  prepared.extra_checks = add_talus_spec;
  return prepared;
}

PreparedTwin prepare_thermal_jako(const nlohmann::json& resolved, const Heightmap& input) {
  require_heightmap(input, "erosion.thermal_jako");
  const ThermalJakoParams params = thermal_jako_params_from_json(resolved);
  const ThermalConstants constants = thermal_jako_constants(params, input);
  PreparedTwin prepared;
  prepared.input = input;
  FieldTwin& twin = prepared.twin;
  twin.reference_double = [=](const Grid<double>& field) {
    return reference::thermal_jako_erosion(field, constants, params.iterations);
  };
  twin.reference_float = [=](const Grid<float>& field) {
    return reference::thermal_jako_erosion(field, constants, params.iterations);
  };
  twin.make_gpu = [=, width = input.width, height = input.height] {
    return field_runner(std::make_shared<gpu::ThermalJakoErosion>(width, height, constants, params.iterations));
  };
  twin.additions_per_cell = 16.0 * params.iterations;  // 8 outflows subtracted, 8 inflows added
  // The talus test switches the whole outflow rate·H/2 on or off, and H is at most the range.
  twin.largest_switched_transfer = 0.5 * params.rate;
  return prepared;
}

}  // namespace

Algorithm thermal_algorithm() {
  return {.name = "erosion.thermal",
          .summary = "two-pass thermal erosion with requests and transfers (Hydra)",
          .source = "seed 000 §4.4.3, Algorithms 9-11, eq. 4.10 (digest 000 §4.6)",
          .params = &thermal_param_specs(),
          .prepare = [](const nlohmann::json& resolved, const LoadedInput& input) {
            return prepare_thermal(resolved, input.heights);
          }};
}

Algorithm thermal_jako_algorithm() {
  return {.name = "erosion.thermal_jako",
          .summary = "8-neighbour thermal erosion with proportional outflow (Jákó & Tóth 2011)",
          .source = "seed 000 §2.6, eqs. 2.30-2.34 (digest 000 §3.6)",
          .params = &thermal_jako_param_specs(),
          .prepare = [](const nlohmann::json& resolved, const LoadedInput& input) {
            return prepare_thermal_jako(resolved, input.heights);
          }};
}

}  // namespace gt
