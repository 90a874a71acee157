// Vegetation growth on the layered ground (digest 001 §3.15), GPU twin.
//
// LayeredVegetation(flood = false) (or layered_vegetation(flood)) compiles
//   gpu/shaders/erosion/layered/vegetation.comp twice: the grow pass writes every column's new density
//   into the outflow buffer (scratch) from the old densities, the store pass copies it into the
//   vegetation buffer — the reference's double buffer. LayeredVegetation(true) compiles the grow pass
//   with LAYERED_FLOOD, the flood death read from the water's wetness (bind the water buffers first).
// step(ground, step, conversions) runs both, drawing rand(0, 1) with the reference's key (seed, cell,
//   step, vegetation_cell_stream).
//
// Inputs:  ground (LayeredGroundBuffers), step; with flood, the water buffers bound. Needs a current
//          GlContext.
// Outputs: the densities after the step; growth converts nothing, so `conversions` stays as it is.
// Units:   K_veg in 1/s, Δt in s, depths in m.
// Throws:  std::runtime_error when a shader does not compile or link or a block does not match its C++
//          mirror.
// Twin:    reference/erosion/layered/vegetation.hpp (decisions there).
#pragma once

#include <cstdint>

#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

class LayeredVegetation {
 public:
  explicit LayeredVegetation(bool flood = false);
  void step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const;

 private:
  ComputeProgram grow_;
  ComputeProgram store_;
};

LayeredVegetation layered_vegetation(bool flood = false);

}  // namespace gt::gpu
