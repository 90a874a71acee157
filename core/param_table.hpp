// Parameter tables: one row per algorithm parameter binds its declaration (name, kind, range or
// choices, unit, description) to the member of the parameter struct that holds it. The default is
// that member's value in a default-constructed struct (its default member initializer), so each
// parameter is written once: the struct says its type and default, the row the rest.
//
// Inputs:  a ParamTable<Params>, a list of rows made by
//            real_param("talus_angle", &ThermalParams::talus_angle_deg, 0.0, 85.0, "degree", "...")
//            integer_param(name, member, min, max, unit, description)
//            boolean_param(name, member, description)
//            choice_param(name, member, choices, unit, description)
//          where `member` is a data member pointer (&Params::x) or element(&Params::xs, i), one
//          element of an array member; nested(&Outer::inner, row or table) lifts rows over a struct
//          held in another.
// Outputs: param_specs(table)           the ParamSpecs of core/params.hpp (resolve_params,
//                                       parse_param_text, `groundtruth list --json` read them), the
//                                       defaults read from Params{} (or a given struct)
//          params_from_json(table, resolved)   the struct from resolve_params' output
//          params_to_json(table, params)       the struct's values by name, as resolve_params gives
//          check_param_ranges(algorithm, table, params)   a struct built in code checked against the
//                                       declared ranges: the InputError a case file would get
// Conventions: real members (double, float) are read as double; integer members (int,
// std::uint32_t) as a JSON integer; a choice is an enum (or any value) named by a Choice list, or a
// std::string member holding one of a list of names. Ranges live in the rows only: resolve_params
// checks them, and a struct-level validation calls check_param_ranges instead of repeating them.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/params.hpp"

namespace gt {

// One named value of a choice parameter.
template <class Value>
struct Choice {
  const char* name;
  Value value;
};

// The name of `value` among `choices`; "?" when it has none.
template <class Value, std::size_t count>
const char* choice_name(const Choice<Value> (&choices)[count], Value value) {
  for (const auto& choice : choices) {
    if (choice.value == value) return choice.name;
  }
  return "?";
}

template <class Params>
struct ParamRow {
  ParamSpec spec;  // default_value is left null: param_specs() reads it from a Params
  std::function<void(Params& params, const nlohmann::json& value)> read;  // the member takes the value
  std::function<nlohmann::json(const Params& params)> write;              // the member's value as JSON
};

template <class Params>
using ParamTable = std::vector<ParamRow<Params>>;

// Element `index` of the array member `array` of Params.
template <class Params, class Array>
struct ArrayElement {
  Array Params::*array;
  std::size_t index;
  auto& operator()(Params& params) const { return (params.*array)[index]; }
  const auto& operator()(const Params& params) const { return (params.*array)[index]; }
};

template <class Params, class Array>
ArrayElement<Params, Array> element(Array Params::*array, std::size_t index) {
  return {array, index};
}

namespace param_table_detail {

// The struct a member belongs to and the member's type.
template <class Member>
struct Bound;
template <class Params, class Value>
struct Bound<Value Params::*> {
  using params = Params;
  using value = Value;
};
template <class Params, class Array>
struct Bound<ArrayElement<Params, Array>> {
  using params = Params;
  using value = typename Array::value_type;
};

template <class Member, class FromJson, class ToJson>
ParamRow<typename Bound<Member>::params> bind(ParamSpec spec, Member member, FromJson from_json, ToJson to_json) {
  using Params = typename Bound<Member>::params;
  return {std::move(spec),
          [member, from_json](Params& params, const nlohmann::json& value) {
            std::invoke(member, params) = from_json(value);
          },
          [member, to_json](const Params& params) { return to_json(std::invoke(member, params)); }};
}

}  // namespace param_table_detail

template <class Member>
auto real_param(std::string name, Member member, double min, double max, std::string unit, std::string description) {
  using Value = typename param_table_detail::Bound<Member>::value;
  static_assert(std::is_floating_point_v<Value>, "a real parameter is a double or float member");
  return param_table_detail::bind(
      {std::move(name), ParamKind::real, {}, min, max, {}, std::move(unit), std::move(description)}, member,
      [](const nlohmann::json& value) { return static_cast<Value>(value.get<double>()); },
      [](Value value) { return nlohmann::json(static_cast<double>(value)); });
}

template <class Member>
auto integer_param(std::string name, Member member, double min, double max, std::string unit,
                   std::string description) {
  using Value = typename param_table_detail::Bound<Member>::value;
  static_assert(std::is_integral_v<Value> && !std::is_same_v<Value, bool>, "an integer parameter is an integer member");
  return param_table_detail::bind(
      {std::move(name), ParamKind::integer, {}, min, max, {}, std::move(unit), std::move(description)}, member,
      [](const nlohmann::json& value) { return static_cast<Value>(value.get<long long>()); },
      [](Value value) { return nlohmann::json(value); });
}

template <class Member>
auto boolean_param(std::string name, Member member, std::string description) {
  static_assert(std::is_same_v<typename param_table_detail::Bound<Member>::value, bool>);
  return param_table_detail::bind({std::move(name), ParamKind::boolean, {}, 0, 0, {}, "", std::move(description)},
                                  member, [](const nlohmann::json& value) { return value.get<bool>(); },
                                  [](bool value) { return nlohmann::json(value); });
}

// A choice among named values. A value with no name (an integer member set in code) is written as
// its number, which the declaration then refuses by name.
template <class Member, class Value, std::size_t count>
auto choice_param(std::string name, Member member, const Choice<Value> (&choices)[count], std::string unit,
                  std::string description) {
  static_assert(std::is_same_v<typename param_table_detail::Bound<Member>::value, Value>);
  std::vector<Choice<Value>> named(std::begin(choices), std::end(choices));
  std::vector<std::string> names;
  for (const auto& choice : named) names.emplace_back(choice.name);
  auto from_json = [named, parameter = name](const nlohmann::json& value) {
    for (const auto& choice : named) {
      if (value == choice.name) return choice.value;
    }
    throw InputError(fmt::format("parameter {}: unknown value {}", parameter, value.dump()));
  };
  auto to_json = [named](Value value) -> nlohmann::json {
    for (const auto& choice : named) {
      if (choice.value == value) return choice.name;
    }
    if constexpr (std::is_integral_v<Value>) {
      return std::to_string(value);
    } else {
      return nullptr;
    }
  };
  return param_table_detail::bind(
      {std::move(name), ParamKind::choice, {}, 0, 0, std::move(names), std::move(unit), std::move(description)}, member,
      from_json, to_json);
}

// A choice held as the name itself, in a std::string member.
template <class Member>
auto choice_param(std::string name, Member member, std::vector<std::string> names, std::string unit,
                  std::string description) {
  static_assert(std::is_same_v<typename param_table_detail::Bound<Member>::value, std::string>);
  return param_table_detail::bind(
      {std::move(name), ParamKind::choice, {}, 0, 0, std::move(names), std::move(unit), std::move(description)}, member,
      [](const nlohmann::json& value) { return value.get<std::string>(); },
      [](const std::string& value) { return nlohmann::json(value); });
}

// A row of Inner as a row of Outer, which holds an Inner in `inner`.
template <class Outer, class Inner>
ParamRow<Outer> nested(Inner Outer::*inner, ParamRow<Inner> row) {
  return {std::move(row.spec),
          [inner, read = std::move(row.read)](Outer& outer, const nlohmann::json& value) { read(outer.*inner, value); },
          [inner, write = std::move(row.write)](const Outer& outer) { return write(outer.*inner); }};
}

template <class Outer, class Inner>
ParamTable<Outer> nested(Inner Outer::*inner, const ParamTable<Inner>& table) {
  ParamTable<Outer> rows;
  for (const auto& row : table) rows.push_back(nested(inner, row));
  return rows;
}

// The declarations, each default the member's value in `defaults`.
template <class Params>
ParamSpecs param_specs(const ParamTable<Params>& table, const Params& defaults = Params{}) {
  ParamSpecs specs;
  for (const auto& row : table) {
    specs.push_back(row.spec);
    specs.back().default_value = row.write(defaults);
  }
  return specs;
}

// `params` with every row's member taken from `resolved` (resolve_params' output: every name there).
template <class Params>
Params params_from_json(const ParamTable<Params>& table, const nlohmann::json& resolved, Params params = Params{}) {
  for (const auto& row : table) row.read(params, resolved.at(row.spec.name));
  return params;
}

template <class Params>
nlohmann::json params_to_json(const ParamTable<Params>& table, const Params& params) {
  nlohmann::json values = nlohmann::json::object();
  for (const auto& row : table) values[row.spec.name] = row.write(params);
  return values;
}

// Throws the InputError resolve_params gives for the first value outside its declared range.
template <class Params>
void check_param_ranges(const std::string& algorithm, const ParamTable<Params>& table, const Params& params) {
  resolve_params(algorithm, param_specs(table), params_to_json(table, params));
}

}  // namespace gt
