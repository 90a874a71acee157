// Priority-Flood+ε depression filling: Barnes, Lehman & Mulla 2014, "Priority-Flood: An optimal
// depression-filling and watershed-labeling algorithm for digital elevation models", Computers &
// Geosciences 62, Algorithm 3 ("Priority-Flood+ε"), written here from the paper.
//
// The outlets seed a priority queue ordered by height. The lowest open cell is taken; each of its
// unvisited neighbours is either no lower than it (queued by height) or in a depression, where it
// is raised to nextafter(parent) and flooded breadth-first from a plain FIFO (the "pit" queue,
// emptied before the priority queue is consulted again). Every visited cell thus ends strictly
// above the neighbour that visited it, which was visited earlier: following parents gives a
// strictly descending path to a seed, and the steepest-descent D8 receiver exists for every cell
// that is not a seed.
// Decisions where the paper leaves a choice:
//   - ε is one step of std::nextafter in double (the paper's suggestion for floating point): a
//     depression of k cells ends at most k ulps above its spill height.
//   - Outlets (seeds): valid cells on the grid's edge or with a no-data 8-neighbour; water leaves
//     the DEM there. No-data cells are never visited, raised or queued.
//   - Ties in the priority queue are broken by cell index, so the result never depends on the
//     queue's implementation.
//   - A cell is counted as raised when its height changed.
// Units: heights in the DEM's vertical unit (metres); no lengths are used.
// Cost: O(n log n) for n cells (each cell enters one of the queues once).
#include "compare/descriptors/priority_flood.hpp"

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

// Peak extra memory of fill_depressions: the output heights and mask (9 B), the visited flags
// (1 B), and a queue entry (16 B) in the worst case for every cell.
constexpr long long fill_bytes_per_cell = 9 + 1 + 16;

struct QueuedCell {
  double height;
  std::size_t index;
  auto operator<=>(const QueuedCell&) const = default;
};

using LowestFirst = std::priority_queue<QueuedCell, std::vector<QueuedCell>, std::greater<>>;

bool touches_outside_or_no_data(const Heightmap& dem, int x, int y) {
  for (const auto step : d8_steps) {
    const int nx = x + step.dx, ny = y + step.dy;
    if (!dem.inside(nx, ny) || !dem.is_valid(nx, ny)) return true;
  }
  return false;
}

void seed_outlets(const Heightmap& dem, std::vector<std::uint8_t>& visited, LowestFirst& open) {
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      const std::size_t i = dem.index(x, y);
      if (!dem.is_valid(i) || !touches_outside_or_no_data(dem, x, y)) continue;
      visited[i] = 1;
      open.push({dem.values[i], i});
    }
  }
}

}  // namespace

void check_drainage_dem(const Heightmap& dem, const std::string& what, long long bytes_per_cell) {
  check_grid_fits(dem.width, dem.height, bytes_per_cell, what);
  const std::size_t cells = static_cast<std::size_t>(dem.width) * static_cast<std::size_t>(dem.height);
  if (dem.values.size() != cells || (dem.has_mask() && dem.valid.size() != cells)) {
    throw InputError(fmt::format("{}: a {}x{} grid holds {} values and a mask of {} bytes", what, dem.width,
                                 dem.height, dem.values.size(), dem.valid.size()));
  }
  check_cell_size(dem, what);
  check_finite(dem, what);
  if (count_valid(dem) == 0) throw InputError(fmt::format("{}: the grid has no valid cell", what));
}

Heightmap fill_depressions(const Heightmap& dem, std::size_t* raised_cells) {
  check_drainage_dem(dem, "fill_depressions", fill_bytes_per_cell);
  Heightmap filled = dem;
  std::vector<std::uint8_t> visited(dem.size(), 0);
  LowestFirst open;
  std::queue<QueuedCell> pit;
  seed_outlets(dem, visited, open);
  std::size_t raised = 0;
  while (!open.empty() || !pit.empty()) {
    QueuedCell cell;
    if (!pit.empty()) {
      cell = pit.front();
      pit.pop();
    } else {
      cell = open.top();
      open.pop();
    }
    const int x = static_cast<int>(cell.index % static_cast<std::size_t>(dem.width));
    const int y = static_cast<int>(cell.index / static_cast<std::size_t>(dem.width));
    for (const auto step : d8_steps) {
      const int nx = x + step.dx, ny = y + step.dy;
      if (!dem.inside(nx, ny)) continue;
      const std::size_t n = dem.index(nx, ny);
      if (!dem.is_valid(n) || visited[n]) continue;
      visited[n] = 1;
      double& height = filled.values[n];
      if (height <= cell.height) {
        height = std::nextafter(cell.height, std::numeric_limits<double>::infinity());
        ++raised;
        pit.push({height, n});
      } else {
        open.push({height, n});
      }
    }
  }
  if (raised_cells) *raised_cells = raised;
  return filled;
}

}  // namespace gt
