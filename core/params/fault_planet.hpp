// Parameters of the fault-line planet (seed 002 §2.5, the survey's baseline after Hugo Elias and
// Paul Bourke, "Modelling fake planets", 2000): N random planes through the sphere's centre, each
// raising the surface on one side by Δ and lowering it on the other. Shared by
// reference/planet/fault_lines.cpp and gpu/planet/fault_lines.cpp; with core/planet/cube_sphere.hpp
// and core/rng.hpp, all the twins share.
//
// Spec (the thesis's plain-English loop, Fig. 2.8; it gives no Δ and no schedule):
//   for i in 0..N-1: n_i = a unit normal; for each region r: votes(r) += dot(n_i, p_r) > 0 ? +1 : -1
//   elevation(r) = Δ·votes(r)
// Decisions of this project:
//   - the surface is the cube sphere's regions (seed 002's own surface), each at its cell's centre
//     on the warped sphere (no jitter): p_r = sphere_position(local_position(r));
//   - n_i is uniform on the sphere from the counter RNG: z = 2·U(i, 0) - 1, φ = 2π·U(i, 1),
//     n = (sqrt(1 - z²)·cos φ, sqrt(1 - z²)·sin φ, z), U(i, k) = uniform01(random_u32(seed, i, k,
//     fault_stream)), computed in double here (fault_normals) and rounded once by each float twin;
//   - a constant Δ (no schedule): the `step` default 0.04 keeps 1000 faults' relief inside the
//     ±4 of seed 002's §4.3 palette; a dot of exactly 0 lowers (the loop's `else`);
//   - each twin counts integer votes (exact in any precision) and multiplies by Δ once, so the float
//     twins can differ from ref<double> only where a dot's sign flips.
// Units: positions on the unit sphere; elevations in generator units (sea level 0), as the
// earth-like planet's.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/param_table.hpp"

namespace gt {

struct FaultPlanetParams {
  int resolution = 50;      // R: cells along a cube face's edge
  int faults = 1000;        // N
  double step = 0.04;       // Δ, generator units
  std::uint32_t seed = 1;
};

// The RNG stream of the fault normals (its own, apart from the earth-like planet's draws).
inline constexpr std::uint32_t fault_stream = 0x66617531u;

// At most regions × faults dot products a run makes (ref<double>, ref<float> and the GPU each): about
// 2 s of ref<double> on one core; more is refused before anything runs.
inline constexpr double max_fault_dot_products = 2.0e9;

const ParamTable<FaultPlanetParams>& fault_planet_param_table();
const ParamSpecs& fault_planet_param_specs();
// The struct from resolve_params' output; throws InputError when 6R²·N exceeds
// max_fault_dot_products.
FaultPlanetParams fault_planet_params_from_json(const nlohmann::json& resolved);

// n_0 .. n_{N-1}, unit length in double, as the spec draws them.
std::vector<std::array<double, 3>> fault_normals(const FaultPlanetParams& params);

// The regions' centres on the warped cube sphere of resolution R, x, y, z per region in region order.
std::vector<double> fault_planet_positions(int resolution);

}  // namespace gt
