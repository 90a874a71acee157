// Host side of the layered soil creep on the GPU (digest 001 §3.11; see creep.hpp).
#include "gpu/erosion/layered/creep.hpp"

namespace gt::gpu {

LayeredSlopeProcess layered_creep() { return {"erosion/layered/creep_outflow.comp", false}; }

}  // namespace gt::gpu
