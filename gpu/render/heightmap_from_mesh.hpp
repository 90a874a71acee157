// Seed 000's heightmap from a mesh (digest 000_water_erosion.md §4.3, eqs. 4.1–4.4) on the GL pipeline, GPU twin.
//
// Same mapping, rows, coverage and decisions as the reference; read them there.
// HeightmapFromMesh(mesh, width, height) compiles gpu/shaders/render/heightmap_from_mesh.vert and
//   .frag, uploads the mesh (positions minus the bounding-box centre, rounded to float once; the index
//   buffer as it is) and makes a framebuffer of an R32F colour texture and a DEPTH_COMPONENT32F depth
//   texture of width x height texels.
// run() clears colour to 0 and depth to 1 and draws every triangle with the depth test LESS and no
//   culling (no synchronisation: bracket with glFinish to time it).
// result() downloads both textures, flips GL's bottom-first rows to the grid's top-first ones and
//   marks texels whose depth is < 1 as covered.
// subpixel_bits() is GL_SUBPIXEL_BITS, what the reference must snap to.
//
// Inputs:  mesh (double positions, uint32 triangles), width and height in texels. Needs a current
//          GlContext.
// Outputs: MeshHeightmap: heights (1 - z' where covered, 0 elsewhere; row 0 = largest y) and covered
//          (1 where a fragment passed the depth test).
// Units:   heights dimensionless, as the reference.
// Throws:  gt::InputError for a mesh without triangles or without extent in x or y, and
//          std::runtime_error when the framebuffer is incomplete or a side exceeds GL_MAX_TEXTURE_SIZE,
//          or when a shader does not compile or link.
// Twin:    reference/render/heightmap_from_mesh.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include <glad/gl.h>

#include "core/grid.hpp"
#include "core/mesh.hpp"
#include "gpu/buffer.hpp"
#include "gpu/render/offscreen_target.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

struct MeshHeightmap {
  Grid<float> heights;          // 1 - z' where covered, 0 elsewhere; row 0 = largest y
  Grid<std::uint8_t> covered;   // 1 where a fragment passed the depth test
};

class HeightmapFromMesh {
 public:
  HeightmapFromMesh(const Mesh& mesh, int width, int height);
  HeightmapFromMesh(const HeightmapFromMesh&) = delete;
  HeightmapFromMesh& operator=(const HeightmapFromMesh&) = delete;
  ~HeightmapFromMesh();

  void run() const;
  MeshHeightmap result() const;

  static int subpixel_bits();

 private:
  using Box = std::array<std::array<double, 3>, 2>;  // lowest and highest corner
  HeightmapFromMesh(const Mesh& mesh, int width, int height, const Box& box);

  OffscreenTarget target_;  // R32F heights
  double cell_size_x_, cell_size_y_;
  std::size_t index_count_;
  GraphicsProgram program_;
  StorageBuffer positions_;  // any buffer object can feed a vertex array; these hold float3 and uint3
  StorageBuffer indices_;
  GLuint vertex_array_ = 0;
};

}  // namespace gt::gpu
