// A noise function or fractal sum sampled on a grid (every function of core/params/noise.hpp), GPU twin.
//
// NoiseField(params) compiles gpu/shaders/noise/noise_field.comp with the defines that select the
//   function, and uploads the permutation (and, for perlin3_texture, the 256x256 texture).
// run() dispatches (not synchronised: bracket with glFinish to time it).
// result() downloads the values.
//
// Inputs:  params (NoiseParams: basis, fractal sum, seed, sampling grid). The origin is params'
//          reduced_origin(), rounded once to float. Needs a current GlContext.
// Outputs: result(): Grid<float> of params.sampling.width x height.
// Units:   coordinates in noise units (one lattice cell = 1); values dimensionless.
// Throws:  std::invalid_argument from fractal_terms for fractal octaves outside [1, 32], lacunarity
//          <= 0 or gain < 0; std::runtime_error when the shader does not compile or link or its block
//          does not match the C++ mirror.
// Twin:    the references in reference/noise/ (reference/noise/noise_field.hpp samples them the same way).
#pragma once

#include <memory>

#include "core/grid.hpp"
#include "core/params/noise.hpp"
#include "gpu/buffer.hpp"
#include "gpu/noise/perlin_texture.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class NoiseField {
 public:
  explicit NoiseField(const NoiseParams& params);
  void run();
  Grid<float> result() const;

 private:
  NoiseSampling sampling_;
  ComputeProgram program_;
  UniformBuffer block_;
  StorageBuffer permutation_;
  StorageBuffer values_;
  std::unique_ptr<PerlinTexture> texture_;
};

}  // namespace gt::gpu
