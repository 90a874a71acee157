// Thermal erosion of Jákó & Tóth 2011 as surveyed by seed 000 (digest 000 §3.6, eqs. 2.30-2.34),
// on the 8-neighbourhood pipe system. Each iteration has two synchronous passes:
//   outflow: A = the neighbours n with b - b_n > (C_a·R(n) + C_i)·l_n (eq. 2.33, C_i = tan angle;
//            R = 1 without a hardness map);
//            H = max over A of (b - b_n) (eq. 2.30 restricted to A, see below);
//            ΔS = rate·R(x, y)·H/2 (eq. 2.32 with a = 1: heights, not volumes, move);
//            ΔS_n = ΔS·(b - b_n)/Σ_A (b - b_j) (eq. 2.34 with height differences: the printed
//            form with absolute heights is not translation-invariant, digest Appendix B item 4).
//   gather:  b' = b - Σ_n ΔS_n + Σ_n (what neighbour n sends to this cell).
// Decisions: H is taken over A rather than over all 8 neighbours, so a cell whose largest drop is
// within the talus limit moves nothing; distances are l_x, l_y and sqrt(l_x² + l_y²); neighbours
// outside the grid or masked are absent (no flow across the border); the thresholds and the rate of
// every cell are computed in double once (core/params/thermal.hpp's jako_cell_constants) and
// rounded once to Real, as the GPU twin receives them. What leaves one cell arrives
// at the other as the same number, so material is conserved up to the rounding of the additions.
// Units: heights and lengths in metres; rate dimensionless in [0, 1].
// Mutants (compare/mutants/thermal.cpp; the GPU twin carries the same ones): unhalved_transfer,
// first_outflow_kept; talus_degree_off and hardness_of_the_cell in the thresholds both twins take
// from core/params/thermal.cpp.
//
// Memory traffic per cell and iteration (ref<double>, the performance table's floor column):
// 2 passes, 152 B read + 72 B written = 224 B (heights read by both passes, the cell's 9 constants
// read by the outflow pass, the outflows double[8] written then read, the next heights written).
#include "reference/erosion/thermal_jako.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/mutant.hpp"
#include "core/rounding_interval.hpp"
#include "reference/erosion/moore_pipes.hpp"

namespace gt::reference {

using std::max;  // unqualified: RoundingInterval (core/rounding_interval.hpp) brings its own
namespace {

template <class Real>
using Outflows = std::vector<std::array<Real, 8>>;

// A cell's thresholds (C_a·R(n) + C_i)·l_k of its 8 pipes and its rate·R, rounded once from double.
template <class Real>
struct CellConstants {
  std::array<Real, 8> talus_limit;
  Real rate;
};

// `half` is 1/2 of eq. 2.32 (mutant erosion.thermal_jako.unhalved_transfer: 1).
template <class Real>
std::array<Real, 8> cell_outflows(const Grid<Real>& heights, int x, int y, const CellConstants<Real>& cell, Real half) {
  const auto& talus_limit = cell.talus_limit;
  const Real rate = cell.rate;
  const Real height = heights.at(x, y);
  std::array<Real, 8> drop{};
  Real largest_drop = Real(0);
  Real drop_total = Real(0);
  for (int k = 0; k < 8; ++k) {
    if (!pipe_open(heights, x, y, k)) continue;
    const Real difference = height - heights.at(x + moore_pipes[k].dx, y + moore_pipes[k].dy);
    if (difference > talus_limit[k]) {
      drop[k] = difference;
      largest_drop = max(largest_drop, difference);
      drop_total = drop_total + difference;
    }
  }
  std::array<Real, 8> outflow{};
  if (drop_total > Real(0)) {
    const Real moved = rate * largest_drop * half;
    for (int k = 0; k < 8; ++k) outflow[k] = moved * drop[k] / drop_total;
  }
  return outflow;
}

// `first_paid` is the first pipe whose outflow the cell pays (mutant
// erosion.thermal_jako.first_outflow_kept: 1, what leaves through pipe 0 is never subtracted).
template <class Real>
Real gathered_height(const Grid<Real>& heights, const Outflows<Real>& outflows, int x, int y, int first_paid) {
  const auto& own = outflows[heights.index(x, y)];
  Real height = heights.at(x, y);
  for (int k = first_paid; k < 8; ++k) height = height - own[k];
  for (int k = 0; k < 8; ++k) {
    if (!pipe_open(heights, x, y, k)) continue;
    height = height + outflows[heights.index(x + moore_pipes[k].dx, y + moore_pipes[k].dy)][opposite_pipe(k)];
  }
  return height;
}

}  // namespace

template <class Real>
Grid<Real> thermal_jako_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations) {
  std::vector<CellConstants<Real>> cells(heights.size());
  const auto exact = jako_cell_constants(constants, heights.width, heights.height);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    for (std::size_t k = 0; k < 8; ++k) cells[c].talus_limit[k] = static_cast<Real>(exact[c][k]);
    cells[c].rate = static_cast<Real>(exact[c][8]);
  }
  const Real half = mutant_active("erosion.thermal_jako.unhalved_transfer") ? Real(1) : Real(0.5);
  const int first_paid = mutant_active("erosion.thermal_jako.first_outflow_kept") ? 1 : 0;

  Grid<Real> current = heights;
  Grid<Real> next = heights;
  Outflows<Real> outflows(heights.size());
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (int y = 0; y < current.height; ++y) {
      for (int x = 0; x < current.width; ++x) {
        outflows[current.index(x, y)] =
            current.is_valid(x, y) ? cell_outflows(current, x, y, cells[current.index(x, y)], half) : std::array<Real, 8>{};
      }
    }
    for (int y = 0; y < current.height; ++y) {
      for (int x = 0; x < current.width; ++x) {
        next.at(x, y) = current.is_valid(x, y) ? gathered_height(current, outflows, x, y, first_paid) : current.at(x, y);
      }
    }
    std::swap(current.values, next.values);
  }
  return current;
}

template Grid<float> thermal_jako_erosion(const Grid<float>&, const ThermalConstants&, int);
template Grid<double> thermal_jako_erosion(const Grid<double>&, const ThermalConstants&, int);
template Grid<RoundingInterval> thermal_jako_erosion(const Grid<RoundingInterval>&, const ThermalConstants&, int);

}  // namespace gt::reference
