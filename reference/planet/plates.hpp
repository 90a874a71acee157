// Step 2–3 of seed 002's Earth-like generator (digest 002 §4.4.2, Algorithm 3; §9.3 steps 2–3), CPU
// reference: tectonic plates by a multi-seed flood fill over the cube sphere's 8-neighbourhoods, and
// the edge regions. GLSL twin: gpu/shaders/planet/plates_*.comp. Spec and RNG streams (seeds,
// rates, expansions per cycle, the synchronous and legacy rules): core/params/planet.hpp.
//
// plate_seeds(params)              -> the seed region of each plate, distinct
// plate_rates(params)              -> each plate's rate, float, as both twins compute it
// plate_expansions(params, rates, plate, cycle) -> expansions of `plate` in `cycle` (synchronous rule)
// grow_plates(sphere, params)      -> the partition by params.plate_rule
// edge_regions(sphere, plate)      -> 1 where a valid neighbour has another plate
// Plates are integers: no Real; the twins must agree region for region.
#pragma once

#include <cstdint>
#include <vector>

#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/planet/planet_state.hpp"

namespace gt::reference {

std::vector<std::int32_t> plate_seeds(const PlanetParams& params);
std::vector<float> plate_rates(const PlanetParams& params);
int plate_expansions(const PlanetParams& params, const std::vector<float>& rates, int plate, int cycle);
PlatePartition grow_plates(const CubeSphere& sphere, const PlanetParams& params);
std::vector<std::uint8_t> edge_regions(const CubeSphere& sphere, const std::vector<std::int32_t>& plate);

}  // namespace gt::reference
