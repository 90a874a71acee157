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

namespace gt {

struct BenchmarkOptions {
  // Shell-style patterns of the algorithms to time (fnmatch); empty: all. The probe always runs.
  std::vector<std::string> patterns;
  std::vector<int> sizes = {256, 512, 1024, 2048};
  int iterations = 10;
  int reps = 3;
  bool quiet = false;  // no progress lines (--quiet)
};

// Throws InputError when a pattern matches no algorithm that has rows in the table.
std::vector<BenchmarkRow> run_benchmarks(const BenchmarkOptions& options, bool gpu_available,
                                         const Environment& environment);

}  // namespace gt
