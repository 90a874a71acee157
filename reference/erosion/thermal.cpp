// Thermal erosion of seed 000 (Hydra, Vlček 2023, §4.4.3; digest 000 §4.6, Algorithms 9-11).
//
// Each iteration has two synchronous passes over a snapshot of the heights:
//   A (requests): for each of the 4 pipes k of the cell, the excess over the talus limit T·l_k.
//     A higher neighbour gives demand_k = (h_k - h) - T·l_k > 0, a lower one supply_k =
//     (h_k - h) + T·l_k < 0. C_d = f_s·max(demand)/Σdemand and C_s = f_s·min(supply)/Σsupply,
//     each clamped to [0, 1]; request_k = supply_k·C_s + demand_k·C_d.
//   B (transfer): for each pipe, the cell and its neighbour hold requests of opposite sign; the
//     smaller magnitude moves (Algorithm 11). Both ends compute the same minimum, so material is
//     conserved exactly up to the rounding of the height additions.
// Decisions where the thesis is vague or its code is wrong (digest Appendix B item 8):
//   - 0/0: when Σdemand (Σsupply) is 0 the coefficient is 0, tested explicitly, never clamp(NaN).
//   - Borders and no-data cells: pipes to cells outside the grid or masked are absent ("no flow
//     across the border"); reading clamp-to-edge would pair a cell with its own request.
//   - Algorithm 11 written as "move min(|r|, |q|) when the signs are opposite, else nothing": equal
//     to the printed branches whenever a transfer exists, and it cannot create material when a
//     request underflows to 0.
//   - The y pipes use l_y (upstream's d.w typo fixed); diagonals use sqrt(l_x² + l_y²).
//   - Odd iteration counts return the last state (upstream returns the previous one).
//   - Normalised heights are clamped to [0, 1] after each iteration, as upstream does.
// Units: heights and lengths in the same unit (metres by default); T dimensionless.
// Mutants (compare/mutants/thermal.cpp; the GPU twin carries the same ones): talus_degree_off,
// unconserved_transfer, doubled_rate, mirrored_slope.
//
// Memory traffic per cell and iteration (ref<double>, the performance table's floor column):
// 2 passes, 48 B read + 40 B written = 88 B (heights read by both passes, the requests
// double[4] written then read, the next heights written).
#include "reference/erosion/thermal.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/mutant.hpp"

namespace gt::reference {
namespace {

struct Pipe {
  int dx;
  int dy;
};

// Pipe k and pipe (k+2) mod 4 point in opposite directions (digest 000 §4.6, upstream order).
constexpr std::array<Pipe, 4> cardinal_pipes{{{-1, 0}, {0, 1}, {1, 0}, {0, -1}}};
constexpr std::array<Pipe, 4> diagonal_pipes{{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}};

template <class Real>
using Requests = std::vector<std::array<Real, 4>>;

template <class Real>
bool pipe_open(const Grid<Real>& heights, int x, int y, const Pipe& pipe) {
  const int nx = x + pipe.dx;
  const int ny = y + pipe.dy;
  return heights.inside(nx, ny) && heights.is_valid(nx, ny);
}

template <class Real>
std::array<Real, 4> cell_requests(const Grid<Real>& heights, int x, int y, const std::array<Pipe, 4>& pipes,
                                  const std::array<Real, 4>& talus_limit, Real request_factor) {
  const Real height = heights.at(x, y);
  std::array<Real, 4> demand{};
  std::array<Real, 4> supply{};
  const bool mirrored = mutant_active("erosion.thermal.mirrored_slope");
  for (int k = 0; k < 4; ++k) {
    if (!pipe_open(heights, x, y, pipes[k])) continue;
    const Pipe& opposite = pipes[(k + 2) % 4];
    const Pipe& read = mirrored && pipe_open(heights, x, y, opposite) ? opposite : pipes[k];
    const Real difference = heights.at(x + read.dx, y + read.dy) - height;
    if (difference > talus_limit[k]) {
      demand[k] = difference - talus_limit[k];
    } else if (difference < -talus_limit[k]) {
      supply[k] = difference + talus_limit[k];
    }
  }
  const Real largest_demand = std::max(std::max(demand[0], demand[1]), std::max(demand[2], demand[3]));
  const Real largest_supply = std::min(std::min(supply[0], supply[1]), std::min(supply[2], supply[3]));
  const Real demand_total = ((demand[0] + demand[1]) + demand[2]) + demand[3];
  const Real supply_total = ((supply[0] + supply[1]) + supply[2]) + supply[3];
  const Real demand_share =
      demand_total > Real(0) ? std::clamp(request_factor * largest_demand / demand_total, Real(0), Real(1)) : Real(0);
  const Real supply_share =
      supply_total < Real(0) ? std::clamp(request_factor * largest_supply / supply_total, Real(0), Real(1)) : Real(0);
  std::array<Real, 4> request{};
  for (int k = 0; k < 4; ++k) request[k] = supply[k] * supply_share + demand[k] * demand_share;
  return request;
}

// Mutant erosion.thermal.unconserved_transfer: the giving cell keeps what it gives.
template <class Real>
Real transferred_height(const Grid<Real>& heights, const Requests<Real>& requests, int x, int y,
                        const std::array<Pipe, 4>& pipes, bool clamp_unit, bool giver_pays) {
  Real height = heights.at(x, y);
  const auto& own = requests[heights.index(x, y)];
  for (int k = 0; k < 4; ++k) {
    if (!pipe_open(heights, x, y, pipes[k])) continue;
    const Real theirs = requests[heights.index(x + pipes[k].dx, y + pipes[k].dy)][(k + 2) % 4];
    if (theirs < Real(0) && own[k] > Real(0)) {
      height = height + std::min(-theirs, own[k]);
    } else if (theirs > Real(0) && own[k] < Real(0) && giver_pays) {
      height = height - std::min(theirs, -own[k]);
    }
  }
  return clamp_unit ? std::clamp(height, Real(0), Real(1)) : height;
}

template <class Real>
void thermal_iteration(const Grid<Real>& heights, Grid<Real>& next, Requests<Real>& requests,
                       const std::array<Pipe, 4>& pipes, const std::array<Real, 4>& talus_limit,
                       const ThermalConstants& constants) {
  // Mutant erosion.thermal.doubled_rate: f_s = strength instead of strength/2.
  const double factor = mutant_active("erosion.thermal.doubled_rate") ? 2.0 : 1.0;
  const Real request_factor = static_cast<Real>(factor * constants.request_factor);
  const bool giver_pays = !mutant_active("erosion.thermal.unconserved_transfer");
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      requests[heights.index(x, y)] =
          heights.is_valid(x, y) ? cell_requests(heights, x, y, pipes, talus_limit, request_factor)
                                 : std::array<Real, 4>{};
    }
  }
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      next.at(x, y) = heights.is_valid(x, y)
                          ? transferred_height(heights, requests, x, y, pipes, constants.clamp_unit, giver_pays)
                          : heights.at(x, y);
    }
  }
}

// T, or under mutant erosion.thermal.talus_degree_off the slope of an angle one degree steeper.
double applied_talus_slope(const ThermalConstants& constants) {
  if (!mutant_active("erosion.thermal.talus_degree_off")) return constants.talus_slope;
  return std::tan(std::atan(constants.talus_slope) + std::numbers::pi / 180.0);
}

}  // namespace

template <class Real>
Grid<Real> thermal_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations,
                           Neighbourhood neighbourhood, int first_iteration) {
  // T·l per pipe, computed in double and rounded once, as the GPU twin receives it.
  const double talus_slope = applied_talus_slope(constants);
  const std::array<Real, 4> cardinal_limit{
      static_cast<Real>(talus_slope * constants.length_x), static_cast<Real>(talus_slope * constants.length_y),
      static_cast<Real>(talus_slope * constants.length_x), static_cast<Real>(talus_slope * constants.length_y)};
  const Real diagonal = static_cast<Real>(talus_slope * constants.length_diagonal);
  const std::array<Real, 4> diagonal_limit{diagonal, diagonal, diagonal, diagonal};

  Grid<Real> current = heights;
  Grid<Real> next = heights;
  Requests<Real> requests(heights.size());
  for (int iteration = first_iteration; iteration < first_iteration + iterations; ++iteration) {
    const bool cardinal = neighbourhood == Neighbourhood::cardinal ||
                          (neighbourhood == Neighbourhood::alternating && iteration % 2 == 0);
    thermal_iteration(current, next, requests, cardinal ? cardinal_pipes : diagonal_pipes,
                      cardinal ? cardinal_limit : diagonal_limit, constants);
    std::swap(current.values, next.values);
  }
  return current;
}

template Grid<float> thermal_erosion(const Grid<float>&, const ThermalConstants&, int, Neighbourhood, int);
template Grid<double> thermal_erosion(const Grid<double>&, const ThermalConstants&, int, Neighbourhood, int);

}  // namespace gt::reference
