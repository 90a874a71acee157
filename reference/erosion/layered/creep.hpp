// Soil creep on the layered ground (digest 001 §3.11, Roering et al. 1999, eq. 3.4), CPU reference.
//
// creep_outflows(ground, params, step) -> Outflows: every column's creep outflow to each neighbour,
//   from `ground` as it is.
// creep_step(ground, params, step, conversions): one step, compute-then-apply like talus.
//   Compute, for every column c from one snapshot, on c's topmost non-empty soil layer (bedrock
//   does not creep; no soil, no creep), thickness V, organic thickness V_org:
//   - per neighbour k with Δh_k = h_c − h_k > 0 (no threshold): slope s_k = Δh_k/l_k and Roering's
//     flux q_k = K_z·s_k/D_k, D_k = 1 − (s_k/S_c)² (thesis), or max(D_k, floor) (seed001_code);
//   - Δmaterial = Δt·(V_org/V)·Σ_k q_k·rand_c(0.9, 1)/2 (eq. 3.4; rand off: 1), clamped to V, split
//     to the neighbours ∝ q_k (the code's split; the thesis says "as talus").
//   Apply: apply_outflows (transfer.hpp) without touching vegetation (creep does not).
//
// Inputs:  ground (LayeredGround<Real>) and params (LayeredParams), both valid (validate_layered_params,
//          check_layered_ground) and not checked here, as talus_step (talus.hpp); step, the counter of
//          the random draws.
// Outputs: the ground after the step. Creep converts nothing; `conversions` is passed for the common
//          step protocol and stays as it is.
// Units:   metres; K_z a height rate (m/s) at unit slope, q_k in m/s, Δt in seconds.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/creep.hpp (layered_creep) with gpu/shaders/erosion/layered/creep_outflow.comp
//          and apply.comp.
// Decisions:
//   - Units: the thesis writes eq. 3.4 with l = 1 m; K_z is taken as a height rate (m/s) at unit
//     slope, so q_k is in m/s and Δmaterial in metres.
//   - The thesis's law is singular: at s_k ≥ S_c (D_k ≤ 0) the flux is unbounded. Taken as its
//     limit: the whole layer moves (when V_org > 0), split among those neighbours ∝ s_k.
//   - rand is one draw per column (eq. 3.4 has one Δmaterial per column), stream creep_cell_stream.
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"
#include "reference/erosion/layered/transfer.hpp"

namespace gt::reference {

// Every column's creep outflow to each neighbour, from `ground` as it is.
template <class Real>
Outflows<Real> creep_outflows(const LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step);

// Checks the ground (check_layered_ground), then one compute-then-apply step. Creep converts
// nothing; `conversions` is passed for the common step protocol and stays as it is.
// Valid parameters and ground assumed, as talus_step (talus.hpp).
template <class Real>
void creep_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions);

}  // namespace gt::reference
