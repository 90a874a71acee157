// What the performance table derives from its timed rows (compare/benchmark.hpp measures them):
//
// annotate_benchmarks(rows)
//   - floor_ms of every row that states its bytes_per_cell: those bytes over every cell and
//     iteration, divided by the copy bandwidth the probe row (algorithm "memory.copy") measured on
//     the same backend and device in the same run. A row without a probe beside it gets none.
//   - times_peer and fastest_peer of every row of ours that has peer rows (same algorithm, size
//     and dimensions): our median over the fastest peer's.
// fit_scaling(rows)
//   - for each algorithm, backend, peer and device timed at >= 4 sizes: the exponent p of
//     time ∝ work^p, work = cells · iterations, by least squares on log time against log work.
// Rows with a note (not run) take part in neither.
#pragma once

#include <string>
#include <vector>

#include "compare/result.hpp"

namespace gt {

// The bandwidth probe's algorithm name in the table.
inline constexpr const char* bandwidth_probe_name = "memory.copy";

// Issue 17: work that is linear in the cells must scale with an exponent of at most this; above
// it the table marks the row superlinear (a defect to fix, not a property to report). Timing
// noise of a few percent at each size moves a fit over 8× in work by about ±0.05.
inline constexpr double linear_exponent_limit = 1.15;

// The fewest sizes a fit is made from.
inline constexpr int scaling_min_sizes = 4;

void annotate_benchmarks(std::vector<BenchmarkRow>& rows);

struct ScalingFit {
  std::string algorithm;
  std::string backend;
  std::string peer;
  std::string device;
  int dimensions = 2;
  std::vector<int> sizes;  // ascending
  double exponent = 0.0;   // d log(median_ms) / d log(cells · iterations)
  bool linear() const { return exponent <= linear_exponent_limit; }
};

std::vector<ScalingFit> fit_scaling(const std::vector<BenchmarkRow>& rows);

// Cells (voxels, samples) times iterations of a row.
double benchmark_work(const BenchmarkRow& row);

}  // namespace gt
