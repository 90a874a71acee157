// The planet drawn as the seed's demo draws it (digest 002 §4.3), on the GL pipeline, GPU twin.
//
// The cube-sphere mesh through the reference's P·V (rounded to float once), each fragment the region
// nearest its direction by Algorithm 1's 5×5 search and that region's elevation in the palette
// (gpu/shaders/planet/render.{vert,frag}).
// PlanetRenderer(mesh, view_projection, sphere, cube_warp, positions, elevation, width, height) uploads the
//   mesh, the neighbour table, the centroids and the elevations and makes an RGBA32F target
//   (gpu/render/offscreen_target.hpp: depth LESS, no culling).
// run() clears and draws (not synchronised: bracket with glFinish to time it).
// image() downloads.
//
// Inputs:  mesh (the cube sphere's), view_projection (row-major P·V in double), sphere and its warp, positions
//          (3 per region), elevation (1 per region), width and height in pixels. Needs a current
//          GlContext.
// Outputs: PlanetPixels: RGB8 rows top first (each channel round(255·c), as the reference quantises)
//          and the region per pixel (−1 where nothing is drawn).
// Units:   elevations in generator units; positions dimensionless.
// Throws:  std::invalid_argument for inputs of the wrong size; std::runtime_error when a side lies
//          outside [1, GL_MAX_TEXTURE_SIZE], the framebuffer is incomplete, or a shader does not
//          compile or link or its block does not match the C++ mirror.
// Twin:    reference/planet/render.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glad/gl.h>

#include "core/mesh.hpp"
#include "core/planet/cube_sphere.hpp"
#include "gpu/buffer.hpp"
#include "gpu/render/offscreen_target.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

struct PlanetPixels {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;      // 3 per pixel, rows top first
  std::vector<std::int32_t> regions;  // per pixel, rows top first; −1 uncovered
};

class PlanetRenderer {
 public:
  PlanetRenderer(const Mesh& mesh, const std::array<double, 16>& view_projection, const CubeSphere& sphere,
                 CubeWarp cube_warp, const std::vector<float>& positions, const std::vector<float>& elevation, int width, int height);
  PlanetRenderer(const PlanetRenderer&) = delete;
  PlanetRenderer& operator=(const PlanetRenderer&) = delete;
  ~PlanetRenderer();

  void run() const;
  PlanetPixels image() const;

 private:
  OffscreenTarget target_;  // RGBA32F: colour, region + 1
  std::size_t index_count_;
  GraphicsProgram program_;
  UniformBuffer block_;
  StorageBuffer vertices_;
  StorageBuffer indices_;
  StorageBuffer neighbours_;
  StorageBuffer positions_;
  StorageBuffer elevation_;
  GLuint vertex_array_ = 0;
};

}  // namespace gt::gpu
