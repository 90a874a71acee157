// Keyed cave mesh comparisons; see cave_mesh.hpp.
#include "compare/checks/cave_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <unordered_map>

#include "compare/checks/error_model.hpp"
#include "core/io/mesh_io.hpp"
#include "core/params/cave.hpp"

namespace gt {

template <class Real>
KeyTriangle key_triangle(const TriangleMesh<Real>& mesh, const std::array<std::uint32_t, 3>& triangle) {
  const auto key_of = [&mesh](std::uint32_t vertex) {
    return vertex < mesh.edge_keys.size() ? mesh.edge_keys[vertex] : missing_vertex_key;
  };
  KeyTriangle keys = {key_of(triangle[0]), key_of(triangle[1]), key_of(triangle[2])};
  std::rotate(keys.begin(), std::min_element(keys.begin(), keys.end()), keys.end());
  return keys;
}

template <class Real>
std::vector<KeyTriangle> key_triangles(const TriangleMesh<Real>& mesh) {
  std::vector<KeyTriangle> keyed;
  keyed.reserve(mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) keyed.push_back(key_triangle(mesh, triangle));
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

std::vector<KeyTriangle> triangles_in_one_only(const std::vector<KeyTriangle>& a, const std::vector<KeyTriangle>& b) {
  std::vector<KeyTriangle> difference;
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(difference));
  return difference;
}

std::size_t triangle_difference(const std::vector<KeyTriangle>& a, const std::vector<KeyTriangle>& b) {
  return triangles_in_one_only(a, b).size();
}

LatticeBox triangle_cube(const KeyTriangle& triangle) {
  LatticeBox box{lattice_edge_from_key(triangle[0]).lower_point, lattice_edge_from_key(triangle[0]).lower_point};
  for (const std::uint64_t key : triangle) {
    const LatticeEdge edge = lattice_edge_from_key(key);
    for (int axis = 0; axis < 3; ++axis) {
      box.low[axis] = std::min(box.low[axis], edge.lower_point[axis]);
      box.high[axis] = std::max(box.high[axis], edge.lower_point[axis] + ((edge.direction >> axis) & 1));
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    if (box.low[axis] == box.high[axis]) {
      --box.low[axis];
      ++box.high[axis];
    }
  }
  return box;
}

template <class Real>
Mesh to_double_mesh(const TriangleMesh<Real>& mesh) {
  Mesh out;
  out.triangles = mesh.triangles;
  out.edge_keys = mesh.edge_keys;
  out.positions.reserve(mesh.positions.size());
  for (const auto& position : mesh.positions) {
    out.positions.push_back({double(position[0]), double(position[1]), double(position[2])});
  }
  return out;
}

template <class RealA, class RealB>
VertexComparison compare_vertices(const TriangleMesh<RealA>& a, const TriangleMesh<RealB>& b,
                                  const std::function<double(std::uint64_t)>& bound) {
  std::unordered_map<std::uint64_t, std::uint32_t> index_in_b;
  index_in_b.reserve(b.edge_keys.size());
  for (std::uint32_t vertex = 0; vertex < b.edge_keys.size(); ++vertex) index_in_b.emplace(b.edge_keys[vertex], vertex);
  VertexComparison comparison;
  for (std::uint32_t vertex = 0; vertex < a.edge_keys.size(); ++vertex) {
    const auto found = index_in_b.find(a.edge_keys[vertex]);
    if (found == index_in_b.end()) {
      ++comparison.only_in_a;
      continue;
    }
    ++comparison.matched;
    double squared = 0.0;
    bool differs = false;
    for (int axis = 0; axis < 3; ++axis) {
      const double pa = a.positions[vertex][axis];
      const double pb = b.positions[found->second][axis];
      differs = differs || pa != pb;
      squared += (pa - pb) * (pa - pb);
    }
    const double distance = std::sqrt(squared);
    comparison.bit_differences += differs ? 1 : 0;
    comparison.max_distance = std::max(comparison.max_distance, distance);
    if (bound) comparison.max_bound_ratio = std::max(comparison.max_bound_ratio, distance / bound(a.edge_keys[vertex]));
  }
  comparison.only_in_b = b.edge_keys.size() - comparison.matched;
  return comparison;
}

template <class Real>
std::vector<std::array<std::uint32_t, 2>> border_edges(const TriangleMesh<Real>& mesh) {
  // Undirected edge -> (uses, the directed pair of its first use).
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<int, std::array<std::uint32_t, 2>>> uses;
  for (const auto& triangle : mesh.triangles) {
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint32_t from = triangle[corner];
      const std::uint32_t to = triangle[(corner + 1) % 3];
      auto& use = uses[{std::min(from, to), std::max(from, to)}];
      if (use.first++ == 0) use.second = {from, to};
    }
  }
  std::vector<std::array<std::uint32_t, 2>> border;
  for (const auto& [edge, use] : uses) {
    if (use.first == 1) border.push_back(use.second);
  }
  return border;
}

bool key_on_plane(std::uint64_t key, int axis, std::int64_t value) {
  const LatticeEdge edge = lattice_edge_from_key(key);
  return edge.lower_point[axis] == value && ((edge.direction >> axis) & 1) == 0;
}

template <class Real>
std::size_t border_edges_off_box(const TriangleMesh<Real>& mesh, const LatticeBox& box) {
  std::size_t off_box = 0;
  for (const auto& edge : border_edges(mesh)) {
    bool on_a_face = false;
    const bool keyed = edge[0] < mesh.edge_keys.size() && edge[1] < mesh.edge_keys.size();  // else off the box
    for (int axis = 0; axis < 3 && keyed && !on_a_face; ++axis) {
      for (const std::int64_t plane : {box.low[axis], box.high[axis]}) {
        on_a_face = on_a_face || (key_on_plane(mesh.edge_keys[edge[0]], axis, plane) &&
                                  key_on_plane(mesh.edge_keys[edge[1]], axis, plane));
      }
    }
    off_box += on_a_face ? 0 : 1;
  }
  return off_box;
}

LatticeBox lattice_box(const CaveParams& params) {
  LatticeBox box{};
  for (int axis = 0; axis < 3; ++axis) {
    box.low[axis] = params.origin[axis];
    box.high[axis] = std::int64_t{params.origin[axis]} + params.size[axis];
  }
  return box;
}

double gpu_vertex_bound(double magnitude) {
  return std::sqrt(3.0) * unit_roundoff_float * (3.0 + 2.0 * (magnitude + 1.0));
}

void write_mesh_artifact(const Mesh& mesh, const std::string& file, const std::string& caption,
                         const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const std::string relative = result.name + "/" + file;
  std::filesystem::create_directories(options.report_dir / result.name);
  write_mesh(mesh, options.report_dir / relative);
  result.artifacts.push_back({relative, "mesh", caption});
}

FieldVolume volume_bound_from_field(const Volume<double>& density, double threshold) {
  const auto rock = [&](int x, int y, int z) {
    const bool inside = x >= 0 && y >= 0 && z >= 0 && x < density.nx && y < density.ny && z < density.nz;
    return inside && density.at(x, y, z) < threshold;
  };
  FieldVolume volume;
  for (int z = 0; z < density.nz; ++z) {
    for (int y = 0; y < density.ny; ++y) {
      for (int x = 0; x < density.nx; ++x) volume.rock_samples += rock(x, y, z) ? 1.0 : 0.0;
    }
  }
  for (int z = -1; z < density.nz; ++z) {
    for (int y = -1; y < density.ny; ++y) {
      for (int x = -1; x < density.nx; ++x) {
        int rock_corners = 0;
        for (int corner = 0; corner < 8; ++corner) {
          rock_corners += rock(x + (corner & 1), y + ((corner >> 1) & 1), z + (corner >> 2)) ? 1 : 0;
        }
        if (rock_corners == 0 || rock_corners == 8) continue;
        ++volume.cut_cubes;
        volume.bound += std::max(rock_corners, 8 - rock_corners) / 8.0;
      }
    }
  }
  return volume;
}

double vertex_crossing_bound(double margin, double magnitude) {
  return margin + 8.0 * unit_roundoff_double * (magnitude + 2.0);
}

VertexCrossings vertex_crossings(const Mesh& mesh, const Volume<double>& density, double threshold,
                                 const std::array<std::int64_t, 3>& origin, bool linear_placement) {
  // The sample at a global lattice point, none in the pad.
  const auto sample = [&](const std::array<std::int64_t, 3>& point) -> std::optional<double> {
    std::array<std::int64_t, 3> local{};
    for (int axis = 0; axis < 3; ++axis) local[axis] = point[axis] - origin[axis];
    if (local[0] < 0 || local[1] < 0 || local[2] < 0 || local[0] >= density.nx || local[1] >= density.ny ||
        local[2] >= density.nz) {
      return std::nullopt;
    }
    return density.at(int(local[0]), int(local[1]), int(local[2]));
  };
  const auto rock = [threshold](const std::optional<double>& value) { return value && *value < threshold; };
  VertexCrossings crossings;
  crossings.vertices = mesh.edge_keys.size();
  for (std::size_t vertex = 0; vertex < mesh.edge_keys.size(); ++vertex) {
    const LatticeEdge edge = lattice_edge_from_key(mesh.edge_keys[vertex]);
    std::array<std::int64_t, 3> upper = edge.lower_point;
    double magnitude = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      upper[axis] += (edge.direction >> axis) & 1;
      magnitude = std::max({magnitude, std::abs(double(edge.lower_point[axis])), std::abs(double(upper[axis]))});
    }
    const std::optional<double> lower_value = sample(edge.lower_point);
    const std::optional<double> upper_value = sample(upper);
    if (rock(lower_value) == rock(upper_value)) {
      ++crossings.not_crossing;
      continue;
    }
    const bool interpolated = linear_placement && lower_value && upper_value;
    const double t = interpolated ? (threshold - *lower_value) / (*upper_value - *lower_value) : 0.5;
    const double margin = interpolated ? edge_margin(edge.lower_point, edge.direction) : 0.0;
    double distance = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double crossing = double(edge.lower_point[axis]) + t * double((edge.direction >> axis) & 1);
      distance = std::max(distance, std::abs(mesh.positions[vertex][axis] - crossing));
    }
    const double ratio = distance / vertex_crossing_bound(margin, magnitude);
    crossings.off_crossing += ratio > 1.0 ? 1 : 0;
    crossings.max_distance = std::max(crossings.max_distance, distance);
    crossings.max_bound_ratio = std::max(crossings.max_bound_ratio, ratio);
  }
  return crossings;
}

template std::vector<KeyTriangle> key_triangles(const TriangleMesh<float>&);
template std::vector<KeyTriangle> key_triangles(const TriangleMesh<double>&);
template Mesh to_double_mesh(const TriangleMesh<float>&);
template Mesh to_double_mesh(const TriangleMesh<double>&);
template std::size_t border_edges_off_box(const TriangleMesh<float>&, const LatticeBox&);
template std::size_t border_edges_off_box(const TriangleMesh<double>&, const LatticeBox&);
template std::vector<std::array<std::uint32_t, 2>> border_edges(const TriangleMesh<float>&);
template std::vector<std::array<std::uint32_t, 2>> border_edges(const TriangleMesh<double>&);
template KeyTriangle key_triangle(const TriangleMesh<float>&, const std::array<std::uint32_t, 3>&);
template KeyTriangle key_triangle(const TriangleMesh<double>&, const std::array<std::uint32_t, 3>&);
template VertexComparison compare_vertices(const TriangleMesh<float>&, const TriangleMesh<float>&,
                                           const std::function<double(std::uint64_t)>&);
template VertexComparison compare_vertices(const TriangleMesh<float>&, const TriangleMesh<double>&,
                                           const std::function<double(std::uint64_t)>&);
template VertexComparison compare_vertices(const TriangleMesh<double>&, const TriangleMesh<double>&,
                                           const std::function<double(std::uint64_t)>&);

}  // namespace gt
