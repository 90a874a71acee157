// How GoogleTest prints the project's parameter types in test names and messages.
#pragma once

#include <ostream>

#include "core/params/thermal.hpp"

namespace gt {

inline void PrintTo(Neighbourhood neighbourhood, std::ostream* out) { *out << neighbourhood_name(neighbourhood); }

}  // namespace gt
