// Properties of the drainage descriptors (compare/descriptors/priority_flood, flow_d8, flow_dinf,
// stream_network, drainage_laws) on surfaces whose drainage is known in closed form: a pit with a
// saddle, tilted planes, a cone, a flat, hand-built receiver trees, and a V-shaped valley network
// whose channel tree, and so whose Strahler orders, is fixed by construction.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compare/descriptors/drainage_laws.hpp"
#include "compare/descriptors/fit.hpp"
#include "compare/descriptors/flow_d8.hpp"
#include "compare/descriptors/flow_dinf.hpp"
#include "compare/descriptors/priority_flood.hpp"
#include "compare/descriptors/stream_network.hpp"
#include "core/errors.hpp"
#include "tests/support/masked_terrain.hpp"

namespace {

using gt::Heightmap;

Heightmap make_grid(int width, int height, double cell_x, double cell_y, double fill) {
  Heightmap grid(width, height, fill);
  grid.cell_size_x = cell_x;
  grid.cell_size_y = cell_y;
  return grid;
}

// The outlets Priority-Flood seeds: valid cells on the edge or beside a no-data cell.
bool is_seed(const Heightmap& dem, int x, int y) {
  if (!dem.is_valid(x, y)) return false;
  for (const auto step : gt::d8_steps) {
    if (!dem.inside(x + step.dx, y + step.dy) || !dem.is_valid(x + step.dx, y + step.dy)) return true;
  }
  return false;
}

bool has_strictly_lower_neighbour(const Heightmap& dem, int x, int y) {
  for (const auto step : gt::d8_steps) {
    const int nx = x + step.dx, ny = y + step.dy;
    if (dem.inside(nx, ny) && dem.is_valid(nx, ny) && dem.at(nx, ny) < dem.at(x, y)) return true;
  }
  return false;
}

// The cell a D8 path from `cell` ends at; -1 when it has not ended after as many steps as cells.
std::int64_t end_of_path(const gt::D8Flow& flow, std::int64_t cell) {
  for (std::size_t steps = 0; steps <= flow.receiver.size(); ++steps) {
    const std::int64_t next = flow.receiver[static_cast<std::size_t>(cell)];
    if (next < 0) return cell;
    cell = next;
  }
  return -1;
}

double advance_ulps(double value, int steps) {
  for (int i = 0; i < steps; ++i) value = std::nextafter(value, std::numeric_limits<double>::infinity());
  return value;
}

double area_at_outlets(const gt::DinfFlow& flow) {
  double total = 0.0;
  for (std::size_t i = 0; i < flow.area_m2.size(); ++i) {
    if (std::isnan(flow.angle_rad[i])) total += flow.area_m2[i];
  }
  return total;
}

// Smallest angle between two directions, in [0, π].
double angle_between(double a, double b) {
  const double difference = std::remainder(a - b, 2 * std::numbers::pi);
  return std::abs(difference);
}

// 500 m base with 40 m of random relief (many pits), 2 m cells, a no-data blob inside.
Heightmap masked_rough_dem() { return gt::testing::masked_terrain(7, 18, 11, 20).cast<double>(); }

// A plane falling east at 0.5 m per column: 12 x 5 cells of 2 m x 3 m.
Heightmap plane_falling_east() {
  Heightmap plane = make_grid(12, 5, 2.0, 3.0, 0.0);
  for (int y = 0; y < plane.height; ++y) {
    for (int x = 0; x < plane.width; ++x) plane.at(x, y) = 100.0 - 0.5 * x;
  }
  return plane;
}

TEST(Drainage, PriorityFloodFillsAPitToItsSpillHeight) {
  // 7 x 7: the edge ring at 0 (outlets), a rim at 10 with one saddle cell at 4, and a 3 x 3 pit
  // at 1 (its centre 0.5) inside. The pit spills over the saddle: its cells must end above 4 by
  // ε steps only. Flooding spreads breadth-first from the saddle, one nextafter per D8 step, so a
  // cell at Chebyshev distance k from the saddle is at most k ulps above 4.
  Heightmap dem = make_grid(7, 7, 1.0, 1.0, 0.0);
  const int saddle_x = 3, saddle_y = 1;
  for (int y = 1; y <= 5; ++y) {
    for (int x = 1; x <= 5; ++x) dem.at(x, y) = 10.0;
  }
  dem.at(saddle_x, saddle_y) = 4.0;
  for (int y = 2; y <= 4; ++y) {
    for (int x = 2; x <= 4; ++x) dem.at(x, y) = 1.0;
  }
  dem.at(3, 3) = 0.5;

  std::size_t raised = 0;
  const Heightmap filled = gt::fill_depressions(dem, &raised);
  EXPECT_EQ(raised, 9u);
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      const bool in_pit = x >= 2 && x <= 4 && y >= 2 && y <= 4;
      if (!in_pit) {
        EXPECT_EQ(filled.at(x, y), dem.at(x, y)) << x << "," << y;
        continue;
      }
      const int chebyshev = std::max(std::abs(x - saddle_x), std::abs(y - saddle_y));
      EXPECT_GT(filled.at(x, y), 4.0) << x << "," << y;
      EXPECT_LE(filled.at(x, y), advance_ulps(4.0, chebyshev)) << x << "," << y;
    }
  }
}

TEST(Drainage, PriorityFloodLeavesEveryCellADescendingPathToAnOutlet) {
  const Heightmap dem = masked_rough_dem();
  std::size_t raised = 0;
  const Heightmap filled = gt::fill_depressions(dem, &raised);
  ASSERT_EQ(filled.valid, dem.valid);

  std::size_t changed = 0;
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      EXPECT_EQ(filled.at(x, y) >= dem.at(x, y), true) << "lowered at " << x << "," << y;
      changed += filled.at(x, y) != dem.at(x, y);
      if (!dem.is_valid(x, y)) {
        EXPECT_EQ(filled.at(x, y), dem.at(x, y)) << "no-data touched at " << x << "," << y;
      }
      if (dem.is_valid(x, y) && !is_seed(dem, x, y)) {
        EXPECT_TRUE(has_strictly_lower_neighbour(filled, x, y)) << "flat or pit at " << x << "," << y;
      }
    }
  }
  EXPECT_GT(raised, 0u);  // random relief of 40 m on 2 m cells is full of pits
  EXPECT_EQ(raised, changed);

  // Following D8 steepest descent, every valid cell reaches an outlet that is a seed.
  const gt::D8Flow flow = gt::d8_flow(filled);
  for (std::size_t i = 0; i < filled.size(); ++i) {
    if (!filled.is_valid(i)) continue;
    const std::int64_t end = end_of_path(flow, static_cast<std::int64_t>(i));
    ASSERT_GE(end, 0) << "cycle from cell " << i;
    const int end_x = static_cast<int>(end % filled.width), end_y = static_cast<int>(end / filled.width);
    EXPECT_TRUE(is_seed(filled, end_x, end_y)) << "cell " << i << " ends in an interior outlet " << end;
  }

  // Filling a filled DEM raises nothing.
  std::size_t raised_again = 1;
  const Heightmap refilled = gt::fill_depressions(filled, &raised_again);
  EXPECT_EQ(raised_again, 0u);
  EXPECT_EQ(refilled.values, filled.values);
}

TEST(Drainage, NoDataCellsNeverReceiveFlow) {
  const Heightmap filled = gt::fill_depressions(masked_rough_dem());
  const gt::D8Flow d8 = gt::d8_flow(filled);
  const gt::DinfFlow dinf = gt::dinf_flow(filled);
  const double cell_area = filled.cell_size_x * filled.cell_size_y;
  double d8_outlet_area = 0.0;
  for (std::size_t i = 0; i < filled.size(); ++i) {
    const std::int64_t r = d8.receiver[i];
    if (r >= 0) {
      EXPECT_TRUE(filled.is_valid(static_cast<std::size_t>(r))) << "cell " << i << " drains into no-data";
    }
    if (filled.is_valid(i)) {
      if (r < 0) d8_outlet_area += d8.area_m2[i];
      continue;
    }
    EXPECT_EQ(r, -1);
    EXPECT_EQ(d8.area_m2[i], 0.0);
    EXPECT_EQ(dinf.area_m2[i], 0.0);
    EXPECT_TRUE(std::isnan(dinf.angle_rad[i]));
  }
  // Nothing is lost into the mask: the outlets gather the whole valid area. D8 adds whole cell
  // areas (exact); D∞ splits them, so its sum is exact to rounding (1e-12 relative).
  const double valid_area = static_cast<double>(gt::count_valid(filled)) * cell_area;
  EXPECT_EQ(d8_outlet_area, valid_area);
  EXPECT_NEAR(area_at_outlets(dinf), valid_area, 1e-12 * valid_area);
}

TEST(Drainage, FlatDemDrainsEverywhereAfterFilling) {
  // A flat has no lower neighbour anywhere: filling must raise every interior cell (each is no
  // higher than the cell that floods it) and leave a descending path to the edge from each.
  const Heightmap flat = make_grid(20, 15, 1.0, 2.0, 250.0);
  std::size_t raised = 0;
  const Heightmap filled = gt::fill_depressions(flat, &raised);
  EXPECT_EQ(raised, static_cast<std::size_t>((flat.width - 2) * (flat.height - 2)));

  const gt::D8Flow d8 = gt::d8_flow(filled);
  const gt::DinfFlow dinf = gt::dinf_flow(filled);
  for (int y = 0; y < flat.height; ++y) {
    for (int x = 0; x < flat.width; ++x) {
      const std::size_t i = flat.index(x, y);
      const std::int64_t end = end_of_path(d8, static_cast<std::int64_t>(i));
      ASSERT_GE(end, 0);
      EXPECT_TRUE(is_seed(flat, static_cast<int>(end % flat.width), static_cast<int>(end / flat.width)));
      if (!is_seed(flat, x, y)) {
        EXPECT_GE(d8.receiver[i], 0) << x << "," << y;
        EXPECT_FALSE(std::isnan(dinf.angle_rad[i])) << x << "," << y;
      }
    }
  }
  const double total_area = static_cast<double>(flat.size()) * flat.cell_size_x * flat.cell_size_y;
  EXPECT_NEAR(area_at_outlets(dinf), total_area, 1e-12 * total_area);
}

TEST(Drainage, D8OnAPlaneTiltedAlongXCountsTheCellsUpstreamInItsRow) {
  // Falling 0.5 m per 2 m column: the east step's slope 0.25 beats the diagonals' 0.5/√13 and the
  // level north and south steps, so every row drains east on its own. A cell's area is then the
  // (x + 1) cells of its row up to it, and its longest path x steps of 2 m; both sums are of
  // integers times exactly representable sizes, hence exact.
  const Heightmap plane = plane_falling_east();
  std::size_t raised = 1;
  const Heightmap filled = gt::fill_depressions(plane, &raised);
  EXPECT_EQ(raised, 0u);
  const gt::D8Flow flow = gt::d8_flow(filled);
  const double cell_area = plane.cell_size_x * plane.cell_size_y;
  for (int y = 0; y < plane.height; ++y) {
    for (int x = 0; x < plane.width; ++x) {
      const std::size_t i = plane.index(x, y);
      const std::int64_t expected_receiver =
          x + 1 < plane.width ? static_cast<std::int64_t>(plane.index(x + 1, y)) : -1;
      EXPECT_EQ(flow.receiver[i], expected_receiver) << x << "," << y;
      EXPECT_EQ(flow.area_m2[i], (x + 1) * cell_area) << x << "," << y;
      EXPECT_EQ(flow.upstream_length_m[i], x * plane.cell_size_x) << x << "," << y;
    }
  }
  // `order` lists every cell once, each before its receiver.
  ASSERT_EQ(flow.order.size(), plane.size());
  std::vector<std::size_t> position(plane.size());
  for (std::size_t k = 0; k < flow.order.size(); ++k) position[static_cast<std::size_t>(flow.order[k])] = k;
  for (std::size_t i = 0; i < plane.size(); ++i) {
    if (flow.receiver[i] >= 0) {
      EXPECT_LT(position[i], position[static_cast<std::size_t>(flow.receiver[i])]);
    }
  }
}

TEST(Drainage, D8BreaksTiesByTheFixedNeighbourOrder) {
  // The centre of a 3 x 3 block at 1 m with two equally low neighbours (0 m, 1 m cells) drains to
  // the one that comes first in E, NE, N, NW, W, SW, S, SE.
  const auto receiver_of_centre = [](std::pair<int, int> low_a, std::pair<int, int> low_b) {
    Heightmap block = make_grid(3, 3, 1.0, 1.0, 5.0);
    block.at(1, 1) = 1.0;
    block.at(low_a.first, low_a.second) = block.at(low_b.first, low_b.second) = 0.0;
    return gt::d8_flow(block).receiver[block.index(1, 1)];
  };
  EXPECT_EQ(receiver_of_centre({0, 1}, {2, 1}), 5);  // W and E: east, index 1·3 + 2
  EXPECT_EQ(receiver_of_centre({1, 2}, {1, 0}), 1);  // S and N: north (row 0)
  EXPECT_EQ(receiver_of_centre({2, 2}, {0, 0}), 0);  // SE and NW: north-west
}

TEST(Drainage, DinfOnAnInclinedPlaneGivesItsExactAngleAndConservesArea) {
  // A plane falling toward direction θ (0 = east, counter-clockwise) on 2 m x 3 m cells: every
  // facet is an exact plane, so an interior cell's angle is θ up to the rounding of the height
  // differences: heights near 100 m carry ulps of 1.4e-14 m and the facet differences are at
  // least 0.5·2·|cos 1.4| ≈ 0.17 m (θ = 1.4 lies 0.17 rad from north, the closest of these to
  // an axis), so the angle is good to ~1e-13; 1e-10 leaves a wide margin.
  // One θ inside each facet range; with dx != dy the ranges are [0, atan(3/2)], [atan(3/2), π/2],
  // ... (boundaries 0.98, 1.57, 2.16, 3.14, 4.12, 4.71, 5.30), so 0.3 to 5.7 visit facets 1, 2, 3,
  // 5, 7 and 8, cardinal-first and diagonal-first alike.
  for (const double theta : {0.3, 1.4, 2.0, 3.5, 4.9, 5.7}) {
    Heightmap plane = make_grid(16, 14, 2.0, 3.0, 0.0);
    for (int y = 0; y < plane.height; ++y) {
      for (int x = 0; x < plane.width; ++x) {
        const double east = x * plane.cell_size_x, north = -y * plane.cell_size_y;
        plane.at(x, y) = 100.0 - 0.5 * (std::cos(theta) * east + std::sin(theta) * north);
      }
    }
    const gt::DinfFlow flow = gt::dinf_flow(plane);
    for (int y = 1; y + 1 < plane.height; ++y) {
      for (int x = 1; x + 1 < plane.width; ++x) {
        EXPECT_NEAR(flow.angle_rad[plane.index(x, y)], theta, 1e-10) << "theta " << theta << " at " << x << "," << y;
      }
    }
    // Every cell drains to strictly lower ones, so the outlets (the downhill edges) gather the
    // whole area, to the rounding of the shares (1e-12 relative).
    const double total_area = static_cast<double>(plane.size()) * 6.0;
    EXPECT_NEAR(area_at_outlets(flow), total_area, 1e-12 * total_area) << "theta " << theta;
  }
}

TEST(Drainage, DinfOnAConeFlowsRadiallyOutward) {
  // Cone z = 500 − ρ around a cell centre, 1 m x 1.5 m cells. A facet's s1 and s2 are the cone's
  // directional derivatives along two perpendicular axes at points of the facet (mean value
  // theorem), all within the diagonal d = √(dx² + dy²) of the cell; there the radial direction
  // turns by at most δ = asin(d/ρ). So (s1, s2) is within √2·δ of the radial unit vector and its
  // angle within asin(√2·δ); clamping to a facet edge only moves toward the radial direction (a
  // clamped facet never beats the unclamped one that shares its edge). Checked where ρ ≥ 3d.
  Heightmap cone = make_grid(41, 37, 1.0, 1.5, 0.0);
  const int centre_x = 20, centre_y = 18;
  for (int y = 0; y < cone.height; ++y) {
    for (int x = 0; x < cone.width; ++x) {
      cone.at(x, y) = 500.0 - std::hypot((x - centre_x) * cone.cell_size_x, (y - centre_y) * cone.cell_size_y);
    }
  }
  const gt::DinfFlow flow = gt::dinf_flow(cone);
  const double diagonal = std::hypot(cone.cell_size_x, cone.cell_size_y);
  int checked = 0;
  for (int y = 1; y + 1 < cone.height; ++y) {
    for (int x = 1; x + 1 < cone.width; ++x) {
      const double east = (x - centre_x) * cone.cell_size_x, north = (centre_y - y) * cone.cell_size_y;
      const double rho = std::hypot(east, north);
      if (rho < 3 * diagonal) continue;
      const double bound = std::asin(std::sqrt(2.0) * std::asin(diagonal / rho));
      const double angle = flow.angle_rad[cone.index(x, y)];
      EXPECT_LE(angle_between(angle, std::atan2(north, east)), bound) << x << "," << y;
      ++checked;
    }
  }
  EXPECT_GT(checked, 800);
  const double total_area = static_cast<double>(cone.size()) * cone.cell_size_x * cone.cell_size_y;
  EXPECT_NEAR(area_at_outlets(flow), total_area, 1e-12 * total_area);
}

TEST(Drainage, StrahlerOrdersOfABinaryTreeOfDepthThree) {
  // Seven cells in a row, 10 m x 5 m: leaves 0, 2, 4, 6 drain to 1 and 5 (one cell away), which
  // drain to the root 3 (two cells away), the outlet. Every cell is a stream (threshold = one
  // cell). Strahler: leaves 1, their junctions 2, the root 3, so N = 4, 2, 1 and R_B = 2; order-1
  // streams are one 10 m step, order-2 ones one 20 m step, the root stream has length 0 (an
  // outlet), so R_L comes from orders 1 and 2 alone: 20/10 = 2.
  const Heightmap row = make_grid(7, 1, 10.0, 5.0, 0.0);
  const gt::D8Flow flow = gt::d8_from_receivers(row, {1, 3, 1, -1, 5, 3, 5});
  const gt::StreamNetwork network = gt::stream_network(flow, row, 50.0);
  EXPECT_EQ(network.strahler, (std::vector<int>{1, 2, 1, 3, 1, 2, 1}));
  EXPECT_EQ(network.max_order, 3);
  EXPECT_EQ(network.streams_per_order, (std::vector<int>{0, 4, 2, 1}));
  EXPECT_EQ(network.mean_length_per_order_m, (std::vector<double>{0.0, 10.0, 20.0, 0.0}));
  ASSERT_TRUE(network.bifurcation_ratio.has_value());
  EXPECT_NEAR(*network.bifurcation_ratio, 2.0, 1e-12);
  ASSERT_TRUE(network.length_ratio.has_value());
  EXPECT_NEAR(*network.length_ratio, 2.0, 1e-12);
  EXPECT_EQ(network.total_length_m, 80.0);
  EXPECT_DOUBLE_EQ(network.drainage_density_per_m, 80.0 / (7 * 50.0));

  // Raising the threshold to three cells drops the leaves: the junctions become sources.
  const gt::StreamNetwork coarse = gt::stream_network(flow, row, 150.0);
  EXPECT_EQ(coarse.strahler, (std::vector<int>{0, 1, 0, 2, 0, 1, 0}));
  EXPECT_EQ(coarse.streams_per_order, (std::vector<int>{0, 2, 1}));
}

TEST(Drainage, StrahlerOrderIsNotRaisedByALowerTributary) {
  // Cells 0 and 1 meet at 2 (order 2); leaf 4 joins at 3, which stays order 2; 3 drains to the
  // outlet 5. One order-2 stream (2 → 3 → 5: 1 m + 2 m) and three order-1 streams (2 m, 1 m,
  // 1 m). With one order-2 stream and three of order 1, R_B = 3.
  const Heightmap row = make_grid(6, 1, 1.0, 1.0, 0.0);
  const gt::D8Flow flow = gt::d8_from_receivers(row, {2, 2, 3, 5, 3, -1});
  const gt::StreamNetwork network = gt::stream_network(flow, row, 1.0);
  EXPECT_EQ(network.strahler, (std::vector<int>{1, 1, 2, 2, 1, 2}));
  EXPECT_EQ(network.streams_per_order, (std::vector<int>{0, 3, 1}));
  EXPECT_DOUBLE_EQ(network.mean_length_per_order_m[1], 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(network.mean_length_per_order_m[2], 3.0);
  ASSERT_TRUE(network.bifurcation_ratio.has_value());
  EXPECT_NEAR(*network.bifurcation_ratio, 3.0, 1e-12);
}

// A V-shaped valley network: an H-shaped binary tree of straight channels on a 97 x 97 grid of
// 10 m cells, in cell coordinates, each flowing from `up` to `down`. The trunk (order 3) runs
// south to the outlet on the south edge; two order-2 channels run along row 64 into its head;
// each of their heads receives two order-1 channels, one from the north edge and one from the
// south edge. The leaves start on the edge because a tip inside the grid would be the bottom of
// a funnel (the cone around a channel's highest point), whose converging D8 rays gather into
// extra first-order streams: a real feature of such a surface, not of the tree.
struct Channel {
  int up_x, up_y, down_x, down_y;
  int order;
  double down_height;  // m; the bed rises upstream at bed_gradient
};

constexpr double valley_cell = 10.0;
constexpr double bed_gradient = 0.05;  // m/m along every channel
constexpr double side_slope = 0.5;     // m/m across: valley sides ten times steeper than the beds

double length_m(const Channel& c) { return valley_cell * std::hypot(c.down_x - c.up_x, c.down_y - c.up_y); }

std::vector<Channel> valley_channels() {
  std::vector<Channel> channels{{48, 64, 48, 96, 3, 100.0}};
  const double fork_height = channels[0].down_height + bed_gradient * length_m(channels[0]);
  for (const int head_x : {24, 72}) {
    const Channel middle{head_x, 64, 48, 64, 2, fork_height};
    const double head_height = fork_height + bed_gradient * length_m(middle);
    channels.push_back(middle);
    channels.push_back({head_x, 0, head_x, 64, 1, head_height});
    channels.push_back({head_x, 96, head_x, 64, 1, head_height});
  }
  return channels;
}

// The lowest of bed height + side_slope·distance over the points of one channel: the bed at arc
// position τ from `up` is h_up − g·τ, and h_up − g·τ + s·√(d² + (τ − a)²) is convex in τ with its
// minimum at τ = a + d·g/√(s² − g²) (a: position of the foot along the channel, d: distance
// across), clamped to the channel.
double height_over_channel(const Channel& c, double px, double py) {
  const double ux = valley_cell * c.up_x, uy = valley_cell * c.up_y;
  const double length = length_m(c);
  const double dir_x = (valley_cell * c.down_x - ux) / length, dir_y = (valley_cell * c.down_y - uy) / length;
  const double along = (px - ux) * dir_x + (py - uy) * dir_y;
  const double across = std::abs((px - ux) * dir_y - (py - uy) * dir_x);
  const double up_height = c.down_height + bed_gradient * length;
  const double tau = std::clamp(
      along + across * bed_gradient / std::sqrt(side_slope * side_slope - bed_gradient * bed_gradient), 0.0, length);
  return up_height - bed_gradient * tau + side_slope * std::hypot(across, tau - along);
}

// Height = the lowest "bed height + side slope · distance" over all channel points, so the beds
// are the valley floors (no channel point lies above another's cone, since the beds' gradient is
// a tenth of the sides') and every other point falls toward a channel.
Heightmap valley_network_dem(const std::vector<Channel>& channels) {
  Heightmap dem = make_grid(97, 97, valley_cell, valley_cell, 0.0);
  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      double height = std::numeric_limits<double>::infinity();
      for (const Channel& c : channels) {
        height = std::min(height, height_over_channel(c, valley_cell * x, valley_cell * y));
      }
      dem.at(x, y) = height;
    }
  }
  return dem;
}

// The highest order of the channels through cell (x, y) (a junction belongs to the channel it
// starts), 0 off the channels. Channels are vertical or horizontal.
int channel_order(const std::vector<Channel>& channels, int x, int y) {
  int order = 0;
  for (const Channel& c : channels) {
    const bool vertical = c.up_x == c.down_x;
    const bool on = vertical ? x == c.up_x && y >= std::min(c.up_y, c.down_y) && y <= std::max(c.up_y, c.down_y)
                             : y == c.up_y && x >= std::min(c.up_x, c.down_x) && x <= std::max(c.up_x, c.down_x);
    if (on) order = std::max(order, c.order);
  }
  return order;
}

TEST(Drainage, ValleyNetworkHasTheOrdersOfItsChannelTree) {
  // Threshold: 100 cells. With beds at a tenth of the side slope (< √2 − 1), the straight step
  // across a valley side toward its channel is steeper than the diagonal one, so hillslope cells
  // drain in straight rays into the nearest channel and gather at most one valley side: 24 cells
  // (a leaf to the west edge, or to the divide between leaves 48 cells apart). The one place
  // where rays converge is the narrow funnel above the trunk's head, where both order-2 beds end
  // (half-width g/√(s² − g²) ≈ 0.1 of the distance, over at most 24 rows: a few dozen cells). A
  // channel cell gathers both of its sides, at least 11 + 11 cells per cell of channel, so every
  // channel passes 100 cells within a few cells of its head, and no hillslope cell reaches it.
  const std::vector<Channel> channels = valley_channels();
  const Heightmap dem = valley_network_dem(channels);
  std::size_t raised = 1;
  const Heightmap filled = gt::fill_depressions(dem, &raised);
  EXPECT_EQ(raised, 0u);  // the network has no pit: every point falls toward a bed, every bed to the outlet
  const gt::D8Flow flow = gt::d8_flow(filled);
  const gt::StreamNetwork network = gt::stream_network(flow, filled, 100 * valley_cell * valley_cell);

  for (int y = 0; y < dem.height; ++y) {
    for (int x = 0; x < dem.width; ++x) {
      const int order = network.strahler[dem.index(x, y)];
      if (order > 0) {
        EXPECT_EQ(order, channel_order(channels, x, y)) << "stream cell " << x << "," << y;
      }
    }
  }
  EXPECT_EQ(network.max_order, 3);
  EXPECT_EQ(network.streams_per_order, (std::vector<int>{0, 4, 2, 1}));
  ASSERT_TRUE(network.bifurcation_ratio.has_value());
  EXPECT_NEAR(*network.bifurcation_ratio, 2.0, 1e-12);
  // A bed cell next to a junction steps diagonally onto the next bed: √2·g·10 m over 10√2 m
  // beats g·10 m over 10 m. So the trunk stream runs from (48, 65), fed diagonally by (47, 64)
  // and (49, 64), down 31 steps of 10 m to the outlet (48, 96); each order-2 stream runs from
  // (25, 64) or (71, 64) along 22 steps of 10 m and one diagonal step into (48, 65).
  EXPECT_NEAR(network.mean_length_per_order_m[3], 31 * valley_cell, 1e-9);
  EXPECT_NEAR(network.mean_length_per_order_m[2], 22 * valley_cell + std::sqrt(2.0) * valley_cell, 1e-9);
  EXPECT_EQ(flow.receiver[dem.index(48, 96)], -1);
  EXPECT_EQ(flow.area_m2[dem.index(48, 96)], static_cast<double>(dem.size()) * valley_cell * valley_cell);
}

TEST(Drainage, HackExponentOfATiltedPlaneLiesWithinItsClosedForm) {
  // On the plane falling east a cell of n = x + 1 cells has L = (n − 1)·dx and A = n·dx·dy, so
  // d ln L / d ln A = n/(n − 1), between 1 and n_min/(n_min − 1) over the band n ≥ n_min. A
  // least-squares slope of a curve whose local slope lies in [m1, m2] lies in [m1, m2] too.
  const Heightmap plane = plane_falling_east();
  const gt::D8Flow flow = gt::d8_flow(plane);
  const double cell_area = plane.cell_size_x * plane.cell_size_y;
  const int n_min = 4;
  const auto fit = gt::hack_fit(flow, n_min * cell_area);
  ASSERT_TRUE(fit.has_value());
  EXPECT_EQ(fit->points, plane.height * (plane.width - n_min + 1));
  EXPECT_GE(fit->slope, 1.0);
  EXPECT_LE(fit->slope, n_min / (n_min - 1.0));
}

TEST(Drainage, ExceedanceOfATiltedPlaneFollowsItsClosedForm) {
  // On the plane falling east (W = 12 columns) a fraction (W + 1 − ⌈a/a_cell⌉)/W of the cells has
  // A ≥ a. Fitted at the documented log-spaced sample areas, the closed form must give the same
  // line as the counting does (to rounding). The band avoids whole multiples of a cell.
  const Heightmap plane = plane_falling_east();
  const gt::D8Flow flow = gt::d8_flow(plane);
  const double cell_area = plane.cell_size_x * plane.cell_size_y;
  const double min_area = 1.5 * cell_area, max_area = 10.5 * cell_area;
  const auto fit = gt::exceedance_fit(flow.area_m2, min_area, max_area);
  ASSERT_TRUE(fit.has_value());

  const int count = std::max(2, static_cast<int>(std::lround(10.0 * std::log10(max_area / min_area))) + 1);
  std::vector<double> log_a, log_p;
  for (int i = 0; i < count; ++i) {
    const double a = min_area * std::pow(max_area / min_area, i / (count - 1.0));
    log_a.push_back(std::log(a));
    log_p.push_back(std::log((plane.width + 1 - std::ceil(a / cell_area)) / plane.width));
  }
  const auto expected = gt::fit_line(log_a, log_p);
  ASSERT_TRUE(expected.has_value());
  EXPECT_EQ(fit->points, count);
  EXPECT_NEAR(fit->slope, expected->slope, 1e-12);
  EXPECT_LT(fit->slope, 0.0);  // fewer cells drain larger areas

  // D∞ sends everything east on this plane (angle 0, no share to the diagonal), so its areas are
  // D8's and the form taking an area array gives the same line.
  const auto dinf_fit = gt::exceedance_fit(gt::dinf_flow(plane).area_m2, min_area, max_area);
  ASSERT_TRUE(dinf_fit.has_value());
  EXPECT_EQ(dinf_fit->slope, fit->slope);
}

TEST(Drainage, RefusesUnusableInput) {
  EXPECT_THROW(gt::fill_depressions(Heightmap{}), gt::InputError);
  EXPECT_THROW(gt::d8_flow(Heightmap{}), gt::InputError);
  EXPECT_THROW(gt::dinf_flow(Heightmap{}), gt::InputError);

  Heightmap masked_out = make_grid(4, 3, 1.0, 1.0, 0.0);
  masked_out.valid.assign(masked_out.size(), 0);
  EXPECT_THROW(gt::fill_depressions(masked_out), gt::InputError);

  Heightmap with_nan = make_grid(4, 3, 1.0, 1.0, 0.0);
  with_nan.at(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(gt::d8_flow(with_nan), gt::InputError);

  const Heightmap row = make_grid(3, 1, 1.0, 1.0, 0.0);
  EXPECT_THROW(gt::d8_from_receivers(row, {1, 0, -1}), gt::InputError);  // a cycle never reaches an outlet
  EXPECT_THROW(gt::d8_from_receivers(row, {1, 5, -1}), gt::InputError);  // off the grid
  const gt::D8Flow flow = gt::d8_from_receivers(row, {1, 2, -1});
  EXPECT_THROW(gt::stream_network(flow, row, 0.0), gt::InputError);
  EXPECT_THROW(gt::stream_network(flow, make_grid(4, 1, 1.0, 1.0, 0.0), 1.0), gt::InputError);
  EXPECT_THROW(gt::exceedance_fit(flow.area_m2, 2.0, 1.0), gt::InputError);
  EXPECT_THROW(gt::hack_fit(flow, -1.0), gt::InputError);
}

}  // namespace
