// One iteration of seed 001's layered ground on the GPU in the code's order (digest 001 §4), GPU twin.
//
// with water, 1 sources and sinks; 2 creep; 3 talus (unless switched off); with water, 4 the pipe flow, 5 force erosion,
// 6 impact erosion, 7 dissolution, 8 sediment diffusion, 9 wetness; 10 vegetation (with the flood death when there is
// water); 11 weathering — each process's passes dispatched in turn on the same buffers.
// LayeredIteration(with_water = false) compiles the programs (the water's only when asked:
//   LayeredWaterProcesses).
// step(ground, step, conversions, water = nullptr) runs one iteration.
//
// Inputs:  ground (LayeredGroundBuffers), step, water (LayeredWaterBuffers), required exactly when
//          built with water. Needs a current GlContext.
// Outputs: the GPU state after the iteration; `conversions` gains what the processes converted.
// Units:   metres, Δt in seconds; conversions in m³.
// Throws:  std::invalid_argument from step() when `water` is given without water processes or missing
//          with them; std::runtime_error when a shader does not compile or link or a block does not
//          match its C++ mirror.
// Twin:    reference/erosion/layered/iteration.hpp.
#pragma once

#include <cstdint>
#include <optional>

#include "gpu/erosion/layered/creep.hpp"
#include "gpu/erosion/layered/force_erosion.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/impact_erosion.hpp"
#include "gpu/erosion/layered/talus.hpp"
#include "gpu/erosion/layered/vegetation.hpp"
#include "gpu/erosion/layered/water.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"
#include "gpu/erosion/layered/weathering.hpp"

namespace gt::gpu {

// The water's processes of an iteration (built only for a ground with water).
struct LayeredWaterProcesses {
  LayeredWaterProcesses();
  LayeredWaterFlow flow;
  LayeredForceErosion force_erosion;
  LayeredImpactErosion impact_erosion;
  LayeredWaterPass dissolution;
  LayeredWaterPass diffusion;
  LayeredWaterPass wetness;
};

class LayeredIteration {
 public:
  explicit LayeredIteration(bool with_water = false);
  void step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions,
            const LayeredWaterBuffers* water = nullptr) const;

 private:
  LayeredSlopeProcess creep_;
  LayeredSlopeProcess talus_;
  LayeredVegetation vegetation_;
  LayeredWeathering weathering_;
  std::optional<LayeredWaterProcesses> water_;
};

}  // namespace gt::gpu
