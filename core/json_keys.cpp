// Strict JSON objects; see core/json_keys.hpp.
#include "core/json_keys.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/closest.hpp"
#include "core/errors.hpp"

namespace gt {

void require_known_keys(const nlohmann::json& object, const std::vector<std::string>& known, const std::string& where) {
  if (!object.is_object()) throw InputError(fmt::format("{}: expected a JSON object, got {}", where, object.dump()));
  for (const auto& [key, value] : object.items()) {
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    throw InputError(fmt::format("{}: unknown key '{}'{}; known: {}", where, key, did_you_mean(key, known),
                                 known.empty() ? "none" : fmt::format("{}", fmt::join(known, ", "))));
  }
}

namespace {

bool has_type(const nlohmann::json& value, const std::string& type) {
  if (type == "number") return value.is_number();
  if (type == "integer") return value.is_number_integer();
  if (type == "boolean") return value.is_boolean();
  if (type == "string") return value.is_string();
  throw std::logic_error("require_shape: unknown type '" + type + "' in a shape");
}

std::string a_or_an(const std::string& type) { return (type == "integer" ? "an " : "a ") + type; }

}  // namespace

void require_shape(const nlohmann::json& value, const nlohmann::json& shape, const std::string& where) {
  if (shape.is_null()) return;
  if (shape.is_string()) {
    const std::string type = shape.get<std::string>();
    if (!has_type(value, type)) throw InputError(fmt::format("{} = {}: expected {}", where, value.dump(), a_or_an(type)));
    return;
  }
  if (shape.is_array()) {
    if (!value.is_array()) throw InputError(fmt::format("{} = {}: expected an array", where, value.dump()));
    if (shape.size() > 1 && value.size() != shape.size()) {
      throw InputError(fmt::format("{} = {}: expected an array of {} elements", where, value.dump(), shape.size()));
    }
    for (std::size_t i = 0; i < value.size(); ++i) {
      require_shape(value[i], shape.size() == 1 ? shape[0] : shape[i], fmt::format("{}[{}]", where, i));
    }
    return;
  }
  std::vector<std::string> known;
  for (const auto& [key, below] : shape.items()) known.push_back(key);
  require_known_keys(value, known, where);
  for (const auto& [key, below] : shape.items()) {
    if (value.contains(key)) require_shape(value[key], below, fmt::format("{}.{}", where, key));
  }
}

long long json_integer(const nlohmann::json& object, const std::string& key, long long fallback, long long min,
                       long long max, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) return fallback;
  const auto& value = object[key];
  const auto refuse = [&](const std::string& why) {
    return InputError(fmt::format("{}: {} = {} {}; expected a whole number in [{}, {}]", where, key, value.dump(), why,
                                  min, max));
  };
  if (value.is_number_unsigned()) {
    const auto number = value.get<unsigned long long>();
    if (number > static_cast<unsigned long long>(max)) throw refuse("is out of range");
    return static_cast<long long>(number);
  }
  if (!value.is_number_integer()) throw refuse(value.is_number() ? "is not whole" : "is not a number");
  const auto number = value.get<long long>();
  if (number < min || number > max) throw refuse("is out of range");
  return number;
}

double json_number(const nlohmann::json& object, const std::string& key, double fallback, double min, double max,
                   const std::string& where) {
  if (!object.is_object() || !object.contains(key)) return fallback;
  const auto& value = object[key];
  if (!value.is_number()) {
    throw InputError(fmt::format("{}: {} = {} is not a number; expected one in [{}, {}]", where, key, value.dump(), min, max));
  }
  const double number = value.get<double>();
  if (!(number >= min && number <= max)) {
    throw InputError(fmt::format("{}: {} = {} is out of range; expected a number in [{}, {}]", where, key, value.dump(),
                                 min, max));
  }
  return number;
}

bool json_bool(const nlohmann::json& object, const std::string& key, bool fallback, const std::string& where) {
  if (!object.is_object() || !object.contains(key)) return fallback;
  const auto& value = object[key];
  if (!value.is_boolean()) throw InputError(fmt::format("{}: {} = {} is not true or false", where, key, value.dump()));
  return value.get<bool>();
}

namespace {

// Refuses `text` when its objects and arrays nest deeper than max_json_depth, in one linear scan
// that skips strings. (nlohmann::json's parser callback, which bounded the depth before, looks
// through the parent object each time a child object ends: 300,000 sibling sets took ten minutes.)
void check_depth(const std::string& text, const std::string& where) {
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      if (++depth > max_json_depth) {
        throw InputError(fmt::format("{}: JSON nested deeper than {} levels", where, max_json_depth));
      }
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

template <class Json>
Json parse_bounded(std::istream& in, const std::string& where) {
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  check_depth(text, where);
  return Json::parse(text);
}

}  // namespace

nlohmann::json parse_json_bounded(std::istream& in, const std::string& where) {
  return parse_bounded<nlohmann::json>(in, where);
}

nlohmann::ordered_json parse_ordered_json_bounded(std::istream& in, const std::string& where) {
  return parse_bounded<nlohmann::ordered_json>(in, where);
}

}  // namespace gt
