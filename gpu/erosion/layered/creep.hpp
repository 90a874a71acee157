// Soil creep on the layered ground (digest 001 §3.11, eq. 3.4, Roering's law), GPU twin.
//
// layered_creep() -> LayeredSlopeProcess: compiles gpu/shaders/erosion/layered/creep_outflow.comp and
//   apply.comp (vegetation untouched); its step(ground, step, conversions) runs one compute-then-apply
//   step on the GPU state with the reference's random keys.
//
// Inputs:  ground: LayeredGroundBuffers (ground_buffers.hpp); step: the random draws' counter. Needs
//          a current GlContext.
// Outputs: the GPU state after the step. Creep moves soil only, so it adds zeros to `conversions`,
//          taken for the common step protocol.
// Units:   metres, K_z in m/s, Δt in seconds.
// Throws:  std::runtime_error when a shader does not compile or link or a block does not match its C++
//          mirror (layered_program).
// Twin:    reference/erosion/layered/creep.hpp (decisions there).
#pragma once

#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

LayeredSlopeProcess layered_creep();

}  // namespace gt::gpu
