// What the droplet eroders' GPU hosts share (gpu/erosion/particle.cpp for Hydra's kernel,
// gpu/erosion/beyer.cpp for Beyer's): the droplet grid of a pass, the buffer sizes, the checked load
// of a heightfield and its mask, and the per-pass uniforms every droplet shader must declare.
// `eroder` names the caller in messages ("ParticleErosion").
#pragma once

#include <cstddef>
#include <cstdint>

#include <glad/gl.h>

#include "core/grid.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// The head every droplet shader's std140 parameter block starts with (particle_block.glsl,
// beyer_block.glsl, flow_map_block.glsl): grid_size, droplet_grid, droplet_spacing, lifetime. Its
// 24 bytes keep the block's own members at the offsets std140 gives them after these four.
struct DropletBlockHead {
  std::int32_t grid_size[2];     // width, height (texels)
  std::int32_t droplet_grid[2];  // ceil(width / spacing), ceil(height / spacing): droplets per pass
  std::int32_t droplet_spacing;  // S
  std::int32_t lifetime;         // steps of one droplet
};

// The layout of a droplet block's mirror whose DropletBlockHead sits at `head_offset`: the head's
// four members (the GLSL block declares them one by one), then `members` (for
// GlProgram::check_block).
BlockLayout droplet_block_layout(std::size_t head_offset, const BlockLayout& members);

// local_size_x/y of the droplet shaders.
constexpr int droplet_local_size = 8;

// The spacing S, refused below 1 (a pass would have no droplet grid): std::invalid_argument.
int checked_droplet_spacing(int spacing, const char* eroder);

// ceil(size / spacing): droplets of one pass along an axis of `size` texels (Hydra's FBO, eq. 4.7).
int droplet_count(int size, int spacing);

std::size_t cell_count(int width, int height);

// The head of a width x height grid's block (the spacing checked as checked_droplet_spacing).
DropletBlockHead droplet_block_head(int width, int height, int spacing, int lifetime, const char* eroder);

// One pass: the program's `pass_offset` (at `offset_location`) set to (offset_x, offset_y), its
// droplets_x x droplets_y droplets dispatched, then a storage barrier.
void dispatch_droplet_pass(const ComputeProgram& program, GLint offset_location, int offset_x, int offset_y,
                           int droplets_x, int droplets_y);

// A per-cell pass over a width x height grid (a batch apply, the plug pass), then a storage barrier.
void dispatch_cell_pass(const ComputeProgram& program, int width, int height);

// A width x height grid without values: what a host holds between loads (the heights live on the GPU).
Grid<float> empty_layout(int width, int height);

// Uploads `heights` into `heights_buffer` and its mask into `valid_buffer` as one uint per cell
// (1 = valid) after checking its size against the constructor's (std::invalid_argument); returns the
// grid's geometry, units and mask without values, which result() gives back with the download.
Grid<float> load_heightfield(const Grid<float>& heights, int width, int height, StorageBuffer& heights_buffer,
                             StorageBuffer& valid_buffer, const char* eroder);


}  // namespace gt::gpu
