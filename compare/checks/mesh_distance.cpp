// Per-vertex distances between meshes and their PLY picture; see mesh_distance.hpp.
#include "compare/checks/mesh_distance.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <fmt/format.h>

#include "compare/checks/image.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"

namespace gt {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

bool usable(const Mesh& mesh, const std::array<std::uint32_t, 3>& triangle) {
  if (triangle[0] == triangle[1] || triangle[1] == triangle[2] || triangle[0] == triangle[2]) return false;
  for (const std::uint32_t vertex : triangle) {
    if (vertex >= mesh.positions.size()) return false;
    for (const double coordinate : mesh.positions[vertex]) {
      if (!std::isfinite(coordinate)) return false;
    }
  }
  return true;
}

Point point_of(const std::array<double, 3>& position) { return {position[0], position[1], position[2]}; }

// Each usable triangle with corners of its own: closest points need no connectivity.
SurfaceMesh triangle_soup(const Mesh& mesh) {
  SurfaceMesh surface;
  for (const auto& triangle : mesh.triangles) {
    if (!usable(mesh, triangle)) continue;
    surface.add_face(surface.add_vertex(point_of(mesh.positions[triangle[0]])),
                     surface.add_vertex(point_of(mesh.positions[triangle[1]])),
                     surface.add_vertex(point_of(mesh.positions[triangle[2]])));
  }
  return surface;
}

}  // namespace

std::vector<VertexDistance> vertex_distances(const Mesh& from, const Mesh& to) {
  constexpr double unused = std::numeric_limits<double>::quiet_NaN();
  std::vector<VertexDistance> distances(from.positions.size(), VertexDistance{unused, {unused, unused, unused}});
  std::vector<bool> used(from.positions.size(), false);
  for (const auto& triangle : from.triangles) {
    if (!usable(from, triangle)) continue;
    for (const std::uint32_t vertex : triangle) used[vertex] = true;
  }
  const SurfaceMesh target = triangle_soup(to);
  if (target.number_of_faces() == 0) {
    for (std::size_t vertex = 0; vertex < used.size(); ++vertex) {
      if (used[vertex]) distances[vertex].distance = std::numeric_limits<double>::infinity();
    }
    return distances;
  }
  Tree tree(faces(target).first, faces(target).second, target);
  tree.accelerate_distance_queries();
  for (std::size_t vertex = 0; vertex < used.size(); ++vertex) {
    if (!used[vertex]) continue;
    const Point query = point_of(from.positions[vertex]);
    const Point nearest = tree.closest_point(query);
    distances[vertex] = {std::sqrt(CGAL::squared_distance(query, nearest)), {nearest.x(), nearest.y(), nearest.z()}};
  }
  return distances;
}

std::size_t write_vertex_values_ply(const Mesh& mesh, const std::vector<double>& values, const std::string& property,
                                    double scale, const std::filesystem::path& file) {
  SurfaceMesh surface;
  auto colour = surface.add_property_map<SurfaceMesh::Vertex_index, CGAL::IO::Color>("v:color").first;
  auto value_map = surface.add_property_map<SurfaceMesh::Vertex_index, double>("v:" + property).first;
  std::vector<SurfaceMesh::Vertex_index> vertices;
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const auto added = surface.add_vertex(point_of(mesh.positions[vertex]));
    const double value = values[vertex];
    const auto heat = heat_colour(std::isfinite(value) ? value : 0.0, scale > 0.0 ? scale : 1.0);
    const auto level = [](float channel) { return static_cast<unsigned char>(std::lround(channel * 255.0f)); };
    colour[added] = CGAL::IO::Color(level(heat[0]), level(heat[1]), level(heat[2]));
    value_map[added] = value;
    vertices.push_back(added);
  }
  std::size_t left_out = 0;
  for (const auto& triangle : mesh.triangles) {
    const bool added = usable(mesh, triangle) &&
                       surface.add_face(vertices[triangle[0]], vertices[triangle[1]], vertices[triangle[2]]) !=
                           SurfaceMesh::null_face();
    left_out += added ? 0 : 1;
  }
  write_file_atomically(file, [&](const std::filesystem::path& temporary) {
    if (!CGAL::IO::write_PLY(temporary.string(), surface, CGAL::parameters::use_binary_mode(true))) {
      throw InputError(fmt::format("cannot write {}: the folder is missing or not writable", file.string()));
    }
  });
  return left_out;
}

}  // namespace gt
