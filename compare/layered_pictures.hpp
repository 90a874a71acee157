// The pictures a geologist reads of seed 001's layered ground after a run (compare/algorithms/layered.cpp):
//   surface_material.png  the top non-empty layer's colour, mixed by composition, greened by vegetation
//   cross_section.png     the middle row: the surface's elevation above, the layers below, true to
//                         scale in depth
//   cross_section_axes.png the same row with axes in metres: the surface's elevation, and the base
//                         of each layer below the surface (matplotlib; a note where unavailable)
//   mask_<material>.png   each material mask with the thesis's transparency (§3.17,
//                         reference/erosion/layered/material_masks.hpp), black to the material's
//                         colour at its largest share, with its colour bar; and as a field (EXR/NPY)
// Colours: compare/layered_look.hpp. Nothing is written without a report folder.
#pragma once

#include <cstddef>
#include <string>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt {

// A material of the ledger's order: the 5 soil components, then each bedrock type ("bedrock type k").
std::string layered_material_name(std::size_t material);

void write_layered_pictures(const LayeredGround<double>& ground, const LayeredParams& params, const RunOptions& options,
                            CaseResult& result);

}  // namespace gt
