// A noise function sampled on a grid by the GPU: the twin of the references in reference/noise/
// for every function and fractal sum of core/params/noise.hpp.
//
// NoiseField(params) compiles gpu/shaders/noise/noise_field.comp with the defines that select the
// function, and uploads the permutation (and, for perlin3_texture, the 256x256 texture); run()
// dispatches (not synchronised: bracket with glFinish to time it); result() downloads the values.
// The origin is params' reduced_origin(), rounded once to float. Needs a current GlContext.
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
