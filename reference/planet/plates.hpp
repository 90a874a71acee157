// Steps 2–3 of seed 002's Earth-like generator (digest 002 §4.4.2, Algorithm 3; §9.3 steps 2–3), CPU reference.
//
// Tectonic plates by a multi-seed flood fill over the cube sphere's 8-neighbourhoods, and the edge
// regions. Spec and RNG streams (seeds, rates, expansions per cycle, the synchronous and legacy
// rules): core/params/planet.hpp.
// plate_seeds(params)              -> the seed region of each plate, distinct
// plate_rates(params)              -> each plate's rate, float, as both twins compute it
// plate_expansions(params, rates, plate, cycle) -> expansions of `plate` in `cycle` (synchronous rule)
// grow_plates(sphere, params)      -> the partition by params.plate_rule
// edge_regions(sphere, plate)      -> 1 where a valid neighbour has another plate
//
// Inputs:  the cube sphere and the planet's parameters (plates at most 6R², as
//          planet_params_from_json enforces); `plate`: one plate per region.
// Outputs: seeds, rates, expansion counts, PlatePartition (core/planet/planet_state.hpp), edge flags.
// Units:   plates are integers: no Real; the twins must agree region for region.
// Throws:  nothing.
// Twin:    gpu/planet/generator.hpp (PlanetGenerator::grow_plates) with gpu/shaders/planet/plate_seeds.comp,
//          plate_expansions.comp, plate_claim.comp, plate_edges.comp and planet.glsl (synchronous rule
//          only: the legacy rules are CPU only).
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
