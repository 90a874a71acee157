// Thermal erosion of Jákó & Tóth 2011 (digest 000 §3.6, eqs. 2.30-2.34), GPU twin.
//
// ThermalJakoErosion(width, height, constants, iterations) compiles
//   gpu/shaders/erosion/thermal_jako_outflow.comp and thermal_jako_gather.comp.
// set_hardness(R) replaces the hardness map (one R a cell, row-major; empty: R = 1) and uploads the
//   cells' constants again; load(heights) uploads; run() dispatches all iterations (not synchronised); step(count) `count` of
//   them from the current state (run() is step(iterations)); result() downloads.
//
// Inputs:  width, height, constants (thermal_jako_constants()), iterations; heights: Grid<float> of
//          that size with its mask. Needs a current GlContext.
// Outputs: result(): the heights with the geometry, units and mask of the last load.
// Units:   heights and lengths in metres; rate dimensionless.
// Throws:  std::invalid_argument for a load of another size (gpu/heightfield_buffers.hpp);
//          std::runtime_error when a shader does not compile or link or its block does not match the
//          C++ mirror.
// Twin:    reference/erosion/thermal_jako.hpp.
#pragma once

#include <vector>

#include "core/grid.hpp"
#include "core/params/thermal.hpp"
#include "gpu/buffer.hpp"
#include "gpu/heightfield_buffers.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class ThermalJakoErosion {
 public:
  ThermalJakoErosion(int width, int height, const ThermalConstants& constants, int iterations);
  void set_hardness(const std::vector<double>& hardness);
  void load(const Grid<float>& heights);
  void run();
  void step(int count);
  Grid<float> result() const;

 private:
  int width_;
  int height_;
  int iterations_;
  ComputeProgram outflow_program_;
  ComputeProgram gather_program_;
  UniformBuffer block_;
  ThermalConstants constants_;
  StorageBuffer cell_constants_;
  StorageBuffer outflows_;
  HeightfieldBuffers heights_;
};

}  // namespace gt::gpu
