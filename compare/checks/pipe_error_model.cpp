// Error models of the `erosion.pipe` checks; see pipe_error_model.hpp.
#include "compare/checks/pipe_error_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/rounding_interval.hpp"
#include "core/sum.hpp"
#include "reference/erosion/pipes.hpp"

namespace gt {
namespace {

constexpr double ledger_slack = 8.0 * pipe_double_roundoff;  // compensated sums, host products
constexpr double second_order = 1.0 + 0x1p-10;

}  // namespace

double pipe_asked_volume_per_step(const PipeConstants& constants, const HydraulicForcing& forcing,
                                  const Grid<double>& terrain) {
  CompensatedSum rate;  // m³/s
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    const double mapped = forcing.rain_map.values.empty() ? 0.0 : forcing.rain_map.values[cell];
    rate.add((constants.rain_rate + mapped) * constants.cell_area);
  }
  for (const auto& source : forcing.sources) rate.add(source.rate);
  return constants.time_step * rate.value();
}

double pipe_water_added_bound(double unit_roundoff, int steps, std::size_t sources) {
  const double additions = (1.0 + static_cast<double>(sources)) * std::max(steps, 0) + 4.0;
  return unit_roundoff * additions * second_order + ledger_slack;
}

double pipe_evaporation_bound(double unit_roundoff, double evaporated_share) {
  const double cancellation = evaporated_share < 1.0 ? std::max(1.0, evaporated_share / (1.0 - evaporated_share)) : 1.0;
  return (3.0 * unit_roundoff + unit_roundoff * unit_roundoff) * second_order + ledger_slack * cancellation;
}

double pipe_rounding_growth(int steps, double scale) { return steps * 32.0 * pipe_float_roundoff * scale; }

}  // namespace gt

namespace gt {

template <class Real>
PipeShadowScales pipe_shadow_scales(const PipeState<Real>& start, const PipeConstants& constants) {
  PipeShadowScales scales;
  const auto& terrain = start.terrain;
  scales.layers.assign(start.layers.size(), 0.0);
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const double height = static_cast<double>(terrain.values[cell]);
      scales.depth = std::max(scales.depth, static_cast<double>(start.water.values[cell]));
      scales.sediment = std::max(scales.sediment, static_cast<double>(start.sediment.values[cell]));
      scales.regolith = std::max(scales.regolith, static_cast<double>(start.regolith.values[cell]));
      for (std::size_t k = 0; k < start.layers.size(); ++k) {
        scales.layers[k] = std::max(scales.layers[k], static_cast<double>(start.layers[k].values[cell]));
      }
      scales.speed = std::max({scales.speed, std::abs(static_cast<double>(start.velocity_x.values[cell])),
                               std::abs(static_cast<double>(start.velocity_y.values[cell]))});
      for (int k = 0; k < constants.pipe_count; ++k) {
        scales.flux = std::max(scales.flux, static_cast<double>(start.outflow[cell][k]));
        const int nx = x + pipe_offsets[k].dx, ny = y + pipe_offsets[k].dy;
        if (terrain.inside(nx, ny) && terrain.is_valid(nx, ny)) {
          scales.relief = std::max(scales.relief, std::abs(height - static_cast<double>(terrain.at(nx, ny))));
        }
      }
    }
  }
  return scales;
}

template PipeShadowScales pipe_shadow_scales(const PipeState<float>&, const PipeConstants&);
template PipeShadowScales pipe_shadow_scales(const PipeState<double>&, const PipeConstants&);

namespace {

// The interval holds the exact step and ref<float>'s (the same operations, each rounded within the
// interval's widening); a candidate that forms the same formulas otherwise (another order, the head
// from base and change, fused multiply-adds) is taken to be no less accurate, within the width of
// the exact step too. So the two lie within twice the width.
constexpr double candidate_and_reference = 2.0;

double bound_of(const RoundingInterval& value) { return candidate_and_reference * value.width(); }

}  // namespace

PipeState<double> pipe_shadow_bounds(const PipeState<double>& start, const PipeConstants& constants,
                                     const HydraulicForcing& forcing, int steps) {
  // The start both twins load: float values, exact.
  const auto exact = [](double value) { return RoundingInterval::exact(value); };
  reference::PipeErosion<RoundingInterval> model(map_pipe_state<RoundingInterval>(start, exact), constants, forcing);
  model.run(steps);
  return map_pipe_state<double>(model.state(), bound_of);
}

}  // namespace gt

namespace gt {

double pipe_water_added_error(const std::vector<PipeLedgerEntry>& ledger, double asked_per_step) {
  double largest = 0.0;
  if (ledger.empty()) return largest;
  const double initial = ledger.front().water;
  for (const auto& entry : ledger) {
    const double asked = entry.step * asked_per_step;
    const double handled = initial + asked;
    if (handled > 0.0) largest = std::max(largest, std::abs(entry.water_added - asked) / handled);
  }
  return largest;
}

double pipe_evaporation_error(const std::vector<PipeLedgerEntry>& ledger, double evaporated_share) {
  if (evaporated_share >= 1.0) return 0.0;
  double largest = 0.0;
  CompensatedSum held;  // Σ W_τ, m³
  for (const auto& entry : ledger) {
    if (entry.step == 0) continue;
    held.add(entry.water);
    const double before = held.value() / (1.0 - evaporated_share);
    const double predicted = evaporated_share * before;
    if (before > 0.0) largest = std::max(largest, std::abs(entry.evaporated - predicted) / before);
  }
  return largest;
}

}  // namespace gt
