// Dissolution on the layered ground (digest 001 §3.13; see dissolution.hpp).
#include "reference/erosion/layered/dissolution.hpp"

#include <algorithm>

#include "reference/erosion/layered/column.hpp"

namespace gt::reference {
namespace {

template <class Real>
void dissolve_column(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params,
                     std::size_t c) {
  Real& organic = water.carried_at(regolith_kind(0), c);
  Real& sand = water.carried_at(regolith_kind(1), c);
  const Real regolith = organic + sand;
  const Real most = std::min(water.water[c], static_cast<Real>(params.regolith_depth));
  if (regolith < most) {
    const Real half = Real(0.5) * (static_cast<Real>(params.regolith_erosion) * (most - regolith));
    organic += erode_component(ground, c, 0, half, params);
    sand += erode_component(ground, c, 1, half, params);
  } else if (regolith > most) {
    const Real share = static_cast<Real>(params.regolith_deposition) * (regolith - most) / regolith;
    Composition<Real> settled{};
    for (auto [kind, regolith_part] : {std::pair{0, &organic}, std::pair{1, &sand}}) {
      const Real part = *regolith_part * share;
      const Real left = *regolith_part - part;
      const bool whole = left < static_cast<Real>(negligible_amount);
      settled[static_cast<std::size_t>(kind)] = whole ? *regolith_part : part;
      *regolith_part = whole ? Real(0) : left;
    }
    deposit_soil(ground, c, settled, static_cast<Real>(params.topsoil_max));
  }
}

}  // namespace

template <class Real>
void dissolution_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params) {
  if (params.regolith_depth <= 0.0) return;
  for (std::size_t c = 0; c < ground.cells(); ++c) dissolve_column(ground, water, params, c);
}

template void dissolution_step(LayeredGround<float>&, LayeredWater<float>&, const LayeredParams&);
template void dissolution_step(LayeredGround<double>&, LayeredWater<double>&, const LayeredParams&);

}  // namespace gt::reference
