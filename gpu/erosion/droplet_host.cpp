#include "gpu/erosion/droplet_host.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

#include "gpu/heightfield_buffers.hpp"

namespace gt::gpu {

BlockLayout droplet_block_layout(std::size_t head_offset, const BlockLayout& members) {
  BlockLayout layout = nested_layout("", head_offset,
                                     {{"grid_size", offsetof(DropletBlockHead, grid_size)},
                                      {"droplet_grid", offsetof(DropletBlockHead, droplet_grid)},
                                      {"droplet_spacing", offsetof(DropletBlockHead, droplet_spacing)},
                                      {"lifetime", offsetof(DropletBlockHead, lifetime)}});
  layout.insert(layout.end(), members.begin(), members.end());
  return layout;
}

int checked_droplet_spacing(int spacing, const char* eroder) {
  if (spacing < 1) throw std::invalid_argument(std::string(eroder) + ": spacing must be at least 1");
  return spacing;
}

int droplet_count(int size, int spacing) { return (size + spacing - 1) / spacing; }

std::size_t cell_count(int width, int height) { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }

DropletBlockHead droplet_block_head(int width, int height, int spacing, int lifetime, const char* eroder) {
  const int checked = checked_droplet_spacing(spacing, eroder);
  return {{width, height}, {droplet_count(width, checked), droplet_count(height, checked)}, checked, lifetime};
}

void dispatch_droplet_pass(const ComputeProgram& program, GLint offset_location, int offset_x, int offset_y,
                           int droplets_x, int droplets_y) {
  glProgramUniform2i(program.id(), offset_location, offset_x, offset_y);
  program.dispatch(droplets_x, droplets_y, droplet_local_size, droplet_local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void dispatch_cell_pass(const ComputeProgram& program, int width, int height) {
  program.dispatch(width, height, droplet_local_size, droplet_local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

Grid<float> empty_layout(int width, int height) {
  Grid<float> layout;
  layout.width = width;
  layout.height = height;
  return layout;
}

Grid<float> load_heightfield(const Grid<float>& heights, int width, int height, StorageBuffer& heights_buffer,
                             StorageBuffer& valid_buffer, const char* eroder) {
  if (heights.width != width || heights.height != height || heights.values.size() != cell_count(width, height)) {
    throw std::invalid_argument(std::string(eroder) + "::load: grid size differs from the constructor's");
  }
  if (heights.has_mask() && heights.valid.size() != heights.values.size()) {
    throw std::invalid_argument(std::string(eroder) + "::load: mask size differs from the grid's");
  }
  heights_buffer.upload(heights.values.data(), heights.values.size() * sizeof(float));
  upload_validity(valid_buffer, heights);
  Grid<float> layout = heights;
  layout.values.clear();
  return layout;
}


}  // namespace gt::gpu
