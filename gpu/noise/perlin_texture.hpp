// The texture of Gustavson's 2004 texture-based Perlin noise (seed 004, digest 004 §2.1) on the GPU:
// the 256x256 GL_RGBA8 table of core/noise/perlin_texture_table.hpp, one level, GL_NEAREST min and
// mag filters, GL_REPEAT in s and t: the sampling gpu/shaders/noise/perlin_texture.glsl and its
// reference (reference/noise/perlin_texture.cpp) assume.
//
// PerlinTexture(permutation) creates and uploads it; bind(unit) binds it to a texture unit: the
// shaders read it as gt_perlin_texture on unit perlin_texture_unit. Move-only RAII; needs a current
// GlContext.
#pragma once

#include <glad/gl.h>

#include "core/noise/permutation.hpp"

namespace gt::gpu {

// The layout binding of gt_perlin_texture in noise/perlin_texture.glsl.
inline constexpr GLuint perlin_texture_unit = 0;

class PerlinTexture {
 public:
  explicit PerlinTexture(const Permutation& permutation);
  PerlinTexture(PerlinTexture&& other) noexcept;
  PerlinTexture& operator=(PerlinTexture&& other) noexcept;
  PerlinTexture(const PerlinTexture&) = delete;
  PerlinTexture& operator=(const PerlinTexture&) = delete;
  ~PerlinTexture();

  GLuint id() const { return id_; }
  void bind(GLuint unit) const;

 private:
  GLuint id_ = 0;
};

}  // namespace gt::gpu
