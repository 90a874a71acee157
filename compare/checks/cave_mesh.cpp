// Keyed cave mesh comparisons; see cave_mesh.hpp.
#include "compare/checks/cave_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <limits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "compare/checks/error_model.hpp"
#include "core/io/mesh_io.hpp"
#include "core/params/cave.hpp"
#include "core/sum.hpp"
#include "core/vec3.hpp"

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

namespace {

// The sample at local lattice point (x, y, z) of a solid block, none in the air pad around it.
std::optional<double> padded_sample(const Volume<double>& density, std::int64_t x, std::int64_t y, std::int64_t z) {
  if (x < 0 || y < 0 || z < 0 || x >= density.nx || y >= density.ny || z >= density.nz) return std::nullopt;
  return density.at(int(x), int(y), int(z));
}

// Rock iff a sample below the threshold; the pad is air.
bool is_rock(const std::optional<double>& value, double threshold) { return value && *value < threshold; }

}  // namespace

FieldVolume volume_bound_from_field(const Volume<double>& density, double threshold) {
  const auto rock = [&](int x, int y, int z) { return is_rock(padded_sample(density, x, y, z), threshold); };
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

namespace {

double tetrahedron_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return std::abs(dot(b - a, cross(c - a, d - a))) / 6.0;
}

}  // namespace

PiecewiseLinearVolume piecewise_linear_volume(const Volume<double>& density, double threshold,
                                              const std::array<std::int64_t, 3>& origin, bool linear_placement) {
  // The digest's Kuhn tetrahedra (seed 004 §2.6), each a list of cube corners (bit 0 x, 1 y, 2 z)
  // in its positively oriented order; its table splits a quad along the diagonal from the first
  // rock vertex's crossing towards the first air vertex to the second's towards the second.
  constexpr std::array<std::array<int, 4>, 6> tetrahedra{
      {{0, 1, 3, 7}, {0, 5, 1, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 6, 4, 7}}};
  PiecewiseLinearVolume result;
  CompensatedSum total;
  for (int z = -1; z < density.nz; ++z) {
    for (int y = -1; y < density.ny; ++y) {
      for (int x = -1; x < density.nx; ++x) {
        for (const auto& tetrahedron : tetrahedra) {
          std::array<std::optional<double>, 4> value;
          std::vector<int> inside, outside;  // tetrahedron vertices 0-3, in its order
          for (int k = 0; k < 4; ++k) {
            const int corner = tetrahedron[k];
            value[k] = padded_sample(density, x + (corner & 1), y + ((corner >> 1) & 1), z + (corner >> 2));
            (is_rock(value[k], threshold) ? inside : outside).push_back(k);
          }
          if (inside.empty()) continue;
          if (outside.empty()) {
            total.add(1.0 / 6.0);
            continue;
          }
          ++result.cut_tetrahedra;
          const auto point = [&](int k) {
            const int corner = tetrahedron[k];
            return Vec3{double(corner & 1), double((corner >> 1) & 1), double(corner >> 2)};
          };
          // The crossing on the edge between vertices i and j, t measured from its lower lattice point.
          const auto crossing = [&](int i, int j) {
            if (tetrahedron[i] > tetrahedron[j]) std::swap(i, j);  // a lower corner's bits are a subset
            const int direction = tetrahedron[j] - tetrahedron[i];
            double t = 0.5;
            if (linear_placement && value[i] && value[j]) {
              const int corner = tetrahedron[i];
              const std::array<std::int64_t, 3> lower{origin[0] + x + (corner & 1), origin[1] + y + ((corner >> 1) & 1),
                                                      origin[2] + z + (corner >> 2)};
              const double margin = edge_margin(lower, direction);
              t = std::clamp((threshold - *value[i]) / (*value[j] - *value[i]), margin, 1.0 - margin);
            }
            const Vec3 a = point(i), b = point(j);
            return a + t * (b - a);
          };
          if (inside.size() == 1) {
            total.add(tetrahedron_volume(point(inside[0]), crossing(inside[0], outside[0]), crossing(inside[0], outside[1]),
                                         crossing(inside[0], outside[2])));
          } else if (inside.size() == 3) {
            total.add(1.0 / 6.0 - tetrahedron_volume(point(outside[0]), crossing(outside[0], inside[0]),
                                                     crossing(outside[0], inside[1]), crossing(outside[0], inside[2])));
          } else {
            // The prism (a0 a1 a2 | b0 b1 b2) between the two rock vertices' cut triangles, a_i ↔ b_i,
            // in three tetrahedra whose cut face is split along a1–b2, the table's diagonal.
            const Vec3 a0 = point(inside[0]), a1 = crossing(inside[0], outside[0]), a2 = crossing(inside[0], outside[1]);
            const Vec3 b0 = point(inside[1]), b1 = crossing(inside[1], outside[0]), b2 = crossing(inside[1], outside[1]);
            total.add(tetrahedron_volume(a0, a1, a2, b2) + tetrahedron_volume(a0, a1, b1, b2) +
                      tetrahedron_volume(a0, b0, b1, b2));
          }
        }
      }
    }
  }
  result.volume = total.value();
  return result;
}

double enclosed_volume(const Mesh& mesh, const std::array<std::int64_t, 3>& origin) {
  CompensatedSum total;
  for (const auto& triangle : mesh.triangles) {
    const Vec3 shift{double(origin[0]), double(origin[1]), double(origin[2])};
    const Vec3 p0 = mesh.positions[triangle[0]] - shift, p1 = mesh.positions[triangle[1]] - shift,
               p2 = mesh.positions[triangle[2]] - shift;
    total.add(dot(p0, cross(p1, p2)) / 6.0);
  }
  return total.value();
}

double vertex_crossing_bound(double margin, double magnitude, double unit_roundoff) {
  return margin + 8.0 * unit_roundoff * (magnitude + 2.0);
}

namespace {

std::array<std::int64_t, 3> upper_point(const LatticeEdge& edge) {
  std::array<std::int64_t, 3> upper = edge.lower_point;
  for (int axis = 0; axis < 3; ++axis) upper[axis] += (edge.direction >> axis) & 1;
  return upper;
}

// A lattice point as one integer (the key of its +x edge: unique within the keys' range).
std::uint64_t point_id(const std::array<std::int64_t, 3>& point) { return lattice_edge_key(point, 1); }

std::unordered_set<std::uint64_t> point_ids(const std::vector<std::array<std::int64_t, 3>>& points) {
  std::unordered_set<std::uint64_t> ids;
  for (const auto& point : points) ids.insert(point_id(point));
  return ids;
}

bool touches(const std::unordered_set<std::uint64_t>& points, std::uint64_t key) {
  const LatticeEdge edge = lattice_edge_from_key(key);
  return points.contains(point_id(edge.lower_point)) || points.contains(point_id(upper_point(edge)));
}

}  // namespace

VertexCrossings vertex_crossings(const Mesh& mesh, const Volume<double>& density, double threshold,
                                 const std::array<std::int64_t, 3>& origin, bool linear_placement,
                                 const CrossingModel& model) {
  // The sample at a global lattice point, none in the pad.
  const auto sample = [&](const std::array<std::int64_t, 3>& point) {
    return padded_sample(density, point[0] - origin[0], point[1] - origin[1], point[2] - origin[2]);
  };
  const auto rock = [threshold](const std::optional<double>& value) { return is_rock(value, threshold); };
  const auto undecided = [&](const std::optional<double>& value) {
    return model.density_error > 0.0 && value && std::abs(*value - threshold) <= model.density_error;
  };
  VertexCrossings crossings;
  crossings.vertices = mesh.edge_keys.size();
  for (std::size_t vertex = 0; vertex < mesh.edge_keys.size(); ++vertex) {
    if (mesh.edge_keys[vertex] == missing_vertex_key) {
      ++crossings.unkeyed;
      continue;
    }
    const LatticeEdge edge = lattice_edge_from_key(mesh.edge_keys[vertex]);
    const std::array<std::int64_t, 3> upper = upper_point(edge);
    double magnitude = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      magnitude = std::max({magnitude, std::abs(double(edge.lower_point[axis])), std::abs(double(upper[axis]))});
    }
    const std::optional<double> lower_value = sample(edge.lower_point);
    const std::optional<double> upper_value = sample(upper);
    if (undecided(lower_value) || undecided(upper_value)) {
      ++crossings.excused;
      continue;
    }
    if (rock(lower_value) == rock(upper_value)) {
      ++crossings.not_crossing;
      continue;
    }
    const bool interpolated = linear_placement && lower_value && upper_value;
    const double t = interpolated ? (threshold - *lower_value) / (*upper_value - *lower_value) : 0.5;
    const double margin = interpolated ? edge_margin(edge.lower_point, edge.direction) : 0.0;
    const double density_shift =
        interpolated && model.density_error > 0.0
            ? std::min(1.0, 2.0 * model.density_error / (std::abs(*upper_value - *lower_value) - 2.0 * model.density_error))
            : 0.0;
    double distance = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      const double crossing = double(edge.lower_point[axis]) + t * double((edge.direction >> axis) & 1);
      distance = std::max(distance, std::abs(mesh.positions[vertex][axis] - crossing));
    }
    const double ratio = distance / (vertex_crossing_bound(margin, magnitude, model.unit_roundoff) + density_shift);
    crossings.off_crossing += ratio > 1.0 ? 1 : 0;
    crossings.max_distance = std::max(crossings.max_distance, distance);
    crossings.max_bound_ratio = std::max(crossings.max_bound_ratio, ratio);
  }
  return crossings;
}

std::size_t key_by_lattice_edges(Mesh& mesh) {
  mesh.edge_keys.assign(mesh.positions.size(), missing_vertex_key);
  std::size_t unkeyed = 0;
  for (std::size_t vertex = 0; vertex < mesh.positions.size(); ++vertex) {
    const auto& position = mesh.positions[vertex];
    std::array<std::int64_t, 3> lower{};
    bool in_range = true;
    for (int axis = 0; axis < 3; ++axis) {
      in_range = in_range && std::isfinite(position[axis]) && position[axis] > double(lattice_coordinate_min) &&
                 position[axis] < double(lattice_coordinate_max);
      if (in_range) lower[axis] = static_cast<std::int64_t>(std::floor(position[axis]));
    }
    std::uint64_t key = missing_vertex_key;
    if (in_range) {
      const double tolerance = edge_margin(lower, 7) / 4.0;
      int direction = 0;
      std::optional<double> along;  // the shared fractional part of the moving coordinates
      bool on_edge = true;
      for (int axis = 0; axis < 3; ++axis) {
        const double nearest = std::round(position[axis]);
        if (std::abs(position[axis] - nearest) <= tolerance) {
          lower[axis] = static_cast<std::int64_t>(nearest);
          continue;
        }
        const double fraction = position[axis] - double(lower[axis]);
        on_edge = on_edge && (!along || std::abs(fraction - *along) <= tolerance);
        along = along.value_or(fraction);
        direction |= 1 << axis;
      }
      if (on_edge && direction != 0) key = lattice_edge_key(lower, direction);
    }
    mesh.edge_keys[vertex] = key;
    unkeyed += key == missing_vertex_key ? 1 : 0;
  }
  return unkeyed;
}

namespace {

// Vertices of a mesh by the lower point of their lattice edge.
using VerticesByPoint = std::unordered_map<std::uint64_t, std::vector<std::size_t>>;

// The distance from a lattice point to the nearest of `vertices` whose edge's lower point lies
// within `radius` points along each axis; infinity when there is none.
double nearest_vertex(const Mesh& mesh, const VerticesByPoint& vertices, const std::array<std::int64_t, 3>& point,
                      int radius) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int dz = -radius; dz <= radius; ++dz) {
    for (int dy = -radius; dy <= radius; ++dy) {
      for (int dx = -radius; dx <= radius; ++dx) {
        const std::array<std::int64_t, 3> near = {point[0] + dx, point[1] + dy, point[2] + dz};
        if (std::ranges::any_of(near, [](std::int64_t c) { return c < lattice_coordinate_min || c > lattice_coordinate_max; })) {
          continue;
        }
        const auto found = vertices.find(point_id(near));
        if (found == vertices.end()) continue;
        for (const std::size_t vertex : found->second) {
          double squared = 0.0;
          for (int axis = 0; axis < 3; ++axis) {
            const double d = mesh.positions[vertex][axis] - double(point[axis]);
            squared += d * d;
          }
          nearest = std::min(nearest, std::sqrt(squared));
        }
      }
    }
  }
  return nearest;
}

}  // namespace

double keyed_hausdorff_bound(const Mesh& truth, const std::vector<std::array<std::int64_t, 3>>& changing_samples,
                             int search_radius) {
  const double diagonal = std::sqrt(3.0);
  const auto changing = point_ids(changing_samples);
  VerticesByPoint all, shared;  // every truth vertex; those on edges with no changing endpoint
  std::unordered_set<std::uint64_t> on_truth_surface;  // changing samples that end a crossing edge of the truth
  for (std::size_t vertex = 0; vertex < truth.edge_keys.size(); ++vertex) {
    const std::uint64_t key = truth.edge_keys[vertex];
    if (key == missing_vertex_key) continue;
    const LatticeEdge edge = lattice_edge_from_key(key);
    all[point_id(edge.lower_point)].push_back(vertex);
    if (!touches(changing, key)) {
      shared[point_id(edge.lower_point)].push_back(vertex);
      continue;
    }
    for (const auto& end : {edge.lower_point, upper_point(edge)}) {
      if (changing.contains(point_id(end))) on_truth_surface.insert(point_id(end));
    }
  }
  double bound = 2.0 * diagonal;
  for (const auto& sample : changing_samples) {
    // A candidate's vertex on an edge of this sample lies within √3 of it, its triangle within √3
    // more; the truth's nearest vertex within D_any.
    bound = std::max(bound, 2.0 * diagonal + nearest_vertex(truth, all, sample, search_radius));
    // A truth triangle at this sample: its points within 2√3 of the sample, the sample within
    // D_shared of a vertex the candidate must have too (within √3 of it on the same edge).
    if (on_truth_surface.contains(point_id(sample))) {
      bound = std::max(bound, 3.0 * diagonal + nearest_vertex(truth, shared, sample, search_radius));
    }
  }
  return bound;
}

std::size_t crossing_edges_unexplained(const Mesh& a, const Mesh& b,
                                       const std::vector<std::array<std::int64_t, 3>>& changing_samples) {
  const auto changing = point_ids(changing_samples);
  const auto keys_of = [](const Mesh& mesh) {
    std::unordered_set<std::uint64_t> keys(mesh.edge_keys.begin(), mesh.edge_keys.end());
    keys.erase(missing_vertex_key);
    return keys;
  };
  const auto keys_a = keys_of(a), keys_b = keys_of(b);
  std::size_t unexplained = 0;
  for (const auto& [from, to] : {std::pair{&keys_a, &keys_b}, std::pair{&keys_b, &keys_a}}) {
    for (const std::uint64_t key : *from) unexplained += !to->contains(key) && !touches(changing, key) ? 1 : 0;
  }
  return unexplained;
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
