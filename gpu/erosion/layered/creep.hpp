// Soil creep on the layered ground (digest 001 §3.11, eq. 3.4, Roering's law), GPU twin of
// reference/erosion/layered/creep.hpp (decisions there). layered_creep() compiles
// gpu/shaders/erosion/layered/creep_outflow.comp and apply.comp (vegetation untouched); its
// step(ground, step, conversions) runs one compute-then-apply step on the GPU state with the
// reference's random keys. Creep moves soil only, so it adds zeros to `conversions`, taken for the
// common step protocol. Needs a current GlContext. Units: metres, K_z in m/s, Δt in seconds.
#pragma once

#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

LayeredSlopeProcess layered_creep();

}  // namespace gt::gpu
