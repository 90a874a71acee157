// Counts in messages and reports: "1 case", "2 cases", never "1 cases".
//
//   counted(count, singular, plural = singular + "s") -> "<count> <singular or plural>"
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace gt {

inline std::string counted(std::size_t count, std::string_view singular, std::string_view plural = {}) {
  if (count == 1) return fmt::format("1 {}", singular);
  return plural.empty() ? fmt::format("{} {}s", count, singular) : fmt::format("{} {}", count, plural);
}

}  // namespace gt
