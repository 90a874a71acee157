// Timing for the driver: steady clock around the work (GPU work bracketed by glFinish,
// gpu/timing.hpp), medians of repetitions recorded in a case's Timings.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

#include "compare/result.hpp"
#include "gpu/timing.hpp"

namespace gt {

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const auto middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

inline double cpu_wall_ms(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// Runs `work` `reps` times, each timed on the CPU's steady clock, and records the median and the
// count as the case's CPU timing; records nothing for reps <= 0.
inline void time_cpu(int reps, const std::function<void()>& work, Timings& timings) {
  if (reps <= 0) return;
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) times.push_back(cpu_wall_ms(work));
  timings.cpu_ms = median(times);
  timings.cpu_reps = reps;
}

// The same for GPU work, each run bracketed by glFinish (gpu_wall_ms).
inline void time_gpu(int reps, const std::function<void()>& work, Timings& timings) {
  if (reps <= 0) return;
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) times.push_back(gpu_wall_ms(work));
  timings.gpu_ms = median(times);
  timings.gpu_reps = reps;
}

}  // namespace gt
