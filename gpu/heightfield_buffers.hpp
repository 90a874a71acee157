// A heightfield on the GPU: heights in two float storage buffers that take turns as the current
// and next state (ping-pong), and the validity mask as one uint per cell (1 = valid).
// Shaders see them at fixed bindings: current heights 1 (readonly), validity 2, next heights 4
// (writeonly); bindings 0 and 3 are the algorithm's parameter block and its own work buffer.
#pragma once

#include <glad/gl.h>

#include "core/grid.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// The mask of `grid` as the shaders read it, one uint per cell (1 = valid; every cell valid when the
// grid has no mask), uploaded into `buffer`.
void upload_validity(StorageBuffer& buffer, const Grid<float>& grid);

class HeightfieldBuffers {
 public:
  HeightfieldBuffers(int width, int height);

  // Uploads heights and mask into the current state; `heights` must have the size given above.
  void load(const Grid<float>& heights);
  // Downloads the current state, with the geometry, units and mask of the last load.
  Grid<float> current() const;
  // One synchronous iteration of a two-pass algorithm: `gather` reads the current heights and
  // fills the algorithm's work buffer, `apply` writes the next heights from it, then the next
  // state becomes the current one. Both programs have local size local_size x local_size.
  void iterate(const ComputeProgram& gather, const ComputeProgram& apply, int local_size);

 private:
  Grid<float> layout_;  // geometry, units and mask of the loaded field, values unused
  StorageBuffer current_;
  StorageBuffer next_;
  StorageBuffer valid_;
};

}  // namespace gt::gpu
