// The render twins' framebuffer and draw; see offscreen_target.hpp.
#include "gpu/render/offscreen_target.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace gt::gpu {
namespace {

void check_size(int width, int height, const char* what) {
  GLint largest = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &largest);
  if (width < 1 || height < 1 || width > largest || height > largest) {
    throw std::runtime_error(
        fmt::format("{} {}x{}: sides must lie in [1, {}] (GL_MAX_TEXTURE_SIZE)", what, width, height, largest));
  }
}

GLuint texture(GLenum format, int width, int height) {
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, 1, format, width, height);
  return id;
}

}  // namespace

OffscreenTarget::OffscreenTarget(GLenum colour_format, int width, int height, const char* what)
    : width_(width), height_(height) {
  check_size(width, height, what);
  colour_texture_ = texture(colour_format, width, height);
  depth_texture_ = texture(GL_DEPTH_COMPONENT32F, width, height);
  glCreateFramebuffers(1, &framebuffer_);
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, colour_texture_, 0);
  glNamedFramebufferTexture(framebuffer_, GL_DEPTH_ATTACHMENT, depth_texture_, 0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &depth_texture_);
    glDeleteTextures(1, &colour_texture_);
    throw std::runtime_error(fmt::format("{} framebuffer incomplete (status 0x{:x})", what, status));
  }
}

OffscreenTarget::~OffscreenTarget() {
  glDeleteFramebuffers(1, &framebuffer_);
  glDeleteTextures(1, &depth_texture_);
  glDeleteTextures(1, &colour_texture_);
}

void OffscreenTarget::draw(const GraphicsProgram& program, GLuint vertex_array, std::size_t index_count) const {
  const float clear_colour[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  const float clear_depth = 1.0f;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
  glViewport(0, 0, width_, height_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glClearNamedFramebufferfv(framebuffer_, GL_COLOR, 0, clear_colour);
  glClearNamedFramebufferfv(framebuffer_, GL_DEPTH, 0, &clear_depth);
  program.use();
  glBindVertexArray(vertex_array);
  glDrawElements(GL_TRIANGLES, GLsizei(index_count), GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace gt::gpu
