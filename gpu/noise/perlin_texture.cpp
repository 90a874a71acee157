// PerlinTexture: creation (DSA, immutable storage), upload and binding (see perlin_texture.hpp).
// A row is 1024 bytes, so any GL_UNPACK_ALIGNMENT reads the table as packed.
#include "gpu/noise/perlin_texture.hpp"

#include <utility>

#include "core/noise/perlin_texture_table.hpp"

namespace gt::gpu {

PerlinTexture::PerlinTexture(const Permutation& permutation) {
  const auto rgba = perlin_texture_rgba(permutation);
  glCreateTextures(GL_TEXTURE_2D, 1, &id_);
  glTextureStorage2D(id_, 1, GL_RGBA8, perlin_texture_size, perlin_texture_size);
  glTextureSubImage2D(id_, 0, 0, 0, perlin_texture_size, perlin_texture_size, GL_RGBA, GL_UNSIGNED_BYTE,
                      rgba.data());
  glTextureParameteri(id_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTextureParameteri(id_, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

PerlinTexture::PerlinTexture(PerlinTexture&& other) noexcept : id_(std::exchange(other.id_, 0)) {}

PerlinTexture& PerlinTexture::operator=(PerlinTexture&& other) noexcept {
  if (this != &other) {
    if (id_ != 0) glDeleteTextures(1, &id_);
    id_ = std::exchange(other.id_, 0);
  }
  return *this;
}

PerlinTexture::~PerlinTexture() {
  if (id_ != 0) glDeleteTextures(1, &id_);
}

void PerlinTexture::bind(GLuint unit) const { glBindTextureUnit(unit, id_); }

}  // namespace gt::gpu
