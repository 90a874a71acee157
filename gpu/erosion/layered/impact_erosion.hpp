// Impact erosion on the layered ground (digest 001 §3.14), GPU twin.
//
// LayeredImpactErosion() compiles gpu/shaders/erosion/layered/impact_erosion.comp's two passes.
// step(ground, water, step, conversions) copies the surface into the water's snapshot, runs the
//   erosion pass and the gather pass, and counts each column's breakdown and eroded bedrock. Nothing
//   runs when impact_rate is 0.
//
// Inputs:  ground (LayeredGroundBuffers), water (LayeredWaterBuffers), step. Needs a current GlContext.
// Outputs: the GPU state after the step; `conversions` gains each column's breakdown and eroded
//          bedrock, in the reference's order.
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  std::runtime_error when a shader does not compile or link or a block does not match its
//          C++ mirror (layered_water_program).
// Twin:    reference/erosion/layered/impact_erosion.hpp (decisions there).
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
