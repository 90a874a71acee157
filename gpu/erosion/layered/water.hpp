// Water sources, sinks and the pipe flow on the layered ground (digest 001 §3.3, §3.7, §3.19), GPU twin.
//
// LayeredWaterFlow() compiles gpu/shaders/erosion/layered/water_sources.comp, water_flux.comp and
//   water_move.comp.
// sources(ground, water, step, conversions) runs the drain at iteration drain_step (the sources
//   pass with DRAIN_ALL), then the sources pass, and counts what the rain and the river added and
//   what the sinks and the drain took.
// flow(ground, water, step) runs the flux pass, the snapshot copy and the move pass.
//
// Inputs:  ground (LayeredGroundBuffers), water (LayeredWaterBuffers), step. Needs a current GlContext.
// Outputs: the water state after the passes; `conversions` gains the water added and sunk and what the
//          sinks took (per column in column order, as the reference).
// Units:   m, m/s, m³/s; conversions in m³.
// Throws:  std::runtime_error when a shader does not compile or link or a block does not match its
//          C++ mirror (layered_water_program).
// Twin:    reference/erosion/layered/water.hpp (decisions there).
#pragma once

#include <cstdint>

#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"

namespace gt::gpu {

class LayeredWaterFlow {
 public:
  LayeredWaterFlow();
  void sources(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step,
               LayeredConversions& conversions) const;
  void flow(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step) const;

 private:
  ComputeProgram sources_;
  ComputeProgram drain_;
  ComputeProgram flux_;
  ComputeProgram move_;
};

}  // namespace gt::gpu
