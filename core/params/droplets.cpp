#include "core/params/droplets.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {

const char* droplet_ordering_name(DropletOrdering ordering) {
  switch (ordering) {
    case DropletOrdering::race: return "race";
    case DropletOrdering::disjoint: return "disjoint";
    case DropletOrdering::batch: return "batch";
  }
  return "?";
}

DropletOrdering droplet_ordering_from_name(const std::string& name) {
  for (auto candidate : {DropletOrdering::race, DropletOrdering::disjoint, DropletOrdering::batch}) {
    if (name == droplet_ordering_name(candidate)) return candidate;
  }
  throw InputError(fmt::format("unknown droplet ordering '{}'; known: race, disjoint, batch", name));
}

DropletOrdering reference_ordering(DropletOrdering ordering) {
  return ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race;
}

double batch_quantum(double max_abs_height) {
  const double magnitude = std::max(1.0, max_abs_height);
  return std::ldexp(1.0, static_cast<int>(std::ceil(std::log2(magnitude))) - 24);
}

}  // namespace gt
