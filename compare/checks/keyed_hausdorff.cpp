// Keyed Hausdorff distance; see keyed_hausdorff.hpp.
#include "compare/checks/keyed_hausdorff.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "compare/checks/cave_mesh.hpp"
#include "compare/checks/mesh.hpp"
#include "core/vec3.hpp"

namespace gt {
namespace {

constexpr std::int64_t reach = 2;                 // lattice units around a sampled triangle's cube
// A vertex may stand this far outside its triangle's cube (rounding; more is a broken mesh, which
// is measured against the whole other mesh). A near distance is exact up to reach - 2·slack.
constexpr double position_slack = 0.25;
constexpr double exact_near_distance = static_cast<double>(reach) - 2 * position_slack;
constexpr double finest_grid_spacing = 0.1;       // lattice units
constexpr double sample_budget = 2e5;             // CGAL samples about area / spacing²
// Twins whose corners moved farther are sampled too: the corner distance bounds a twin's points,
// but along a lattice edge it reaches √3 where a sample sits at the threshold in one precision.
constexpr double moved_corner = finest_grid_spacing;

struct IndexedKeyTriangle {
  KeyTriangle keys;
  std::uint32_t index;
  bool operator<(const IndexedKeyTriangle& other) const { return keys < other.keys; }
};

std::vector<IndexedKeyTriangle> indexed_key_triangles(const Mesh& mesh) {
  std::vector<IndexedKeyTriangle> keyed;
  keyed.reserve(mesh.triangles.size());
  for (std::uint32_t index = 0; index < mesh.triangles.size(); ++index) {
    keyed.push_back({key_triangle(mesh, mesh.triangles[index]), index});
  }
  std::sort(keyed.begin(), keyed.end());
  return keyed;
}

// Which triangles CGAL samples: those without a twin of the same keys in the other mesh
// (multisets), and twins with a corner farther than moved_corner from its twin's. The largest
// corner distance of the other twins is the shared bound.
struct Matching {
  std::vector<bool> a_sampled;
  std::vector<bool> b_sampled;
  std::size_t shared = 0;
  double shared_bound = 0.0;
};

double corner_distance(const Mesh& a, std::uint32_t a_triangle, const Mesh& b, std::uint32_t b_triangle) {
  double largest = 0.0;
  for (const std::uint32_t a_vertex : a.triangles[a_triangle]) {
    for (const std::uint32_t b_vertex : b.triangles[b_triangle]) {
      const bool named = a_vertex < std::min(a.positions.size(), a.edge_keys.size()) &&
                         b_vertex < std::min(b.positions.size(), b.edge_keys.size());
      if (!named) return std::numeric_limits<double>::infinity();
      if (a.edge_keys[a_vertex] != b.edge_keys[b_vertex]) continue;
      double squared = 0.0;
      for (int axis = 0; axis < 3; ++axis) {
        const double difference = a.positions[a_vertex][axis] - b.positions[b_vertex][axis];
        squared += difference * difference;
      }
      if (!std::isfinite(squared)) return std::numeric_limits<double>::infinity();
      largest = std::max(largest, std::sqrt(squared));
    }
  }
  return largest;
}

Matching match_triangles(const Mesh& a, const Mesh& b) {
  const auto keyed_a = indexed_key_triangles(a);
  const auto keyed_b = indexed_key_triangles(b);
  Matching matching{std::vector<bool>(a.triangles.size(), true), std::vector<bool>(b.triangles.size(), true)};
  for (auto in_a = keyed_a.begin(), in_b = keyed_b.begin(); in_a != keyed_a.end() && in_b != keyed_b.end();) {
    if (in_a->keys < in_b->keys) {
      ++in_a;
    } else if (in_b->keys < in_a->keys) {
      ++in_b;
    } else {
      const double distance = corner_distance(a, in_a->index, b, in_b->index);
      if (distance <= moved_corner) {
        matching.a_sampled[in_a->index] = false;
        matching.b_sampled[in_b->index] = false;
        matching.shared_bound = std::max(matching.shared_bound, distance);
      }
      ++matching.shared;
      ++in_a;
      ++in_b;
    }
  }
  return matching;
}

bool has_keys(const Mesh& mesh, const std::array<std::uint32_t, 3>& triangle) {
  return std::all_of(triangle.begin(), triangle.end(), [&](std::uint32_t vertex) { return vertex < mesh.edge_keys.size(); });
}

// Whether every triangle has keys and its corners lie in its cube, up to position_slack: what the
// near triangles' argument needs.
bool triangles_in_their_cubes(const Mesh& mesh) {
  return std::all_of(mesh.triangles.begin(), mesh.triangles.end(), [&](const auto& triangle) {
    if (!has_keys(mesh, triangle)) return false;
    const LatticeBox cube = triangle_cube(key_triangle(mesh, triangle));
    return std::all_of(triangle.begin(), triangle.end(), [&](std::uint32_t vertex) {
      if (vertex >= mesh.positions.size()) return false;
      for (int axis = 0; axis < 3; ++axis) {
        const double coordinate = mesh.positions[vertex][axis];
        if (!(coordinate >= double(cube.low[axis]) - position_slack &&
              coordinate <= double(cube.high[axis]) + position_slack)) {
          return false;
        }
      }
      return true;
    });
  });
}

// The lattice box of both meshes' triangle cubes, widened by reach; none when a triangle breaks
// the near triangles' argument (triangles_in_their_cubes) or the box holds more lattice points
// than max_points_per_triangle per triangle (scattered keys of a broken mesh).
constexpr double max_points_per_triangle = 64.0;

std::optional<LatticeBox> near_region_bounds(const Mesh& a, const Mesh& b) {
  if (!triangles_in_their_cubes(a) || !triangles_in_their_cubes(b)) return std::nullopt;
  LatticeBox bounds{};
  bounds.low.fill(std::numeric_limits<std::int64_t>::max());
  bounds.high.fill(std::numeric_limits<std::int64_t>::min());
  for (const Mesh* mesh : {&a, &b}) {
    for (const auto& triangle : mesh->triangles) {
      const LatticeBox cube = triangle_cube(key_triangle(*mesh, triangle));
      for (int axis = 0; axis < 3; ++axis) {
        bounds.low[axis] = std::min(bounds.low[axis], cube.low[axis] - reach);
        bounds.high[axis] = std::max(bounds.high[axis], cube.high[axis] + reach);
      }
    }
  }
  double points = 1.0;
  for (int axis = 0; axis < 3; ++axis) points *= double(bounds.high[axis] - bounds.low[axis] + 1);
  if (points > max_points_per_triangle * double(a.triangles.size() + b.triangles.size()) + 1e6) return std::nullopt;
  return bounds;
}

// Lattice points marked around the sampled triangles' cubes, dilated by reach; a dense grid over
// near_region_bounds.
class NearRegion {
 public:
  explicit NearRegion(const LatticeBox& bounds) : low_(bounds.low) {
    for (int axis = 0; axis < 3; ++axis) extent_[axis] = static_cast<std::size_t>(bounds.high[axis] - low_[axis] + 1);
    marked_.assign(extent_[0] * extent_[1] * extent_[2], 0);
  }

  void mark(const LatticeBox& box) {
    for_each_point(box, [&](std::size_t index) {
      marked_[index] = 1;
      return false;
    });
  }

  // Grows the marked points by reach along each axis in turn (the ∞-norm ball).
  void dilate() {
    for (int axis = 0; axis < 3; ++axis) {
      for (std::int64_t step = 0; step < reach; ++step) dilate_by_one(axis);
    }
  }

  bool touches(const LatticeBox& box) const {
    return for_each_point(box, [&](std::size_t index) { return marked_[index] != 0; });
  }

 private:
  std::size_t stride(int axis) const { return axis == 0 ? 1 : axis == 1 ? extent_[0] : extent_[0] * extent_[1]; }

  // Visits the grid indices of the box's points until `visit` returns true; whether it did.
  template <class Visit>
  bool for_each_point(const LatticeBox& box, Visit visit) const {
    for (std::int64_t z = box.low[2]; z <= box.high[2]; ++z) {
      for (std::int64_t y = box.low[1]; y <= box.high[1]; ++y) {
        for (std::int64_t x = box.low[0]; x <= box.high[0]; ++x) {
          const std::size_t index = static_cast<std::size_t>(x - low_[0]) * stride(0) +
                                    static_cast<std::size_t>(y - low_[1]) * stride(1) +
                                    static_cast<std::size_t>(z - low_[2]) * stride(2);
          if (visit(index)) return true;
        }
      }
    }
    return false;
  }

  void dilate_by_one(int axis) {
    const std::size_t step = stride(axis);
    const std::size_t length = extent_[axis];
    std::vector<std::uint8_t> grown = marked_;
    for (std::size_t index = 0; index < marked_.size(); ++index) {
      if (!marked_[index]) continue;
      const std::size_t position = index / step % length;
      if (position > 0) grown[index - step] = 1;
      if (position + 1 < length) grown[index + step] = 1;
    }
    marked_ = std::move(grown);
  }

  std::array<std::int64_t, 3> low_{};
  std::array<std::size_t, 3> extent_{};
  std::vector<std::uint8_t> marked_;
};

// The triangles of `mesh` that `keep` selects, with only the vertices they use.
template <class Keep>
Mesh submesh(const Mesh& mesh, Keep keep) {
  Mesh part;
  std::vector<std::uint32_t> new_index(mesh.positions.size(), std::numeric_limits<std::uint32_t>::max());
  for (std::size_t triangle = 0; triangle < mesh.triangles.size(); ++triangle) {
    if (!keep(triangle)) continue;
    std::array<std::uint32_t, 3> corners{};
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint32_t vertex = mesh.triangles[triangle][corner];
      if (vertex >= mesh.positions.size()) {
        corners[corner] = vertex;  // out of range stays out of range: the distance skips the triangle
        continue;
      }
      if (new_index[vertex] == std::numeric_limits<std::uint32_t>::max()) {
        new_index[vertex] = static_cast<std::uint32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[vertex]);
      }
      corners[corner] = new_index[vertex];
    }
    part.triangles.push_back(corners);
  }
  return part;
}

double area(const Mesh& mesh) {
  double total = 0.0;
  for (const auto& triangle : mesh.triangles) {
    if (std::max({triangle[0], triangle[1], triangle[2]}) >= mesh.positions.size()) continue;
    const Vec3& corner = mesh.positions[triangle[0]];
    const double doubled = length(cross(mesh.positions[triangle[1]] - corner, mesh.positions[triangle[2]] - corner));
    if (std::isfinite(doubled)) total += 0.5 * doubled;
  }
  return total;
}

// CGAL's sampled distance of `sampled` to `near`, or to `whole` when a sample lies beyond reach.
double one_side(const Mesh& sampled, const Mesh& near, const Mesh& whole, double spacing, bool& fell_back) {
  if (sampled.triangles.empty()) return 0.0;
  const double distance = approximate_one_sided_hausdorff_distance(sampled, near, spacing);
  if (distance <= exact_near_distance) return distance;
  fell_back = true;
  return approximate_one_sided_hausdorff_distance(sampled, whole, spacing);
}

// The triangles of a and of b whose cubes lie within reach of a sampled triangle's cube.
std::pair<Mesh, Mesh> near_triangles(const LatticeBox& bounds, const Mesh& a, const Mesh& b, const Matching& matching) {
  NearRegion region(bounds);
  for (const auto& [mesh, sampled] : {std::pair{&a, &matching.a_sampled}, std::pair{&b, &matching.b_sampled}}) {
    for (std::size_t triangle = 0; triangle < mesh->triangles.size(); ++triangle) {
      if ((*sampled)[triangle]) region.mark(triangle_cube(key_triangle(*mesh, mesh->triangles[triangle])));
    }
  }
  region.dilate();
  const auto near = [&region](const Mesh& mesh) {
    return submesh(mesh, [&](std::size_t triangle) {
      return region.touches(triangle_cube(key_triangle(mesh, mesh.triangles[triangle])));
    });
  };
  return {near(a), near(b)};
}

}  // namespace

KeyedHausdorff keyed_hausdorff(const Mesh& a, const Mesh& b) {
  KeyedHausdorff result;
  if (a.triangles.empty() || b.triangles.empty()) {
    result.distance = a.triangles.empty() && b.triangles.empty() ? 0.0 : std::numeric_limits<double>::infinity();
    return result;
  }
  const Matching matching = match_triangles(a, b);
  result.shared_bound = matching.shared_bound;
  const Mesh a_sampled = submesh(a, [&](std::size_t triangle) { return bool(matching.a_sampled[triangle]); });
  const Mesh b_sampled = submesh(b, [&](std::size_t triangle) { return bool(matching.b_sampled[triangle]); });
  result.sampled_triangles = a_sampled.triangles.size() + b_sampled.triangles.size();
  result.grid_spacing = std::max(finest_grid_spacing, std::sqrt((area(a_sampled) + area(b_sampled)) / sample_budget));
  std::optional<std::pair<Mesh, Mesh>> near;
  if (const auto bounds = near_region_bounds(a, b)) near = near_triangles(*bounds, a, b, matching);
  result.whole_mesh_fallback = !near;
  const Mesh& a_near = near ? near->first : a;
  const Mesh& b_near = near ? near->second : b;
  result.sampled_distance = std::max(one_side(a_sampled, b_near, b, result.grid_spacing, result.whole_mesh_fallback),
                                     one_side(b_sampled, a_near, a, result.grid_spacing, result.whole_mesh_fallback));
  result.distance = std::max(result.shared_bound, result.sampled_distance);
  return result;
}

}  // namespace gt
