// Seed 000's heightmap from a mesh on the reference rasterizer; see heightmap_from_mesh.hpp.
#include "reference/render/heightmap_from_mesh.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "reference/render/rasterizer.hpp"

namespace gt::reference {
namespace {

struct Box {
  std::array<double, 3> low{}, high{};
  double extent(int axis) const { return high[axis] - low[axis]; }
  double centre(int axis) const { return 0.5 * (low[axis] + high[axis]); }  // eq. 4.1's mean of opposite faces
};

Box box_of(const Mesh& mesh) {
  const Box3<double> bounds = bounding_box(mesh);
  return {bounds.low, bounds.high};
}

// Eq. 4.2 applied to every vertex: (s_x(x - c_x), s_y(y - c_y), 0.5 - s_z(z - c_z), 1), with z'
// also as the one attribute the fragment shader reads. Mutant render.heightmap_from_mesh.lowest_surface
// (in both twins): the depth is 1 - z', the box seen from below, so the lowest surface wins.
RasterInput project_from_above(const Mesh& mesh, const Box& box, const std::array<double, 3>& scale) {
  RasterInput input;
  input.attribute_count = 1;
  input.triangles = mesh.triangles;
  const bool from_below = mutant_active("render.heightmap_from_mesh.lowest_surface");
  for (const auto& p : mesh.positions) {
    const double z_prime = 0.5 - scale[2] * (p[2] - box.centre(2));
    input.clip_positions.push_back({scale[0] * (p[0] - box.centre(0)), scale[1] * (p[1] - box.centre(1)),
                                    from_below ? 1.0 - z_prime : z_prime, 1.0});
    input.attributes.push_back(z_prime);
  }
  return input;
}

template <class T>
Grid<T> texel_grid(int width, int height, const Box& box) {
  Grid<T> grid(width, height);
  grid.cell_size_x = box.extent(0) / width;
  grid.cell_size_y = box.extent(1) / height;
  grid.horizontal_unit = "mesh";
  grid.vertical_unit = "1";
  return grid;
}

}  // namespace

void require_visible_from_above(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw InputError("heightmap from a mesh: the mesh has no triangles");
  const Box box = box_of(mesh);
  if (!(box.extent(0) > 0.0) || !(box.extent(1) > 0.0)) {
    throw InputError("heightmap from a mesh: the mesh has no extent in x or y, so nothing is seen from above");
  }
}

MeshHeightmap heightmap_from_mesh(const Mesh& mesh, int width, int height, int subpixel_bits) {
  require_visible_from_above(mesh);
  const Box box = box_of(mesh);
  const std::array<double, 3> scale = {2.0 / box.extent(0), 2.0 / box.extent(1),
                                       box.extent(2) > 0.0 ? 1.0 / box.extent(2) : 1.0};  // eq. 4.1
  RasterTarget target(width, height, 1, 0.0, 1.0);
  const FragmentShader height_from_depth = [](std::span<const double> z_prime, std::span<double> red) {
    red[0] = 1.0 - z_prime[0];  // eq. 4.4
  };
  rasterize(project_from_above(mesh, box, scale), height_from_depth, target, {.subpixel_bits = subpixel_bits});

  MeshHeightmap result{texel_grid<double>(width, height, box), texel_grid<std::uint8_t>(width, height, box),
                       scale[0] / scale[1], scale[0] / scale[2]};
  // Mutant render.heightmap_from_mesh.rows_flipped (in both twins): grid row r is GL row r.
  const bool flipped = mutant_active("render.heightmap_from_mesh.rows_flipped");
  for (int row = 0; row < height; ++row) {
    const int gl_row = flipped ? row : height - 1 - row;
    for (int x = 0; x < width; ++x) {
      result.heights.at(x, row) = target.colour_at(x, gl_row, 0);
      result.covered.at(x, row) = target.depth_at(x, gl_row) < 1.0 ? 1 : 0;
    }
  }
  return result;
}

}  // namespace gt::reference
