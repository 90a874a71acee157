// One iteration of the layered ground on the GPU (see iteration.hpp).
#include "gpu/erosion/layered/iteration.hpp"

#include <stdexcept>

namespace gt::gpu {

LayeredWaterProcesses::LayeredWaterProcesses()
    : dissolution("erosion/layered/dissolution.comp"), diffusion("erosion/layered/diffusion.comp"),
      wetness("erosion/layered/wetness.comp") {}

LayeredIteration::LayeredIteration(bool with_water)
    : creep_(layered_creep()), talus_(layered_talus()), vegetation_(layered_vegetation(with_water)),
      weathering_(layered_weathering()) {
  if (with_water) water_.emplace();
}

void LayeredIteration::step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions,
                            const LayeredWaterBuffers* water) const {
  if (water_.has_value() != (water != nullptr)) {
    throw std::invalid_argument("LayeredIteration::step: water buffers are needed exactly when built with water");
  }
  if (water != nullptr) water_->flow.sources(ground, *water, step, conversions);
  creep_.step(ground, step, conversions);
  if (ground.params().talus) talus_.step(ground, step, conversions);
  if (water != nullptr) {
    water_->flow.flow(ground, *water, step);
    water_->force_erosion.step(ground, *water, step, conversions);
    water_->impact_erosion.step(ground, *water, step, conversions);
    if (ground.params().regolith_depth > 0.0) water_->dissolution.step(ground, *water, step);
    if (ground.params().sediment_diffusion > 0.0) {
      water->snapshot();  // diffusion.comp reads the carried kinds as they were before the pass
      water_->diffusion.step(ground, *water, step);
    }
    water_->wetness.step(ground, *water, step);
    water->bind();
  }
  vegetation_.step(ground, step, conversions);
  weathering_.step(ground, step, conversions);
}

}  // namespace gt::gpu
