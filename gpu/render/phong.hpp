// Seed 004's Phong look (digest 004_cave.md §2.9) on a mesh through a perspective camera on the GL pipeline, GPU twin.
//
// Camera conventions, shading formula and its decisions are documented in the reference;
// gpu/shaders/render/phong.{vert,frag} write the formula again.
// PhongRenderer(draw) takes what the reference computed once on the CPU (PhongDraw: the mesh, its
//   per-vertex normals, P·V in double, the eye, the albedo and the light power) and rounds it to
//   float: positions and normals into one vertex buffer, P·V, eye, albedo and light power into
//   uniforms. It makes a framebuffer of an RGBA8 colour texture and a DEPTH_COMPONENT32F depth texture.
// run() clears colour to 0 and depth to 1 and draws every triangle with the depth test LESS and no
//   culling (no synchronisation: bracket with glFinish to time it).
// image() downloads the colour texture and returns RGB8, rows top first (alpha dropped).
// PhongCaveLook, PhongTerrainLook, PhongTerrainDrape: the fields of reference::CaveLook, TerrainLook
//   and TerrainDrape.
//
// Looks (PhongDraw::look; formulas in reference/render/phong.hpp "Looks" and cave_look.hpp): one
// shader source, the look picks it at compile time with the define GT_PHONG_LOOK (0 plain, 1 cave,
// 2 terrain), so the plain program holds no look code after preprocessing.
// cave and terrain read gpu/shaders/render/phong_look.glsl: a std140 block PhongLookBlock
// (uniform binding 0, mirrored in phong.cpp and checked against the linked program) and the strip
// (colour strip or height ramp) as a storage buffer of vec4 (binding 6); the cave look also binds
// the permutation buffer (binding 5) of its improved Perlin bump and the texture of Gustavson's
// Perlin noise (unit 0) of its colour, both of seeded_permutation(noise_seed). The host derives, in
// double and rounded to float once: bump slope a·s, the terrain's 1/(high - low), cos(rock_start)
// and 1/(cos(rock_start) - cos(rock_full)), the drape's 1/(x_east - x_west) and 1/(z_south - z_north).
// A terrain drape (PhongTerrainLook::drape) adds the define GT_TERRAIN_DRAPE (without one the
// terrain program holds no drape code) and a storage buffer (binding 7) of one uint per texel, RGBA8
// packed as unpackUnorm4x8 reads it (r in the low byte, alpha 255), row-major, row 0 at v = 0; the
// shader reads its four texels by index and blends them in arithmetic, never through a sampler.
//
// Inputs:  PhongDraw: mesh, normals (one per vertex), view_projection (row-major P·V), eye, albedo,
//          light power, image size in pixels, look with its cave or terrain fields. Needs a current
//          GlContext.
// Outputs: Rgb8Pixels: 3 bytes per pixel, row-major, row 0 at the top.
// Units:   as the reference: positions in the mesh's unit; colours in [0, 1] before quantising.
// Throws:  std::invalid_argument when normals and positions differ in count, for an empty strip (cave,
//          terrain), for a terrain look without height_low < height_high and 0 <= rock_start <
//          rock_full <= 180, and for a drape without 3·width·height bytes, x_west < x_east and
//          z_north < z_south; std::runtime_error when a side exceeds GL_MAX_TEXTURE_SIZE or the
//          framebuffer is incomplete, or when a shader does not compile or link or PhongLookBlock does
//          not match its mirror.
// Twin:    reference/render/phong.hpp and reference/render/cave_look.hpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glad/gl.h>

#include "core/mesh.hpp"
#include "gpu/buffer.hpp"
#include "gpu/noise/perlin_texture.hpp"
#include "gpu/render/offscreen_target.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

enum class PhongLook { plain = 0, cave = 1, terrain = 2 };

// reference::CaveLook's fields (reference/render/cave_look.hpp).
struct PhongCaveLook {
  std::vector<std::array<double, 3>> colour_strip;  // 256 entries in [0, 1]
  double colour_frequency = 2.0;                    // noise cells per world unit at the reference height
  double colour_reference_height = 0.0;
  double colour_octaves_per_unit = 0.0072134752044448170;
  double colour_octave_limit = 4.0;
  double bump_amplitude = 0.04, bump_frequency = 4.0;
  double moss = 1.0 / 40.0;
  std::uint32_t noise_seed = 0;
};

// reference::TerrainDrape's fields (reference/render/phong.hpp "Colour drape").
struct PhongTerrainDrape {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 per texel, row-major, row 0 at v = 0 (north)
  double x_west = 0.0, x_east = 1.0, z_north = 0.0, z_south = 1.0;
};

// reference::TerrainLook's fields (reference/render/phong.hpp).
struct PhongTerrainLook {
  std::vector<std::array<double, 3>> ramp;  // colour over normalised height
  std::array<double, 3> up{0.0, 1.0, 0.0};
  double height_low = 0.0, height_high = 1.0;
  std::array<double, 3> rock{0.42, 0.40, 0.38};
  double rock_start_deg = 30.0, rock_full_deg = 45.0;
  std::optional<PhongTerrainDrape> drape;  // replaces the ramp when set
};

struct PhongDraw {
  const Mesh& mesh;
  const std::vector<std::array<double, 3>>& normals;  // one per vertex
  std::array<double, 16> view_projection{};            // row-major P·V
  std::array<double, 3> eye{};
  std::array<double, 3> albedo{};
  double light_power = 1.0;
  int width = 0, height = 0;  // pixels
  PhongLook look = PhongLook::plain;
  PhongCaveLook cave{};         // used when look == cave
  PhongTerrainLook terrain{};   // used when look == terrain
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
  PhongLook look_;
  GraphicsProgram program_;
  StorageBuffer vertices_;  // float3 position, float3 normal per vertex
  StorageBuffer indices_;
  GLuint vertex_array_ = 0;
  std::optional<UniformBuffer> look_block_;      // cave, terrain
  std::optional<StorageBuffer> strip_;           // cave, terrain
  std::optional<StorageBuffer> drape_;           // terrain with a drape
  std::optional<StorageBuffer> permutation_;     // cave
  std::optional<PerlinTexture> noise_texture_;   // cave
};

}  // namespace gt::gpu
