// The error model of float noise against double (compare/algorithms/noise.cpp's precision bound),
// shared with the cave block, whose density is seed 004's simplex noise (compare/algorithms/cave.cpp).
//
// Absolute, in output units, for coordinates up to |x| = extent (noise units, as the float twin
// forms them):
//   coordinates: each float coordinate is rounded twice, so off by at most 2u·extent; the value
//     then moves by at most lipschitz·2u·extent·sqrt(dimension) (times the fractal's weighted
//     frequencies);
//   arithmetic: each evaluation rounds its operations; its terms are at most `arithmetic_terms` in
//     magnitude and each carries a few roundings: 8u·terms (times the fractal's weights);
//   kernel 0.6: corners the kernel reaches beyond their simplex switch when a rounding moves a
//     coordinate across a boundary (switched_contribution).
//   cellular bases: continuous between lattice planes (the sorted distances are 1-Lipschitz), and
//     a jump of up to their whole range where a rounding moves a coordinate across one, which no
//     bound covers: those samples are found before any twin runs (lattice_jump_samples) and left
//     out of the comparisons with ref<double>.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/params/noise.hpp"

namespace gt {

struct NoiseTraits {
  double lipschitz;         // largest gradient norm, noise units^-1 (measured, see below)
  double arithmetic_terms;  // output scale x corner contributions
  double scale;             // output scale of a simplex sum (70, 32, 27); 0 for Perlin
  double gradient_length;   // |g| of the simplex gradient set: sqrt(2) in 3-D, sqrt(3) in 4-D
  double largest_value;     // a bound on |value| (the blend's and the scaling's roundings scale with it)
};

// Largest gradient norms over 10^6 uniform random points of [0, 256)^d with Perlin's table, from
// the double references' analytic gradients (central differences, h = 1e-6, over 2·10^5 points for
// simplex4 and the texture variant), rounded up by 25 %: simplex2 7.33 -> 9.2; simplex3 6.38
// (kernel 0.6; 2.90 with 0.5) -> 8.0; simplex4 11.07 (0.6; 2.90 with 0.5) -> 13.9; perlin3 3.12
// and the texture variant 3.10 -> 3.9. The cellular bases' are derived in noise_error_model.cpp.
NoiseTraits traits_of(NoiseBasis basis);

// Σ_k weight_k and Σ_k weight_k·lacunarity^k of a fractal sum (1 and 1 for a single function):
// how the arithmetic and coordinate errors of the octaves add up.
std::pair<double, double> octave_sums(const NoiseParams& params);

// Seed 004's kernel radius² 0.6 (3-D, 4-D) reaches corners outside the simplex a point lies in:
// a corner at distance² >= 0.5 from every point of a simplex boundary still contributes
// scale·t⁴·(g·d) with t = r² - |d|² <= r² - 0.5, and is dropped when the point crosses into the
// next simplex (digest 004 §2.2.5). A rounding that moves a coordinate across the boundary can
// therefore switch up to two such corners: 2·scale·(r² - 0.5)⁴·|g|·sqrt(r²). 0 for r² = 0.5.
double switched_contribution(const NoiseParams& params);

// The arithmetic term alone: 8u·terms·Σweights. It is also the GPU-vs-float bound (the same float
// operations in the same order, no division).
double noise_arithmetic_bound(const NoiseParams& params);

// The samples (row-major, 1 = left out) of a cellular basis, alone or in a fractal sum, whose value
// may jump between ref<double> and a float implementation: where, at some octave k and axis of one
// of the sample's points (four where tileable), the float twins' coordinate (formed as they form
// it: float(reduced origin) + float(i)·float(step), times float(lacunarity) per octave, shifted back
// by the reduction's period) and ref<double>'s have different floors, or ref<double>'s lies within
// (3 + k)·u·extent·lacunarity^k of a lattice plane without lying on it (another implementation's
// rounding may put it on the other side; extent: the float twins' largest |coordinate|, u = 2^-24).
// Empty for the continuous bases.
std::vector<std::uint8_t> lattice_jump_samples(const NoiseParams& params);

// The float-vs-double bound of `params`' function at float coordinates up to |x| = extent: the
// three terms above, summed (strict; an upper bound).
double noise_precision_bound(const NoiseParams& params, double extent);

}  // namespace gt
