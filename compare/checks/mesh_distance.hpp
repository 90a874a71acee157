// Where two triangle meshes differ (`groundtruth compare-mesh`): the distance from every vertex of
// one mesh to the other's surface, and a mesh file that shows it.
//
// vertex_distances(from, to): for each vertex of `from` that a usable triangle uses (three distinct
// in-range indices, finite corners), the Euclidean distance to the nearest point of `to`'s usable
// triangles and that point (CGAL's AABB tree, exact closest-point queries in double); unused
// vertices get NaN. `to` without usable triangles gives +infinity everywhere. The largest of these
// is a lower bound of the one-sided Hausdorff distance (it is attained at vertices only for
// meshes whose differences are at their vertices); compare-mesh reports CGAL's sampled distance
// beside it.
//
// write_vertex_values_ply(mesh, values, property, scale, file): the mesh as binary PLY with one
// value a vertex as the double property `property` (compare-mesh: the distance, NaN where unused;
// check-mesh: the problems at the vertex) and its heat-map colour of compare/checks/image.hpp
// (black 0 → red → yellow → white at `scale`) as red/green/blue, written under a temporary name
// and renamed. Faces the half-edge structure cannot hold (a non-manifold edge or vertex, a
// misoriented neighbour, an unusable triangle) are left out and counted in the return value.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace gt {

struct VertexDistance {
  double distance = 0.0;
  std::array<double, 3> nearest{};  // the closest point of the other surface
};

std::vector<VertexDistance> vertex_distances(const Mesh& from, const Mesh& to);

std::size_t write_vertex_values_ply(const Mesh& mesh, const std::vector<double>& values, const std::string& property,
                                    double scale, const std::filesystem::path& file);

}  // namespace gt
