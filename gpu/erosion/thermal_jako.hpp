// Thermal erosion of Jákó & Tóth 2011, GPU twin of reference/erosion/thermal_jako.hpp.
//
// ThermalJakoErosion(width, height, constants, iterations) compiles
// gpu/shaders/erosion/thermal_jako_outflow.comp and thermal_jako_gather.comp; load() uploads,
// run() dispatches all iterations (not synchronised), step(count) `count` of them from the current
// state (run() is step(iterations)), result() downloads. Needs a current GlContext.
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"
#include "gpu/buffer.hpp"
#include "gpu/heightfield_buffers.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class ThermalJakoErosion {
 public:
  ThermalJakoErosion(int width, int height, const ThermalConstants& constants, int iterations);
  void load(const Grid<float>& heights);
  void run();
  void step(int count);
  Grid<float> result() const;

 private:
  int iterations_;
  ComputeProgram outflow_program_;
  ComputeProgram gather_program_;
  UniformBuffer block_;
  StorageBuffer outflows_;
  HeightfieldBuffers heights_;
};

}  // namespace gt::gpu
