// The calibration kernel (issue 15): a fixed memory-bound pass timed in every run, so that timings
// of two reports can be compared as ratios to it and a faster or slower machine cancels out.
//
// The pass copies 32 MiB of doubles into a second 32 MiB buffer (larger than the last-level caches
// of the machines we run on, so it measures memory bandwidth like the twins' sweeps do) five times
// after one warm-up; the median wall time of one copy, in milliseconds, is the calibration.
#pragma once

namespace gt {

double calibration_ms();

}  // namespace gt
