// Steps 4–9 of seed 002's Earth-like generator (digest 002 §4.4.3, eq. 5.2–5.3; §9.3 steps 4–9), CPU reference.
//
// Plate centres and motion, base elevation, Perlin noise, collision pressure at plate borders and
// smoothing. Spec and RNG streams: core/params/planet.hpp.
// plate_motion(params, positions, partition) -> per plate: centre, shift (motion), base elevation
// pressure(formula, p_i, s_A, p_n, s_B)       -> the pressure between two regions of different plates
// smoothed_elevation(sphere, smoothing, elevation) -> step 9 on any field (jacobi, legacy or off)
// planet_elevation(sphere, params, positions, partition) -> every stage per region: E0 (base +
//   noise), E1 (+ collisions), E2 (smoothed: the result)
// Real = double is the truth; Real = float repeats the shader's operations in the order written in
// core/params/planet.hpp.
//
// Inputs:  positions 3 per region (unit length, from jitter_regions), the partition of grow_plates,
//          the cube sphere and the planet's parameters.
// Outputs: PlateMotion, the pressure, the smoothed field, PlanetElevation (core/planet/planet_state.hpp).
// Units:   elevations in generator units (sea level 0); positions dimensionless.
// Throws:  nothing.
// Twin:    gpu/planet/generator.hpp (PlanetGenerator::elevation) with gpu/shaders/planet/centre_sums.comp,
//          plate_motion.comp, elevation_noise.comp, elevation_collision.comp, elevation_smooth.comp and
//          planet.glsl.
#pragma once

#include <array>
#include <vector>

#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "reference/planet/plates.hpp"

namespace gt::reference {

template <class Real>
PlateMotion<Real> plate_motion(const PlanetParams& params, const std::vector<Real>& positions,
                               const PlatePartition& partition);

template <class Real>
Real pressure(PressureFormula formula, const Vector3<Real>& position, const Vector3<Real>& shift,
              const Vector3<Real>& neighbour_position, const Vector3<Real>& neighbour_shift);

template <class Real>
std::vector<Real> smoothed_elevation(const CubeSphere& sphere, Smoothing smoothing, std::vector<Real> elevation);

template <class Real>
PlanetElevation<Real> planet_elevation(const CubeSphere& sphere, const PlanetParams& params,
                                       const std::vector<Real>& positions, const PlatePartition& partition);

}  // namespace gt::reference
