// spec.step.<field>.cpu: one step of ref<double> held value by value to the host spec of the pipe
// step (compare/algorithms/pipe_spec.hpp), for the fields terrain, water, sediment, regolith (where
// the parameters have it), Šťava's layer_1 .. layer_N (with layers = N), velocity_x, velocity_y and
// outflow (each cell's 4 or 8 pipes).
//
// Error model: ref<double>'s step and the spec's, both from the same start, are each within their
// rounding-interval width of the exact step (core/rounding_interval.hpp: both are run once more in
// interval arithmetic from the start taken as exact). The interval widens by float's unit per
// operation (5 units for ÷ and √); a first-order bound is linear in the unit, so double's is the
// width times 2^-53/2^-24 = 2^-29 (double's ÷ and √ round correctly, so the 5 is slack). The bound
// of a value is the sum of the two scaled widths; a check reports the value farthest beyond (or
// nearest to) its own bound, with where it is and both numbers. Neither bound reads the step's
// result: the widths come from the start state alone.
//
// Inputs:  start (a state ref<double> reached), the twins' constants (what ref<double> steps with), params (what the spec
//          steps with), forcing, and the number of the step graded (for the text).
// Outputs: six checks, one more with regolith and one per layer, named as above.
#pragma once

#include <vector>

#include "compare/result.hpp"
#include "core/params/hydraulic.hpp"

namespace gt {

std::vector<Check> pipe_spec_checks(const PipeState<double>& start, const PipeConstants& constants,
                                    const HydraulicParams& params, const HydraulicForcing& forcing, int step);

}  // namespace gt
