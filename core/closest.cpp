// Edit distance and closest names; see core/closest.hpp.
#include "core/closest.hpp"

#include <algorithm>
#include <numeric>

namespace gt {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  std::iota(previous.begin(), previous.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::vector<std::string> closest_names(const std::string& name, const std::vector<std::string>& known) {
  std::vector<std::string> closest;
  std::size_t best = std::string::npos;
  for (const auto& candidate : known) {
    const std::size_t distance = edit_distance(name, candidate);
    if (distance > std::max(name.size(), candidate.size()) / 3 + 1) continue;
    if (distance < best) {
      best = distance;
      closest.clear();
    }
    if (distance == best) closest.push_back(candidate);
  }
  return closest;
}

std::string did_you_mean(const std::string& name, const std::vector<std::string>& known) {
  const auto closest = closest_names(name, known);
  if (closest.empty()) return "";
  std::string text = " (did you mean ";
  for (std::size_t i = 0; i < closest.size(); ++i) {
    if (i > 0) text += i + 1 == closest.size() ? " or " : ", ";
    text += "'" + closest[i] + "'";
  }
  return text + "?)";
}

}  // namespace gt
