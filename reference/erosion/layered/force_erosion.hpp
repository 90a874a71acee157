// Force erosion and deposition on seed 001's layered ground (digest 001 §3.4-3.5, §3.12; step 5 of §4), CPU reference.
//
// force_erosion_step(ground, water, params, conversions): per column, reading the neighbours' surface
//   heights from a snapshot taken before the step (§4: the code reads them in place, which makes it
//   scan-order dependent):
//   water strength (eq. 2.1 without its constant, §3.12 [code]'s water_info):
//     x = K_c·max(sin φ, slope_floor)·|v|·l(w) / (1 + K_wveg·veg), m
//     - velocity (eq. 2.2): F_x = ½((F_{left,R} − F_L) + (F_R − F_{right,L})), F_y likewise with the
//       T and B pipes (a missing neighbour's flux is 0); v_x = F_x/(l_y·w̄), v_y = F_y/(l_x·w̄) with
//       w̄ = max(½(w + w_prev), velocity_depth_floor) — the flux through a face l_y (l_x) wide;
//       |v| = 0 where w̄ = 0;
//     - sin φ = sqrt(g²/(1 + g²)) with g² = g_x² + g_y², g_x = (h_R − h_L)/(2l_x) (thesis: the true
//       slope) or h_R − h_L (seed001_code: un-halved, l = 1); a missing neighbour counts as the column;
//     - l(w) = min(w/K_w, 1) for w > 0, else 0 (the thesis's bounds read K_w, §3.5).
//   organic: C_org = organic_capacity·x; below it erode K_e·(C_org − s_org) (erode_component,
//     column.hpp), above it deposit K_d·(s_org − C_org).
//   rock fragments, for each result size i = sand .. boulders and source size j = i .. boulders:
//     m_ij = K_e·a(x) with a(x) = max(A_ji·(x − B_ji), 0) (thesis eq. 3.5) or max(A_ji·x − B_ji, 0)
//     (breakdown_form seed001_code); erode_component(j, m_ij) and the taken amount joins the
//     suspended size i — a conversion j → i when i ≠ j, counted in `broken_*`. Then bedrock: the first
//     non-empty bedrock layer, of type t, loses min(K_e·a_t(x)·soil_transparency, thickness) to
//     suspended size i (A^rock, B^rock of the type; counted in `bedrock_eroded_*`).
//   rock deposition, for each size i: C_i = a_ii(x) (eq. 3.11, clamped to 0); above it deposit
//     K_d·(s_i − C_i). Whenever what would stay suspended falls below negligible_amount, all of it
//     settles (layered_water.hpp).
//   Erosion runs first from the ground as it stands, then everything deposited in the column is laid
//   down once with reserve-then-deposit (decision, as the talus apply pass).
// net_flux(ground, water, params, x, y) -> NetFlux: the column's net flux (eq. 2.2's ½-averaged pipe
//   pairs): x toward +x (pipe R), y toward +y (pipe T); a missing neighbour's flux is 0.
// mean_depth(water, params, c) -> w̄ = max(½(w + w_prev), velocity_depth_floor) of column c.
// water_strength(ground, surface, water, params, x, y) -> x of column (x, y) with neighbour surfaces
//   from `surface` (the snapshot).
// breakdown(form, slope, threshold, strength) -> a(x) of one matrix entry: max(A·(x − B), 0) or, for
//   seed001_code, max(A·x − B, 0).
//
// Inputs:  ground (LayeredGround<Real>), water (LayeredWater<Real>: w, w_prev, the pipe fluxes and
//          the suspended sediment), params (LayeredParams, valid).
// Outputs: ground and water changed in place; `conversions` gains the breakdown j → i (`broken_*`)
//          and the eroded bedrock (`bedrock_eroded_*`).
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/force_erosion.hpp (LayeredForceErosion) with
//          gpu/shaders/erosion/layered/force_erosion.comp.
// Decisions: K_e scales the rock requests as the code's K_EROSION does (eq. 3.5 states the column's
//          capacity, not a per-step amount); the bedrock input is x, as the thesis (the code feeds the
//          soil layers' leftover request into the bedrock matrices, a unit mix, not kept); one
//          reserve-then-deposit after all erosion (above).
#pragma once

#include <vector>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

// The column's net flux (eq. 2.2's ½-averaged pipe pairs), m³/s: x toward +x (pipe R), y toward +y
// (pipe T); a missing neighbour's flux is 0.
template <class Real>
struct NetFlux {
  Real x = 0;
  Real y = 0;
};
template <class Real>
NetFlux<Real> net_flux(const LayeredGround<Real>& ground, const LayeredWater<Real>& water, const LayeredParams& params,
                       int x, int y);
// w̄ = max(½(w + w_prev), velocity_depth_floor) of column c, m.
template <class Real>
Real mean_depth(const LayeredWater<Real>& water, const LayeredParams& params, std::size_t c);

// x of column (x, y) with neighbour surfaces from `surface` (the snapshot), m.
template <class Real>
Real water_strength(const LayeredGround<Real>& ground, const std::vector<Real>& surface,
                    const LayeredWater<Real>& water, const LayeredParams& params, int x, int y);

// a(x) of one matrix entry: max(A·(x − B), 0) or, for seed001_code, max(A·x − B, 0).
template <class Real>
Real breakdown(BreakdownForm form, double slope, double threshold, Real strength);

template <class Real>
void force_erosion_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                        LayeredConversions& conversions);

}  // namespace gt::reference
