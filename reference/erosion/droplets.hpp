// What a droplet eroder's reference returns (reference/erosion/particle.hpp for Hydra's kernel,
// reference/erosion/beyer.hpp for Beyer's): the heights, the side maps, the droplet ledger and (Hydra,
// when asked) the transported colour map.
//
// The ledger (double, summed over every pass) names every place where material enters or leaves
// the terrain, so that
//   Σ heights after + sediment_at_end + sediment_left + deposited_outside
//     = Σ heights before + eroded_outside + clamp_created + apply_rounding      (up to rounding)
// and in batch ordering the same identity holds exactly in quanta (the *_quanta fields).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/grid.hpp"
#include "core/mutant.hpp"

namespace gt::reference {

// A colour map (Hydra's rgba32f colour texture, §4.4.1, §4.5): RGBA per texel, linear, any values.
// A droplet eroder that transports it reads masked and off-grid texels as (0, 0, 0, 0) and loses
// writes there, as it does heights (the heights' mask decides; the colour map's own is not read).
template <class Real>
using ColourMap = Grid<std::array<Real, 4>>;

struct DropletLedger {
  double eroded = 0.0;             // taken from terrain cells (inside the grid, valid)
  double deposited = 0.0;          // given to terrain cells
  double eroded_outside = 0.0;     // picked up at texels outside the grid or masked: created from nothing
  double deposited_outside = 0.0;  // dropped at texels outside the grid or masked: lost
  double clamp_created = 0.0;      // Hydra without interpolation, h stored as max(h - add, 0): add - removed
  double sediment_at_end = 0.0;    // carried by droplets whose lifetime ran out: lost with them
  double sediment_left = 0.0;      // carried by droplets that left across x <= 0 or y <= 0
  double apply_rounding = 0.0;     // batch: what rounding the heights + delta to Real added
  // batch: the most that rounding may add, Σ u·(|delta·quantum| + |height after|) over the applied
  // cells (Real(delta) rounds once, the product is exact, the sum rounds once), u Real's unit roundoff
  double apply_rounding_bound = 0.0;
  long long droplets = 0;
  long long droplets_left = 0;     // of them, ended by the position check
  long long steps = 0;             // droplet steps taken (a droplet's steps up to its end)
  // Batch ordering, in quanta: exact integers.
  long long eroded_quanta = 0, deposited_quanta = 0, eroded_outside_quanta = 0, deposited_outside_quanta = 0,
            clamp_created_quanta = 0, sediment_end_quanta = 0;
  long long applied_quanta = 0;  // Σ of the deltas applied to terrain cells: the terrain's change in quanta
  long long largest_cell_delta_quanta = 0;  // the largest |delta| of one cell in one pass (int32 on the GPU)
};

template <class Real>
struct DropletRun {
  Grid<Real> heights;
  // The side maps, before any contrast: what each droplet eroded in all and deposited, at the texel
  // it stood on (Hydra's depth and sediment maps, as its kernel writes them). Hydra's reference sums
  // them in Real, as the GPU does, and stores the sums here as double (exactly the Real values).
  Grid<double> eroded_at_droplet;
  Grid<double> deposited_at_droplet;
  DropletLedger ledger;
  ColourMap<Real> colour;  // the transported colour map; empty when the run transported none
};

// The batch ordering's change of each cell during one pass, in quanta, and its application when the
// pass ends as the shaders' *_apply.comp do: height + Real(delta)·quantum, rounded once to Real.
// The GPU counts in int32: a delta beyond it is refused (RunawayRun naming `algorithm`: the case
// cannot be compared from there on, which no twin is to blame for).
template <class Real>
class BatchDelta {
 public:
  BatchDelta(std::size_t cells, Real quantum, std::string algorithm)
      : delta_(cells, 0), quantum_(quantum), algorithm_(std::move(algorithm)) {}

  void add(std::size_t cell, long long count) { delta_[cell] += count; }

  void apply(Grid<Real>& heights, DropletLedger& ledger) {
    constexpr double unit_roundoff = std::numeric_limits<Real>::epsilon() / 2.0;
    const Real scale = apply_scale();
    for (std::size_t i = 0; i < delta_.size(); ++i) {
      const long long delta = delta_[i];
      if (delta == 0) continue;
      delta_[i] = 0;
      ledger.applied_quanta += delta;
      ledger.largest_cell_delta_quanta = std::max(ledger.largest_cell_delta_quanta, std::llabs(delta));
      if (std::llabs(delta) > std::numeric_limits<std::int32_t>::max()) refuse(delta);
      const Real before = heights.values[i];
      Real change = static_cast<Real>(delta) * quantum_;
      change = change * scale;
      const Real after = before + change;
      const double exact_change = static_cast<double>(delta) * static_cast<double>(quantum_);
      ledger.apply_rounding += (static_cast<double>(after) - static_cast<double>(before)) - exact_change;
      ledger.apply_rounding_bound += unit_roundoff * (std::abs(exact_change) + std::abs(static_cast<double>(after)));
      heights.values[i] = after;
    }
  }

 private:
  // Mutants erosion.beyer.apply_scaled (both twins; beyer_apply.comp alike): each change 2^-10 too
  // large, far above ledger.apply_rounding's bound; its calibrated pair _above_bound (2^-15, a few
  // times the bound on the probe) and _below_bound (2^-23, one rounding). 1 on an honest run.
  Real apply_scale() const {
    if (mutant_active(algorithm_ + ".apply_scaled")) return static_cast<Real>(1.0 + 0x1p-10);
    if (mutant_active(algorithm_ + ".apply_scaled_above_bound")) return static_cast<Real>(1.0 + 0x1p-15);
    if (mutant_active(algorithm_ + ".apply_scaled_below_bound")) return static_cast<Real>(1.0 + 0x1p-23);
    return Real(1);
  }

  // The counter holds 2^31 quanta, 128 times the magnitude the quantum was sized for
  // (core/params/droplets.hpp): one cell changing more in one pass is no longer erosion of that map.
  [[noreturn]] void refuse(long long delta) const {
    const double quantum = static_cast<double>(quantum_);
    const double change = static_cast<double>(delta) * quantum;
    const double limit = static_cast<double>(std::numeric_limits<std::int32_t>::max()) * quantum;
    throw RunawayRun(fmt::format(
        "{}: one cell's height changed by {:.6g} in one pass ({} quanta), beyond the GPU's 32-bit counter (128 times "
        "the heights' magnitude, {:.6g}): the run left the range in which the twins can be compared. Either it ran "
        "away (Beyer's `physical` speed rule does without friction: the speed and the capacity grow on every "
        "downhill step) or the droplets of a pass, blind to each other, piled that much into one pit (a larger "
        "spacing or the race ordering avoids that)",
        algorithm_, change, delta, quantum * 16777216.0),
        std::abs(change), limit);
  }

  std::vector<long long> delta_;
  Real quantum_;
  std::string algorithm_;
};

// The batch ordering's colour deposits of one pass (Hydra's colour transport, reference/erosion/
// particle.cpp), order-independent as the GPU's atomics need: each cell collects Σ factor_k and
// Σ factor_k·colour_k per channel, each term rounded to a count of `unit` = 2^-20
// (nearbyint(x·2^20), ties to even as GLSL's roundEven), and apply() replaces the cell's colour by
// the weighted mean of its start colour (weight 1) and the deposits:
//   C = (C + Real(Σ factor·colour)·unit) / (1 + Real(Σ factor)·unit)        per channel,
// as particle_apply.comp does, then clears the sums. Cells without deposits are left alone. The GPU
// counts in int32: a term or a sum beyond it is refused (runtime_error naming `algorithm`).
template <class Real>
class ColourDelta {
 public:
  static constexpr double unit = 1.0 / 1048576.0;  // 2^-20
  static constexpr double units_per_one = 1048576.0;

  ColourDelta(std::size_t cells, std::string algorithm) : sums_(cells), algorithm_(std::move(algorithm)) {}

  // A deposit of `colour` with weight `factor` (f_col·w) into `cell`; the quanta of factor and of
  // each factor·colour[ch], the products rounded to Real first.
  void add(std::size_t cell, Real factor, const std::array<Real, 4>& colour) {
    auto& sums = sums_[cell];
    sums[0] += count(factor);
    for (int ch = 0; ch < 4; ++ch) {
      const Real weighted = factor * colour[ch];
      sums[1 + ch] += count(weighted);
    }
  }

  void apply(ColourMap<Real>& colour) {
    const Real to_real = static_cast<Real>(unit);
    for (std::size_t i = 0; i < sums_.size(); ++i) {
      auto& sums = sums_[i];
      if (sums == std::array<long long, 5>{}) continue;
      for (const long long sum : sums) check(sum, "sum in one cell");
      const Real denominator = Real(1) + static_cast<Real>(sums[0]) * to_real;
      for (int ch = 0; ch < 4; ++ch) {
        const Real numerator = colour.values[i][ch] + static_cast<Real>(sums[1 + ch]) * to_real;
        colour.values[i][ch] = numerator / denominator;
      }
      sums = {};
    }
  }

 private:
  long long count(Real amount) const {
    const Real scaled = amount * static_cast<Real>(units_per_one);  // exact: a power of two
    if (!(std::abs(scaled) <= static_cast<Real>(std::numeric_limits<std::int32_t>::max()))) refuse("term");
    const long long result = static_cast<long long>(std::nearbyint(scaled));
    check(result, "term");
    return result;
  }

  void check(long long value, const char* what) const {
    if (std::llabs(value) > std::numeric_limits<std::int32_t>::max()) refuse(what);
  }

  [[noreturn]] void refuse(const char* what) const {
    throw std::runtime_error(fmt::format(
        "{}: a batch colour {} beyond the GPU's 32-bit counter (units of 2^-20): the colours or the droplets "
        "depositing into one cell in one pass are too many or too large; scale the colours down, or use a larger "
        "spacing or the race ordering",
        algorithm_, what));
  }

  std::vector<std::array<long long, 5>> sums_;
  std::string algorithm_;
};

}  // namespace gt::reference
