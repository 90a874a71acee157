// A mesh with a value a vertex as coloured PLY; see vertex_values_ply.hpp.
#include "compare/checks/vertex_values_ply.hpp"

#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <fmt/format.h>

#include "compare/checks/image.hpp"
#include "compare/checks/mesh.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"

namespace gt {

std::size_t write_vertex_values_ply(const Mesh& mesh, const std::vector<double>& values, const std::string& property,
                                    double scale, const std::filesystem::path& file) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  using SurfaceMesh = CGAL::Surface_mesh<Point>;
  SurfaceMesh surface;
  auto colour = surface.add_property_map<SurfaceMesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  auto value_map = surface.add_property_map<SurfaceMesh::Vertex_index, double>("v:" + property).first;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const auto& position = mesh.positions[vertex];
    const auto added = surface.add_vertex(Point(position[0], position[1], position[2]));
    const double value = values[vertex];
    const auto heat = heat_colour(std::isfinite(value) ? value : 0.0, scale > 0.0 ? scale : 1.0);
    const auto level = [](float channel) { return static_cast<unsigned char>(std::lround(channel * 255.0f)); };
    colour[added] = CGAL::IO::Color(level(heat[0]), level(heat[1]), level(heat[2]));
    value_map[added] = value;
    vertices.push_back(added);
  }
  std::size_t added_faces = 0;
  for (const auto& triangle : usable_triangles(mesh)) {
    const bool added = surface.add_face(vertices[triangle[0]], vertices[triangle[1]], vertices[triangle[2]]) !=
                       SurfaceMesh::null_face();
    added_faces += added ? 1 : 0;
  }
  write_file_atomically(file, [&](const std::filesystem::path& temporary) {
    if (!CGAL::IO::write_PLY(temporary.string(), surface, CGAL::parameters::use_binary_mode(true))) {
      throw InputError(fmt::format("cannot write {}: the folder is missing or not writable", file.string()));
    }
  });
  return mesh.triangles.size() - added_faces;
}

}  // namespace gt
