// Fractal sums of a basis noise (fBm of seed 002, Musgrave's ridged multifractal and hetero terrain), CPU reference.
//
// fbm(basis, terms, x, y, z) (seed 002's normalizedOctaveNoise3D, digest 002 §4.4.3, with Blender's
// fractional octave):
//   value = (Σ_{k<n} n(q_k)·g^k + r·(n(q_n)·g^n)) · fbm_normalisation,
//   fbm_normalisation = 1/(Σ_{k<n} g^k + r·g^n). Always normalised: the only seed that uses fBm
//   (002) normalises, and the unnormalised sum is this times the known weight sum, so no flag.
//   Equals PerlinNoise.hpp's normalizedOctaveNoise3D for g = 0.5, lacunarity = 2 and whole octaves,
//   except that it multiplies by the reciprocal where that code divides (<= 1 ulp in double).
//   Keeps the basis range: |value| <= max|n|.
// ridged_multifractal(basis, terms, x, y, z) (Musgrave 1994 as Blender's BLI_noise_mg_ridged_multifractal):
//   s_0 = (offset − |n(q_0)|)², result = s_0;
//   for k = 1 .. n−1: weight = clamp(s_{k−1}·gain, 0, 1), s_k = (offset − |n(q_k)|)²·weight,
//                     result += s_k·lacunarity^(−H·k).
//   Unnormalised, as Blender: for |n| <= offset the result lies in [0, offset²·Σ_k lacunarity^(−H·k)].
//   Fractional octaves are ignored (Blender loops to (int)octaves and has no remainder term).
// hetero_terrain(basis, terms, x, y, z) (Musgrave as Blender's BLI_noise_mg_hetero_terrain, digest 001 §3.18):
//   value = offset + n(q_0);
//   for k = 1 .. n−1: value += ((n(q_k) + offset)·lacunarity^(−H·k))·value;
//   if r != 0:        value += r·(((n(q_n) + offset)·lacunarity^(−H·n))·value).
//   Continuous in octaves (the last octave fades in with r).
// OctavePoint, ridge_signal, hetero_increment: the octave point q_k and the per-octave terms above.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation
// (when the basis does).
//
// Inputs:  basis: any callable Real basis(Real x, Real y, Real z) (perlin3, perlin3_texture, simplex3
//          bound to their tables). terms: FractalTerms (core/params/noise_fractal.hpp: the parameters
//          and the constants derived from them), with n = terms.whole_octaves, r = terms.remainder.
//          Octave k samples q_k = p·lacunarity^k, computed as q_{k+1} = q_k·lacunarity per component;
//          weights are running products (amplitude *= gain, pwr *= lacunarity^(−H)).
// Outputs: the fractal value at p = (x, y, z).
// Units:   p in the basis's units (lattice cells); values in the basis's (dimensionless).
// Throws:  nothing (fractal_terms, which builds `terms`, refuses bad parameters: std::invalid_argument).
// Twin:    gpu/shaders/noise/fractal.glsl (in noise_field.comp, gpu/noise/noise_field.hpp, and planet.glsl,
//          gpu/planet/generator.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "core/mutant.hpp"
#include "core/params/noise_fractal.hpp"

namespace gt::reference {

template <class Real>
struct OctavePoint {
  std::array<Real, 3> q;

  template <class Basis>
  Real sample(const Basis& basis) const {
    return basis(q[0], q[1], q[2]);
  }
  void advance(Real lacunarity) {
    for (Real& coordinate : q) coordinate = coordinate * lacunarity;
  }
};

template <class Real, class Basis>
Real fbm(const Basis& basis, const FractalTerms<Real>& terms, Real x, Real y, Real z) {
  OctavePoint<Real> point{{x, y, z}};
  Real value = 0;
  Real amplitude = 1;
  // Mutant noise.fbm.gain_before_sample (both twins): each weight updated before its
  // octave is added, so octave k weighs gain^(k+1) against a normalisation of Σ gain^k.
  const bool gain_first = mutant_active("noise.fbm.gain_before_sample");
  for (int octave = 0; octave < terms.whole_octaves; ++octave) {
    if (gain_first) amplitude = amplitude * terms.gain;
    value = value + point.sample(basis) * amplitude;
    if (!gain_first) amplitude = amplitude * terms.gain;
    point.advance(terms.lacunarity);
  }
  if (terms.remainder != Real(0)) value = value + terms.remainder * (point.sample(basis) * amplitude);
  return value * terms.fbm_normalisation;
}

// (offset − |n(q)|)²
template <class Real, class Basis>
Real ridge_signal(const Basis& basis, const OctavePoint<Real>& point, Real offset) {
  const Real ridge = offset - std::abs(point.sample(basis));
  return ridge * ridge;
}

template <class Real, class Basis>
Real ridged_multifractal(const Basis& basis, const FractalTerms<Real>& terms, Real x, Real y, Real z) {
  OctavePoint<Real> point{{x, y, z}};
  Real signal = ridge_signal(basis, point, terms.offset);
  Real result = signal;
  Real spectral_weight = terms.spectral_ratio;
  for (int octave = 1; octave < terms.whole_octaves; ++octave) {
    point.advance(terms.lacunarity);
    // Mutant noise.ridged.unclamped_weight (both twins): the weight left unclamped.
    const Real weight = mutant_active("noise.ridged.unclamped_weight") ? signal * terms.gain
                                                                       : std::clamp(signal * terms.gain, Real(0), Real(1));
    signal = ridge_signal(basis, point, terms.offset) * weight;
    result = result + signal * spectral_weight;
    spectral_weight = spectral_weight * terms.spectral_ratio;
  }
  return result;
}

// ((n(q) + offset)·spectral_weight)·value
template <class Real, class Basis>
Real hetero_increment(const Basis& basis, const OctavePoint<Real>& point, Real offset, Real spectral_weight,
                      Real value) {
  return (point.sample(basis) + offset) * spectral_weight * value;
}

template <class Real, class Basis>
Real hetero_terrain(const Basis& basis, const FractalTerms<Real>& terms, Real x, Real y, Real z) {
  OctavePoint<Real> point{{x, y, z}};
  Real value = terms.offset + point.sample(basis);
  point.advance(terms.lacunarity);
  Real spectral_weight = terms.spectral_ratio;
  for (int octave = 1; octave < terms.whole_octaves; ++octave) {
    value = value + hetero_increment(basis, point, terms.offset, spectral_weight, value);
    spectral_weight = spectral_weight * terms.spectral_ratio;
    point.advance(terms.lacunarity);
  }
  if (terms.remainder != Real(0)) {
    value = value + terms.remainder * hetero_increment(basis, point, terms.offset, spectral_weight, value);
  }
  return value;
}

}  // namespace gt::reference
