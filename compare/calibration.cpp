// One memory-bound copy, timed: see calibration.hpp.
#include "compare/calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace gt {

double calibration_ms() {
  constexpr std::size_t doubles = (32u << 20) / sizeof(double);
  constexpr int repetitions = 5;
  std::vector<double> source(doubles, 1.0), target(doubles, 0.0);
  std::vector<double> times;
  for (int repetition = -1; repetition < repetitions; ++repetition) {
    source[static_cast<std::size_t>(repetition + 1)] += 1.0;  // a different copy each time: not elided
    const auto start = std::chrono::steady_clock::now();
    std::copy(source.begin(), source.end(), target.begin());
    const auto stop = std::chrono::steady_clock::now();
    if (repetition >= 0) times.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
  }
  std::nth_element(times.begin(), times.begin() + repetitions / 2, times.end());
  volatile double keep = target[doubles / 2];  // the copy's result is read
  (void)keep;
  return times[repetitions / 2];
}

}  // namespace gt
