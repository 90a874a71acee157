// The framebuffer both render twins draw into (gpu/render/heightmap_from_mesh.hpp, phong.hpp): a
// colour texture of the given format and a 32-bit float depth texture, and the one way they draw
// into it, as the reference rasterizer works (reference/render/rasterizer.hpp): colour cleared to
// 0, depth to 1, depth test LESS, depth writes on, no face culling, one indexed triangle draw.
//
// OffscreenTarget(colour_format, width, height, what) creates the textures and the framebuffer;
// std::runtime_error, naming `what`, when a side lies outside [1, GL_MAX_TEXTURE_SIZE] or the
// framebuffer is incomplete. draw(program, vertex_array, index_count) clears and draws (not
// synchronised: bracket with glFinish to time it); read colour_texture() / depth_texture() back
// with glGetTextureImage (GL rows: row 0 at the bottom). Needs a current GL context; not copyable.
#pragma once

#include <cstddef>

#include <glad/gl.h>

#include "gpu/shader_program.hpp"

namespace gt::gpu {

class OffscreenTarget {
 public:
  OffscreenTarget(GLenum colour_format, int width, int height, const char* what);
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;
  ~OffscreenTarget();

  void draw(const GraphicsProgram& program, GLuint vertex_array, std::size_t index_count) const;

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint colour_texture() const { return colour_texture_; }
  GLuint depth_texture() const { return depth_texture_; }

 private:
  int width_, height_;
  GLuint colour_texture_ = 0;
  GLuint depth_texture_ = 0;
  GLuint framebuffer_ = 0;
};

}  // namespace gt::gpu
