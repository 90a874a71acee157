// The colours of the layered ground in pictures (see layered_look.hpp).
#include "compare/layered_look.hpp"

#include "reference/erosion/layered/column.hpp"

namespace gt {
namespace {

constexpr std::array<LayeredColour, soil_component_count> component_colours{
    LayeredColour{0.32f, 0.22f, 0.12f}, LayeredColour{0.93f, 0.83f, 0.56f}, LayeredColour{0.68f, 0.66f, 0.62f},
    LayeredColour{0.48f, 0.48f, 0.50f}, LayeredColour{0.32f, 0.34f, 0.40f}};
constexpr std::array<LayeredColour, 3> bedrock_colours{LayeredColour{0.72f, 0.42f, 0.32f},
                                                       LayeredColour{0.36f, 0.36f, 0.36f},
                                                       LayeredColour{0.16f, 0.16f, 0.18f}};
constexpr LayeredColour leaf{0.20f, 0.55f, 0.15f};
constexpr float vegetation_tint = 0.35f;
constexpr float subsoil_shade = 0.8f;

LayeredColour soil_colour(const LayeredGround<double>& ground, int layer, std::size_t c) {
  const double thickness = ground.soil_thickness(layer, c);
  LayeredColour mixed{0, 0, 0};
  for (int component = 0; component < soil_component_count; ++component) {
    const auto share = float(ground.soil_at(layer, component, c) / thickness);
    const LayeredColour colour = layered_component_colour(component);
    for (int channel = 0; channel < 3; ++channel) mixed[channel] += share * colour[channel];
  }
  return mixed;
}

}  // namespace

LayeredColour layered_component_colour(int component) { return component_colours.at(std::size_t(component)); }

LayeredColour layered_bedrock_colour(int type) { return bedrock_colours[std::size_t(type) % bedrock_colours.size()]; }

LayeredColour layered_surface_colour(const LayeredGround<double>& ground, std::size_t c) {
  const int layer = reference::top_nonempty_layer(ground, c);
  LayeredColour colour = layer < 0                  ? LayeredColour{1, 1, 1}
                         : layer < soil_layer_count ? soil_colour(ground, layer, c)
                                                    : layered_bedrock_colour(ground.bedrock_type_at(layer - soil_layer_count, c));
  const float green = vegetation_tint * float(ground.vegetation[c]);
  for (int channel = 0; channel < 3; ++channel) colour[channel] = (1 - green) * colour[channel] + green * leaf[channel];
  return colour;
}

LayeredColour layered_colour_at_depth(const LayeredGround<double>& ground, std::size_t c, double depth) {
  double top = 0.0;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const double thickness = ground.soil_thickness(layer, c);
    if (depth < top + thickness) {
      LayeredColour colour = soil_colour(ground, layer, c);
      for (float& channel : colour) channel *= layer == 0 ? 1.0f : subsoil_shade;
      return colour;
    }
    top += thickness;
  }
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    top += ground.bedrock_at(layer, c);
    if (depth < top) return layered_bedrock_colour(ground.bedrock_type_at(layer, c));
  }
  return {0, 0, 0};
}

}  // namespace gt
