// Beyer's blend with a blurred map (seed 000 §2.7, eq. 2.43; digest 000 §3.7), GPU twin: one
// dispatch of gpu/shaders/erosion/blur_blend.comp over the grid.
//
// BlurBlend(width, height, blend, inverse_quantum) compiles the shader, for the batch ordering when
//   inverse_quantum > 0 (the blend's exchanges as quanta into the caller's delta) and in place
//   otherwise (a buffer of its own for the blended heights, copied back over the caller's).
// run(heights, valid, delta) blends: in place, `heights` holds the blended heights afterwards; batch,
//   `delta` holds each cell's quanta (overwritten; the caller applies them and clears it). A storage
//   barrier follows.
//
// Inputs:  heights and valid: the caller's float and uint buffers of width·height cells; blend c_b in
//          [0, 1]; inverse_quantum 1/quantum (a power of two) or 0. Needs a current GlContext.
// Outputs: see run().
// Units:   heights in the caller's units; c_b dimensionless.
// Throws:  std::runtime_error when the shader does not compile or link or lacks its uniforms.
// Twin:    reference/erosion/blur_blend.hpp (the decisions).
#pragma once

#include <optional>

#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class BlurBlend {
 public:
  BlurBlend(int width, int height, double blend, double inverse_quantum);
  void run(StorageBuffer& heights, const StorageBuffer& valid, StorageBuffer* delta) const;

 private:
  bool batch() const { return !blended_.has_value(); }

  int width_;
  int height_;
  ComputeProgram program_;
  std::optional<StorageBuffer> blended_;  // in place only: the blended heights before the copy
};

}  // namespace gt::gpu
