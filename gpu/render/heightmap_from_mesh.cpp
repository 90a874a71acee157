// Host side of the heightmap from a mesh on the GPU: the bounding box and eq. 4.2's matrix, the
// vertex array, the framebuffer and one indexed draw. Shaders: gpu/shaders/render/.
#include "gpu/render/heightmap_from_mesh.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include "core/errors.hpp"
#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

using Box = std::array<std::array<double, 3>, 2>;  // lowest and highest corner

double extent(const Box& box, int axis) { return box[1][axis] - box[0][axis]; }

// The bounding box of all vertex positions; InputError when nothing can be seen from above.
Box checked_box(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw InputError("heightmap from a mesh: the mesh has no triangles");
  const Box3<double> bounds = bounding_box(mesh);
  const Box box{bounds.low, bounds.high};
  if (!(extent(box, 0) > 0.0) || !(extent(box, 1) > 0.0)) {
    throw InputError("heightmap from a mesh: the mesh has no extent in x or y, so nothing is seen from above");
  }
  return box;
}

// Positions relative to the box centre, rounded to float once.
std::vector<std::array<float, 3>> centred_positions(const Mesh& mesh, const Box& box) {
  std::vector<std::array<float, 3>> centred;
  centred.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) {
    std::array<float, 3> q{};
    for (int axis = 0; axis < 3; ++axis) q[axis] = float(p[axis] - 0.5 * (box[0][axis] + box[1][axis]));
    centred.push_back(q);
  }
  return centred;
}

// Eq. 4.2 times the translation by the centre, row-major: s_x, s_y, -s_z on the diagonal and
// 0.5 in z's translation; s_z = 1 for a flat box (the reference's decision).
std::array<float, 16> projection_row_major(const Box& box) {
  const double dz = extent(box, 2);
  const auto s_x = float(2.0 / extent(box, 0));
  const auto s_y = float(2.0 / extent(box, 1));
  const auto s_z = float(dz > 0.0 ? 1.0 / dz : 1.0);
  return {s_x, 0, 0, 0,  //
          0, s_y, 0, 0,  //
          0, 0, -s_z, 0.5f,  //
          0, 0, 0, 1};
}

template <class T>
Grid<T> texel_grid(int width, int height, double cell_size_x, double cell_size_y) {
  Grid<T> grid(width, height);
  grid.cell_size_x = cell_size_x;
  grid.cell_size_y = cell_size_y;
  grid.horizontal_unit = "mesh";
  grid.vertical_unit = "1";
  return grid;
}

std::vector<float> download(GLuint texture_id, GLenum format, int width, int height) {
  std::vector<float> texels(std::size_t(width) * std::size_t(height));
  glGetTextureImage(texture_id, 0, format, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
  return texels;
}

}  // namespace

HeightmapFromMesh::HeightmapFromMesh(const Mesh& mesh, int width, int height)
    : HeightmapFromMesh(mesh, width, height, checked_box(mesh)) {}

HeightmapFromMesh::HeightmapFromMesh(const Mesh& mesh, int width, int height, const Box& box)
    : target_(GL_R32F, width, height, "heightmap"),
      cell_size_x_(extent(box, 0) / width),
      cell_size_y_(extent(box, 1) / height),
      // Mutant (GPU only): the triangle count passed where glDrawElements wants the index count.
      index_count_(mesh.triangles.size() * (mutant_active("render.heightmap_from_mesh.gpu_count_in_triangles") ? 1 : 3)),
      program_(GraphicsProgram::load("render/heightmap_from_mesh.vert", "render/heightmap_from_mesh.frag")),
      positions_(StorageBuffer::from(centred_positions(mesh, box))),
      indices_(StorageBuffer::from(mesh.triangles)) {
  const auto projection = projection_row_major(box);
  glProgramUniformMatrix4fv(program_.id(), 0, 1, GL_TRUE, projection.data());

  glCreateVertexArrays(1, &vertex_array_);
  glVertexArrayVertexBuffer(vertex_array_, 0, positions_.id(), 0, sizeof(std::array<float, 3>));
  glVertexArrayAttribFormat(vertex_array_, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array_, 0, 0);
  glEnableVertexArrayAttrib(vertex_array_, 0);
  glVertexArrayElementBuffer(vertex_array_, indices_.id());
}

HeightmapFromMesh::~HeightmapFromMesh() { glDeleteVertexArrays(1, &vertex_array_); }

void HeightmapFromMesh::run() const { target_.draw(program_, vertex_array_, index_count_); }

MeshHeightmap HeightmapFromMesh::result() const {
  const int width = target_.width(), height = target_.height();
  const auto red = download(target_.colour_texture(), GL_RED, width, height);
  const auto depth = download(target_.depth_texture(), GL_DEPTH_COMPONENT, width, height);
  MeshHeightmap result{texel_grid<float>(width, height, cell_size_x_, cell_size_y_),
                       texel_grid<std::uint8_t>(width, height, cell_size_x_, cell_size_y_)};
  for (int row = 0; row < height; ++row) {
    const std::size_t gl_row = std::size_t(height - 1 - row);
    for (int x = 0; x < width; ++x) {
      const std::size_t texel = gl_row * std::size_t(width) + std::size_t(x);
      result.heights.at(x, row) = red[texel];
      result.covered.at(x, row) = depth[texel] < 1.0f ? 1 : 0;
    }
  }
  return result;
}

int HeightmapFromMesh::subpixel_bits() {
  GLint bits = 0;
  glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
  return bits;
}

}  // namespace gt::gpu
