// Soil creep on the layered ground (digest 001 §3.11, eq. 3.4; decisions and units in creep.hpp).
#include "reference/erosion/layered/creep.hpp"

#include <algorithm>

#include "reference/erosion/layered/column.hpp"

namespace gt::reference {
namespace {

// Roering's flux towards each lower neighbour, and whether any slope reached S_c with the singular
// (thesis) law; then `weights` holds those slopes instead.
template <class Real>
struct CreepFluxes {
  NeighbourAmounts<Real> weights{};
  bool unbounded = false;
};

template <class Real>
CreepFluxes<Real> creep_fluxes(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c,
                               const NeighbourAmounts<Real>& surfaces) {
  CreepFluxes<Real> fluxes;
  NeighbourAmounts<Real> steep{};
  const auto rate = static_cast<Real>(params.creep_rate);
  const auto critical = static_cast<Real>(params.critical_slope);
  const auto floor = static_cast<Real>(params.creep_denominator_floor);
  for (int k = 0; k < layered_neighbour_count; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const Real drop = ground.surface[c] - surfaces[i];
    if (!(drop > Real(0))) continue;
    const Real slope = drop / static_cast<Real>(layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k));
    const Real ratio = slope / critical;
    Real denominator = Real(1) - ratio * ratio;
    if (params.creep_denominator == CreepDenominator::seed001_code) denominator = std::max(denominator, floor);
    if (denominator <= Real(0)) {
      fluxes.unbounded = true;
      steep[i] = slope;
    } else {
      fluxes.weights[i] = rate * slope / denominator;
    }
  }
  if (fluxes.unbounded) fluxes.weights = steep;
  return fluxes;
}

template <class Real>
NeighbourAmounts<Real> column_outflow(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y,
                                      std::uint32_t step) {
  const std::size_t c = ground.cell(x, y);
  const int layer = top_nonempty_layer(ground, c);
  if (layer < 0 || layer >= soil_layer_count) return {};
  const Real thickness = ground.soil_thickness(layer, c);
  const Real organic_share = ground.soil_at(layer, static_cast<int>(SoilComponent::org), c) / thickness;
  const CreepFluxes<Real> fluxes = creep_fluxes(ground, params, c, neighbour_surfaces(ground, params.border, x, y));
  Real weight_sum = 0;
  for (Real weight : fluxes.weights) weight_sum += weight;
  NeighbourAmounts<Real> amounts{};
  if (!(weight_sum > Real(0)) || !(organic_share > Real(0))) return amounts;
  const Real random = random_factor<Real>(params.creep_random, params.seed, c, step, creep_cell_stream);
  const Real wanted = fluxes.unbounded
                          ? thickness
                          : static_cast<Real>(params.time_step) * organic_share * weight_sum * random * Real(0.5);
  const Real total = std::min(wanted, thickness);
  for (std::size_t k = 0; k < amounts.size(); ++k) amounts[k] = total * (fluxes.weights[k] / weight_sum);
  return amounts;
}

}  // namespace

template <class Real>
Outflows<Real> creep_outflows(const LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step) {
  Outflows<Real> outflows(ground.cells());
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) outflows[ground.cell(x, y)] = column_outflow(ground, params, x, y, step);
  }
  return outflows;
}

template <class Real>
void creep_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions) {
  const Outflows<Real> outflows = creep_outflows(ground, params, step);
  apply_outflows(ground, outflows, params, false, conversions);
}

#define GT_LAYERED_CREEP_INSTANTIATE(Real)                                                               \
  template Outflows<Real> creep_outflows(const LayeredGround<Real>&, const LayeredParams&, std::uint32_t); \
  template void creep_step(LayeredGround<Real>&, const LayeredParams&, std::uint32_t, LayeredConversions&);
GT_LAYERED_CREEP_INSTANTIATE(float)
GT_LAYERED_CREEP_INSTANTIATE(double)
#undef GT_LAYERED_CREEP_INSTANTIATE

}  // namespace gt::reference
