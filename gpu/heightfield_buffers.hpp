// A heightfield on the GPU: heights in two float storage buffers that take turns as the current
// and next state (ping-pong), and the validity mask as one uint per cell (1 = valid).
// Shaders see them at the bindings given to bind(): current heights readonly, next writeonly.
#pragma once

#include <glad/gl.h>

#include "core/grid.hpp"
#include "gpu/buffer.hpp"

namespace gt::gpu {

class HeightfieldBuffers {
 public:
  HeightfieldBuffers(int width, int height);

  // Uploads heights and mask into the current state; `heights` must have the size given above.
  void load(const Grid<float>& heights);
  // Downloads the current state, with the geometry, units and mask of the last load.
  Grid<float> current() const;
  void bind(GLuint current_binding, GLuint valid_binding, GLuint next_binding) const;
  // The next state becomes the current one (after a pass that wrote it).
  void swap();

 private:
  Grid<float> layout_;  // geometry, units and mask of the loaded field, values unused
  StorageBuffer current_;
  StorageBuffer next_;
  StorageBuffer valid_;
};

}  // namespace gt::gpu
