// The colours of seed 001's layered ground in pictures (compare/algorithms/layered.cpp's surface
// material and cross-section; render.terrain's drape of an eroded layered ground): one colour per
// soil component — organic dark brown, sand pale yellow, gravel light grey, stones grey, boulders
// slate — and per bedrock type — soft rock red sandstone, hard rock dark grey, granite near black
// (types past the third repeat them). Linear RGB in [0, 1].
//   layered_surface_colour(g, c): the top non-empty layer of column c, a soil layer as the mix of
//     its components' colours by thickness, bedrock as its type's colour (white for an empty
//     column), blended toward leaf green by 35 % of the vegetation density (enough to read the plant
//     cover, little enough to leave the material visible beneath it).
//   layered_colour_at_depth(g, c, depth): the layer holding the point `depth` m below the surface of
//     column c (a subsoil 20 % darker than the same mix in a topsoil), black below the last layer.
#pragma once

#include <array>
#include <cstddef>

#include "core/layered/layered_ground.hpp"

namespace gt {

using LayeredColour = std::array<float, 3>;

LayeredColour layered_component_colour(int component);
LayeredColour layered_bedrock_colour(int type);
LayeredColour layered_surface_colour(const LayeredGround<double>& ground, std::size_t c);
LayeredColour layered_colour_at_depth(const LayeredGround<double>& ground, std::size_t c, double depth);

}  // namespace gt
