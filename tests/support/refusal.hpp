// The message of the InputError an action throws, or "(accepted)" when it throws none: for tests
// that check what a refusal says.
#pragma once

#include <functional>
#include <string>

#include "core/errors.hpp"

namespace gt::testing {

inline std::string refusal(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  return "(accepted)";
}

}  // namespace gt::testing
