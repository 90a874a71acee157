// The seed's marching cubes (digest §2.5): the 256-case table built from 14 base configurations by
// the cube's rotations and mirrorings, and the mesher; conventions in marching_cubes.hpp.
#include "reference/cave/marching_cubes.hpp"

#include <deque>
#include <vector>

namespace gt::reference {
namespace {

using Polygon = std::vector<CornerPair>;  // a cycle of cube edges

struct BaseConfiguration {
  std::vector<int> rock_corners;
  std::vector<Polygon> polygons;
};

// Corners c = dx + 2·dy + 4·dz; edges (lower corner, upper corner). Polygons as cycles around the
// rock group, winding fixed later (oriented_triangles).
const std::vector<BaseConfiguration>& base_configurations() {
  static const std::vector<BaseConfiguration> bases = {
      {{0}, {{{0, 1}, {0, 2}, {0, 4}}}},
      {{0, 1}, {{{0, 2}, {1, 3}, {1, 5}, {0, 4}}}},
      {{0, 3}, {{{0, 1}, {0, 2}, {0, 4}}, {{1, 3}, {2, 3}, {3, 7}}}},
      {{0, 7}, {{{0, 1}, {0, 2}, {0, 4}}, {{3, 7}, {5, 7}, {6, 7}}}},
      {{1, 2, 3}, {{{0, 1}, {1, 5}, {3, 7}, {2, 6}, {0, 2}}}},
      {{0, 1, 7}, {{{0, 2}, {1, 3}, {1, 5}, {0, 4}}, {{3, 7}, {5, 7}, {6, 7}}}},
      {{1, 2, 4}, {{{0, 1}, {1, 3}, {1, 5}}, {{0, 2}, {2, 3}, {2, 6}}, {{0, 4}, {4, 5}, {4, 6}}}},
      {{0, 1, 2, 3}, {{{0, 4}, {1, 5}, {3, 7}, {2, 6}}}},
      {{0, 1, 2, 4}, {{{1, 3}, {2, 3}, {2, 6}, {4, 6}, {4, 5}, {1, 5}}}},
      {{0, 1, 6, 7}, {{{0, 2}, {1, 3}, {1, 5}, {0, 4}}, {{2, 6}, {3, 7}, {5, 7}, {4, 6}}}},
      {{0, 1, 2, 6}, {{{1, 3}, {2, 3}, {6, 7}, {4, 6}, {0, 4}, {1, 5}}}},
      {{1, 2, 3, 4}, {{{0, 1}, {1, 5}, {3, 7}, {2, 6}, {0, 2}}, {{0, 4}, {4, 5}, {4, 6}}}},
      {{0, 3, 5, 6},
       {{{0, 1}, {0, 2}, {0, 4}}, {{1, 3}, {2, 3}, {3, 7}}, {{1, 5}, {4, 5}, {5, 7}}, {{2, 6}, {4, 6}, {6, 7}}}},
      {{0, 1, 2, 5}, {{{1, 3}, {2, 3}, {2, 6}, {0, 4}, {4, 5}, {5, 7}}}},
  };
  return bases;
}

using Vector3 = std::array<double, 3>;
using Triangle = std::array<CornerPair, 3>;

Vector3 corner_position(int corner) {
  const LatticePoint offset = corner_offset(corner);
  return {double(offset[0]), double(offset[1]), double(offset[2])};
}

Vector3 edge_midpoint(const CornerPair& edge) {
  const Vector3 a = corner_position(edge[0]);
  const Vector3 b = corner_position(edge[1]);
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// Newell's normal of the polygon through the edge midpoints.
Vector3 newell_normal(const Polygon& polygon) {
  Vector3 normal{};
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vector3 p = edge_midpoint(polygon[i]);
    const Vector3 q = edge_midpoint(polygon[(i + 1) % polygon.size()]);
    normal[0] += (p[1] - q[1]) * (p[2] + q[2]);
    normal[1] += (p[2] - q[2]) * (p[0] + q[0]);
    normal[2] += (p[0] - q[0]) * (p[1] + q[1]);
  }
  return normal;
}

// Σ over the polygon's edges of (air corner - rock corner).
Vector3 rock_to_air(const Polygon& polygon, unsigned rock) {
  Vector3 direction{};
  for (const CornerPair& edge : polygon) {
    const bool lower_is_rock = (rock >> edge[0]) & 1u;
    const Vector3 air = corner_position(lower_is_rock ? edge[1] : edge[0]);
    const Vector3 solid = corner_position(lower_is_rock ? edge[0] : edge[1]);
    for (int axis = 0; axis < 3; ++axis) direction[axis] += air[axis] - solid[axis];
  }
  return direction;
}

// The polygon wound from rock into air and split as a fan from its first vertex.
std::vector<Triangle> oriented_triangles(const Polygon& polygon, unsigned rock) {
  const Vector3 normal = newell_normal(polygon);
  const Vector3 outward = rock_to_air(polygon, rock);
  const bool reverse = normal[0] * outward[0] + normal[1] * outward[1] + normal[2] * outward[2] < 0;
  std::vector<Triangle> triangles;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    triangles.push_back(reverse ? Triangle{polygon[0], polygon[i + 1], polygon[i]}
                                : Triangle{polygon[0], polygon[i], polygon[i + 1]});
  }
  return triangles;
}

struct Symmetry {
  std::array<int, 8> corner_map;  // corner c goes to corner_map[c]
  bool mirrored;
};

Symmetry corner_symmetry(bool mirror, int axis) {
  Symmetry symmetry{{}, mirror};
  for (int corner = 0; corner < 8; ++corner) {
    LatticePoint p = corner_offset(corner);
    if (mirror) {
      p[axis] = 1 - p[axis];
    } else {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      const int rotated_u = 1 - p[v];
      p[v] = p[u];
      p[u] = rotated_u;
    }
    symmetry.corner_map[corner] = p[0] + 2 * p[1] + 4 * p[2];
  }
  return symmetry;
}

Symmetry then(const Symmetry& first, const Symmetry& second) {
  Symmetry composed{{}, first.mirrored != second.mirrored};
  for (int corner = 0; corner < 8; ++corner) composed.corner_map[corner] = second.corner_map[first.corner_map[corner]];
  return composed;
}

// The 48 symmetries, breadth first from the identity over rotate x, y, z, flip x, y, z.
std::vector<Symmetry> cube_symmetries() {
  std::vector<Symmetry> generators;
  for (bool mirror : {false, true}) {
    for (int axis = 0; axis < 3; ++axis) generators.push_back(corner_symmetry(mirror, axis));
  }
  std::vector<Symmetry> found{{{0, 1, 2, 3, 4, 5, 6, 7}, false}};
  std::deque<Symmetry> frontier(found.begin(), found.end());
  while (!frontier.empty()) {
    const Symmetry current = frontier.front();
    frontier.pop_front();
    for (const Symmetry& generator : generators) {
      const Symmetry next = then(current, generator);
      bool known = false;
      for (const Symmetry& symmetry : found) known = known || symmetry.corner_map == next.corner_map;
      if (known) continue;
      found.push_back(next);
      frontier.push_back(next);
    }
  }
  return found;
}

unsigned corner_bits(const std::vector<int>& corners) {
  unsigned bits = 0;
  for (int corner : corners) bits |= 1u << corner;
  return bits;
}

unsigned mapped_corners(const Symmetry& symmetry, const std::vector<int>& corners) {
  unsigned bits = 0;
  for (int corner : corners) bits |= 1u << symmetry.corner_map[corner];
  return bits;
}

CornerPair mapped_edge(const Symmetry& symmetry, const CornerPair& edge) {
  const int a = symmetry.corner_map[edge[0]];
  const int b = symmetry.corner_map[edge[1]];
  return a < b ? CornerPair{a, b} : CornerPair{b, a};
}

CubeCase transformed_case(int base_number, const Symmetry& symmetry, bool complemented) {
  const BaseConfiguration& base = base_configurations()[base_number - 1];
  CubeCase cube_case{base_number, complemented, symmetry.mirrored, {}};
  const unsigned base_rock = corner_bits(base.rock_corners);
  const bool reverse = symmetry.mirrored != complemented;
  for (const Polygon& polygon : base.polygons) {
    for (const Triangle& triangle : oriented_triangles(polygon, base_rock)) {
      const Triangle mapped{mapped_edge(symmetry, triangle[0]), mapped_edge(symmetry, triangle[1]),
                            mapped_edge(symmetry, triangle[2])};
      cube_case.triangles.push_back(reverse ? Triangle{mapped[0], mapped[2], mapped[1]} : mapped);
    }
  }
  return cube_case;
}

// The first (complement, symmetry, base) in the documented order that produces `code`.
CubeCase build_case(unsigned code, const std::vector<Symmetry>& symmetries) {
  if (code == 0 || code == 0xFFu) return {};
  for (bool complemented : {false, true}) {
    for (const Symmetry& symmetry : symmetries) {
      for (int base = 1; base <= static_cast<int>(base_configurations().size()); ++base) {
        unsigned rock = mapped_corners(symmetry, base_configurations()[base - 1].rock_corners);
        if (complemented) rock = ~rock & 0xFFu;
        if (rock == code) return transformed_case(base, symmetry, complemented);
      }
    }
  }
  return {};  // unreachable: the bases cover all 254 non-empty cases (tested)
}

}  // namespace

const std::array<CubeCase, 256>& marching_cubes_table() {
  static const std::array<CubeCase, 256> table = [] {
    const std::vector<Symmetry> symmetries = cube_symmetries();
    std::array<CubeCase, 256> cases{};
    for (unsigned code = 0; code < 256; ++code) cases[code] = build_case(code, symmetries);
    return cases;
  }();
  return table;
}

template <class Real>
TriangleMesh<Real> marching_cubes(const Volume<Real>& density, Real threshold, bool solid,
                                  const std::array<std::int64_t, 3>& lattice_origin, EdgePlacement placement) {
  const std::array<CubeCase, 256>& table = marching_cubes_table();
  CaveMeshBuilder<Real> builder("marching cubes", density, threshold, solid, lattice_origin, placement);
  for_each_cube(builder, [&](const LatticePoint& cube) {
    for (const auto& triangle : table[builder.rock_corners(cube)].triangles) builder.add_triangle(cube, triangle);
  });
  return builder.take_mesh();
}

template TriangleMesh<float> marching_cubes(const Volume<float>&, float, bool, const std::array<std::int64_t, 3>&,
                                            EdgePlacement);
template TriangleMesh<double> marching_cubes(const Volume<double>&, double, bool, const std::array<std::int64_t, 3>&,
                                             EdgePlacement);

}  // namespace gt::reference
