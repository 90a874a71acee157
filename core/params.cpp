#include "core/params.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/closest.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

const char* kind_name(ParamKind kind) {
  switch (kind) {
    case ParamKind::real: return "real";
    case ParamKind::integer: return "integer";
    case ParamKind::choice: return "choice";
    case ParamKind::boolean: return "boolean";
  }
  return "?";
}

std::string range_text(const ParamSpec& spec) {
  if (spec.kind == ParamKind::choice) return fmt::format("one of {}", fmt::join(spec.choices, ", "));
  if (spec.kind == ParamKind::boolean) return "true or false";
  return fmt::format("{} in [{}, {}] {}", kind_name(spec.kind), spec.min, spec.max, spec.unit);
}

nlohmann::json checked_value(const std::string& algorithm, const ParamSpec& spec, const nlohmann::json& value) {
  const auto refuse = [&](const std::string& why) {
    return InputError(fmt::format("{}: parameter {} = {} {}; expected {}", algorithm, spec.name, value.dump(), why,
                                  range_text(spec)));
  };
  switch (spec.kind) {
    case ParamKind::boolean:
      if (!value.is_boolean()) throw refuse("is not a boolean");
      return value;
    case ParamKind::choice: {
      if (!value.is_string()) throw refuse("is not a name");
      const auto text = value.get<std::string>();
      if (std::find(spec.choices.begin(), spec.choices.end(), text) == spec.choices.end()) throw refuse("is unknown");
      return value;
    }
    case ParamKind::integer: {
      if (!value.is_number_integer()) {
        const bool integral_real = value.is_number_float() && std::floor(value.get<double>()) == value.get<double>();
        if (!integral_real) throw refuse("is not an integer");
      }
      const double number = value.get<double>();
      if (number < spec.min || number > spec.max) throw refuse("is out of range");
      return static_cast<long long>(number);
    }
    case ParamKind::real: {
      if (!value.is_number()) throw refuse("is not a number");
      const double number = value.get<double>();
      if (!std::isfinite(number) || number < spec.min || number > spec.max) throw refuse("is out of range");
      return number;
    }
  }
  return value;
}

}  // namespace

const ParamSpec& find_spec(const std::string& algorithm, const ParamSpecs& specs, const std::string& name) {
  for (const auto& spec : specs) {
    if (spec.name == name) return spec;
  }
  std::vector<std::string> names;
  for (const auto& spec : specs) names.push_back(spec.name);
  throw InputError(fmt::format("{}: unknown parameter '{}'{}; known: {}", algorithm, name, did_you_mean(name, names),
                               fmt::join(names, ", ")));
}

nlohmann::json to_json(const ParamSpec& spec) {
  nlohmann::json out = {{"name", spec.name},
                        {"kind", kind_name(spec.kind)},
                        {"default", spec.default_value},
                        {"unit", spec.unit},
                        {"description", spec.description}};
  if (spec.kind == ParamKind::choice) {
    out["choices"] = spec.choices;
  } else if (spec.kind != ParamKind::boolean) {
    out["min"] = spec.min;
    out["max"] = spec.max;
  }
  return out;
}

nlohmann::json resolve_params(const std::string& algorithm, const ParamSpecs& specs, const nlohmann::json& given) {
  if (!given.is_null() && !given.is_object()) {
    throw InputError(fmt::format("{}: parameters must be a JSON object, got {}", algorithm, given.dump()));
  }
  nlohmann::json resolved = nlohmann::json::object();
  for (const auto& spec : specs) resolved[spec.name] = spec.default_value;
  if (given.is_object()) {
    for (const auto& [name, value] : given.items()) {
      resolved[name] = checked_value(algorithm, find_spec(algorithm, specs, name), value);
    }
  }
  return resolved;
}

nlohmann::json parse_param_text(const std::string& algorithm, const ParamSpecs& specs, const std::string& name,
                                const std::string& text) {
  const auto& spec = find_spec(algorithm, specs, name);
  switch (spec.kind) {
    case ParamKind::choice: return checked_value(algorithm, spec, text);
    case ParamKind::boolean:
      if (text == "true" || text == "1") return true;
      if (text == "false" || text == "0") return false;
      return checked_value(algorithm, spec, text);
    case ParamKind::integer:
    case ParamKind::real: {
      char* end = nullptr;
      const double number = std::strtod(text.c_str(), &end);
      if (text.empty() || end != text.c_str() + text.size()) {
        throw InputError(fmt::format("{}: parameter {} = '{}' is not a number; expected {}", algorithm, name, text,
                                     range_text(spec)));
      }
      if (!std::isfinite(number)) {
        throw InputError(fmt::format("{}: parameter {} = '{}' is not finite; expected {}", algorithm, name, text,
                                     range_text(spec)));
      }
      // Whole numbers that a long long holds exactly become integers; 1e300 would not convert
      // (undefined) and is refused below as out of range.
      if (spec.kind == ParamKind::integer && std::abs(number) < 9.0e15 && std::floor(number) == number) {
        return checked_value(algorithm, spec, static_cast<long long>(number));
      }
      return checked_value(algorithm, spec, number);
    }
  }
  return text;
}

}  // namespace gt
