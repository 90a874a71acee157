// Error models of the `erosion.pipe` checks; see pipe_error_model.hpp.
#include "compare/checks/pipe_error_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/sum.hpp"

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
  const double rain_depth = constants.rain_rate * constants.time_step;
  // The most a step can add to what a cell carries: max(k_s, k_d)·K_c·(l_max/Δt) (|v| ≤ l_max/Δt,
  // sin α ≤ 1), and the regolith exchange's share of K_r.
  const double carried_most =
      std::max(constants.dissolving_fraction, constants.deposition_fraction) * constants.capacity *
          std::max(constants.length_x, constants.length_y) / constants.time_step +
      (constants.regolith_depth > 0.0 ? constants.regolith_depth : 0.0);
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      if (!terrain.is_valid(cell)) continue;
      const double height = static_cast<double>(terrain.values[cell]);
      const double depth = static_cast<double>(start.water.values[cell]);
      scales.surface = std::max(scales.surface, std::abs(height + depth));
      const double wetted = depth + rain_depth;  // d_A without the rain map and sources: smaller, so Q larger
      const double sediment = static_cast<double>(start.sediment.values[cell]) + static_cast<double>(start.regolith.values[cell]);
      if (wetted > 0.0) scales.concentration = std::max(scales.concentration, (sediment + carried_most) / wetted);
      scales.depth = std::max(scales.depth, depth);
      scales.sediment = std::max(scales.sediment, static_cast<double>(start.sediment.values[cell]));
      scales.regolith = std::max(scales.regolith, static_cast<double>(start.regolith.values[cell]));
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

}  // namespace gt

namespace gt {

// The model. Both twins start from the same floats; on a correctly rounding device they then
// differ only where ref<float> rounds what the GPU's base + change storage keeps: the surface
// b + d_A (u·|b + d_A| on each side of a head) and the heights it writes (u·|b|). Everything else
// is the same float operation on the same operands — until those first differences reach it. So
// the model injects, per step, h0 = 2u·H + 4u·(G + 2D) into every head (ref<float>'s two surface
// roundings and the heads' own) plus 32 float roundings of each field's scale (`pass`: GLSL's
// 2.5-ulp division and square root on other devices), and carries the accumulated errors E of
// flux, depth, terrain, sediment and regolith through the stages by their largest first-order
// sensitivities (the constants of the step), step after step:
//   head   e_h = h0 + 2·E_d + 2·E_b                            (both cells' depth and height)
//   flux   E_f ← 2·(E_f + g·e_h) + (l_x·l_y/Δt)·E_d + pass·F       g = Δt·A·g/l, the largest gain;
//          2: K = min(1, d_A·l_x·l_y/(Δt·Σf̂)) scales f̂_k by c/Σf̂ < 1, whose derivative sums to
//          at most 2; the d_A term: K's dependence on the depth
//   depth  E_d ← E_d + 2P·E_f·Δt/(l_x·l_y) + pass·D             (P pipes out, P in)
//   speed  E_v = (P·E_f/l + (l_max/Δt)·(E_d + E_d'))/(2·floor) + pass·l_max/Δt
//          (u = ΔW/(l·d̄) with d̄ ≥ floor; |u| ≤ l_max/Δt by the K scaling)
//   capacity e_C = K_c·(E_v + (l_max/Δt)·(e_sin + E_d/K_w)), e_sin = 2·E_b/span + pass
//   moved  e_m = max(k_s, k_d)·(e_C + E_s)
//   terrain E_b ← E_b + e_m + 2u·(H + D) (+ the regolith exchange, + the thermal step's
//          16·rate·E_b + 16u·(H + G))
//   sediment E_s ← E_s + e_m + transport + pass·S; transport: the shares f·Δt/(d_A·l_x·l_y) move
//          by P·E_f·Δt/(l_x·l_y·d_A), so what is sent by at most 2P·E_f·Δt/(l_x·l_y)·Q, Q = the
//          largest s/d_A of the start (capped at 2·the carried sediment: shares lie in [0, 1]);
//          the backtrace moves by E_v·Δt/l cells (2·carried·that); water-weighted diffusion's
//          shares by 8·E_d/d (8·E_d·Q)
//   regolith likewise with R and the exchange max(k_re, k_rd)·(E_d + E_r).
// This is a first-order worst case: every sensitivity at its largest, every error adding up. It
// is sharp for one step (the flux reaches 80 % of its bound on the 500 m slope) and wide after
// several (the depth and flux feed each other through K and the heads, ~10× a step), so the
// one-step comparison carries the resolving power and the four-step one guards against errors
// that only build up. It is not a proof: a threshold (max(0, ·), K < 1, C > s) switching on one
// rounding moves a whole transfer; should that happen the check fails and says where.
PipeShadowBounds pipe_shadow_bounds(const PipeShadowScales& scales, const PipeConstants& c, int steps) {
  const double u = pipe_float_roundoff;
  const double pass = 32.0 * u;
  const double pipes = c.pipe_count;
  const double shortest = std::min(c.length_x, c.length_y);
  const double longest = std::max(c.length_x, c.length_y);
  const double pipe_length = c.pipe_count == 8 ? std::min(shortest, c.length_diagonal) : shortest;
  const double gain = c.time_step * c.pipe_area * c.gravity / pipe_length;
  const double area_per_time = c.cell_area / c.time_step;
  const double fastest = longest / c.time_step;
  const double span = tilt_span(c.tilt_differences, 2, shortest);
  const double fraction = std::max(c.dissolving_fraction, c.deposition_fraction);
  const double regolith_fraction =
      c.regolith_depth > 0.0 ? std::max(c.regolith_dissolving_fraction, c.regolith_deposition_fraction) : 0.0;
  const double carried = scales.sediment + fraction * c.capacity * fastest;
  const double loose = scales.regolith + regolith_fraction * c.regolith_depth;
  const bool semi_lagrangian = c.transport == SedimentTransport::semi_lagrangian;
  const bool water_diffusion = c.sediment_diffusion > 0.0 && c.diffusion_weighting == DiffusionWeighting::water;
  const double h0 = 2.0 * u * scales.surface + 4.0 * u * (scales.relief + 2.0 * scales.depth);
  double flux = 0.0, depth = 0.0, terrain = 0.0, sediment = 0.0, regolith = 0.0, velocity = 0.0;
  const auto transported = [&](double amount, double flux_error, double depth_error, double speed_error) {
    double error = std::min(2.0 * amount, 2.0 * pipes * flux_error / area_per_time * scales.concentration);
    if (semi_lagrangian) error += 2.0 * amount * speed_error * c.time_step / shortest;
    if (water_diffusion) error += std::min(2.0 * amount, 8.0 * depth_error * scales.concentration);
    return error;
  };
  for (int step = 0; step < steps; ++step) {
    const double head = h0 + 2.0 * depth + 2.0 * terrain;
    const double next_flux = 2.0 * (flux + gain * head) + area_per_time * depth + pass * scales.flux;
    const double next_depth = depth + 2.0 * pipes * next_flux / area_per_time + pass * scales.depth;
    velocity = (pipes * next_flux / shortest + fastest * (depth + next_depth)) / (2.0 * c.velocity_depth_floor) +
               pass * fastest;
    const double tilt = 2.0 * terrain / span + pass;
    const double ramp = c.depth_ramp > 0.0 ? next_depth / c.depth_ramp : 0.0;
    const double capacity = c.capacity * (velocity + fastest * (tilt + ramp));
    const double moved = fraction * (capacity + sediment);
    const double exchanged = regolith_fraction * (next_depth + regolith);
    double next_terrain = terrain + moved + exchanged + 2.0 * u * (scales.surface + scales.depth);
    if (c.thermal_step) next_terrain += 16.0 * c.thermal.request_factor * terrain + 16.0 * u * (scales.surface + scales.relief);
    sediment += moved + transported(carried, next_flux, next_depth, velocity) + pass * scales.sediment;
    if (c.regolith_depth > 0.0) regolith += exchanged + transported(loose, next_flux, next_depth, velocity) + pass * loose;
    flux = next_flux;
    depth = next_depth;
    terrain = next_terrain;
  }
  return {terrain, depth, sediment, regolith, velocity, flux};
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
