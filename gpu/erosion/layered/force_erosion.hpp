// Force erosion and deposition on the layered ground on the GPU (digest 001 §3.12), twin of
// reference/erosion/layered/force_erosion.hpp (decisions there). LayeredForceErosion() compiles
// force_erosion.comp; step(ground, water, step, conversions) copies the surface into the water's
// snapshot, runs the pass and counts the size-to-size breakdown and the eroded bedrock (m³, per
// column in the reference's order). Needs a current GlContext.
#pragma once

#include <cstdint>

#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"

namespace gt::gpu {

class LayeredForceErosion {
 public:
  LayeredForceErosion();
  void step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
            LayeredConversions& conversions) const;

 private:
  ComputeProgram program_;
};

}  // namespace gt::gpu
