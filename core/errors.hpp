// Error types shared by every layer.
//
// InputError: the user's data or parameters are unusable (NaN heights, unknown parameter,
// unreadable file, size that does not fit in memory). The CLI prints the message and exits 2.
// GpuUnavailable: no GL context could be made; GPU checks become `skip` with this message.
// RunawayRun: the reference's own run left the range its twin can represent (a height change beyond
// the GPU's fixed-point counter): the parameters, not a twin, are at fault, and no comparison is
// possible from there on. The case ends `inconclusive` with this message (stability.runaway).
#pragma once

#include <stdexcept>
#include <string>

namespace gt {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct GpuUnavailable : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RunawayRun : std::runtime_error {
  RunawayRun(const std::string& what, double change_, double limit_)
      : std::runtime_error(what), change(change_), limit(limit_) {}
  double change;  // the change that left the range (in the heights' units)
  double limit;   // the largest the twin can represent
};

}  // namespace gt
