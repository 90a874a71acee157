#include "gpu/heightfield_buffers.hpp"

#include <stdexcept>
#include <utility>
#include <vector>

namespace gt::gpu {

void upload_validity(StorageBuffer& buffer, const Grid<float>& grid) {
  std::vector<GLuint> valid(grid.size(), 1u);
  if (grid.has_mask()) valid.assign(grid.valid.begin(), grid.valid.end());
  buffer.upload(valid.data(), valid.size() * sizeof(GLuint));
}

HeightfieldBuffers::HeightfieldBuffers(int width, int height)
    : layout_(width, height),
      current_(layout_.size() * sizeof(float)),
      next_(layout_.size() * sizeof(float)),
      valid_(layout_.size() * sizeof(GLuint)) {}

void HeightfieldBuffers::load(const Grid<float>& heights) {
  if (heights.width != layout_.width || heights.height != layout_.height) {
    throw std::invalid_argument("HeightfieldBuffers::load: grid size differs from the buffers'");
  }
  layout_ = heights;
  layout_.values.clear();
  current_.upload(heights.values.data(), heights.values.size() * sizeof(float));
  upload_validity(valid_, heights);
}

Grid<float> HeightfieldBuffers::current() const {
  Grid<float> heights = layout_;
  heights.values = current_.download<float>(static_cast<std::size_t>(layout_.width) * layout_.height);
  return heights;
}

void HeightfieldBuffers::iterate(const ComputeProgram& gather, const ComputeProgram& apply, int local_size) {
  constexpr GLuint heights_binding = 1, valid_binding = 2, next_binding = 4;
  current_.bind(heights_binding);
  valid_.bind(valid_binding);
  next_.bind(next_binding);
  gather.dispatch(layout_.width, layout_.height, local_size, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  apply.dispatch(layout_.width, layout_.height, local_size, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  std::swap(current_, next_);
}

}  // namespace gt::gpu
