// Improved Perlin noise in 3-D (Perlin 2002, "Improving noise"; seed 002's noise3D, digest 002 §4.4.3), CPU reference.
//
// perlin3(perm, x, y, z) -> noise value, 0 at every lattice point, |value| <= 1.5 (each corner term
//   is g·d with two ±1 components, and Σ_c w_c (|d_x| + |d_y| + |d_z|) = Σ_axis e(t_axis) with
//   e(t) = (1 − fade(t))·t + fade(t)·(1 − t) <= 1/2); the largest value found by search is 1.0.
// perlin3_gradient(perm, x, y, z) -> {value, ∂/∂x, ∂/∂y, ∂/∂z}; the value is bit-identical to perlin3.
// perlin_fade(t), perlin_lerp(t, a, b): the fade and the one interpolation form of both twins (below).
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  perm (core/noise/permutation.hpp); coordinates in lattice units (one cell = 1), |x|, |y|,
//          |z| < 2^31 (the cell index is an int); period 256 in every axis.
// Outputs: the value (and gradient) at (x, y, z).
// Units:   coordinates in lattice units; values dimensionless, derivatives per lattice unit.
// Throws:  nothing.
// Twin:    gpu/shaders/noise/perlin.glsl (with permutation.glsl); seed 002's PerlinNoise.hpp noise3D.
#pragma once

#include <array>

#include "core/mutant.hpp"
#include "core/noise/permutation.hpp"

namespace gt::reference {

// fade(t) = t³(t(6t − 15) + 10), evaluated as ((t·t)·t)·(t·(t·6 − 15) + 10). Mutant
// noise.perlin3.fade_square (both twins): t² where t³ belongs (still 0 and 1 at the ends).
template <class Real>
Real perlin_fade(Real t) {
  const Real cube = mutant_active("noise.perlin3.fade_square") ? t * t : t * t * t;
  return cube * (t * (t * Real(6) - Real(15)) + Real(10));
}

// The one interpolation form of both twins: lerp(t, a, b) = a + t·(b − a).
template <class Real>
Real perlin_lerp(Real t, Real a, Real b) {
  return a + t * (b - a);
}

template <class Real>
Real perlin3(const Permutation& permutation, Real x, Real y, Real z);

template <class Real>
std::array<Real, 4> perlin3_gradient(const Permutation& permutation, Real x, Real y, Real z);

}  // namespace gt::reference
