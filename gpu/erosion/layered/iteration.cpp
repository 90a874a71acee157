// One iteration of the layered ground on the GPU (see iteration.hpp).
#include "gpu/erosion/layered/iteration.hpp"

namespace gt::gpu {

LayeredIteration::LayeredIteration()
    : creep_(layered_creep()), talus_(layered_talus()), vegetation_(layered_vegetation()),
      weathering_(layered_weathering()) {}

void LayeredIteration::step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const {
  creep_.step(ground, step, conversions);
  talus_.step(ground, step, conversions);
  vegetation_.step(ground, step, conversions);
  weathering_.step(ground, step, conversions);
}

}  // namespace gt::gpu
