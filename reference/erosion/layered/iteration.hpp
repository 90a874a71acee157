// One iteration of seed 001's layered ground, CPU reference, in its code's order (digest 001 §4):
// soil creep (step 2, creep.hpp), talus collapse (3, talus.hpp), vegetation (10, vegetation.hpp),
// weathering (11, weathering.hpp), each on the state the previous one left. The water processes
// (steps 4–9: water, force erosion, impact erosion, dissolution, sediment diffusion, wetness) are not
// built yet. Every process draws its random factors with the same `step` counter, on its own
// streams (core/layered/layered_ground.hpp). GPU twin: gpu/erosion/layered/iteration.hpp. Units:
// metres, Δt in seconds; conversions in m³.
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void layered_iteration(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                       LayeredConversions& conversions);

}  // namespace gt::reference
