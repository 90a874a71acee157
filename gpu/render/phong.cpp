// Host side of the Phong twin on the GPU: float vertex buffer (position and normal interleaved),
// uniforms, the RGBA8 + depth framebuffer and one indexed draw. Shaders: gpu/shaders/render/phong.*.
#include "gpu/render/phong.hpp"

#include <stdexcept>

namespace gt::gpu {
namespace {

using Vertex = std::array<float, 6>;  // position, normal

std::vector<Vertex> interleaved_vertices(const PhongDraw& draw) {
  if (draw.normals.size() != draw.mesh.positions.size()) {
    throw std::invalid_argument("Phong render: one normal per vertex is needed");
  }
  std::vector<Vertex> vertices;
  vertices.reserve(draw.mesh.positions.size());
  for (std::size_t k = 0; k < draw.mesh.positions.size(); ++k) {
    const auto& p = draw.mesh.positions[k];
    const auto& n = draw.normals[k];
    vertices.push_back({float(p[0]), float(p[1]), float(p[2]), float(n[0]), float(n[1]), float(n[2])});
  }
  return vertices;
}

template <std::size_t N>
std::array<float, N> rounded(const std::array<double, N>& values) {
  std::array<float, N> out{};
  for (std::size_t k = 0; k < N; ++k) out[k] = float(values[k]);
  return out;
}

void set_uniforms(GLuint program, const PhongDraw& draw) {
  const auto view_projection = rounded(draw.view_projection);
  const auto eye = rounded(draw.eye), albedo = rounded(draw.albedo);
  glProgramUniformMatrix4fv(program, 0, 1, GL_TRUE, view_projection.data());
  glProgramUniform3fv(program, 1, 1, eye.data());
  glProgramUniform3fv(program, 2, 1, albedo.data());
  glProgramUniform1f(program, 3, float(draw.light_power));
}

void attach_attribute(GLuint vertex_array, GLuint location, GLuint offset) {
  glVertexArrayAttribFormat(vertex_array, location, 3, GL_FLOAT, GL_FALSE, offset);
  glVertexArrayAttribBinding(vertex_array, location, 0);
  glEnableVertexArrayAttrib(vertex_array, location);
}

}  // namespace

PhongRenderer::PhongRenderer(const PhongDraw& draw)
    : target_(GL_RGBA8, draw.width, draw.height, "Phong image"),
      index_count_(draw.mesh.triangles.size() * 3),
      program_(GraphicsProgram::load("render/phong.vert", "render/phong.frag")),
      vertices_(StorageBuffer::from(interleaved_vertices(draw))),
      indices_(StorageBuffer::from(draw.mesh.triangles)) {
  set_uniforms(program_.id(), draw);

  glCreateVertexArrays(1, &vertex_array_);
  glVertexArrayVertexBuffer(vertex_array_, 0, vertices_.id(), 0, sizeof(Vertex));
  attach_attribute(vertex_array_, 0, 0);
  attach_attribute(vertex_array_, 1, 3 * sizeof(float));
  glVertexArrayElementBuffer(vertex_array_, indices_.id());
}

PhongRenderer::~PhongRenderer() { glDeleteVertexArrays(1, &vertex_array_); }

void PhongRenderer::run() const { target_.draw(program_, vertex_array_, index_count_); }

Rgb8Pixels PhongRenderer::image() const {
  const int width = target_.width(), height = target_.height();
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  std::vector<std::uint8_t> rgba(pixels * 4);
  glGetTextureImage(target_.colour_texture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(rgba.size()), rgba.data());
  Rgb8Pixels image{width, height, {}};
  image.rgb.reserve(pixels * 3);
  for (int row = 0; row < height; ++row) {
    const std::size_t gl_row = std::size_t(height - 1 - row);
    for (int x = 0; x < width; ++x) {
      const std::size_t texel = (gl_row * std::size_t(width) + std::size_t(x)) * 4;
      image.rgb.insert(image.rgb.end(), rgba.begin() + std::ptrdiff_t(texel), rgba.begin() + std::ptrdiff_t(texel + 3));
    }
  }
  return image;
}

}  // namespace gt::gpu
