// The slope processes of one iteration of seed 001's layered ground, in the code's order (digest 001
// §4, steps 2-3): soil creep (creep.hpp), then talus collapse (talus.hpp), each compute-then-apply
// on the state the previous one left. Both draw their random factors with the same `step` counter,
// on different streams. Units: metres, Δt in seconds; conversions in m³.
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void slope_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                LayeredConversions& conversions);

}  // namespace gt::reference
