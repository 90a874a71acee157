// One iteration of seed 001's layered ground on the GPU, twin of reference/erosion/layered/
// iteration.hpp: creep, talus, vegetation, weathering (digest 001 §4, steps 2, 3, 10, 11), each
// process's passes dispatched in turn on the same LayeredGroundBuffers. LayeredIteration() compiles
// the four processes' programs; step(ground, step, conversions) runs one iteration. Needs a
// current GlContext.
#pragma once

#include <cstdint>

#include "gpu/erosion/layered/creep.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/talus.hpp"
#include "gpu/erosion/layered/vegetation.hpp"
#include "gpu/erosion/layered/weathering.hpp"

namespace gt::gpu {

class LayeredIteration {
 public:
  LayeredIteration();
  void step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const;

 private:
  LayeredSlopeProcess creep_;
  LayeredSlopeProcess talus_;
  LayeredVegetation vegetation_;
  LayeredWeathering weathering_;
};

}  // namespace gt::gpu
