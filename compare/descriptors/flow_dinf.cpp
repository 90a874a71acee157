// D-infinity flow routing: Tarboton 1997, "A new method for the determination of flow directions
// and upslope areas in grid digital elevation models", Water Resources Research 33(2), written here
// from the paper. The 8 triangular facets around a cell each join the centre e0, a cardinal
// neighbour e1 and the diagonal neighbour e2 next to it (Tarboton's Table 1: facet k has
// a_c = 0,1,1,2,2,3,3,4 and a_f = 1,-1,1,-1,1,-1,1,-1). On a facet, s1 = (e0 − e1)/d1 and
// s2 = (e1 − e2)/d2, r = atan2(s2, s1), slope sqrt(s1² + s2²); r is clamped to the facet's edges
// [0, r_max], r_max = atan(d2/d1), with the slope of that edge. The steepest facet gives the
// angle a_c·π/2 + a_f·r.
// Decisions where the paper is vague:
//   - dx != dy: d1 is the cell size along e1's axis and d2 the other one, so r_max = atan(d2/d1)
//     and the facets still tile the circle (facet 2's range ends where facet 1's does).
//   - Flow split: r/r_max of the area to e2 and 1 − r/r_max to e1 (proportional to angle, as the
//     paper does for square cells).
//   - Facets at the grid's edge or at no-data: a facet missing one neighbour reduces to its edge
//     toward the other (r = 0 with slope s1, or r = r_max with the slope to e2); a facet missing
//     both is skipped. Cells without a positive facet slope are outlets (angle NaN).
//   - Equal slopes: the first facet in Tarboton's order (starting east-north-east) wins.
//   - Accumulation visits cells from the highest down (ties by index): all flow goes to strictly
//     lower cells (a share is passed only to a neighbour with a positive drop), so this is a
//     topological order.
// Units: angles in radians, areas in m², heights and cell sizes in metres. Cost O(n log n).
#include "compare/descriptors/flow_dinf.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

#include "compare/descriptors/priority_flood.hpp"

namespace gt {
namespace {

// Peak extra memory: the outputs (16 B), the per-cell routing (32 B) and the sorted cell list (8 B).
constexpr long long dinf_bytes_per_cell = 16 + 32 + 8;

struct Facet {
  GridStep cardinal;  // e1
  GridStep diagonal;  // e2
  int quarter_turns;  // a_c
  int sense;          // a_f
};

constexpr std::array<Facet, 8> facets{{{{1, 0}, {1, -1}, 0, 1},
                                       {{0, -1}, {1, -1}, 1, -1},
                                       {{0, -1}, {-1, -1}, 1, 1},
                                       {{-1, 0}, {-1, -1}, 2, -1},
                                       {{-1, 0}, {-1, 1}, 2, 1},
                                       {{0, 1}, {-1, 1}, 3, -1},
                                       {{0, 1}, {1, 1}, 3, 1},
                                       {{1, 0}, {1, 1}, 4, -1}}};

// A facet's lengths on this grid: d1 along the cardinal step, d2 across it (the step from e1 to
// e2), the diagonal, and the opening angle r_max = atan(d2/d1).
struct FacetGeometry {
  double d1;
  double d2;
  double diagonal;
  double r_max;
};

struct FacetDescent {
  double slope;
  double r;  // angle from the cardinal direction toward the diagonal one, in [0, r_max]
};

// How a cell drains: the two receivers of its steepest facet and the diagonal one's share.
struct CellRoute {
  double angle = std::numeric_limits<double>::quiet_NaN();
  std::int64_t cardinal = -1;
  std::int64_t diagonal = -1;
  double diagonal_share = 0.0;
};

std::array<FacetGeometry, 8> facet_geometry(const Heightmap& dem) {
  std::array<FacetGeometry, 8> geometry{};
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const bool along_x = facets[k].cardinal.dx != 0;
    const double d1 = along_x ? dem.cell_size_x : dem.cell_size_y;
    const double d2 = along_x ? dem.cell_size_y : dem.cell_size_x;
    geometry[k] = {d1, d2, std::hypot(d1, d2), std::atan2(d2, d1)};
  }
  return geometry;
}

std::optional<double> height_at(const Heightmap& dem, int x, int y) {
  if (!dem.inside(x, y) || !dem.is_valid(x, y)) return std::nullopt;
  return dem.at(x, y);
}

std::optional<FacetDescent> facet_descent(double e0, std::optional<double> e1, std::optional<double> e2,
                                          const FacetGeometry& g) {
  if (!e1 && !e2) return std::nullopt;
  const double to_diagonal = e2 ? (e0 - *e2) / g.diagonal : 0.0;
  if (!e1) return FacetDescent{to_diagonal, g.r_max};
  const double s1 = (e0 - *e1) / g.d1;
  if (!e2) return FacetDescent{s1, 0.0};
  const double s2 = (*e1 - *e2) / g.d2;
  const double r = std::atan2(s2, s1);
  if (r < 0.0) return FacetDescent{s1, 0.0};
  if (r > g.r_max) return FacetDescent{to_diagonal, g.r_max};
  return FacetDescent{std::hypot(s1, s2), r};
}

CellRoute steepest_facet(const Heightmap& dem, int x, int y, const std::array<FacetGeometry, 8>& geometry) {
  const double e0 = dem.at(x, y);
  CellRoute route;
  double best_slope = 0.0;
  for (std::size_t k = 0; k < facets.size(); ++k) {
    const Facet& facet = facets[k];
    const int x1 = x + facet.cardinal.dx, y1 = y + facet.cardinal.dy;
    const int x2 = x + facet.diagonal.dx, y2 = y + facet.diagonal.dy;
    const auto descent = facet_descent(e0, height_at(dem, x1, y1), height_at(dem, x2, y2), geometry[k]);
    if (!descent || descent->slope <= best_slope) continue;
    best_slope = descent->slope;
    const double share = descent->r / geometry[k].r_max;
    route.angle = facet.quarter_turns * (std::numbers::pi / 2) + facet.sense * descent->r;
    if (route.angle >= 2 * std::numbers::pi) route.angle -= 2 * std::numbers::pi;
    route.diagonal_share = share;
    route.cardinal = share < 1.0 ? static_cast<std::int64_t>(dem.index(x1, y1)) : -1;
    route.diagonal = share > 0.0 ? static_cast<std::int64_t>(dem.index(x2, y2)) : -1;
  }
  return route;
}

std::vector<std::size_t> valid_cells_highest_first(const Heightmap& dem) {
  std::vector<std::size_t> cells;
  cells.reserve(count_valid(dem));
  for (std::size_t i = 0; i < dem.size(); ++i) {
    if (dem.is_valid(i)) cells.push_back(i);
  }
  std::sort(cells.begin(), cells.end(), [&](std::size_t a, std::size_t b) {
    return dem.values[a] != dem.values[b] ? dem.values[a] > dem.values[b] : a < b;
  });
  return cells;
}

}  // namespace

DinfFlow dinf_flow(const Heightmap& filled) {
  check_drainage_dem(filled, "dinf_flow", dinf_bytes_per_cell);
  const auto geometry = facet_geometry(filled);
  std::vector<CellRoute> routes(filled.size());
  for (int y = 0; y < filled.height; ++y) {
    for (int x = 0; x < filled.width; ++x) {
      if (filled.is_valid(x, y)) routes[filled.index(x, y)] = steepest_facet(filled, x, y, geometry);
    }
  }
  DinfFlow flow;
  flow.angle_rad.resize(filled.size());
  flow.area_m2.assign(filled.size(), 0.0);
  const double cell_area = filled.cell_size_x * filled.cell_size_y;
  for (std::size_t i = 0; i < filled.size(); ++i) {
    flow.angle_rad[i] = routes[i].angle;
    if (filled.is_valid(i)) flow.area_m2[i] = cell_area;
  }
  for (const std::size_t i : valid_cells_highest_first(filled)) {
    const CellRoute& route = routes[i];
    const double area = flow.area_m2[i];
    if (route.diagonal >= 0) flow.area_m2[static_cast<std::size_t>(route.diagonal)] += area * route.diagonal_share;
    if (route.cardinal >= 0) {
      flow.area_m2[static_cast<std::size_t>(route.cardinal)] += area * (1.0 - route.diagonal_share);
    }
  }
  return flow;
}

}  // namespace gt
