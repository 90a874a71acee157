// Thermal erosion of seed 000 (Hydra; digest 000 §4.6, Algorithms 9-11), GPU twin.
//
// ThermalErosion(width, height, constants, neighbourhood, iterations) compiles
//   gpu/shaders/erosion/thermal_requests.comp and thermal_transfer.comp and allocates the buffers.
// load(heights) uploads a float heightfield (mask honoured as in the reference).
// run() dispatches all iterations (two passes each, no synchronisation: bracket with glFinish to time
//   it); step(first, count) dispatches `count` iterations from the current state numbered from
//   `first` (the number picks an alternating run's pipes; run() is step(0, iterations)).
// result() downloads.
//
// Inputs:  width, height, constants (core/params/thermal.hpp), neighbourhood, iterations; heights:
//          Grid<float> of that size with its mask. Needs a current GlContext.
// Outputs: result(): the heights with the geometry, units and mask of the last load.
// Units:   heights and lengths in the units of `constants`, as the reference.
// Throws:  std::invalid_argument for a load of another size (gpu/heightfield_buffers.hpp);
//          std::runtime_error when a shader does not compile or link or its block does not match the
//          C++ mirror.
// Twin:    reference/erosion/thermal.hpp.
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"
#include "gpu/buffer.hpp"
#include "gpu/heightfield_buffers.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class ThermalErosion {
 public:
  ThermalErosion(int width, int height, const ThermalConstants& constants, Neighbourhood neighbourhood,
                 int iterations);
  void load(const Grid<float>& heights);
  void run();
  void step(int first_iteration, int count);
  Grid<float> result() const;

 private:
  Neighbourhood neighbourhood_;
  int iterations_;
  ComputeProgram requests_program_;
  ComputeProgram transfer_program_;
  UniformBuffer cardinal_block_;
  UniformBuffer diagonal_block_;
  StorageBuffer requests_;
  HeightfieldBuffers heights_;
};

}  // namespace gt::gpu
