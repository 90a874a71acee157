// Beneš's dissolution erosion (Beneš 2002, "Visual simulation of hydraulic erosion", as surveyed by
// seed 000 §2.3; digest 000 §3.3, eqs. 2.1-2.9). Slow water dissolves the ground it stands on and
// lays it down where it comes to rest: a smoothing model for lake beds and slow rivers. Cells and
// time steps are 1 (the thesis's units); one iteration, in the order the thesis prints its equations:
//   1. rain (eq. 2.1):         d ← d + K_r
//   2. evaporation (2.2-2.3):  d_e = d·e^{-K_e}; d ← 0 if d_e < T, else d_e − T; the cell's
//                              `evaporated` gains what left
//   3. dissolution (2.4-2.5):  S = K_s·d; where s < S the terrain gives c = rate_dissolution·(S − s)
//                              (b ← b − c, s ← s + c), else it takes c = rate_deposition·(s − S)
//                              (b ← b + c, s ← s − c); with both rates 1 this is eq. 2.5, s ← S
//   4. transport (2.6-2.9):    with h = b + d, each of the 8 neighbours n with Δh_n = h − h_n > 0
//                              would take min(d, Δh_n/2) to level the pair (eq. 2.9: ŵ < 0 moves all
//                              of d, else d − ŵ = Δh_n/2); the cell gives Δw = min(d, Σ of those)
//                              (the thesis's "sum the transfers, clamp to the column"), shared by
//                              eq. 2.8: Δw_n = Δw·Δh_n/Σ_m Δh_m; the dissolved material goes with
//                              its water, s·Δw_n/d (the thesis gives no formula: digest note).
//                              water_share = mean_level gives min(d, h − h̄) instead, h̄ the mean
//                              surface of the cell and its n lower neighbours (Σ_n Δh_n/(n + 1)).
//                              Two synchronous passes: outflows from the state after step 3, then
//                              each cell loses its outflows and gains its neighbours' towards it.
// Decisions where the source is vague: the thesis's "Δh ≤ 0" for the receiving neighbours is read
// as the sign slip the digest shows (Δh ≥ 0; a neighbour at the same level takes nothing either
// way); distances play no part (eq. 2.7 weighs diagonal neighbours like the others, as printed);
// neighbours outside the grid or masked are absent, so water and material never leave the grid;
// evaporation follows rain within an iteration (eq. 2.3 applied once per iteration, t = 1).
// The sum of pairwise moves can exceed what levels the cell with all its neighbours at once (eight
// neighbours each Δh lower take 4·Δh); the clamp to the column is the thesis's only limit, so
// water on a plain can overshoot and oscillate from iteration to iteration: the model as printed
// (on the volcano's crater lake, neighbouring columns end alternately full and empty). mean_level
// cannot send more than levels the cell with the mean of its lower neighbours.
// What leaves one cell arrives at the other as the same number, so water (with what evaporated)
// and material (terrain + dissolved) are conserved up to the rounding of the additions; a cell
// that gives all its water keeps the rounding of its eight subtractions (|d| ≤ 8u·d, either sign)
// until the next rain or evaporation.
// Units: heights, depths and dissolved material in the terrain's vertical unit (metres).
// Mutants (compare/mutants/dissolution.cpp; the GPU twin carries the same ones): unhalved_pair,
// deposition_kept, threshold_ignored; and in ref<float> and the GPU, float_evaporated_uncounted.
//
// Memory traffic per cell and iteration (ref<double>, the performance table's floor column): the
// local step reads and writes 4 doubles (64 B), the outflow pass reads terrain and water (16 B) and
// writes 8 doubles (64 B), the gather reads water, dissolved and the outflows (80 B) and writes 2
// doubles (16 B): 240 B, neighbours' values taken as cached.
#include "reference/erosion/dissolution.hpp"

#include <array>
#include <type_traits>
#include <vector>

#include "core/mutant.hpp"
#include "core/rounding_interval.hpp"
#include "reference/erosion/moore_pipes.hpp"

namespace gt::reference {

using std::min;  // unqualified: RoundingInterval (core/rounding_interval.hpp) brings its own
namespace {

// The constants rounded once to Real, as the GPU twin receives them.
template <class Real>
struct Rounded {
  Real rain, retained, threshold, saturation, dissolution_rate, deposition_rate, pair_share;
  bool mean_level;
  bool threshold_applied;
  bool deposition_paid;
  bool evaporation_booked_short;
};

template <class Real>
Rounded<Real> rounded(const DissolutionConstants& constants) {
  return {.rain = static_cast<Real>(constants.rain),
          .retained = static_cast<Real>(constants.retained),
          .threshold = static_cast<Real>(constants.evaporation_threshold),
          .saturation = static_cast<Real>(constants.saturation),
          .dissolution_rate = static_cast<Real>(constants.dissolution_rate),
          .deposition_rate = static_cast<Real>(constants.deposition_rate),
          // ½ of eq. 2.9's levelling (mutant erosion.dissolution.unhalved_pair: 1).
          .pair_share = mutant_active("erosion.dissolution.unhalved_pair") ? Real(1) : Real(0.5),
          .mean_level = constants.water_share == DissolutionShare::mean_level,
          // Mutant erosion.dissolution.threshold_ignored: d_e kept whole, T never subtracted.
          .threshold_applied = !mutant_active("erosion.dissolution.threshold_ignored"),
          // Mutant erosion.dissolution.deposition_kept: deposited material stays in the water too.
          .deposition_paid = !mutant_active("erosion.dissolution.deposition_kept"),
          // Mutant erosion.dissolution.float_evaporated_uncounted (the float twins, ref<float> and the
          // GPU): what e^{-K_e} took is not booked as evaporated.
          .evaporation_booked_short =
              std::is_same_v<Real, float> && mutant_active("erosion.dissolution.float_evaporated_uncounted")};
}

// Steps 1-3 on one cell, in place.
template <class Real>
void rain_evaporate_dissolve(DissolutionState<Real>& state, std::size_t cell, const Rounded<Real>& c) {
  Real water = state.water.values[cell] + c.rain;
  const Real kept = water * c.retained;
  Real remaining = kept;
  if (c.threshold_applied) remaining = kept < c.threshold ? Real(0) : kept - c.threshold;
  state.evaporated.values[cell] = state.evaporated.values[cell] + ((c.evaporation_booked_short ? kept : water) - remaining);
  water = remaining;
  state.water.values[cell] = water;
  const Real capacity = c.saturation * water;
  Real& terrain = state.terrain.values[cell];
  Real& dissolved = state.dissolved.values[cell];
  if (dissolved < capacity) {
    const Real taken = c.dissolution_rate * (capacity - dissolved);
    terrain = terrain - taken;
    dissolved = dissolved + taken;
  } else {
    const Real laid = c.deposition_rate * (dissolved - capacity);
    terrain = terrain + laid;
    if (c.deposition_paid) dissolved = dissolved - laid;
  }
}

// Step 4's first pass: the water cell (x, y) sends down each pipe.
template <class Real>
std::array<Real, 8> water_outflows(const DissolutionState<Real>& state, int x, int y, const Rounded<Real>& c) {
  std::array<Real, 8> outflow{};
  const std::size_t cell = state.terrain.index(x, y);
  const Real water = state.water.values[cell];
  if (!(water > Real(0))) return outflow;
  const Real surface = state.terrain.values[cell] + water;
  std::array<Real, 8> fall{};
  Real fall_total = Real(0);
  Real levelling_total = Real(0);
  int lower = 0;
  for (int k = 0; k < 8; ++k) {
    if (!pipe_open(state.terrain, x, y, k)) continue;
    const std::size_t neighbour = state.terrain.index(x + moore_pipes[k].dx, y + moore_pipes[k].dy);
    const Real difference = surface - (state.terrain.values[neighbour] + state.water.values[neighbour]);
    if (difference > Real(0)) {
      fall[k] = difference;
      fall_total = fall_total + difference;
      levelling_total = levelling_total + min(water, difference * c.pair_share);
      ++lower;
    }
  }
  if (!(fall_total > Real(0))) return outflow;
  const Real given = min(water, c.mean_level ? fall_total / Real(lower + 1) : levelling_total);
  for (int k = 0; k < 8; ++k) outflow[k] = given * fall[k] / fall_total;
  return outflow;
}

// The dissolved material that goes with `sent` of a cell's `water`.
template <class Real>
Real carried(Real dissolved, Real sent, Real water) {
  return sent > Real(0) ? dissolved * sent / water : Real(0);
}

template <class Real>
using Outflows = std::vector<std::array<Real, 8>>;

// Step 4's second pass on one cell: its water and dissolved material after the exchange.
template <class Real>
std::pair<Real, Real> gathered(const DissolutionState<Real>& state, const Outflows<Real>& outflows, int x, int y) {
  const std::size_t cell = state.terrain.index(x, y);
  const Real own_water = state.water.values[cell];
  const Real own_dissolved = state.dissolved.values[cell];
  Real water = own_water;
  Real dissolved = own_dissolved;
  for (int k = 0; k < 8; ++k) {
    const Real sent = outflows[cell][k];
    water = water - sent;
    dissolved = dissolved - carried(own_dissolved, sent, own_water);
  }
  for (int k = 0; k < 8; ++k) {
    if (!pipe_open(state.terrain, x, y, k)) continue;
    const std::size_t neighbour = state.terrain.index(x + moore_pipes[k].dx, y + moore_pipes[k].dy);
    const Real received = outflows[neighbour][opposite_pipe(k)];
    water = water + received;
    dissolved = dissolved + carried(state.dissolved.values[neighbour], received, state.water.values[neighbour]);
  }
  return {water, dissolved};
}

template <class Real>
void iterate(DissolutionState<Real>& state, DissolutionState<Real>& next, Outflows<Real>& outflows,
             const Rounded<Real>& constants) {
  const Grid<Real>& terrain = state.terrain;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (terrain.is_valid(cell)) rain_evaporate_dissolve(state, cell, constants);
  }
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      outflows[terrain.index(x, y)] =
          terrain.is_valid(x, y) ? water_outflows(state, x, y, constants) : std::array<Real, 8>{};
    }
  }
  next.terrain.values = state.terrain.values;
  next.evaporated.values = state.evaporated.values;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) {
        next.water.values[cell] = state.water.values[cell];
        next.dissolved.values[cell] = state.dissolved.values[cell];
        continue;
      }
      std::tie(next.water.values[cell], next.dissolved.values[cell]) = gathered(state, outflows, x, y);
    }
  }
  std::swap(state, next);
}

}  // namespace

template <class Real>
DissolutionState<Real> dissolution_erosion(const DissolutionState<Real>& state, const DissolutionConstants& constants,
                                           int iterations) {
  const Rounded<Real> rounded_constants = rounded<Real>(constants);
  DissolutionState<Real> current = state;
  DissolutionState<Real> next = state;
  Outflows<Real> outflows(state.terrain.size());
  for (int iteration = 0; iteration < iterations; ++iteration) iterate(current, next, outflows, rounded_constants);
  return current;
}

template DissolutionState<float> dissolution_erosion(const DissolutionState<float>&, const DissolutionConstants&, int);
template DissolutionState<double> dissolution_erosion(const DissolutionState<double>&, const DissolutionConstants&, int);
template DissolutionState<RoundingInterval> dissolution_erosion(const DissolutionState<RoundingInterval>&,
                                                                const DissolutionConstants&, int);

}  // namespace gt::reference
