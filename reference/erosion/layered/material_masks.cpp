// Material masks with transparency (digest 001 §3.17; see material_masks.hpp).
#include "reference/erosion/layered/material_masks.hpp"

#include <algorithm>

namespace gt::reference {

std::vector<double> material_masks(const LayeredGround<double>& ground, const LayeredParams& params, std::size_t c) {
  std::vector<double> masks(soil_component_count + params.bedrock_types.size(), 0.0);
  double left = 1.0;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const double thickness = ground.soil_thickness(layer, c);
    if (thickness <= 0.0) continue;
    const double through = std::max(1.0 - thickness / params.transparency_depth, 0.0);
    const double shown = left * (1.0 - through);
    for (int component = 0; component < soil_component_count; ++component) {
      masks[std::size_t(component)] += shown * ground.soil_at(layer, component, c) / thickness;
    }
    left *= through;
  }
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    if (ground.bedrock_at(layer, c) <= 0.0) continue;
    masks.at(soil_component_count + std::size_t(ground.bedrock_type_at(layer, c))) += left;
    break;
  }
  return masks;
}

}  // namespace gt::reference
