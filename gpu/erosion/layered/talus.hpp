// Per-material talus collapse on the layered ground (digest 001 §3.10, eq. 3.1-3.3), GPU twin.
//
// layered_talus() -> LayeredSlopeProcess: compiles gpu/shaders/erosion/layered/talus_outflow.comp and
//   apply.comp with LAYERED_CLEAR_VEGETATION (a column that gives or receives loses its vegetation,
//   §3.15); its step(ground, step, conversions) runs one compute-then-apply step on the GPU state,
//   drawing rand(0.9, 1) with the reference's keys (seed, cell, step, stream).
//
// Inputs:  ground (LayeredGroundBuffers), step. Needs a current GlContext.
// Outputs: the GPU state after the step; `conversions` gains the bedrock fragmentation.
// Units:   metres, Δt in seconds; conversions in m³.
// Throws:  std::runtime_error when a shader does not compile or link or a block does not match its C++
//          mirror (layered_program).
// Twin:    reference/erosion/layered/talus.hpp (decisions there).
#pragma once

#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

LayeredSlopeProcess layered_talus();

}  // namespace gt::gpu
