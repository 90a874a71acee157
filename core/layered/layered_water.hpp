// The water on seed 001's layered ground (digest 001 §3.3-3.5, §3.12-3.13, §3.15, §3.19), shared by
// the CPU reference and the GPU twin, stored as flat arrays beside LayeredGround<Real> (same size and
// cell order c = y·width + x).
//
// Per column:
//   - water: depth w, m; previous_water: w before the step's flow (eq. 2.2's w^{t−Δt}), m;
//   - water_flux: the outflow F of pipe k (L, R, T, B: gt::pipe_offsets 0..3, k and k^1 opposite)
//     at k·cells + c, m³/s; it persists between steps (§3.3 [code]);
//   - carried: what the water carries, kind q at q·cells + c, as a thickness over the cell (m; the
//     volume is carried·l_x·l_y): q = 0..4 suspended org, sand, gravel, stones, boulders (§3.12);
//     q = 5, 6 regolith org and sand (§3.13, only the finest material dissolves);
//   - wetness (eq. 3.12), m·s.
// Pipes: a pipe to no neighbour (outside a closed border) carries nothing; periodic borders wrap.
// Water leaves the grid only through the river's sink rows (§3.19), which take what it carries too.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt {

inline constexpr int water_pipe_count = 4;
// Amounts that only relax toward 0 (what stays suspended above a capacity of 0, the regolith of a
// drying column, the wetness of a dry one) would shrink geometrically into the subnormal floats,
// which a GPU may flush to zero (GLSL 4.50 §4.7.1) while the CPU keeps them. Decision: below this,
// such an amount becomes 0 — the material settles whole, the wetness is gone. m (wetness: m·s).
inline constexpr double negligible_amount = 0x1p-64;
inline constexpr int regolith_kind_count = 2;  // org, sand
inline constexpr int carried_kind_count = soil_component_count + regolith_kind_count;
// The kind of the suspended component i, and of the regolith of component i (org or sand).
inline constexpr int suspended_kind(int component) { return component; }
inline constexpr int regolith_kind(int component) { return soil_component_count + component; }
// The soil component kind q carries.
inline constexpr int carried_component(int kind) { return kind < soil_component_count ? kind : kind - soil_component_count; }

template <class Real>
struct LayeredWater {
  std::vector<Real> water;           // w, m
  std::vector<Real> previous_water;  // w before the step's flow, m
  std::vector<Real> water_flux;      // m³/s
  std::vector<Real> carried;         // m
  std::vector<Real> wetness;         // m·s

  Real& flux_at(int pipe, std::size_t c) { return water_flux[static_cast<std::size_t>(pipe) * water.size() + c]; }
  Real flux_at(int pipe, std::size_t c) const { return water_flux[static_cast<std::size_t>(pipe) * water.size() + c]; }
  Real& carried_at(int kind, std::size_t c) { return carried[static_cast<std::size_t>(kind) * water.size() + c]; }
  Real carried_at(int kind, std::size_t c) const { return carried[static_cast<std::size_t>(kind) * water.size() + c]; }
};

// `cells` columns of depth `depth` (m), nothing carried, no flux, no wetness.
template <class Real>
LayeredWater<Real> make_layered_water(std::size_t cells, double depth);

// What the processes refuse (InputError, "erosion.layered: ..."): arrays of another size than
// `cells`, non-finite or negative depths, fluxes, carried amounts or wetness.
template <class Real>
void check_layered_water(const LayeredWater<Real>& water, std::size_t cells);

// The river's columns (§3.19 [code]): the source (W/2, H/16) and whether row y is a sink row
// (y ≥ 15H/16, as 16·y ≥ 15·H).
std::size_t river_source_cell(int width, int height);
bool river_sink_row(int y, int height);

// Volumes in the water, m³, summed in double: water, and per soil component what it carries
// (suspended plus regolith).
struct LayeredWaterLedger {
  double water = 0.0;
  std::array<double, soil_component_count> carried{};
};

template <class Real>
LayeredWaterLedger layered_water_ledger(const LayeredWater<Real>& water, double cell_area);

}  // namespace gt
