// Weathering of soil rock and bedrock → soil on the layered ground (digest 001 §3.16; decisions and
// units in weathering.hpp).
#include "reference/erosion/layered/weathering.hpp"

#include <algorithm>
#include <array>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

// Step 1 in soil layer `layer`: a_p = min(base·K_p, V_{p+1}) moves component p + 1 into p.
template <class Real>
void break_rock(LayeredGround<Real>& ground, const LayeredParams& params, int layer, std::size_t c, Real base,
                double area, LayeredConversions& conversions) {
  std::array<Real, soil_component_count> old{};
  for (int i = 0; i < soil_component_count; ++i) old[static_cast<std::size_t>(i)] = ground.soil_at(layer, i, c);
  std::array<Real, fragment_size_count> amounts{};
  for (std::size_t p = 0; p < amounts.size(); ++p) {
    amounts[p] = std::min(base * static_cast<Real>(params.weathering_shares[p]), old[p + 1]);
    conversions.weathered_from[p + 1] += static_cast<double>(amounts[p]) * area;
    conversions.weathered_into[p] += static_cast<double>(amounts[p]) * area;
  }
  // Mutant: the sand that roots turn organic leaves the sand but never arrives.
  ground.soil_at(layer, 0, c) = mutant_active("erosion.layered.weathering_loses_organic") ? old[0] : old[0] + amounts[0];
  for (std::size_t i = 1; i + 1 < old.size(); ++i) {
    ground.soil_at(layer, static_cast<int>(i), c) = old[i] + amounts[i] - amounts[i - 1];
  }
  ground.soil_at(layer, soil_component_count - 1, c) = old[soil_component_count - 1] - amounts[fragment_size_count - 1];
}

// Step 2: the top non-empty bedrock layer under a soil thinner than the reach becomes subsoil.
template <class Real>
void form_soil(LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c, Real veg, double area,
               LayeredConversions& conversions) {
  const Real soil = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
  if (!(soil < static_cast<Real>(params.weathering_reach))) return;
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    Real& thickness = ground.bedrock_at(layer, c);
    if (thickness <= Real(0)) continue;
    const auto type = static_cast<std::size_t>(ground.bedrock_type_at(layer, c));
    const BedrockType& rock = params.bedrock_types[type];
    const Real wanted = static_cast<Real>(rock.soil_rate) * static_cast<Real>(params.time_step) * veg;
    const Real formed = std::min(wanted, thickness);
    if (formed <= Real(0)) return;
    thickness -= formed;
    conversions.soil_formed_from[type] += static_cast<double>(formed) * area;
    Real given = 0;
    for (int component = 0; component < soil_component_count; ++component) {
      const bool last = component + 1 == soil_component_count;
      const Real part = last ? std::max(formed - given, Real(0))
                             : static_cast<Real>(rock.soil_composition[static_cast<std::size_t>(component)]) * formed;
      given += part;
      ground.soil_at(1, component, c) += part;
      conversions.soil_formed_into[static_cast<std::size_t>(component)] += static_cast<double>(part) * area;
    }
    return;
  }
}

}  // namespace

template <class Real>
void weather_column(LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c,
                    LayeredConversions& conversions) {
  const Real veg = ground.vegetation[c];
  if (veg <= Real(0)) return;
  conversions.fit_types(params.bedrock_types.size());
  const double area = ground.cell_size_x * ground.cell_size_y;
  const Real base = static_cast<Real>(params.weathering_rate) * static_cast<Real>(params.time_step) * veg;
  for (int layer = 0; layer < soil_layer_count; ++layer) break_rock(ground, params, layer, c, base, area, conversions);
  form_soil(ground, params, c, veg, area, conversions);
}

template <class Real>
void weathering_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t /*step*/,
                     LayeredConversions& conversions) {
  conversions.fit_types(params.bedrock_types.size());
  for (std::size_t c = 0; c < ground.cells(); ++c) weather_column(ground, params, c, conversions);
}

#define GT_LAYERED_WEATHERING_INSTANTIATE(Real)                                                           \
  template void weather_column(LayeredGround<Real>&, const LayeredParams&, std::size_t, LayeredConversions&); \
  template void weathering_step(LayeredGround<Real>&, const LayeredParams&, std::uint32_t, LayeredConversions&);
GT_LAYERED_WEATHERING_INSTANTIATE(float)
GT_LAYERED_WEATHERING_INSTANTIATE(double)
#undef GT_LAYERED_WEATHERING_INSTANTIATE

}  // namespace gt::reference
