// Impact erosion on seed 001's layered ground (digest 001 §3.14; step 6 of §4), CPU reference.
//
// impact_erosion_step(ground, water, params, conversions), in the thesis's parallel target-side form
// with two passes (the code's serial water-side loop has the bugs the digest lists and is not kept):
// Pass 1, per target column c, its neighbours n through pipes k = L, R, T, B in order:
//   - n's water must stand (w_n > 0, w̄_n > 0) and move toward c: with F the net flux of n
//     (force_erosion.hpp's net_flux) along the axis of k, F_toward = −F·(the offset of k's sign)
//     must be > 0; v = F_toward/(l_face·w̄_n), m/s, where l_face is the face between the columns
//     (l_y for L and R, l_x for T and B).
//   - For each non-empty layer of c, top down — the soil layers, then the first non-empty bedrock
//     layer only (remove_soil's rule) — its top and bottom elevations (the column as it stands),
//     the contact with n's water c_top = min(top, h_n + w_n), c_bottom = max(bottom, h_n),
//     A = l_face·max(c_top − c_bottom, 0), and the impact strength
//       S = K_i·v·A·Δt/(l_x·l_y), m
//     (the thesis's S_c = K_i·v·A as a volume rate; decision: times Δt over the cell's area, a
//     thickness per step, so that it plays force erosion's water strength x).
//   - S erodes that layer "as force erosion does" (§3.12), on this layer alone (the contact already
//     chose it): organic K_e·organic_capacity·S, and for each result size i, source j ≥ i,
//     K_e·a_ji(S) (eq. 3.5), each through take_from_layer (the share rule, no transparency); from
//     bedrock K_e·a_t,i(S) (A^rock, B^rock), at most its thickness. The surface is lowered by what
//     was taken. A component is only asked for where the layer holds some (so an emptied layer is
//     never divided by).
//   - The material goes into c's virtual pipe toward n (not into c's water), as suspended sizes.
//   The neighbours' heights come from a snapshot of the surface before the step (h_n; c's own layers
//   change as it erodes them), so no column reads what another writes.
// Pass 2, per column n: its suspended sediment gains what each neighbour's pipe toward it holds, in
// pipe order.
//
// Inputs:  ground (LayeredGround<Real>), water (LayeredWater<Real>: w, w_prev, fluxes, suspended
//          sediment), params (LayeredParams, valid).
// Outputs: ground and water changed in place; `conversions`: per column, the breakdown j → i and the
//          bedrock eroded are summed in Real over neighbours, layers and sizes (in that order), then
//          counted in double once a column (the GPU twin's order).
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/impact_erosion.hpp (LayeredImpactErosion) with
//          gpu/shaders/erosion/layered/impact_erosion.comp.
// Decisions: S as a thickness per step (above); a column gives bedrock of one type a step — when an
//          earlier neighbour's impact emptied its first bedrock layer and the next is of another type,
//          that one waits for the next step — so that a column's tally names one type.
#pragma once

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void impact_erosion_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                         LayeredConversions& conversions);

}  // namespace gt::reference
