// Error models of the `erosion.pipe` checks (issue 11): every bound here is fixed before a run
// from the parameters, the forcing and the state a comparison starts from, never from what the
// run measures. Used by compare/algorithms/pipes.cpp and tests/pipes_*_test.cpp.
//
// Notation: u is the unit roundoff of the arithmetic in question (2^-24 float, 2^-53 double); one
// correctly rounded operation changes a value v by at most u·|v|. GLSL 4.50 §4.7.1 licenses 2.5
// ulp (5u) for division and square root; llvmpipe rounds them correctly, other devices may not,
// so the GPU bounds allow 5u where a division or square root enters.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/params/hydraulic.hpp"

namespace gt {

inline constexpr double pipe_float_roundoff = 0x1p-24;
inline constexpr double pipe_double_roundoff = 0x1p-53;

// ---------------------------------------------------------------------------------------------
// Ledgers against what was asked.

// The volume of water asked for per step, m³: Δt·(Σ_valid (rain_rate + rain_map)·l_x·l_y +
// Σ source rates), in double from the parameters and the forcing alone (no twin involved).
double pipe_asked_volume_per_step(const PipeConstants& constants, const HydraulicForcing& forcing,
                                  const Grid<double>& terrain);

// Bound on |water added − asked| after `steps` steps, relative to the water handled W_0 + asked.
// Model: stage 1 adds the depth r = Δt·(rate + map) to d, rounded: r itself carries at most 4
// roundings (the casts of Δt, rate and map, their sum, the product; in double 2 plus the
// difference d_A − d the ledger forms and the product with the cell area), so r errs by 4u·r; the
// addition d + r rounds by u·d_A per cell, and Σ d_A·l_x·l_y ≤ W_0 + asked (water only leaves
// otherwise). Each of the `sources` additions rounds once more, by at most u·d_A·l_x·l_y ≤ u·(W_0 +
// asked) at its cell. Over n steps: |added − asked| ≤ u·((1 + sources)·n + 4)·(W_0 + asked), plus
// the double ledger's compensated sums and the host's products (8·2^-53) and second-order terms
// (the rounding of W itself, below 2^-10 of the bound).
double pipe_water_added_bound(double unit_roundoff, int steps, std::size_t sources);

// Bound on |E_t − K/(1 − K)·Σ_{τ≤t} W_τ| relative to Σ_{τ≤t} W_τ/(1 − K), K = K_e·Δt: E_t is the
// evaporation the twin booked (Σ of d_B − d over cells and steps), W_τ the water it holds after
// step τ (after evaporation). Model per cell: d = fl(d_B·fl(1 − K)) errs from d_B·(1 − K) by the
// rounding of the kept share (u) and of the product (u); d_B − d is exact for 1 − K ≥ ½ (Sterbenz)
// and rounds once (u) otherwise. Predicting d_B·K from d·K/(1 − K) carries the first two
// roundings, the booked d_B − d all three: |booked − predicted| ≤ (3u + u²)·d_B. The double
// terms: K, 1 − K and K/(1 − K) formed on the host, the compensated sums (8·2^-53, times
// max(1, K/(1 − K)) for the cancellation in 1 − K). Evaporation at another rate than K_e (twice
// it, say) moves the ratio by about K: far beyond 3u whenever K_e·Δt > 1e-5 or so.
double pipe_evaporation_bound(double unit_roundoff, double evaporated_share);

// max over the ledger's entries of |water_added_t − t·V| / (W_0 + t·V), V = asked volume per step.
// `water_added` is what the twin's additions put into its depths, Σ(d_A − d), read from its
// state: a rain pass that adds half the rain shows here, where the water balance (which uses the
// same `water_added`) still closes.
double pipe_water_added_error(const std::vector<PipeLedgerEntry>& ledger, double asked_per_step);

// max over entries (after entry 0) of |E_t − K/(1 − K)·Σ_{τ≤t} W_τ| / (Σ_{τ≤t} W_τ/(1 − K)), K =
// K_e·Δt from the parameters: the ratio of what the twin booked as evaporated to the water it held
// is the rate it evaporated at, so evaporation at twice the rate shows here even though the water
// balance, booking what was taken, closes. 0 for K ≥ 1 (nothing is left to predict from).
double pipe_evaporation_error(const std::vector<PipeLedgerEntry>& ledger, double evaporated_share);

// ---------------------------------------------------------------------------------------------
// Rounding growth of a run.

// The growth model of tests/pipes_gpu_test.cpp (StepsFollowTheDoubleReferenceAtAHighBase): each
// step adds at most 32 float roundings of the scale S a field is computed from, and the stable
// pipe model (K ≤ 1, CFL ≤ 1) does not amplify them over a short stretch: e_n ≤ n·32·u·S.
double pipe_rounding_growth(int steps, double scale);

// ---------------------------------------------------------------------------------------------
// Shadow steps: the GPU loaded with ref<float>'s state, both stepped `steps` times.

// The fields' own sizes in the state a shadow step starts from: a bound wider than a share of them
// cannot tell a bug from rounding (compare/stepped_case.hpp ShadowBound::scale).
struct PipeShadowScales {
  double depth = 0.0;     // max d, m
  double relief = 0.0;    // max |b − b_n| over neighbours, m (the terrain's: its changes are small beside b)
  double sediment = 0.0;  // max s, m
  double regolith = 0.0;  // max r, m
  double flux = 0.0;      // max f, m³/s
  double speed = 0.0;     // max(|u|, |v|), m/s
  std::vector<double> layers;  // max b_k of each of Šťava's layers, m
};

template <class Real>
PipeShadowScales pipe_shadow_scales(const PipeState<Real>& start, const PipeConstants& constants);

// Bounds on |candidate − ref<float>| value by value (cell by cell, pipe by pipe) after `steps` steps
// from the same state `start` (float values, held in double): a state of the same layout whose
// values are the bounds. The model is the reference's own step run in interval arithmetic with each
// operation's rounding folded in (core/rounding_interval.hpp): every value carries the interval
// of what a float implementation of the step may hold there (u for + − ×, GLSL's 2.5 ulp for ÷ and
// √). ref<float> lies in that interval, and so does the exact step; a candidate that forms the same
// formulas in another order is taken to lie within the interval's width of the exact step too, so
// the bound is twice the width. So every bound comes from the cell's own depth, speed, sediment,
// tilt and its neighbours' fluxes, stage by stage, and grows over several steps as the errors
// themselves do. Decided before the candidate is read, from `start`, the constants and the forcing
// alone.
// What it leaves out: a branch that jumps where one rounding can switch it (the thermal step's
// talus threshold, a cell dry in one twin and wet by an ulp in the other) moves a whole transfer;
// should that happen the check fails at that cell and says where.
PipeState<double> pipe_shadow_bounds(const PipeState<double>& start, const PipeConstants& constants,
                                     const HydraulicForcing& forcing, int steps);

}  // namespace gt
