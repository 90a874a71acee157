// The apply pass shared by talus collapse (§3.10) and soil creep (§3.11) of seed 001's layered ground, CPU reference.
//
// apply_outflows(ground, outflows, params, clear_vegetation, conversions): given every column's outflow
// to each of its 8 neighbours (computed from one snapshot of the ground), move the material. Both
// processes are "compute all fluxes, then all deposits" (digest §3.10, §4), so the result does not
// depend on any scan order:
//   for each column c, reading the donors' layers from the snapshot:
//   1. remove_soil(c, min(Σ_k out[c][k], thickness of c's topmost non-empty layer));
//   2. gather the fluxes of the neighbours n_k, k = 0..7 in gt::pipe_offsets order: the flux
//      out[n_k][k^1] carries the composition of n_k's topmost non-empty layer (S_j = V_j·(a/h_layer),
//      the soil–rock flux of §3.10) or, from bedrock, fragments(type, a) — a conversion, counted;
//   3. deposit the gathered composition once with reserve-then-deposit (§3.1).
//   With `clear_vegetation` (talus, §3.15), a column that gives or receives material loses its
//   vegetation.
// random_factor(on, seed, c, step, stream) -> rand(0.9, 1) = 0.9 + 0.1·u with
//   u = uniform01(random_u32(seed, c, step, stream)); 1 when off.
// neighbour_surfaces(ground, border, x, y) -> the surface heights of column (x, y)'s 8 neighbours;
//   +∞ where a closed border has none.
// clamp_to_available(amounts, available): the availability clamp: when Σ_k amounts > available,
//   every amount × available/Σ.
//
// Inputs:  ground and params (valid); outflows: per column, to neighbour k, in metres.
// Outputs: the ground after the move; `conversions` gains the fragmentation of bedrock.
// Units:   metres; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/ground_buffers.hpp (LayeredGroundBuffers::compute_then_apply) with
//          gpu/shaders/erosion/layered/apply.comp.
// Decisions: the fluxes of one step are summed and deposited together (the code deposits them one by
//          one, which would push part of one neighbour's arrival into the subsoil under another's).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
using NeighbourAmounts = std::array<Real, layered_neighbour_count>;
template <class Real>
using Outflows = std::vector<NeighbourAmounts<Real>>;  // per column, to neighbour k, m

// rand(0.9, 1) = 0.9 + 0.1·u with u = uniform01(random_u32(seed, c, step, stream)); 1 when off.
template <class Real>
Real random_factor(bool on, std::uint32_t seed, std::size_t c, std::uint32_t step, std::uint32_t stream);

// Surface heights of column (x, y)'s 8 neighbours; +∞ where a closed border has none.
template <class Real>
NeighbourAmounts<Real> neighbour_surfaces(const LayeredGround<Real>& ground, LayeredBorder border, int x, int y);

// The availability clamp: when Σ_k amounts > available, every amount × available/Σ.
template <class Real>
void clamp_to_available(NeighbourAmounts<Real>& amounts, Real available);

template <class Real>
void apply_outflows(LayeredGround<Real>& ground, const Outflows<Real>& outflows, const LayeredParams& params,
                    bool clear_vegetation, LayeredConversions& conversions);

}  // namespace gt::reference
