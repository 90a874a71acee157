// Weathering on the layered ground (digest 001 §3.16), GPU twin.
//
// LayeredWeathering() (or layered_weathering()) compiles gpu/shaders/erosion/layered/weathering.comp.
// step(ground, step, conversions) runs it once (one invocation per column, in place), reads back each
//   column's record (the amounts of the four soil conversions in each soil layer, the bedrock turned
//   into soil, its type and parts) and adds them to `conversions` in double, in the reference's order
//   (column, layer, conversion), so the counts equal the reference<float>'s bit for bit. Its record
//   buffer (16 floats per column) is made on the first step for the ground's size.
//
// Inputs:  ground (LayeredGroundBuffers), step. Needs a current GlContext.
// Outputs: the GPU state after the step; `conversions` gains what weathering converted.
// Units:   metres; conversions in m³.
// Throws:  std::runtime_error when the shader does not compile or link or a block does not match its
//          C++ mirror.
// Twin:    reference/erosion/layered/weathering.hpp (decisions there).
#pragma once

#include <cstdint>
#include <optional>

#include "gpu/buffer.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

class LayeredWeathering {
 public:
  LayeredWeathering();
  void step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const;

 private:
  ComputeProgram program_;
  mutable std::optional<StorageBuffer> records_;
};

LayeredWeathering layered_weathering();

}  // namespace gt::gpu
