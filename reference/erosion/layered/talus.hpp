// Per-material talus collapse on the layered ground (digest 001 §3.10, eq. 3.1-3.3), CPU reference.
//
// talus_step(ground, params, step, conversions): one step, compute-then-apply.
//   Compute, for every column c from one snapshot:
//   - the moving layer: c's topmost non-empty layer (topsoil, subsoil, or — only when both are
//     empty — the first non-empty bedrock layer); h_layer its thickness;
//   - the threshold tan φ: over soil, tan φ_min = min over the non-empty soil layers j of
//     K_depth^j · repose_j · (1 + K_sveg·veg), repose_j = (Σ_i tan φ_i·V_i)/V in component order
//     (eq. 3.1; an empty layer has no repose); over bedrock, the least tan φ of the non-empty
//     bedrock layers exposed to air, i.e. whose top lies above the lowest neighbour's surface;
//   - per neighbour k (8, eq. 3.2): Δh = h_c − h_k, slope = Δh/l_k; if slope ≥ tan φ, the amount
//       thesis (eq. 3.3):  Δt·Δh·rand_k(0.9, 1)/2, then the availability clamp to h_layer;
//       seed001_code:      total min(½·max_k Δh·rand_c(0.9, 1), h_layer) split ∝ Δh_k/ΣΔh.
//     rand is drawn from the counter-based RNG keyed (seed, c, step, stream), streams in
//     core/layered/layered_ground.hpp, so a GPU twin draws the same numbers.
//   Apply: apply_outflows (transfer.hpp): remove, carry the layer's composition (bedrock breaks into
//   fragments by K_rock, counted in `conversions`), deposit with reserve-then-deposit; donor and
//   receiver lose their vegetation.
// soil_repose(ground, params, c) -> tan φ_min of column c's soil layers (eq. 3.1 with the depth
//   factor); +∞ when the soil is empty.
// talus_outflows(ground, params, step) -> Outflows: every column's talus outflow to each neighbour,
//   from `ground` as it is.
//
// Inputs:  ground and params, which must be valid (validate_layered_params, check_layered_ground:
//          make_layered_ground's grounds are, and the steps keep them so); they are not checked every
//          step, so that what a bug does to the state reaches the comparison's layers.* checks.
//          step: the random draws' counter.
// Outputs: the ground after the step; `conversions` gains the bedrock fragmentation.
// Units:   metres, Δt in seconds; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/talus.hpp (layered_talus) with gpu/shaders/erosion/layered/talus_outflow.comp
//          and apply.comp.
// Decisions where the thesis is vague: one layer per step (the thesis's simplification); Δh is
//   measured between surface heights; the random factor is 1 when `talus_random` is off; borders as
//   LayeredParams::border.
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"
#include "reference/erosion/layered/transfer.hpp"

namespace gt::reference {

// tan φ_min of column c's soil layers (eq. 3.1 with the depth factor); +∞ when the soil is empty.
template <class Real>
Real soil_repose(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c);

// Every column's talus outflow to each neighbour, from `ground` as it is.
template <class Real>
Outflows<Real> talus_outflows(const LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step);

// One compute-then-apply step. The parameters and the ground must be valid (validate_layered_params,
// check_layered_ground: make_layered_ground's grounds are, and the steps keep them so); they are not
// checked every step, so that what a bug does to the state reaches the comparison's layers.* checks.
template <class Real>
void talus_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions);

}  // namespace gt::reference
