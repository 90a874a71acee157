// What the droplet eroders (erosion.particle: Hydra's kernel; erosion.beyer: Beyer 2015) share:
// how the droplets of one pass are ordered, and the fixed-point unit of the batch ordering.
//
// Ordering of the droplets of one pass (one draw of seed 000's Algorithm 7: one droplet per
// spacing² block):
//   race      every droplet at once on one height buffer, as Hydra dispatches them (the GPU races:
//             droplets overwrite each other); the references run the droplets one after the other
//             in row-major order, the defined truth, and the GPU is compared statistically.
//   disjoint  the same dispatch with spacing > twice the droplet's reach (Hydra: lifetime + 2, a
//             unit step a step and texels up to two beyond its path), so no two droplets of a pass
//             read or write a common texel: the GPU equals the sequential reference within rounding.
//   batch     every droplet of a pass reads the heights as they were at the pass's start and adds
//             what it erodes and deposits, as fixed-point integers of `quantum`, into a delta that
//             is applied when the pass ends: order-independent, so the GPU equals ref<float> bit for
//             bit at any spacing. The droplet carries its sediment as an integer count of quanta.
#pragma once

#include "core/param_table.hpp"

namespace gt {

enum class DropletOrdering { race, disjoint, batch };

// The names of an `ordering` parameter.
inline constexpr Choice<DropletOrdering> droplet_ordering_choices[] = {
    {"race", DropletOrdering::race}, {"disjoint", DropletOrdering::disjoint}, {"batch", DropletOrdering::batch}};

// "race", "disjoint" or "batch".
const char* droplet_ordering_name(DropletOrdering ordering);

// The ordering the CPU references run for a GPU `ordering`: batch as batch, race and disjoint as the
// sequential truth (their `race` ordering, droplets one after the other).
DropletOrdering reference_ordering(DropletOrdering ordering);

// The fixed-point unit for heights whose magnitude is at most `max_abs_height`: 2^-24 times the
// smallest power of two >= max(1, max_abs_height), about one float ulp at the top of the range, so
// an int32 delta holds ±128 times the heights' magnitude per pass.
double batch_quantum(double max_abs_height);

}  // namespace gt
