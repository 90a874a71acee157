#include "compare/algorithm.hpp"

#include <algorithm>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"

namespace gt {

CaseRun in_turn(CaseRun first, CaseRun second) {
  return [first = std::move(first), second = std::move(second)](const nlohmann::json& expect, const RunOptions& options,
                                                                 CaseResult& result) {
    first(expect, options, result);
    second(expect, options, result);
  };
}

const std::vector<Algorithm>& algorithms() {
  static const std::vector<Algorithm> all = [] {
    std::vector<Algorithm> list = {thermal_algorithm(),  thermal_jako_algorithm(), dissolution_algorithm(),
                                   pipe_algorithm(),     particle_algorithm(),     beyer_algorithm(),
                                   layered_algorithm()};
    for (auto& algorithm : noise_algorithms()) list.push_back(std::move(algorithm));
    for (auto& algorithm : cave_algorithms()) list.push_back(std::move(algorithm));
    list.push_back(cave_endless_algorithm());
    list.push_back(planet_algorithm());
    list.push_back(fault_lines_algorithm());
    list.push_back(mesh_check_algorithm());
    list.push_back(render_heightmap_algorithm());
    list.push_back(render_phong_algorithm());
    list.push_back(render_terrain_algorithm());
    return list;
  }();
  return all;
}

const Algorithm& find_algorithm(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& algorithm : algorithms()) {
    if (algorithm.name == name) return algorithm;
    names.push_back(algorithm.name);
  }
  throw InputError(fmt::format("unknown algorithm '{}'; known: {}", name, fmt::join(names, ", ")));
}

namespace {

const char* kind_name(CaseKind kind) {
  switch (kind) {
    case CaseKind::generated: return "generated";
    case CaseKind::stepped: return "stepped";
    case CaseKind::custom: return "custom";
  }
  return "?";
}

nlohmann::json field_json(const FieldDecl& field) {
  return {{"name", field.name},
          {"unit", field.unit},
          {"meaning", field.meaning},
          {"extent", extent_name(field.extent)},
          {"components", field.components},
          {"component_names", field.component_names},
          {"conserved", field.conserved},
          {"read_only", field.read_only},
          {"standard_name", field.standard_name}};
}

// A stepped algorithm's declared state at its default parameters, read off a case prepared on a
// flat 4 x 4 grid (nothing is stepped): some declarations depend on parameters (the pipes' count).
nlohmann::json state_json(const Algorithm& algorithm) {
  LoadedInput probe;
  probe.heights = Heightmap(4, 4, 1.0);
  const PreparedTwin prepared = algorithm.prepare(resolve_params(algorithm.name, *algorithm.params, {}), probe);
  nlohmann::json fields = nlohmann::json::array();
  for (const FieldDecl& field : std::get<SteppedTwin>(prepared.kind).fields) fields.push_back(field_json(field));
  return fields;
}

}  // namespace

nlohmann::json algorithm_json(const Algorithm& algorithm) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& spec : *algorithm.params) params.push_back(to_json(spec));
  const char* input = algorithm.ad_hoc_input == AdHocInput::heightmap         ? "heightmap"
                      : algorithm.ad_hoc_input == AdHocInput::mesh            ? "mesh"
                      : algorithm.ad_hoc_input == AdHocInput::optional_volume ? "optional_volume"
                      : algorithm.ad_hoc_input == AdHocInput::optional_global_grid ? "optional_global_grid"
                                                                              : "none";
  nlohmann::json json = {{"name", algorithm.name}, {"summary", algorithm.summary}, {"source", algorithm.source},
                         {"input", input},         {"kind", kind_name(algorithm.kind)}, {"params", params}};
  if (algorithm.kind == CaseKind::stepped) json["state"] = state_json(algorithm);
  if (!algorithm.input_fields.empty()) {
    json["input_fields"] = nlohmann::json::array();
    for (const InputFieldSpec& field : algorithm.input_fields) {
      json["input_fields"].push_back({{"name", field.name}, {"unit", field.unit}, {"description", field.description}});
    }
  }
  return json;
}

void require_known_fields(const Algorithm& algorithm, const LoadedInput& input) {
  for (const auto& given : input.fields) {
    const std::string& name = given.first;
    const auto declared = std::find_if(algorithm.input_fields.begin(), algorithm.input_fields.end(),
                                       [&](const InputFieldSpec& known) { return known.name == name; });
    if (declared != algorithm.input_fields.end()) continue;
    std::vector<std::string> known;
    for (const InputFieldSpec& field_spec : algorithm.input_fields) known.push_back(field_spec.name);
    throw InputError(fmt::format("{} reads no input field '{}'{}", algorithm.name, name,
                                 known.empty() ? std::string(" (it reads none)")
                                               : fmt::format("; it reads: {}", fmt::join(known, ", "))));
  }
}

}  // namespace gt
