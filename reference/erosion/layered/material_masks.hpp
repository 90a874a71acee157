// Material masks of seed 001's layered ground (digest 001 §3.17, thesis §4.3), CPU reference.
//
// material_masks(ground, params, c) -> for column c, how much of its visible surface each material
//   is, for shading. The thesis's transparency rule: a layer thinner than K_pmin lets the one below
//   show through with the share K_p = max(1 − h/K_pmin, 0) (the same K_p as erosion's, §3.12). Top
//   down over the non-empty soil layers, with w the share still to be given (1 at the top):
//     mask_i += w·(1 − K_p)·V_i/h   for each component i of the layer;   w ← w·K_p
//   then the first non-empty bedrock layer takes what is left, w, on its type's mask.
//
// Inputs:  ground (LayeredGround<double>, valid), params (K_pmin = transparency_depth, the bedrock
//          types), column index c.
// Outputs: the masks in the order org, sand, gravel, stones, boulders, then bedrock type 0, 1, ...
//          (`types` of them). The masks of a column sum to 1 (0 for a column with nothing in it).
// Units:   dimensionless.
// Throws:  nothing for a valid ground (a bedrock type index beyond params' types would make
//          std::vector::at throw std::out_of_range).
// Twin:    none: a shading output drawn from the double reference's ground (compare/layered_pictures.cpp),
//          not a compared algorithm.
// Decisions: the code's composition (normalise(top) + multiplier·normalise(sub), renormalised,
//          × (1 − multiplier)) gives the subsoil more than its share and forgets the multiplier on the
//          subsoil's organic matter (a bug, §3.17); the telescoping form above is the thesis's rule and
//          sums to 1 exactly.
#pragma once

#include <cstddef>
#include <vector>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

std::vector<double> material_masks(const LayeredGround<double>& ground, const LayeredParams& params, std::size_t c);

}  // namespace gt::reference
