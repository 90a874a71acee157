// Parameter declarations: every algorithm declares its parameters with kind, default, range and
// unit (as landlab components declare their fields). Case files, `--set key=value` and
// `groundtruth list --json` all go through these declarations, so an unknown name or an
// out-of-range value is refused the same way everywhere (InputError naming the range).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

enum class ParamKind { real, integer, choice, boolean };

struct ParamSpec {
  std::string name;
  ParamKind kind = ParamKind::real;
  nlohmann::json default_value;
  double min = 0.0;  // inclusive bounds for real and integer parameters
  double max = 0.0;
  std::vector<std::string> choices;  // for choice parameters
  std::string unit;                  // "m", "degree", "1" (dimensionless), "count"
  std::string description;
};

using ParamSpecs = std::vector<ParamSpec>;

// The declaration as JSON: {"name", "kind", "default", "min", "max" | "choices", "unit", "description"}.
nlohmann::json to_json(const ParamSpec& spec);

// The declaration of `name`; throws InputError naming the known ones (and the closest) otherwise.
const ParamSpec& find_spec(const std::string& algorithm, const ParamSpecs& specs, const std::string& name);

// Returns every declared parameter, taking the given value where there is one and the default
// otherwise. Throws InputError for an unknown name (listing the known ones), a value of the wrong
// kind, or a value outside [min, max] or not among the choices (naming them).
nlohmann::json resolve_params(const std::string& algorithm, const ParamSpecs& specs, const nlohmann::json& given);

// Parses the text of `--set name=text` according to the declaration of `name`.
nlohmann::json parse_param_text(const std::string& algorithm, const ParamSpecs& specs, const std::string& name,
                                const std::string& text);

}  // namespace gt
