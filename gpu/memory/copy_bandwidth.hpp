// The device's copy bandwidth through GL: a compute shader (gpu/shaders/memory/copy.comp) copying
// one float buffer into another. The performance table divides each kernel's bytes per cell by it
// to get the memory-bound floor (compare/benchmark.hpp). Each invocation copies a vec4.
//
// CopyKernel(elements) -> two storage buffers of `elements` floats (the source holds its index)
// run()                -> one copy dispatch followed by the storage barrier; time it with
//                         gpu_wall_ms (gpu/timing.hpp), which brackets it by glFinish.
// bytes_per_run()      -> 8 · elements: 4 B read and 4 B written per element.
// Needs a current GlContext. Throws std::invalid_argument unless elements is a positive
// multiple of 4.
#pragma once

#include <cstddef>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class CopyKernel {
 public:
  explicit CopyKernel(std::size_t elements);

  void run() const;
  double bytes_per_run() const { return 8.0 * static_cast<double>(elements_); }
  // The target buffer's contents (tests: the copy really happened).
  std::vector<float> target() const { return target_.download<float>(elements_); }

 private:
  std::size_t elements_;
  ComputeProgram program_;
  StorageBuffer source_;
  StorageBuffer target_;
};

}  // namespace gt::gpu
