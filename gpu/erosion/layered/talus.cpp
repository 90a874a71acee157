// Host side of the layered talus collapse on the GPU (digest 001 §3.10; see talus.hpp).
#include "gpu/erosion/layered/talus.hpp"

namespace gt::gpu {

LayeredSlopeProcess layered_talus() { return {"erosion/layered/talus_outflow.comp", true}; }

}  // namespace gt::gpu
