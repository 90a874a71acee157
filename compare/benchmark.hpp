// The performance table: each field algorithm on generated square grids of the given sides,
// CPU reference (double) and GPU, median wall time of `reps` runs of `iterations` iterations
// after one warm-up run, and Mcell-iterations per second. GPU runs exclude upload and download
// and are bracketed by glFinish (llvmpipe's timer queries read 0 for compute).
#pragma once

#include <string>
#include <vector>

#include "compare/result.hpp"

namespace gt {

struct BenchmarkOptions {
  std::vector<int> sizes = {256, 512, 1024, 2048};
  int iterations = 10;
  int reps = 3;
  bool quiet = false;  // no progress lines (--quiet)
};

std::vector<BenchmarkRow> run_benchmarks(const BenchmarkOptions& options, bool gpu_available,
                                         const Environment& environment);

}  // namespace gt
