// What the droplet eroders' GPU hosts share (gpu/erosion/particle.cpp for Hydra's kernel,
// gpu/erosion/beyer.cpp for Beyer's): the droplet grid of a pass, the buffer sizes, the checked load
// of a heightfield and its mask, and the per-pass uniforms every droplet shader must declare.
// `eroder` names the caller in messages ("ParticleErosion").
#pragma once

#include <cstddef>

#include <glad/gl.h>

#include "core/grid.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// The spacing S, refused below 1 (a pass would have no droplet grid): std::invalid_argument.
int checked_droplet_spacing(int spacing, const char* eroder);

// ceil(size / spacing): droplets of one pass along an axis of `size` texels (Hydra's FBO, eq. 4.7).
int droplet_count(int size, int spacing);

std::size_t cell_count(int width, int height);

// A width x height grid without values: what a host holds between loads (the heights live on the GPU).
Grid<float> empty_layout(int width, int height);

// Uploads `heights` into `heights_buffer` and its mask into `valid_buffer` as one uint per cell
// (1 = valid) after checking its size against the constructor's (std::invalid_argument); returns the
// grid's geometry, units and mask without values, which result() gives back with the download.
Grid<float> load_heightfield(const Grid<float>& heights, int width, int height, StorageBuffer& heights_buffer,
                             StorageBuffer& valid_buffer, const char* eroder);

// The location of the active uniform `name` of `program` (the shader file `shader`), or
// std::runtime_error when the shader has none.
GLint required_uniform(const ComputeProgram& program, const char* shader, const char* name);

}  // namespace gt::gpu
