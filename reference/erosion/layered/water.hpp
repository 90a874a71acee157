// Water sources, sinks and pipe flow on seed 001's layered ground (digest 001 §3.3, §3.7, §3.19), CPU reference.
//
// water_sources(ground, water, params, step, conversions), per column (step 1 of §4), in this order:
//   drain (the code's one-shot "Drain water", at the start of iteration drain_step): every column
//   loses its water and what the water carries. Rain, on iterations below rain_steps (all with 0):
//   w ← w + Δt·rain_rate (the thesis's "add a constant to every column"; the code's rain is a
//   one-shot operator, made a rate here so that rain falls through a run). River (the code's river
//   mode): the source column (W/2, H/16) gets w ← river_depth; every column of a sink row
//   (y ≥ 15H/16) loses its water and what the water carries.
// water_flow(ground, water, params), two passes (step 4 of §4), moving the water and everything it
// carries:
//   1. outflow, per column from the state as it stands (w, h): for pipe k to neighbour n,
//      F_k ← max(0, F_k + P_k·((h + w) − (h_n + w_n))) with P_k = Δt·l_x·l_y·g/l_k (steps 1-4 of
//      §3.3 with A = l_x·l_y, the cell's area, and l_k the distance to the neighbour: l_x or l_y);
//      a pipe to no neighbour has F = 0. If ΔV = Δt·(F_L + F_R + F_T + F_B) > l_x·l_y·w, every
//      F_k × (l_x·l_y·w)/ΔV (step 6).
//   2. move: the donor's fraction through pipe k is f_k = Δt·F_k/(l_x·l_y·w) (0 when w = 0; §3.3
//      [code]); water and each carried kind q move alike (§3.7): q' = kept + Σ_k q_{n_k}·f_{n_k, k^1},
//      sums in pipe order, with kept = max(q − Σ_k q·f_k, 0), or 0 when step 6 scaled the outflows
//      of a column that holds water (it is drained; a dry column sends nothing and keeps what it
//      carries, which sediment diffusion can bring). previous_water ← w before the move (w^{t−Δt}
//      of eq. 2.2's w̄).
//
// Inputs:  ground (its surface h, read only), water (LayeredWater<Real>: w, fluxes, carried kinds),
//          params (rain_rate, rain_steps, drain_step, the river, Δt, g, cell sizes); step: the iteration,
//          counted from 0.
// Outputs: water changed in place; water_sources counts in `conversions` (m³): water_added (rain, and
//          the river's rise), water_sunk (the sinks and the drain, and the river's fall), sunk[i] per
//          component.
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/water.hpp (LayeredWaterFlow) with gpu/shaders/erosion/layered/water_sources.comp,
//          water_flux.comp and water_move.comp.
// Decisions:
//   - The max(…, 0) of the move guards the rounding of Σ_k f_k ≤ 1; a drained column keeps nothing,
//     not the rounding residue of q − Σ_k q·f_k (≈ 2^-24·q), which would halve its exponent's
//     distance to the subnormals every step it drains and leave dust that a GPU may flush to zero.
//     Either rounding costs at most a few ulps of q, within the ledger's bound.
//   - Thesis vs code: every column's flux is updated, also a dry one (the code skips dry columns and
//     keeps their flux); with w = 0 step 6 scales it to 0, so dry columns send nothing in both.
//     Regolith moves with the water like the sediment (thesis and code agree).
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void water_sources(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                   std::uint32_t step, LayeredConversions& conversions);

template <class Real>
void water_flow(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params);

}  // namespace gt::reference
