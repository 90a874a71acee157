// The float noise error model; see noise_error_model.hpp.
#include "compare/checks/noise_error_model.hpp"

#include <algorithm>
#include <cmath>

#include "compare/checks/error_model.hpp"

namespace gt {

NoiseTraits traits_of(NoiseBasis basis) {
  switch (basis) {
    case NoiseBasis::simplex2: return {9.2, 70.0 * 3, 70.0, std::sqrt(2.0)};
    case NoiseBasis::simplex3: return {8.0, 32.0 * 4, 32.0, std::sqrt(2.0)};
    case NoiseBasis::simplex4: return {13.9, 27.0 * 5, 27.0, std::sqrt(3.0)};
    case NoiseBasis::perlin3:
    case NoiseBasis::perlin3_texture: return {3.9, 8.0, 0.0, 0.0};
  }
  return {13.9, 210.0, 0.0, 0.0};
}

std::pair<double, double> octave_sums(const NoiseParams& params) {
  if (params.fractal == Fractal::none) return {1.0, 1.0};
  const auto& fractal = params.fractal_params;
  double weight = 1.0, frequency = 1.0, weights = 0.0, weighted_frequencies = 0.0;
  const double ratio = params.fractal == Fractal::fbm ? fractal.gain : std::pow(fractal.lacunarity, -fractal.H);
  for (int octave = 0; octave < static_cast<int>(std::ceil(fractal.octaves)); ++octave) {
    weights += weight;
    weighted_frequencies += weight * frequency;
    weight *= ratio;
    frequency *= fractal.lacunarity;
  }
  // fbm is normalised by Σ weights. Ridged squares (offset - |n|) and feeds back a weight clamped
  // to [0, 1]: an error δn grows to at most 2(|offset| + 1)·max(1, gain)·δn per term.
  // Hetero_terrain multiplies the running value by (1 + (n + offset)·w_k): errors grow with the
  // value, at most Π_k (1 + (|offset| + 1)·w_k).
  if (params.fractal == Fractal::fbm) return {1.0, weighted_frequencies / weights};
  double amplification = 2.0 * (std::abs(fractal.offset) + 1.0) * std::max(1.0, fractal.gain);
  if (params.fractal == Fractal::hetero_terrain) {
    amplification = 1.0;
    double octave_weight = 1.0;
    for (int octave = 0; octave < static_cast<int>(std::ceil(fractal.octaves)); ++octave) {
      amplification *= 1.0 + (std::abs(fractal.offset) + 1.0) * octave_weight;
      octave_weight *= ratio;
    }
  }
  return {weights * amplification, weighted_frequencies * amplification};
}

double switched_contribution(const NoiseParams& params) {
  const auto traits = traits_of(params.basis);
  const double reach = params.kernel_radius_squared - 0.5;
  if (traits.scale == 0.0 || params.basis == NoiseBasis::simplex2 || reach <= 0.0) return 0.0;
  return 2.0 * traits.scale * std::pow(reach, 4) * traits.gradient_length * std::sqrt(params.kernel_radius_squared);
}

double noise_arithmetic_bound(const NoiseParams& params) {
  return 8.0 * unit_roundoff_float * traits_of(params.basis).arithmetic_terms * octave_sums(params).first;
}

double noise_precision_bound(const NoiseParams& params, double extent) {
  const auto traits = traits_of(params.basis);
  const auto [weights, weighted_frequencies] = octave_sums(params);
  const double coordinates = traits.lipschitz * 2.0 * unit_roundoff_float * extent * weighted_frequencies *
                             std::sqrt(static_cast<double>(noise_dimension(params.basis)));
  return noise_arithmetic_bound(params) + coordinates + switched_contribution(params) * weights;
}

}  // namespace gt
