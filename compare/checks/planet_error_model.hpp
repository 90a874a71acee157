// The error model of seed 002's planet twins (compare/algorithms/planet.cpp): how far a float
// computation of the generator (ref<float>, or the GPU fed ref<float>'s state) may lie from the one
// it is compared with, per region, fixed from the reference's state before any difference is
// measured. The spec of each step: core/params/planet.hpp.
//
// Two knobs describe the comparison: `position_error`, the largest error of a position component
// that the compared computation started from (32u for ref<float>'s own positions against
// ref<double>'s, see float_position_error; 0 when the GPU is fed ref<float>'s positions), and
// `operation_error`, the relative error of one float operation (u = 2^-24 for ref<float> against
// ref<double>; 4u between the GPU and ref<float>: GLSL allows 2.5 ulp for a division and leaves tan
// and sqrt to the implementation, and each side rounds once more).
//
// Step by step (absolute errors; n the regions summed into a centre, |S| the sum's length, |t| the
// length of eq. 5.2's tangent before normalisation, D = |p_n − p_i|, w = |p_i + s_A|; each
// normalisation amplifies an error δ of its argument by at most 2δ/|argument|):
//   centre  δc ≤ 2·n·(√3·e_p + 2^-30)/|S| + 6u     (the sum: double or 64-bit fixed point)
//   shift   δs ≤ 2m·(3δc + 4u)/|t| + 4u·m
//   noise   δE0 ≤ 4u·|b| + S·(L·f·√3·(e_p + u)·A + 64u) + 3u·S    (L = 3.9, the Perlin noise's
//           largest gradient, compare/algorithms/noise.cpp; A = Σ_k (g·2)^k / Σ_k g^k = the
//           octaves' gradient gain for g = 0.5; 64u the noise's arithmetic, ibid.)
//   pair    code: δd ≤ 2(2√3·e_p + 2u)/D + 4u; δt ≤ 2((e_p + δs)·√3 + 2u)/w + 4u + √3·e_p + 2u;
//           δterm ≤ √3·δs·|t| + |s|·(δt + |t|·δd) + 4u·|s|·|t| per side
//           thesis: δv ≤ √3·δs + 2√3·|s|·e_p + 6u; δterm ≤ 2|v|·D·δv + |v|²·(2√3·e_p + 2u) + 6u·|v|²·D
//   collide δE1 ≤ δE0 + C·Σ pairs δpair + 3u·(|E0| + C·Σ|pressure|)
//   smooth  jacobi: the largest δE1 of the stencil + 11u·its largest |E1|; legacy: the largest δE1
//           anywhere + 11u·max|E1| (the blend chains through regions already blended).
#pragma once

#include <vector>

#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/planet/planet_state.hpp"

namespace gt {

struct PlanetErrorModel {
  double position_error = 0.0;   // e_p
  double operation_error = 0.0;  // u
};

// 32u: a, b take 4 roundings; u = 2a − 1 one more, doubled; tan(θu)/tan θ three (θ and tan θ
// rounded once each) times the warp's slope θ/(cos²θ·tan θ) <= 1.77; the normalisation 6.
double float_position_error();
// What the GPU's own positions may differ from ref<float>'s: the same operations, each within 4u.
double gpu_position_error();

struct ElevationBounds {
  std::vector<double> noisy;
  std::vector<double> collided;
  std::vector<double> smoothed;
};

// Per-region bounds of |E_float − E_reference| for each stage, from ref<double>'s state.
ElevationBounds elevation_bounds(const CubeSphere& sphere, const PlanetParams& params,
                                 const std::vector<double>& positions, const PlatePartition& partition,
                                 const PlanetElevation<double>& reference, const PlanetErrorModel& model);

}  // namespace gt
