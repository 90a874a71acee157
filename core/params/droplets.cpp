// Names of the droplet orderings and the batch quantum (see droplets.hpp).
#include "core/params/droplets.hpp"

#include <algorithm>
#include <cmath>

namespace gt {

const char* droplet_ordering_name(DropletOrdering ordering) {
  return choice_name(droplet_ordering_choices, ordering);
}

DropletOrdering reference_ordering(DropletOrdering ordering) {
  return ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race;
}

double batch_quantum(double max_abs_height) {
  const double magnitude = std::max(1.0, max_abs_height);
  return std::ldexp(1.0, static_cast<int>(std::ceil(std::log2(magnitude))) - 24);
}

}  // namespace gt
