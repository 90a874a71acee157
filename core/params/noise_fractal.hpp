// Parameters of the fractal sums of a basis noise (reference/noise/fractal.hpp and
// gpu/shaders/noise/fractal.glsl) and the per-run constants both twins derive from them.
//
//   fbm             seed 002's normalizedOctaveNoise3D (digest 002 §4.4.3): Σ gain^k·n(lacunarity^k·p)
//                   divided by Σ gain^k; uses octaves, lacunarity, gain.
//   ridged          Musgrave's ridged multifractal as Blender's BLI_noise_mg_ridged_multifractal;
//                   uses octaves (whole part only), lacunarity, H, offset, gain (the weight feedback).
//   hetero_terrain  Musgrave's heterogeneous terrain as Blender's BLI_noise_mg_hetero_terrain
//                   (digest 001 §3.18); uses octaves, lacunarity, H, offset.
//
// Exact twins: every power is a repeated multiplication in Real, in the same order on both sides,
// starting from constants derived here once in double and rounded once to Real (float for the GPU):
//   spectral_ratio = lacunarity^(−H) (Blender's pwHL; std::pow in double, never pow in a shader),
//   fbm_normalisation = 1 / (Σ_{k<n} gain^k + r·gain^n), n = floor(octaves), r = octaves − n
//   (the sum by repeated multiplication in double; a multiplication replaces the division in the
//   shader, whose `/` is not correctly rounded on every GPU).
// `octaves` may be fractional: fbm and hetero_terrain add r times one more octave (as Blender does),
// so the sum is continuous in `octaves`; ridged uses the whole part only (as Blender does).
// All quantities are dimensionless (noise units).
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace gt {

struct FractalParams {
  double octaves = 6.0;     // >= 1, at most max_fractal_octaves; may be fractional
  double lacunarity = 2.0;  // frequency ratio of successive octaves, > 0
  double gain = 0.5;        // fbm: amplitude ratio of successive octaves; ridged: weight feedback gain
  double H = 1.0;           // ridged, hetero_terrain: octave k is weighted lacunarity^(−H·k)
  double offset = 1.0;      // ridged, hetero_terrain: added to the basis noise
};

inline constexpr double max_fractal_octaves = 32.0;

// What the twins compute with. FractalTerms<float> has the layout of the GLSL struct GtFractalTerms
// (gpu/shaders/noise/fractal.glsl) under std140 and std430: 7 scalars at offsets 0, 4, ..., 24
// (checked against the linked programs through gpu/noise/fractal_terms_layout.hpp).
template <class Real>
struct FractalTerms {
  int whole_octaves;       // n = floor(octaves)
  Real remainder;          // r = octaves − n, in [0, 1)
  Real lacunarity;
  Real gain;
  Real spectral_ratio;     // lacunarity^(−H)
  Real fbm_normalisation;  // 1 / (Σ_{k<n} gain^k + r·gain^n)
  Real offset;
};

// 1 / (Σ_{k<n} gain^k + r·gain^n), in double.
inline double fbm_normalisation(const FractalParams& params) {
  const double whole = std::floor(params.octaves);
  double weight_sum = 0.0;
  double amplitude = 1.0;
  for (int octave = 0; octave < static_cast<int>(whole); ++octave) {
    weight_sum += amplitude;
    amplitude *= params.gain;
  }
  weight_sum += (params.octaves - whole) * amplitude;
  return 1.0 / weight_sum;
}

// Throws std::invalid_argument for octaves outside [1, max_fractal_octaves], a lacunarity <= 0 or a
// negative gain (each would make a sum that is empty, undefined or of alternating sign).
template <class Real>
FractalTerms<Real> fractal_terms(const FractalParams& params) {
  if (!(params.octaves >= 1.0 && params.octaves <= max_fractal_octaves)) {
    throw std::invalid_argument("fractal octaves must lie in [1, 32]");
  }
  if (!(params.lacunarity > 0.0)) throw std::invalid_argument("fractal lacunarity must be > 0");
  if (!(params.gain >= 0.0)) throw std::invalid_argument("fractal gain must be >= 0");
  const double whole = std::floor(params.octaves);
  return {static_cast<int>(whole),
          static_cast<Real>(params.octaves - whole),
          static_cast<Real>(params.lacunarity),
          static_cast<Real>(params.gain),
          static_cast<Real>(std::pow(params.lacunarity, -params.H)),
          static_cast<Real>(fbm_normalisation(params)),
          static_cast<Real>(params.offset)};
}

}  // namespace gt
