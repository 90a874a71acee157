// Step 1 of seed 002's Earth-like generator (digest 002 §4.4.1, eq. 5.1; §9.3 step 1), CPU reference.
//
// Each region's jittered offset in its cell and its centroid on the unit sphere. Spec and RNG
// streams: core/params/planet.hpp.
// jitter_regions(sphere, params) -> offsets (a, b per region, in [0, 1]) and positions (x, y, z
// per region, unit length).
//   offset = 0.5 + (U − 0.5)·j per axis;
//   a = (x + offset_a)/R, b = (y + offset_b)/R (eq. 4.1 corrected, erratum 4);
//   u = 2a − 1, v = 1 − 2b; w = P_face·(f(u), f(v), 1) with f(t) = tan(θt)/tan θ (eq. 3.5, 4.3; θ of
//   the `warp` parameter, f(t) = t for none);
//   position = w·(1/sqrt(w·w)).
// Real = double is the truth; Real = float repeats the shader's operations in that order (tan θ
// rounded to float once).
//
// Inputs:  the cube sphere (R cells along a face's edge) and the planet's parameters (jitter j, warp, seed).
// Outputs: JitteredRegions (core/planet/planet_state.hpp): offsets and positions.
// Units:   offsets in cells, positions dimensionless.
// Throws:  nothing.
// Twin:    gpu/planet/generator.hpp (PlanetGenerator::jitter) with gpu/shaders/planet/jitter.comp and
//          planet.glsl.
#pragma once

#include <vector>

#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/planet/planet_state.hpp"

namespace gt::reference {

template <class Real>
JitteredRegions<Real> jitter_regions(const CubeSphere& sphere, const PlanetParams& params);

}  // namespace gt::reference
