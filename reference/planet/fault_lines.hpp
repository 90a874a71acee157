// The fault-line planet (seed 002 §2.5 after Elias and Bourke), CPU reference: how many of the
// fault planes put each region on their raised side, minus how many on their lowered side.
//
// fault_votes<Real>(positions, normals) -> votes per region: Σ_i (dot(n_i, p_r) > 0 ? +1 : -1), the
//   dot in Real as ((n_x·p_x + n_y·p_y) + n_z·p_z), the order gpu/shaders/planet/fault_lines.comp
//   keeps (`precise`); the count is an exact integer in any Real.
// dot_error_bound(normal, position, unit_roundoff) -> how far a Real dot of the rounded inputs can
//   lie from the exact dot: 6u·Σ_c |n_c·p_c| (two input roundings, the product's and at most two
//   sums', γ_5 < 6u).
//
// Inputs:  positions x, y, z per region (unit sphere) and normals (unit length), in Real (a float
//          twin rounds core's doubles once); the spec and its decisions: core/params/fault_planet.hpp.
// Outputs: one vote count per region; elevation = Δ·votes (the caller).
// Units:   positions and normals dimensionless (unit sphere); votes a count.
// Throws:  nothing.
// Twin:    gpu/planet/fault_lines.hpp with gpu/shaders/planet/fault_lines.comp.
// Mutants (compare/mutants/planet.cpp): planet.fault_lines.raise_only (both twins: the lowered
//   side is never lowered, votes count the raised side alone), .plane_off_centre (both twins: the
//   planes miss the centre by 0.05, dot > 0.05) and .float_dot_nudged (the float twins: each dot
//   2^-12·Σ|n_c·p_c| too high, 680 times the error model's 6u).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gt::reference {

template <class Real>
std::vector<std::int32_t> fault_votes(const std::vector<Real>& positions, const std::vector<Real>& normals);

double dot_error_bound(const std::array<double, 3>& normal, const double* position, double unit_roundoff);

}  // namespace gt::reference
