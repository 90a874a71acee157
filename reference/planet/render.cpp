// The planet drawn with the per-pixel spherical Voronoi; see render.hpp.
#include "reference/planet/render.hpp"

#include <algorithm>
#include <cmath>

#include "reference/planet/voronoi.hpp"
#include "reference/render/rasterizer.hpp"

namespace gt::reference {

Vec3 elevation_colour(double elevation) {
  const Vec3 base = elevation < 0.0 ? Vec3{107.0, 193.0, 255.0} : Vec3{255.0, 189.0, 97.0};
  const double factor = std::clamp(1.0 - std::abs(elevation) / 4.0, 0.0, 1.0);
  return {base[0] * factor / 255.0, base[1] * factor / 255.0, base[2] * factor / 255.0};
}

PlanetImage render_planet(const Mesh& mesh, const Camera& camera, const std::vector<double>& positions,
                          const std::vector<double>& elevation, int subpixel_bits) {
  const Matrix4 view_projection = multiply(projection_matrix(camera), view_matrix(camera));
  RasterInput input;
  input.attribute_count = 3;
  for (const Vec3& position : mesh.positions) {
    input.clip_positions.push_back(transform_point(view_projection, position));
    input.attributes.insert(input.attributes.end(), position.begin(), position.end());
  }
  input.triangles = mesh.triangles;
  const VoronoiSearch search(positions);
  // Channels: red, green, blue, and the region + 1 (0 where nothing is drawn, as cleared).
  RasterTarget target(camera.width, camera.height, 4, 0.0, 1.0);
  const FragmentShader shade = [&](std::span<const double> attributes, std::span<double> colour) {
    const double length = std::sqrt(attributes[0] * attributes[0] + attributes[1] * attributes[1] + attributes[2] * attributes[2]);
    const auto region = search.nearest({attributes[0] / length, attributes[1] / length, attributes[2] / length}).region;
    const Vec3 rgb = elevation_colour(elevation[static_cast<std::size_t>(region)]);
    std::copy(rgb.begin(), rgb.end(), colour.begin());
    colour[3] = double(region) + 1.0;
  };
  rasterize(input, shade, target, {.subpixel_bits = subpixel_bits});
  PlanetImage result{quantised_top_first(target), {}};
  for (int row = camera.height - 1; row >= 0; --row) {
    for (int x = 0; x < camera.width; ++x) result.regions.push_back(static_cast<std::int32_t>(target.colour_at(x, row, 3)) - 1);
  }
  result.image.covered_pixels = static_cast<std::size_t>(
      std::count_if(result.regions.begin(), result.regions.end(), [](std::int32_t region) { return region >= 0; }));
  return result;
}

}  // namespace gt::reference
