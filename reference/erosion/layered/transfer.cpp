// Apply pass of layered talus and creep (digest 001 §3.10-3.11; see transfer.hpp). Units: metres.
#include "reference/erosion/layered/transfer.hpp"

#include <algorithm>
#include <limits>
#include <type_traits>

#include "core/mutant.hpp"
#include "core/rng.hpp"
#include "reference/erosion/layered/column.hpp"

namespace gt::reference {
namespace {

template <class Real>
Real layer_thickness(const LayeredGround<Real>& ground, int layer, std::size_t c) {
  return layer < soil_layer_count ? ground.soil_thickness(layer, c) : ground.bedrock_at(layer - soil_layer_count, c);
}

// What `amount` m leaving donor n carries, from the snapshot `before`: its topmost non-empty
// layer's composition, or the fragments of its bedrock (counted in `conversions`, m³).
template <class Real>
Composition<Real> flux_composition(const LayeredGround<Real>& before, std::size_t n, Real amount,
                                   const LayeredParams& params, LayeredConversions& conversions) {
  const int layer = top_nonempty_layer(before, n);
  if (layer < soil_layer_count) {
    const Real share = amount / before.soil_thickness(layer, n);
    Composition<Real> carried{};
    for (int component = 0; component < soil_component_count; ++component) {
      // Mutant: each component arrives as the next one (organic as sand, ..., boulders as organic).
      const int arriving = mutant_active("erosion.layered.flux_components_shifted") ? (component + 1) % soil_component_count
                                                                                     : component;
      carried[static_cast<std::size_t>(arriving)] = before.soil_at(layer, component, n) * share;
    }
    return carried;
  }
  const auto type = before.bedrock_type_at(layer - soil_layer_count, n);
  const Composition<Real> broken = fragments(params.bedrock_types[static_cast<std::size_t>(type)], amount);
  const double area = before.cell_size_x * before.cell_size_y;
  for (std::size_t i = 0; i < broken.size(); ++i) conversions.fragmented_into[i] += static_cast<double>(broken[i]) * area;
  return broken;
}

template <class Real>
void give(LayeredGround<Real>& ground, const LayeredGround<Real>& before, std::size_t c, Real outflow,
          LayeredConversions& conversions) {
  const int layer = top_nonempty_layer(before, c);
  const Removed<Real> removed = remove_soil(ground, c, std::min(outflow, layer_thickness(before, layer, c)));
  if (removed.bedrock_layer >= 0) {
    const auto type = static_cast<std::size_t>(before.bedrock_type_at(removed.bedrock_layer, c));
    conversions.fragmented_from[type] += static_cast<double>(removed.bedrock) * before.cell_size_x * before.cell_size_y;
  }
}

// The material arriving at column (x, y) from its neighbours, in neighbour order.
template <class Real>
Composition<Real> gather(const LayeredGround<Real>& before, const Outflows<Real>& outflows, const LayeredParams& params,
                         int x, int y, LayeredConversions& conversions) {
  Composition<Real> arriving{};
  // Mutant erosion.layered.diagonal_arrivals_dropped: only the 4 edge neighbours (k < 4) are gathered.
  const int gathered = mutant_active("erosion.layered.diagonal_arrivals_dropped") ? 4 : layered_neighbour_count;
  for (int k = 0; k < gathered; ++k) {
    const auto n = layered_neighbour(before, params.border, x, y, k);
    if (!n) continue;
    const Real amount = outflows[*n][static_cast<std::size_t>(k ^ 1)];
    if (amount <= Real(0)) continue;
    const Composition<Real> carried = flux_composition(before, *n, amount, params, conversions);
    for (std::size_t i = 0; i < carried.size(); ++i) arriving[i] += carried[i];
  }
  return arriving;
}

// The calibrated pair of the float ledger's model (ledger.* in compare/algorithms/layered.cpp:
// 2u·R = 72u of the volume a step, dry), in both float twins (apply.comp alike): every stored
// thickness times 1 − 2^-16 after each creep and talus pass (2^-16/72u = 3.6 times the bound a pass;
// a dry step runs both: 7.1 times) or 1 − 2^-22 (0.11 times a step).
template <class Real>
void calibrated_leak(LayeredGround<Real>& ground) {
  if constexpr (std::is_same_v<Real, float>) {
    const float kept = mutant_active("erosion.layered.float_leak_above_bound")   ? 1.0f - 0x1p-16f
                       : mutant_active("erosion.layered.float_leak_below_bound") ? 1.0f - 0x1p-22f
                                                                                  : 1.0f;
    if (kept == 1.0f) return;
    for (float& thickness : ground.soil) thickness *= kept;
    for (float& thickness : ground.bedrock) thickness *= kept;
  }
}

}  // namespace

template <class Real>
Real random_factor(bool on, std::uint32_t seed, std::size_t c, std::uint32_t step, std::uint32_t stream) {
  if (!on) return Real(1);
  const float u = uniform01(random_u32(seed, static_cast<std::uint32_t>(c), step, stream));
  return Real(0.9) + Real(0.1) * static_cast<Real>(u);
}

template <class Real>
NeighbourAmounts<Real> neighbour_surfaces(const LayeredGround<Real>& ground, LayeredBorder border, int x, int y) {
  NeighbourAmounts<Real> surfaces;
  for (int k = 0; k < layered_neighbour_count; ++k) {
    const auto n = layered_neighbour(ground, border, x, y, k);
    surfaces[static_cast<std::size_t>(k)] = n ? ground.surface[*n] : std::numeric_limits<Real>::infinity();
  }
  return surfaces;
}

template <class Real>
void clamp_to_available(NeighbourAmounts<Real>& amounts, Real available) {
  const Real total = ordered_total(amounts);
  if (total <= available) return;
  const Real factor = available / total;
  for (Real& amount : amounts) amount *= factor;
}

template <class Real>
void apply_outflows(LayeredGround<Real>& ground, const Outflows<Real>& outflows, const LayeredParams& params,
                    bool clear_vegetation, LayeredConversions& conversions) {
  const LayeredGround<Real> before = ground;
  conversions.fragmented_from.resize(std::max(conversions.fragmented_from.size(), params.bedrock_types.size()), 0.0);
  const auto topsoil_max = static_cast<Real>(params.topsoil_max);
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const Real outflow = ordered_total(outflows[c]);
      if (outflow > Real(0)) give(ground, before, c, outflow, conversions);
      const Composition<Real> arriving = gather(before, outflows, params, x, y, conversions);
      const bool received = composition_total(arriving) > Real(0);
      if (received) deposit_soil(ground, c, arriving, topsoil_max);
      if (clear_vegetation && (received || outflow > Real(0))) ground.vegetation[c] = Real(0);
    }
  }
  calibrated_leak(ground);
}

#define GT_LAYERED_TRANSFER_INSTANTIATE(Real)                                                              \
  template Real random_factor(bool, std::uint32_t, std::size_t, std::uint32_t, std::uint32_t);            \
  template NeighbourAmounts<Real> neighbour_surfaces(const LayeredGround<Real>&, LayeredBorder, int, int);         \
  template void clamp_to_available(NeighbourAmounts<Real>&, Real);                                         \
  template void apply_outflows(LayeredGround<Real>&, const Outflows<Real>&, const LayeredParams&, bool,    \
                               LayeredConversions&);
GT_LAYERED_TRANSFER_INSTANTIATE(float)
GT_LAYERED_TRANSFER_INSTANTIATE(double)
#undef GT_LAYERED_TRANSFER_INSTANTIATE

}  // namespace gt::reference
