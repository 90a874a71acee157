// The first iteration of each thermal model from a heightmap, on the host in double, written apart
// from both twins from the thesis's equations: the spec that mass.moved_first_iteration.cpu holds
// the references to (compare/algorithms/thermal.cpp).
//
// Inputs:  heights (no-data cells take no part), the model's constants.
// Outputs: the heights after one iteration.
// Units:   the heights' own.
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"

namespace gt {

// Seed 000's first iteration (Algorithms 9-11), visiting each pair of neighbours once (the twins
// visit each cell's four pipes): requests by Algorithm 10, then across each pipe the smaller of two
// opposite requests moves (Algorithm 11). Iteration 0 uses the cardinal pipes unless the
// neighbourhood is diagonal.
Grid<double> hydra_first_iteration(const Grid<double>& heights, const ThermalConstants& constants,
                                   Neighbourhood neighbourhood);

// Jákó & Tóth's first iteration (eqs. 2.30-2.34 as decided in reference/erosion/thermal_jako.cpp),
// sending each outflow to its neighbour as it is computed: A = the lower neighbours n beyond
// (C_a·R(n) + C_i)·l, ΔS = rate·R·H/2 with H the largest drop in A, shared by the drops (R = 1
// without a hardness map).
// Real: double, or core/rounding_interval.hpp's RoundingInterval (the pipe step's spec, compare/
// algorithms/pipe_spec.hpp, runs it as its combined thermal step).
template <class Real>
Grid<Real> jako_first_iteration(const Grid<Real>& heights, const ThermalConstants& constants);

}  // namespace gt
