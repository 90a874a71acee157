// The float noise error model; see noise_error_model.hpp.
#include "compare/checks/noise_error_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "compare/checks/error_model.hpp"

namespace gt {

// The lattice bases bound |value| by their arithmetic terms (scale times corners).
//
// The cellular bases (reference/noise/cellular.hpp), F_k <= sqrt(4.25) = 2.062 for k <= 4:
//   lipschitz: the distances are 1-Lipschitz in p, so 2·F_k − 1 is 2-Lipschitz, 2·(F2 − F1) − 1
//   4-Lipschitz, crackle 2·10·2 = 40; cell noise is constant between planes (0).
//   arithmetic: a distance rounds (local − feature) on each axis (u), its square (3u relative with
//   it) and two sums (2u): 5u on d², 2.5u on d, plus the square root's own rounding, u in C++ and 5u
//   (GLSL's licence, core/rounding_interval.hpp) on the GPU, so two implementations' distances
//   differ by at most 11u·d, and so their F_k (the k-th smallest of values each within 11u·d of the
//   other's) by 11u·2.062 = 22.7u. Signed, 2·F − 1 doubles that and rounds once more in each
//   (u·3.13 each): 51.8u. 2·(F2 − F1) − 1: 2·(2·22.7u + 2·u·2.062) + 6.3u = 105.3u. Crackle,
//   2·min(1, 10·(F2 − F1)) − 1: 2·(10·49.5u + 2u) + 2u = 996u. As 8u·terms: 7, 14, 125. Cell noise's
//   values are exact in float; its 1 term is a fractal sum's own roundings of values up to 1.
//   largest_value: 2·2.062 − 1 = 3.13 (1 for crackle and cell noise).
NoiseTraits traits_of(NoiseBasis basis) {
  constexpr double farthest_signed = 2.0 * 2.0616 - 1.0;
  switch (basis) {
    case NoiseBasis::simplex2: return {9.2, 70.0 * 3, 70.0, std::sqrt(2.0), 70.0 * 3};
    case NoiseBasis::simplex3: return {8.0, 32.0 * 4, 32.0, std::sqrt(2.0), 32.0 * 4};
    case NoiseBasis::simplex4: return {13.9, 27.0 * 5, 27.0, std::sqrt(3.0), 27.0 * 5};
    case NoiseBasis::perlin3:
    case NoiseBasis::perlin3_texture: return {3.9, 8.0, 0.0, 0.0, 8.0};
    case NoiseBasis::voronoi_f1:
    case NoiseBasis::voronoi_f2:
    case NoiseBasis::voronoi_f3:
    case NoiseBasis::voronoi_f4: return {2.0, 7.0, 0.0, 0.0, farthest_signed};
    case NoiseBasis::voronoi_f2f1: return {4.0, 14.0, 0.0, 0.0, farthest_signed};
    case NoiseBasis::voronoi_crackle: return {40.0, 125.0, 0.0, 0.0, 1.0};
    case NoiseBasis::cell_noise: return {0.0, 1.0, 0.0, 0.0, 1.0};
  }
  return {13.9, 210.0, 0.0, 0.0, 210.0};
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

std::vector<std::uint8_t> lattice_jump_samples(const NoiseParams& params) {
  if (!is_cellular(params.basis)) return {};
  const auto& sampling = params.sampling;
  const auto reduced = reduced_origin(params);
  const auto& fractal = params.fractal_params;
  const int octaves = params.fractal == Fractal::none ? 1 : static_cast<int>(std::ceil(fractal.octaves));
  NoiseParams float_side = params;
  float_side.sampling.origin = reduced;
  const double extent = largest_coordinate(float_side);  // of the coordinates the float twins form
  // Whether the point of grid position (i, j) may jump.
  const auto may_jump = [&](int i, int j) {
    std::array<double, 3> exact{}, shift{};
    std::array<float, 3> rounded{};
    for (int axis = 0; axis < 3; ++axis) {
      const int index = axis == 0 ? i : (axis == 1 ? j : 0);
      exact[axis] = sampling.origin[axis] + static_cast<double>(index) * sampling.step;
      rounded[axis] = axis == 2 ? static_cast<float>(reduced[axis])
                                : static_cast<float>(reduced[axis]) +
                                      static_cast<float>(index) * static_cast<float>(sampling.step);
      shift[axis] = sampling.origin[axis] - reduced[axis];
    }
    double frequency = 1.0;
    for (int octave = 0; octave < octaves; ++octave) {
      const double margin = (3.0 + octave) * unit_roundoff_float * extent * frequency;
      for (int axis = 0; axis < 3; ++axis) {
        const double nearest_plane = std::round(exact[axis]);
        if (std::floor(static_cast<double>(rounded[axis])) + shift[axis] * frequency != std::floor(exact[axis])) return true;
        if (exact[axis] != nearest_plane && std::abs(exact[axis] - nearest_plane) <= margin) return true;
        exact[axis] = exact[axis] * fractal.lacunarity;
        rounded[axis] = rounded[axis] * static_cast<float>(fractal.lacunarity);
      }
      frequency *= fractal.lacunarity;
    }
    return false;
  };
  const int width = sampling.width, height = sampling.height;
  std::vector<std::uint8_t> jumps(static_cast<std::size_t>(width) * height, 0);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      bool jump = may_jump(i, j);
      if (params.tileable) jump = jump || may_jump(i + width, j) || may_jump(i, j + height) || may_jump(i + width, j + height);
      jumps[static_cast<std::size_t>(j) * width + i] = jump ? 1 : 0;
    }
  }
  return jumps;
}

double noise_precision_bound(const NoiseParams& params, double extent) {
  const auto traits = traits_of(params.basis);
  const auto [weights, weighted_frequencies] = octave_sums(params);
  const double coordinates = traits.lipschitz * 2.0 * unit_roundoff_float * extent * weighted_frequencies *
                             std::sqrt(static_cast<double>(noise_dimension(params.basis)));
  return noise_arithmetic_bound(params) + coordinates + switched_contribution(params) * weights;
}

}  // namespace gt
