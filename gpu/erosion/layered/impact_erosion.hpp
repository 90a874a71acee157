// Impact erosion on the layered ground on the GPU (digest 001 §3.14), twin of
// reference/erosion/layered/impact_erosion.hpp (decisions there). LayeredImpactErosion() compiles
// impact_erosion.comp's two passes; step(ground, water, step, conversions) copies the surface into
// the water's snapshot, runs the erosion pass and the gather pass, and counts each column's
// breakdown and eroded bedrock (m³, in the reference's order). Nothing runs when impact_rate is 0.
// Needs a current GlContext.
#pragma once

#include <cstdint>

#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"

namespace gt::gpu {

class LayeredImpactErosion {
 public:
  LayeredImpactErosion();
  void step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
            LayeredConversions& conversions) const;

 private:
  ComputeProgram erode_;
  ComputeProgram gather_;
};

}  // namespace gt::gpu
