// The process-wide mutant switch of core/mutant.hpp.
#include "core/mutant.hpp"

#include <cctype>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/names.hpp"

namespace gt {
namespace {

std::string& active_name() {
  static std::string name;
  return name;
}

}  // namespace

const std::string& active_mutant() { return active_name(); }

bool detail::any_mutant_active = false;

bool detail::is_active_mutant(std::string_view name) { return active_name() == name; }

void set_active_mutant(const std::string& name) {
  if (!name.empty() && !is_dotted_identifier(name)) {
    throw InputError(fmt::format("mutant '{}': a mutant name is a dotted lower-case identifier", name));
  }
  active_name() = name;
  detail::any_mutant_active = !name.empty();
}

std::string mutant_define(std::string_view name) {
  std::string define = "GT_MUTANT_";
  for (const char c : name) define += c == '.' ? '_' : static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return define;
}

}  // namespace gt
