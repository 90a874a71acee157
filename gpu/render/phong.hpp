// Seed 004's Phong look (digest 004_cave.md §2.9) on a mesh through a perspective camera on the GL
// pipeline, GPU twin of reference/render/phong.hpp (camera conventions, shading formula and its
// decisions are documented there; gpu/shaders/render/phong.{vert,frag} write the formula again).
//
// PhongRenderer(scene) takes what the reference computed once on the CPU (PhongDraw: the mesh, its
// per-vertex normals, P·V in double, the eye, the albedo and the light power) and rounds it to float:
// positions and normals into one vertex buffer, P·V, eye, albedo and light power into uniforms. It
// makes a framebuffer of an RGBA8 colour texture and a DEPTH_COMPONENT32F depth texture. run()
// clears colour to 0 and depth to 1 and draws every triangle with the depth test LESS and no
// culling (no synchronisation: bracket with glFinish to time it); image() downloads the colour
// texture and returns RGB8, rows top first (alpha dropped). Needs a current GlContext; throws
// std::invalid_argument when normals and positions differ in count, std::runtime_error when a
// side exceeds GL_MAX_TEXTURE_SIZE or the framebuffer is incomplete.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glad/gl.h>

#include "core/mesh.hpp"
#include "gpu/buffer.hpp"
#include "gpu/render/offscreen_target.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

struct PhongDraw {
  const Mesh& mesh;
  const std::vector<std::array<double, 3>>& normals;  // one per vertex
  std::array<double, 16> view_projection{};            // row-major P·V
  std::array<double, 3> eye{};
  std::array<double, 3> albedo{};
  double light_power = 1.0;
  int width = 0, height = 0;  // pixels
};

struct Rgb8Pixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 per pixel, row-major, row 0 at the top
};

class PhongRenderer {
 public:
  explicit PhongRenderer(const PhongDraw& draw);
  PhongRenderer(const PhongRenderer&) = delete;
  PhongRenderer& operator=(const PhongRenderer&) = delete;
  ~PhongRenderer();

  void run() const;
  Rgb8Pixels image() const;

 private:
  OffscreenTarget target_;  // RGBA8
  std::size_t index_count_;
  GraphicsProgram program_;
  StorageBuffer vertices_;  // float3 position, float3 normal per vertex
  StorageBuffer indices_;
  GLuint vertex_array_ = 0;
};

}  // namespace gt::gpu
