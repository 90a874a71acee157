// Host side of the Phong twin on the GPU: float vertex buffer (position and normal interleaved),
// uniforms, the RGBA8 + depth framebuffer and one indexed draw. Shaders: gpu/shaders/render/phong.*.
#include "gpu/render/phong.hpp"

#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/noise/permutation.hpp"

namespace gt::gpu {
namespace {

using Vertex = std::array<float, 6>;  // position, normal

// Mirror of `PhongLookBlock` in gpu/shaders/render/phong_look.glsl (std140).
struct PhongLookBlock {
  float colour_frequency;
  float colour_reference_height;
  float colour_octaves_per_unit;
  float bump_slope;  // a·s
  float bump_frequency;
  float moss;
  float height_low;
  float inverse_height_range;
  float up[3];
  float rock_start_cos;
  float rock[3];
  float inverse_rock_width;  // 1/(cos(rock_start) - cos(rock_full))
  std::int32_t strip_size;
  float colour_octave_limit;
  std::int32_t drape_width;
  std::int32_t drape_height;
  float drape_x_west;
  float drape_inverse_width;  // 1/(x_east - x_west)
  float drape_z_north;
  float drape_inverse_depth;  // 1/(z_south - z_north)
};

// The program's PhongLookBlock (instance `look`: members are named "PhongLookBlock.member") against
// its mirror.
void check_look_block(const GraphicsProgram& program) {
  program.check_block("PhongLookBlock", sizeof(PhongLookBlock),
                      {{"PhongLookBlock.colour_frequency", offsetof(PhongLookBlock, colour_frequency)},
                       {"PhongLookBlock.colour_reference_height", offsetof(PhongLookBlock, colour_reference_height)},
                       {"PhongLookBlock.colour_octaves_per_unit", offsetof(PhongLookBlock, colour_octaves_per_unit)},
                       {"PhongLookBlock.bump_slope", offsetof(PhongLookBlock, bump_slope)},
                       {"PhongLookBlock.bump_frequency", offsetof(PhongLookBlock, bump_frequency)},
                       {"PhongLookBlock.moss", offsetof(PhongLookBlock, moss)},
                       {"PhongLookBlock.height_low", offsetof(PhongLookBlock, height_low)},
                       {"PhongLookBlock.inverse_height_range", offsetof(PhongLookBlock, inverse_height_range)},
                       {"PhongLookBlock.up", offsetof(PhongLookBlock, up)},
                       {"PhongLookBlock.rock_start_cos", offsetof(PhongLookBlock, rock_start_cos)},
                       {"PhongLookBlock.rock", offsetof(PhongLookBlock, rock)},
                       {"PhongLookBlock.inverse_rock_width", offsetof(PhongLookBlock, inverse_rock_width)},
                       {"PhongLookBlock.strip_size", offsetof(PhongLookBlock, strip_size)},
                       {"PhongLookBlock.colour_octave_limit", offsetof(PhongLookBlock, colour_octave_limit)},
                       {"PhongLookBlock.drape_width", offsetof(PhongLookBlock, drape_width)},
                       {"PhongLookBlock.drape_height", offsetof(PhongLookBlock, drape_height)},
                       {"PhongLookBlock.drape_x_west", offsetof(PhongLookBlock, drape_x_west)},
                       {"PhongLookBlock.drape_inverse_width", offsetof(PhongLookBlock, drape_inverse_width)},
                       {"PhongLookBlock.drape_z_north", offsetof(PhongLookBlock, drape_z_north)},
                       {"PhongLookBlock.drape_inverse_depth", offsetof(PhongLookBlock, drape_inverse_depth)}});
}

constexpr GLuint look_block_binding = 0, strip_binding = 6, permutation_binding = 5, drape_binding = 7;

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

bool has_drape(const PhongDraw& draw) { return draw.look == PhongLook::terrain && draw.terrain.drape.has_value(); }

const std::vector<std::array<double, 3>>& look_strip(const PhongDraw& draw) {
  return draw.look == PhongLook::cave ? draw.cave.colour_strip : draw.terrain.ramp;
}

void set_drape(PhongLookBlock& block, const PhongTerrainDrape& drape) {
  if (drape.width < 1 || drape.height < 1 ||
      drape.rgb.size() != 3 * std::size_t(drape.width) * std::size_t(drape.height) ||
      !(drape.x_east > drape.x_west && drape.z_south > drape.z_north)) {
    throw std::invalid_argument("Phong render: the terrain drape needs 3·width·height bytes, x_west < x_east and "
                                "z_north < z_south");
  }
  block.drape_width = drape.width;
  block.drape_height = drape.height;
  block.drape_x_west = float(drape.x_west);
  block.drape_inverse_width = float(1.0 / (drape.x_east - drape.x_west));
  block.drape_z_north = float(drape.z_north);
  block.drape_inverse_depth = float(1.0 / (drape.z_south - drape.z_north));
}

PhongLookBlock look_block(const PhongDraw& draw) {
  const PhongTerrainLook& terrain = draw.terrain;
  if (draw.look == PhongLook::terrain &&
      !(terrain.height_high > terrain.height_low && terrain.rock_start_deg >= 0.0 &&
        terrain.rock_start_deg < terrain.rock_full_deg && terrain.rock_full_deg <= 180.0)) {
    throw std::invalid_argument("Phong render: the terrain look needs height_low < height_high and "
                                "0 <= rock_start_deg < rock_full_deg <= 180");
  }
  PhongLookBlock block{};
  const PhongCaveLook& cave = draw.cave;
  block.colour_frequency = float(cave.colour_frequency);
  block.colour_reference_height = float(cave.colour_reference_height);
  block.colour_octaves_per_unit = float(cave.colour_octaves_per_unit);
  block.colour_octave_limit = float(cave.colour_octave_limit);
  block.bump_slope = float(cave.bump_amplitude * cave.bump_frequency);
  block.bump_frequency = float(cave.bump_frequency);
  block.moss = float(cave.moss);
  block.height_low = float(terrain.height_low);
  block.inverse_height_range = float(1.0 / (terrain.height_high - terrain.height_low));
  const double cos_start = std::cos(radians(terrain.rock_start_deg));
  const double cos_full = std::cos(radians(terrain.rock_full_deg));
  block.rock_start_cos = float(cos_start);
  block.inverse_rock_width = float(1.0 / (cos_start - cos_full));
  for (int axis = 0; axis < 3; ++axis) {
    block.up[axis] = float(terrain.up[axis]);
    block.rock[axis] = float(terrain.rock[axis]);
  }
  block.strip_size = std::int32_t(look_strip(draw).size());
  if (has_drape(draw)) set_drape(block, *terrain.drape);
  return block;
}

// The drape's texels packed for unpackUnorm4x8: r | g << 8 | b << 16 | 255 << 24.
std::vector<std::uint32_t> packed_drape(const PhongTerrainDrape& drape) {
  std::vector<std::uint32_t> texels;
  texels.reserve(drape.rgb.size() / 3);
  for (std::size_t first = 0; first + 2 < drape.rgb.size(); first += 3) {
    texels.push_back(std::uint32_t(drape.rgb[first]) | std::uint32_t(drape.rgb[first + 1]) << 8 |
                     std::uint32_t(drape.rgb[first + 2]) << 16 | 0xff000000u);
  }
  return texels;
}

std::vector<std::array<float, 4>> strip_texels(const PhongDraw& draw) {
  const auto& strip = look_strip(draw);
  if (strip.empty()) throw std::invalid_argument("Phong render: the look's colour strip has no entries");
  std::vector<std::array<float, 4>> texels;
  texels.reserve(strip.size());
  for (const auto& entry : strip) texels.push_back({float(entry[0]), float(entry[1]), float(entry[2]), 1.0f});
  return texels;
}

std::vector<std::string> look_defines(const PhongDraw& draw) {
  std::vector<std::string> defines = {"GT_PHONG_LOOK=" + std::to_string(static_cast<int>(draw.look))};
  if (has_drape(draw)) defines.emplace_back("GT_TERRAIN_DRAPE");
  return defines;
}

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
      look_(draw.look),
      program_(GraphicsProgram::load("render/phong.vert", "render/phong.frag", look_defines(draw))),
      vertices_(StorageBuffer::from(interleaved_vertices(draw))),
      indices_(StorageBuffer::from(draw.mesh.triangles)) {
  set_uniforms(program_.id(), draw);
  if (look_ != PhongLook::plain) {
    check_look_block(program_);
    strip_.emplace(StorageBuffer::from(strip_texels(draw)));
    look_block_.emplace(UniformBuffer::from(look_block(draw)));
  }
  if (has_drape(draw)) drape_.emplace(StorageBuffer::from(packed_drape(*draw.terrain.drape)));
  if (look_ == PhongLook::cave) {
    const Permutation permutation = seeded_permutation(draw.cave.noise_seed);
    permutation_.emplace(StorageBuffer::from(doubled_permutation(permutation)));
    noise_texture_.emplace(permutation);
  }

  glCreateVertexArrays(1, &vertex_array_);
  glVertexArrayVertexBuffer(vertex_array_, 0, vertices_.id(), 0, sizeof(Vertex));
  attach_attribute(vertex_array_, 0, 0);
  attach_attribute(vertex_array_, 1, 3 * sizeof(float));
  glVertexArrayElementBuffer(vertex_array_, indices_.id());
}

PhongRenderer::~PhongRenderer() { glDeleteVertexArrays(1, &vertex_array_); }

void PhongRenderer::run() const {
  if (look_block_) look_block_->bind(look_block_binding);
  if (strip_) strip_->bind(strip_binding);
  if (drape_) drape_->bind(drape_binding);
  if (permutation_) permutation_->bind(permutation_binding);
  if (noise_texture_) noise_texture_->bind(perlin_texture_unit);
  target_.draw(program_, vertex_array_, index_count_);
}

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
