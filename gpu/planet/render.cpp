// The planet on the GL pipeline; see render.hpp.
#include "gpu/planet/render.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "gpu/planet/voronoi.hpp"

namespace gt::gpu {
namespace {

// Bindings of planet/voronoi_search.glsl (0, 1 and the block at 0) and render.frag (4).
constexpr GLuint neighbours_binding = 0;
constexpr GLuint positions_binding = 1;
constexpr GLuint elevation_binding = 4;
constexpr GLuint block_binding = 0;

std::vector<float> vertex_positions(const Mesh& mesh) {
  std::vector<float> values;
  values.reserve(3 * mesh.positions.size());
  for (const auto& position : mesh.positions) {
    for (const double coordinate : position) values.push_back(static_cast<float>(coordinate));
  }
  return values;
}

// The centroids as vec4s, once their count and the elevations' match the sphere's regions.
StorageBuffer centroid_buffer(const CubeSphere& sphere, const std::vector<float>& positions,
                              const std::vector<float>& elevation) {
  if (positions.size() != 3 * sphere.region_count() || elevation.size() != sphere.region_count()) {
    throw std::invalid_argument(fmt::format("planet render: {} position values and {} elevations for {} regions",
                                            positions.size(), elevation.size(), sphere.region_count()));
  }
  return StorageBuffer::from(padded_xyz(positions));
}

std::uint8_t quantised(float channel) {
  return static_cast<std::uint8_t>(std::lround(255.0 * std::fmin(std::fmax(double(channel), 0.0), 1.0)));
}

}  // namespace

PlanetRenderer::PlanetRenderer(const Mesh& mesh, const std::array<double, 16>& view_projection,
                               const CubeSphere& sphere, CubeWarp cube_warp, const std::vector<float>& positions,
                               const std::vector<float>& elevation, int width, int height)
    : target_(GL_RGBA32F, width, height, "planet image"),
      index_count_(mesh.triangles.size() * 3),
      program_(GraphicsProgram::load("planet/render.vert", "planet/render.frag")),
      block_(voronoi_block(sphere.resolution(), 0, cube_warp)),
      vertices_(StorageBuffer::from(vertex_positions(mesh))),
      indices_(StorageBuffer::from(mesh.triangles)),
      neighbours_(StorageBuffer::from(sphere.neighbour_table())),
      positions_(centroid_buffer(sphere, positions, elevation)),
      elevation_(StorageBuffer::from(elevation)) {
  check_voronoi_block(program_);
  std::array<float, 16> matrix{};
  for (std::size_t k = 0; k < matrix.size(); ++k) matrix[k] = static_cast<float>(view_projection[k]);
  glProgramUniformMatrix4fv(program_.id(), 0, 1, GL_TRUE, matrix.data());
  glCreateVertexArrays(1, &vertex_array_);
  glVertexArrayVertexBuffer(vertex_array_, 0, vertices_.id(), 0, 3 * sizeof(float));
  glVertexArrayAttribFormat(vertex_array_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array_, 0, 0);
  glEnableVertexArrayAttrib(vertex_array_, 0);
  glVertexArrayElementBuffer(vertex_array_, indices_.id());
}

PlanetRenderer::~PlanetRenderer() { glDeleteVertexArrays(1, &vertex_array_); }

void PlanetRenderer::run() const {
  block_.bind(block_binding);
  neighbours_.bind(neighbours_binding);
  positions_.bind(positions_binding);
  elevation_.bind(elevation_binding);
  target_.draw(program_, vertex_array_, index_count_);
}

PlanetPixels PlanetRenderer::image() const {
  const int width = target_.width(), height = target_.height();
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  std::vector<float> rgba(pixels * 4);
  glGetTextureImage(target_.colour_texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  PlanetPixels image{width, height, {}, {}};
  image.rgb.reserve(pixels * 3);
  image.regions.reserve(pixels);
  for (int row = 0; row < height; ++row) {
    const std::size_t gl_row = std::size_t(height - 1 - row);
    for (int x = 0; x < width; ++x) {
      const std::size_t texel = (gl_row * std::size_t(width) + std::size_t(x)) * 4;
      for (std::size_t channel = 0; channel < 3; ++channel) image.rgb.push_back(quantised(rgba[texel + channel]));
      image.regions.push_back(static_cast<std::int32_t>(rgba[texel + 3]) - 1);
    }
  }
  return image;
}

}  // namespace gt::gpu
