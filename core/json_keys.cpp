// Strict JSON objects; see core/json_keys.hpp.
#include "core/json_keys.hpp"

#include <algorithm>

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

void require_shape(const nlohmann::json& value, const nlohmann::json& shape, const std::string& where) {
  std::vector<std::string> known;
  for (const auto& [key, below] : shape.items()) known.push_back(key);
  require_known_keys(value, known, where);
  for (const auto& [key, below] : shape.items()) {
    if (!value.contains(key)) continue;
    const auto& given = value[key];
    const std::string inner = fmt::format("{}.{}", where, key);
    if (below.is_object() && given.is_object()) require_shape(given, below, inner);
    if (below.is_array() && below.size() == 1 && given.is_array()) {
      for (std::size_t i = 0; i < given.size(); ++i) require_shape(given[i], below[0], fmt::format("{}[{}]", inner, i));
    }
  }
}

}  // namespace gt
