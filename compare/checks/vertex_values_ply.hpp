// A mesh with one value a vertex, for any mesh viewer: `groundtruth compare-mesh --out` (each
// vertex's distance to the other mesh) and `check-mesh --annotate` (the problems at each vertex).
//
// write_vertex_values_ply(mesh, values, property, scale, file): the mesh as binary PLY with
// values[v] as the double vertex property `property` (NaN where a vertex has none) and its
// heat-map colour of compare/checks/image.hpp (black 0 → red → yellow → white at `scale`, black for
// a non-finite value) as red/green/blue, written under a temporary name and renamed. The usable
// triangles (compare/checks/mesh.hpp) that a half-edge structure cannot hold (a non-manifold edge
// or vertex, a misoriented neighbour) and the unusable ones are left out: the return value counts
// them.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace gt {

std::size_t write_vertex_values_ply(const Mesh& mesh, const std::vector<double>& values, const std::string& property,
                                    double scale, const std::filesystem::path& file);

}  // namespace gt
