// The performance table: each field algorithm on generated square grids of the given sides,
// CPU reference (double) and GPU, median wall time of `reps` runs of `iterations` iterations
// after one warm-up run, and Mcell-iterations per second. GPU runs exclude upload and download
// and are bracketed by glFinish (llvmpipe's timer queries read 0 for compute).
// Beside them, in the same run:
//   - the bandwidth probe "memory.copy" (a float copy over 64 MiB buffers, CPU and GL), which
//     gives every row that states its bytes per cell its memory-bound floor;
//   - peer rows (backend "peer"): other libraries' implementations of the same work
//     (Algorithm::peers, compare/peers/), on the same grid and on one thread like our CPU rows.
// compare/benchmark_table.hpp derives the floor, "× peer" and the scaling exponents.
#pragma once

#include <string>
#include <vector>

#include "compare/result.hpp"
#include "compare/stepped_case.hpp"

namespace gt {

struct BenchmarkOptions {
  // Shell-style patterns of the algorithms to time (fnmatch); empty: all. The probe always runs.
  std::vector<std::string> patterns;
  std::vector<int> sizes = {256, 512, 1024, 2048};
  int iterations = 10;
  int reps = 3;
  bool quiet = false;  // no progress lines (--quiet)
  // The parameter studies beside the main rows (Hydra's droplet spacing and interpolation, thesis
  // Tables 5.3–5.5); the report's quick tier leaves them out.
  bool studies = true;
};

// Whether an algorithm's own row of `cells` cells (voxels, samples of a sphere) belongs to a table of
// `options.sizes`: at most four times the cells of its largest 2-D grid. The full table (2048²)
// holds every cave block up to 256³; the report's (256²) the 32³ and 64³ blocks.
bool within_table_sizes(double cells, const BenchmarkOptions& options);

// A figure a paper or thesis published for the same work (backend "published"): `total_ms` for
// `iterations` iterations of a size×size grid on `device` (as the source names it, with the table),
// in cell-iterations per second like our rows; `detail` says what was measured.
BenchmarkRow published_row(const std::string& algorithm, const std::string& device, int size, int iterations,
                           double total_ms, const std::string& detail);

// Throws InputError when a pattern matches no algorithm that has rows in the table.
// The times (ms) of `reps` runs of a stepped twin's iterations from its start state after a warm-up
// run, on ref<double> (steady clock) and on the GPU (glFinish and a steady clock; needs a current GL
// context): the generic rows' measurements, for an algorithm's own rows.
std::vector<double> time_stepped_cpu(const SteppedTwin& twin, int reps);
std::vector<double> time_stepped_gpu(const SteppedTwin& twin, int reps);

std::vector<BenchmarkRow> run_benchmarks(const BenchmarkOptions& options, bool gpu_available,
                                         const Environment& environment);

}  // namespace gt
