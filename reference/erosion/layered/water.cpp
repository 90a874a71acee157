// Sources, sinks and the virtual-pipe flow of the water on the layered ground (digest 001 §3.3,
// §3.7, §3.19; see water.hpp).
#include "reference/erosion/layered/water.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <vector>

#include <cmath>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

template <class Real>
using PipeValues = std::array<Real, water_pipe_count>;

// The neighbours through pipes L, R, T, B (none outside a closed border).
template <class Real>
std::array<std::optional<std::size_t>, water_pipe_count> pipe_neighbours(const LayeredGround<Real>& ground,
                                                                        LayeredBorder border, int x, int y) {
  std::array<std::optional<std::size_t>, water_pipe_count> out;
  for (int k = 0; k < water_pipe_count; ++k) out[static_cast<std::size_t>(k)] = layered_neighbour(ground, border, x, y, k);
  return out;
}

// Column c's new outflows (pass 1), from the water and surface as they stand; `drained`: step 6
// scaled the outflows of a column that holds water, so they take everything it holds.
template <class Real>
PipeValues<Real> outflows(const LayeredGround<Real>& ground, const LayeredWater<Real>& water,
                          const LayeredParams& params, int x, int y, bool& drained) {
  const std::size_t c = ground.cell(x, y);
  const Real level = ground.surface[c] + water.water[c];
  const auto neighbours = pipe_neighbours(ground, params.border, x, y);
  PipeValues<Real> flux{};
  for (int k = 0; k < water_pipe_count; ++k) {
    const auto& n = neighbours[static_cast<std::size_t>(k)];
    if (!n) continue;
    const auto coefficient = static_cast<Real>(params.time_step * ground.cell_size_x * ground.cell_size_y *
                                               params.gravity /
                                               layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k));
    const Real difference = level - (ground.surface[*n] + water.water[*n]);
    flux[static_cast<std::size_t>(k)] = std::max(Real(0), water.flux_at(k, c) + coefficient * difference);
  }
  const auto time_step = static_cast<Real>(params.time_step);
  const auto area = static_cast<Real>(ground.cell_size_x * ground.cell_size_y);
  const Real leaving = time_step * (((flux[0] + flux[1]) + flux[2]) + flux[3]);
  const Real held = area * water.water[c];
  if (leaving > held) {
    const Real scale = held / leaving;
    for (Real& f : flux) f *= scale;
  }
  // A dry column sends nothing, so it keeps what it carries (sediment diffusion can bring some).
  drained = leaving > held && held > Real(0);
  return flux;
}

// Column c's fractions through its pipes: Δt·F_k/(l_x·l_y·w), 0 when dry.
template <class Real>
PipeValues<Real> fractions(const LayeredWater<Real>& water, const LayeredParams& params, Real area, std::size_t c) {
  PipeValues<Real> out{};
  const Real depth = water.water[c];
  if (depth <= Real(0)) return out;
  const Real held = area * depth;
  for (int k = 0; k < water_pipe_count; ++k) {
    out[static_cast<std::size_t>(k)] = static_cast<Real>(params.time_step) * water.flux_at(k, c) / held;
  }
  return out;
}

// q' of one quantity of column c (pass 2): what stays (nothing from a drained column), then what
// arrives in pipe order.
template <class Real>
Real moved(const std::vector<Real>& before, std::size_t offset, std::size_t c, const PipeValues<Real>& own,
           bool drained, const std::array<std::optional<std::size_t>, water_pipe_count>& neighbours,
           const std::vector<PipeValues<Real>>& all_fractions, bool gathers = true) {
  const Real amount = before[offset + c];
  Real sent = 0;
  for (Real f : own) sent += amount * f;
  Real result = drained ? Real(0) : std::max(amount - sent, Real(0));
  for (int k = 0; k < water_pipe_count && gathers; ++k) {
    const auto& n = neighbours[static_cast<std::size_t>(k)];
    if (!n) continue;
    result += before[offset + *n] * all_fractions[*n][static_cast<std::size_t>(k ^ 1)];
  }
  return result;
}

}  // namespace

template <class Real>
void water_sources(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                   std::uint32_t step, LayeredConversions& conversions) {
  const double area = ground.cell_size_x * ground.cell_size_y;
  // A sink: the column loses its water and what it carries, booked as sunk.
  const auto sink = [&](std::size_t c) {
    conversions.water_sunk += static_cast<double>(water.water[c]) * area;
    water.water[c] = 0;
    for (int kind = 0; kind < carried_kind_count; ++kind) {
      // Mutant: the sinks take the sediment without saying so.
      if (!mutant_active("erosion.layered.sinks_uncounted")) {
        conversions.sunk[static_cast<std::size_t>(carried_component(kind))] +=
            static_cast<double>(water.carried_at(kind, c)) * area;
      }
      water.carried_at(kind, c) = 0;
    }
  };
  if (drains(params, step)) {
    const double water_sunk_before = conversions.water_sunk;
    for (std::size_t c = 0; c < ground.cells(); ++c) sink(c);
    // Mutant (both twins): the drain's water is not booked.
    if (mutant_active("erosion.layered.drain_water_uncounted")) conversions.water_sunk = water_sunk_before;
  }
  const auto rain = static_cast<Real>(params.time_step * params.rain_rate);
  if (rain > Real(0) && rains(params, step)) {
    for (std::size_t c = 0; c < ground.cells(); ++c) water.water[c] += rain;
    // Counted once a step: the cells' equal shares summed one by one would drift by ~cells·u.
    if (!mutant_active("erosion.layered.rain_uncounted")) {
      conversions.water_added += static_cast<double>(rain) * area * static_cast<double>(ground.cells());
    }
  }
  if (!params.river) return;
  const std::size_t source = river_source_cell(ground.width, ground.height);
  const auto depth = static_cast<Real>(params.river_depth);
  const double change = static_cast<double>(depth) - static_cast<double>(water.water[source]);
  (change >= 0.0 ? conversions.water_added : conversions.water_sunk) += std::abs(change) * area;
  water.water[source] = depth;
  for (int y = 0; y < ground.height; ++y) {
    if (!river_sink_row(y, ground.height)) continue;
    for (int x = 0; x < ground.width; ++x) sink(ground.cell(x, y));
  }
}

template <class Real>
void water_flow(const LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params) {
  const std::size_t cells = ground.cells();
  std::vector<Real> new_flux(water.water_flux.size());
  std::vector<unsigned char> drained(cells);
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      bool column_drained = false;
      const auto flux = outflows(ground, water, params, x, y, column_drained);
      drained[ground.cell(x, y)] = column_drained ? 1 : 0;
      for (int k = 0; k < water_pipe_count; ++k) {
        new_flux[static_cast<std::size_t>(k) * cells + ground.cell(x, y)] = flux[static_cast<std::size_t>(k)];
      }
    }
  }
  water.water_flux = std::move(new_flux);

  const auto area = static_cast<Real>(ground.cell_size_x * ground.cell_size_y);
  std::vector<PipeValues<Real>> all_fractions(cells);
  for (std::size_t c = 0; c < cells; ++c) all_fractions[c] = fractions(water, params, area, c);
  const std::vector<Real> depth_before = water.water;
  const std::vector<Real> carried_before = water.carried;
  // Mutant: what the water carries leaves with it and never arrives.
  const bool carried_arrives = !mutant_active("erosion.layered.sediment_stays_behind");
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const auto neighbours = pipe_neighbours(ground, params.border, x, y);
      water.water[c] = moved(depth_before, 0, c, all_fractions[c], drained[c] != 0, neighbours, all_fractions);
      for (int kind = 0; kind < carried_kind_count; ++kind) {
        water.carried_at(kind, c) = moved(carried_before, static_cast<std::size_t>(kind) * cells, c, all_fractions[c],
                                          drained[c] != 0, neighbours, all_fractions, carried_arrives);
      }
    }
  }
  water.previous_water = depth_before;
}

#define GT_LAYERED_WATER_FLOW_INSTANTIATE(Real)                                                              \
  template void water_sources(const LayeredGround<Real>&, LayeredWater<Real>&, const LayeredParams&, std::uint32_t, \
                              LayeredConversions&);                                                                \
  template void water_flow(const LayeredGround<Real>&, LayeredWater<Real>&, const LayeredParams&);
GT_LAYERED_WATER_FLOW_INSTANTIATE(float)
GT_LAYERED_WATER_FLOW_INSTANTIATE(double)
#undef GT_LAYERED_WATER_FLOW_INSTANTIATE

}  // namespace gt::reference
