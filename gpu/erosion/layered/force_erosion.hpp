// Force erosion and deposition on the layered ground (digest 001 §3.4, §3.5, §3.12), GPU twin.
//
// LayeredForceErosion() compiles gpu/shaders/erosion/layered/force_erosion.comp.
// step(ground, water, step, conversions) copies the surface into the water's snapshot, runs the pass
//   and counts the size-to-size breakdown and the eroded bedrock.
//
// Inputs:  ground (LayeredGroundBuffers), water (LayeredWaterBuffers), step. Needs a current GlContext.
// Outputs: the GPU state after the pass; `conversions` gains the breakdown and the eroded bedrock,
//          per column in the reference's order.
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  std::runtime_error when the shader does not compile or link or a block does not match its
//          C++ mirror (layered_water_program).
// Twin:    reference/erosion/layered/force_erosion.hpp (decisions there).
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
