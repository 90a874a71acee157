// Column operations of the layered ground: reserve-then-deposit, removal, fragmentation (digest 001
// §3.1, §3.10; decisions in column.hpp). Units: metres.
#include "reference/erosion/layered/column.hpp"

#include <algorithm>
#include <type_traits>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

// Takes the share `fraction` (in [0, 1]) of every component of soil layer `layer`; returns it.
template <class Real>
Composition<Real> take_share(LayeredGround<Real>& ground, int layer, std::size_t c, Real fraction) {
  Composition<Real> taken{};
  for (int component = 0; component < soil_component_count; ++component) {
    Real& stored = ground.soil_at(layer, component, c);
    const Real part = fraction == Real(1) ? stored : stored * fraction;
    stored -= part;
    taken[static_cast<std::size_t>(component)] = part;
  }
  return taken;
}

// Takes up to `left` from soil layer `layer` proportionally, adds it to `removed` and lowers `left`
// by it. A layer thicker than the request meets it whole (left = 0), so that the rounding of the
// proportional shares never reaches into the layer below.
template <class Real>
void take_from_soil_layer(LayeredGround<Real>& ground, int layer, std::size_t c, Real& left, Composition<Real>& removed) {
  const Real thickness = ground.soil_thickness(layer, c);
  if (thickness <= Real(0) || left <= Real(0)) return;
  const bool whole_layer = left >= thickness;
  const Composition<Real> taken = take_share(ground, layer, c, whole_layer ? Real(1) : left / thickness);
  for (std::size_t i = 0; i < taken.size(); ++i) removed[i] += taken[i];
  left = whole_layer ? left - thickness : Real(0);
}

// The calibrated pair of ledger.conversions' model (32u of what was converted, counted out and in:
// 64u of it), in both float twins (column.glsl alike): the rock breaks into 1 − 2^-16 of itself,
// 2^-16/64u = 4 times the bound where fragmentation is all that converts, or 1 − 2^-22 (1/16).
template <class Real>
Real calibrated_broken(Real amount) {
  if constexpr (std::is_same_v<Real, float>) {
    if (mutant_active("erosion.layered.fragments_short_above_bound")) return amount * (1.0f - 0x1p-16f);
    if (mutant_active("erosion.layered.fragments_short_below_bound")) return amount * (1.0f - 0x1p-22f);
  }
  return amount;
}

}  // namespace

template <class Real>
int top_nonempty_layer(const LayeredGround<Real>& ground, std::size_t c) {
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    if (ground.soil_thickness(layer, c) > Real(0)) return layer;
  }
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    if (ground.bedrock_at(layer, c) > Real(0)) return soil_layer_count + layer;
  }
  return -1;
}

template <class Real>
void organize_horizon(LayeredGround<Real>& ground, std::size_t c, Real needed, Real topsoil_max) {
  const Real topsoil = ground.soil_thickness(0, c);
  if (topsoil <= Real(0) || topsoil + needed <= topsoil_max) return;
  const Real fraction = std::clamp((topsoil + needed - topsoil_max) / topsoil, Real(0), Real(1));
  const Composition<Real> moved = take_share(ground, 0, c, fraction);
  for (int component = 0; component < soil_component_count; ++component) {
    ground.soil_at(1, component, c) += moved[static_cast<std::size_t>(component)];
  }
}

template <class Real>
void deposit_soil(LayeredGround<Real>& ground, std::size_t c, const Composition<Real>& material, Real topsoil_max) {
  const Real total = composition_total(material);
  if (total <= Real(0)) return;
  const bool reserve = !mutant_active("erosion.layered.deposit_without_reserve");  // mutant: no room made
  if (reserve) organize_horizon(ground, c, total, topsoil_max);
  for (int component = 0; component < soil_component_count; ++component) {
    ground.soil_at(0, component, c) += material[static_cast<std::size_t>(component)];
  }
  if (reserve) organize_horizon(ground, c, Real(0), topsoil_max);
  ground.surface[c] += total;
}

template <class Real>
Removed<Real> remove_soil(LayeredGround<Real>& ground, std::size_t c, Real amount) {
  Removed<Real> removed;
  Real left = amount;
  for (int layer = 0; layer < soil_layer_count; ++layer) take_from_soil_layer(ground, layer, c, left, removed.soil);
  const int top = top_nonempty_layer(ground, c);
  if (left > Real(0) && top >= soil_layer_count) {
    removed.bedrock_layer = top - soil_layer_count;
    Real& thickness = ground.bedrock_at(removed.bedrock_layer, c);
    removed.bedrock = std::min(left, thickness);
    thickness -= removed.bedrock;
  }
  if (!mutant_active("erosion.layered.surface_not_lowered")) ground.surface[c] -= removed.total();
  return removed;
}

template <class Real>
Composition<Real> fragments(const BedrockType& type, Real amount) {
  const Real broken = calibrated_broken(amount);
  Composition<Real> out{};
  Real given = 0;
  for (int size = 0; size + 1 < fragment_size_count; ++size) {
    const Real part = static_cast<Real>(type.fragments[static_cast<std::size_t>(size)]) * broken;
    out[static_cast<std::size_t>(size + 1)] = part;
    given += part;
  }
  // Mutant: the boulders' remainder is lost.
  out[fragment_size_count] = mutant_active("erosion.layered.fragments_without_boulders") ? Real(0)
                                                                                          : std::max(broken - given, Real(0));
  return out;
}

template <class Real>
Real take_from_layer(LayeredGround<Real>& ground, std::size_t c, int layer, int component, Real request,
                     const LayeredParams& params) {
  const Real thickness = ground.soil_thickness(layer, c);
  Real& stored = ground.soil_at(layer, component, c);
  const Real before = stored;
  const Real share = std::max(static_cast<Real>(params.least_share), before / thickness);
  const Real take = params.share_form == ShareForm::thesis ? std::min(request * share, before)
                                                           : std::min(before, request) * share;
  stored = before - take;
  return take;
}

template <class Real>
Real erode_component(LayeredGround<Real>& ground, std::size_t c, int component, Real request,
                     const LayeredParams& params) {
  const auto transparency_depth = static_cast<Real>(params.transparency_depth);
  Real taken = 0;
  Real left = request;
  for (int layer = 0; layer < soil_layer_count && left > Real(0); ++layer) {
    const Real thickness = ground.soil_thickness(layer, c);
    if (thickness <= Real(0)) continue;
    const Real before = ground.soil_at(layer, component, c);
    taken += take_from_layer(ground, c, layer, component, left, params);
    left = std::max(left - before, Real(0)) * std::max(Real(1) - thickness / transparency_depth, Real(0));
  }
  ground.surface[c] -= taken;
  return taken;
}

template <class Real>
Real soil_transparency(const LayeredGround<Real>& ground, std::size_t c, const LayeredParams& params) {
  const auto transparency_depth = static_cast<Real>(params.transparency_depth);
  Real through = 1;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const Real thickness = ground.soil_thickness(layer, c);
    if (thickness > Real(0)) through *= std::max(Real(1) - thickness / transparency_depth, Real(0));
  }
  return through;
}

template <class Real>
ErodedBedrock<Real> erode_bedrock(LayeredGround<Real>& ground, std::size_t c, Real amount) {
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    Real& thickness = ground.bedrock_at(layer, c);
    if (thickness <= Real(0)) continue;
    const Real taken = std::min(amount, thickness);
    thickness -= taken;
    ground.surface[c] -= taken;
    return {layer, taken};
  }
  return {};
}

#define GT_LAYERED_COLUMN_INSTANTIATE(Real)                                                             \
  template int top_nonempty_layer(const LayeredGround<Real>&, std::size_t);                             \
  template void organize_horizon(LayeredGround<Real>&, std::size_t, Real, Real);                        \
  template void deposit_soil(LayeredGround<Real>&, std::size_t, const Composition<Real>&, Real);       \
  template Removed<Real> remove_soil(LayeredGround<Real>&, std::size_t, Real);                          \
  template Composition<Real> fragments(const BedrockType&, Real);                                        \
  template Real take_from_layer(LayeredGround<Real>&, std::size_t, int, int, Real, const LayeredParams&); \
  template Real erode_component(LayeredGround<Real>&, std::size_t, int, Real, const LayeredParams&);     \
  template Real soil_transparency(const LayeredGround<Real>&, std::size_t, const LayeredParams&);        \
  template ErodedBedrock<Real> erode_bedrock(LayeredGround<Real>&, std::size_t, Real);
GT_LAYERED_COLUMN_INSTANTIATE(float)
GT_LAYERED_COLUMN_INSTANTIATE(double)
#undef GT_LAYERED_COLUMN_INSTANTIATE

}  // namespace gt::reference
