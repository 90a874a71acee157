// Water sources, sinks and the pipe flow on the layered ground on the GPU (digest 001 §3.3, §3.7,
// §3.19), twin of reference/erosion/layered/water.hpp (decisions there).
// LayeredWaterFlow() compiles water_sources.comp, water_flux.comp and water_move.comp;
// sources(ground, water, step, conversions) runs the sources pass and counts what the rain and the
// river added and what the sinks took (m³, per column in column order, as the reference);
// flow(ground, water, step) runs the flux pass, the snapshot copy and the move pass. Needs a
// current GlContext.
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
  ComputeProgram flux_;
  ComputeProgram move_;
};

}  // namespace gt::gpu
