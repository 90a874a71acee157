// D8 flow routing: O'Callaghan & Mark 1984, "The extraction of drainage networks from digital
// elevation data", Computer Vision, Graphics, and Image Processing 28. Each cell drains to the one
// neighbour of steepest descent; the contributing area of a cell is its own area plus that of
// every cell draining into it.
// Decisions where the paper is vague:
//   - Slope = drop / centre distance with the grid's own dx, dy and sqrt(dx² + dy²), so
//     rectangular cells are routed by their true slopes.
//   - Only strictly lower valid neighbours are candidates: flats and pits are outlets (the filled
//     DEM has neither away from its seeds). No-data cells neither drain nor receive.
//   - Ties: the first neighbour in the order E, NE, N, NW, W, SW, S, SE (d8_steps) wins.
//   - The order (upstream before downstream) comes from Kahn's topological sort on the receiver
//     forest; area and the longest upstream path are carried down it in one pass.
// Units: areas in m² (cell_size_x·cell_size_y), lengths in m. Cost O(n).
#include "compare/descriptors/flow_d8.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "compare/descriptors/priority_flood.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

// Peak extra memory: the four output arrays (32 B), the donor counts (4 B) and the ready stack (8 B).
constexpr long long d8_bytes_per_cell = 32 + 4 + 8;

std::array<double, 8> step_distances(const Heightmap& grid) {
  std::array<double, 8> distance{};
  for (std::size_t k = 0; k < d8_steps.size(); ++k) {
    distance[k] = std::hypot(d8_steps[k].dx * grid.cell_size_x, d8_steps[k].dy * grid.cell_size_y);
  }
  return distance;
}

std::int64_t steepest_lower_neighbour(const Heightmap& dem, int x, int y, const std::array<double, 8>& distance) {
  const double height = dem.at(x, y);
  std::int64_t best = -1;
  double best_slope = 0.0;
  for (std::size_t k = 0; k < d8_steps.size(); ++k) {
    const int nx = x + d8_steps[k].dx, ny = y + d8_steps[k].dy;
    if (!dem.inside(nx, ny) || !dem.is_valid(nx, ny)) continue;
    const double slope = (height - dem.at(nx, ny)) / distance[k];
    if (slope > best_slope) {
      best_slope = slope;
      best = static_cast<std::int64_t>(dem.index(nx, ny));
    }
  }
  return best;
}

void check_receivers(const Heightmap& grid, const std::vector<std::int64_t>& receiver) {
  if (receiver.size() != grid.size()) {
    throw InputError(fmt::format("d8_from_receivers: {} receivers for {} cells", receiver.size(), grid.size()));
  }
  const auto cells = static_cast<std::int64_t>(grid.size());
  for (std::size_t i = 0; i < receiver.size(); ++i) {
    const std::int64_t r = receiver[i];
    if (r == -1) continue;
    if (r < 0 || r >= cells || r == static_cast<std::int64_t>(i)) {
      throw InputError(fmt::format("d8_from_receivers: cell {} drains to {}, not a cell of the {}x{} grid other "
                                   "than itself", i, r, grid.width, grid.height));
    }
    if (!grid.is_valid(i) || !grid.is_valid(static_cast<std::size_t>(r))) {
      throw InputError(fmt::format("d8_from_receivers: flow from cell {} to cell {} involves a no-data cell", i, r));
    }
  }
}

// Kahn's algorithm: a cell is ready once every donor has been placed.
std::vector<std::int64_t> upstream_first_order(const Heightmap& grid, const std::vector<std::int64_t>& receiver) {
  std::vector<std::uint32_t> pending_donors(grid.size(), 0);
  for (const std::int64_t r : receiver) {
    if (r >= 0) ++pending_donors[static_cast<std::size_t>(r)];
  }
  std::vector<std::int64_t> ready;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.is_valid(i) && pending_donors[i] == 0) ready.push_back(static_cast<std::int64_t>(i));
  }
  std::vector<std::int64_t> order;
  order.reserve(count_valid(grid));
  while (!ready.empty()) {
    const std::int64_t cell = ready.back();
    ready.pop_back();
    order.push_back(cell);
    const std::int64_t r = receiver[static_cast<std::size_t>(cell)];
    if (r >= 0 && --pending_donors[static_cast<std::size_t>(r)] == 0) ready.push_back(r);
  }
  if (order.size() != count_valid(grid)) {
    throw InputError("d8_from_receivers: the receivers form a cycle (some cells never reach an outlet)");
  }
  return order;
}

D8Flow accumulate(const Heightmap& grid, std::vector<std::int64_t> receiver) {
  D8Flow flow;
  flow.order = upstream_first_order(grid, receiver);
  flow.area_m2.assign(grid.size(), 0.0);
  flow.upstream_length_m.assign(grid.size(), 0.0);
  const double cell_area = grid.cell_size_x * grid.cell_size_y;
  for (const std::int64_t cell : flow.order) flow.area_m2[static_cast<std::size_t>(cell)] = cell_area;
  for (const std::int64_t cell : flow.order) {
    const auto i = static_cast<std::size_t>(cell);
    const std::int64_t r = receiver[i];
    if (r < 0) continue;
    const auto down = static_cast<std::size_t>(r);
    flow.area_m2[down] += flow.area_m2[i];
    flow.upstream_length_m[down] =
        std::max(flow.upstream_length_m[down], flow.upstream_length_m[i] + step_length_m(grid, i, down));
  }
  flow.receiver = std::move(receiver);
  return flow;
}

}  // namespace

double step_length_m(const Heightmap& grid, std::size_t from, std::size_t to) {
  const auto width = static_cast<long long>(grid.width);
  const auto from_cell = static_cast<long long>(from), to_cell = static_cast<long long>(to);
  const double columns = static_cast<double>(to_cell % width - from_cell % width);
  const double rows = static_cast<double>(to_cell / width - from_cell / width);
  return std::hypot(columns * grid.cell_size_x, rows * grid.cell_size_y);
}

D8Flow d8_from_receivers(const Heightmap& grid, std::vector<std::int64_t> receiver) {
  check_drainage_dem(grid, "d8_from_receivers", d8_bytes_per_cell);
  check_receivers(grid, receiver);
  return accumulate(grid, std::move(receiver));
}

D8Flow d8_flow(const Heightmap& filled) {
  check_drainage_dem(filled, "d8_flow", d8_bytes_per_cell);
  const auto distance = step_distances(filled);
  std::vector<std::int64_t> receiver(filled.size(), -1);
  for (int y = 0; y < filled.height; ++y) {
    for (int x = 0; x < filled.width; ++x) {
      if (filled.is_valid(x, y)) receiver[filled.index(x, y)] = steepest_lower_neighbour(filled, x, y, distance);
    }
  }
  return accumulate(filled, std::move(receiver));
}

}  // namespace gt
