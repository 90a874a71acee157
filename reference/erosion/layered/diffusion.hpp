// Sediment diffusion on seed 001's layered ground (digest 001 §3.8; step 8 of §4), CPU reference.
//
// diffusion_step(ground, water, params), double-buffered: every column's shares σ_k toward its edge
//   neighbours (pipes L, R, T, B; none outside a closed border) are computed first, from the water
//   as it stands:
//     uniform (the thesis): σ_k = sediment_diffusion for each neighbour;
//     water (its code):     σ_k = ½·w_k / base with base = w + ½·w_L + ½·w_R + ½·w_T + ½·w_B summed
//                           in that order over the neighbours there are; base = 0: σ = 0.
//   Then each diffused kind q of every column becomes, from the values before the step,
//     q' = max(q − Σ_k q·σ_k, 0) + Σ_k q_{n_k}·σ_{n_k, k^1}      (sums in pipe order)
//   — the thesis's scatter-then-gather form of a 5-point blur: what leaves one column arrives, as
//   the same float product, in its neighbour. The diffused kinds are the suspended org .. boulders,
//   and with `regolith_diffusion` (the thesis) the regolith's org and sand as well.
//   Nothing when sediment_diffusion = 0.
//
// Inputs:  ground (its grid and border only), water (LayeredWater<Real>: w and the carried kinds),
//          params (sediment_diffusion, diffusion_weighting, regolith_diffusion, border).
// Outputs: water.carried in place; nothing is converted.
// Units:   metres (the carried thicknesses), σ dimensionless.
// Throws:  nothing.
// Twin:    gpu/shaders/erosion/layered/diffusion.comp, run by gpu/erosion/layered/iteration.hpp.
// Decisions:
//   - The uniform weights move sediment into dry columns too (the thesis's blur knows no water);
//     there force erosion's capacity is 0 and it settles. The code's weights send nothing to a dry
//     neighbour and keep everything in a column whose neighbourhood is dry.
//   - The max(…, 0) guards the rounding of Σσ = 1 (the water weighting of a dry column among wet
//     ones sends all it holds): an ulp too many would leave −0-ish dust; the material ledger's
//     model counts the rounding (compare/algorithms/layered.cpp).
#pragma once

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void diffusion_step(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params);

}  // namespace gt::reference
