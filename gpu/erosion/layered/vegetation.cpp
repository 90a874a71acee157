// Host side of vegetation growth on the layered ground (digest 001 §3.15; see vegetation.hpp).
#include "gpu/erosion/layered/vegetation.hpp"

#include <string>
#include <vector>

#include "gpu/erosion/layered/water_buffers.hpp"

namespace gt::gpu {

LayeredVegetation::LayeredVegetation(bool flood)
    : grow_(layered_water_program("erosion/layered/vegetation.comp",
                                  flood ? std::vector<std::string>{"LAYERED_FLOOD"} : std::vector<std::string>{})),
      store_(layered_water_program("erosion/layered/vegetation.comp", std::vector<std::string>{"VEGETATION_STORE"})) {}

void LayeredVegetation::step(LayeredGroundBuffers& ground, std::uint32_t step,
                             LayeredConversions& /*conversions*/) const {
  ground.dispatch_pass(grow_, step);
  ground.dispatch_pass(store_, step);
}

LayeredVegetation layered_vegetation(bool flood) { return LayeredVegetation(flood); }

}  // namespace gt::gpu
