// One iteration of seed 001's layered ground in its code's order (digest 001 §4), CPU reference.
//
// layered_iteration(ground, params, step, conversions, water = nullptr): each process on the state
// the previous one left:
//   with `water`: 1 sources and sinks (water.hpp); 2 soil creep (creep.hpp); 3 talus collapse
//   (talus.hpp; unless params.talus is off); with `water`: 4 the pipe flow (water.hpp), 5 force
//   erosion (force_erosion.hpp), 6 impact erosion (impact_erosion.hpp), 7 dissolution
//   (dissolution.hpp), 8 sediment diffusion (diffusion.hpp), 9 wetness (wetness.hpp); 10 vegetation
//   (vegetation.hpp, with the flood death when there is water); 11 weathering (weathering.hpp).
//
// Inputs:  ground and params (valid, as the processes assume); step: every process draws its random
//          factors with the same `step` counter, on its own streams (core/layered/layered_ground.hpp);
//          water: the ground's water, or null for a dry ground.
// Outputs: ground (and water) after the iteration; `conversions` gains what the processes converted.
// Units:   metres, Δt in seconds; conversions in m³.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/iteration.hpp (LayeredIteration).
#pragma once

#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void layered_iteration(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                       LayeredConversions& conversions, LayeredWater<Real>* water = nullptr);

}  // namespace gt::reference
