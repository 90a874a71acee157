// Error types shared by every layer.
//
// InputError: the user's data or parameters are unusable (NaN heights, unknown parameter,
// unreadable file, size that does not fit in memory). The CLI prints the message and exits 2.
// GpuUnavailable: no GL context could be made; GPU checks become `skip` with this message.
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

}  // namespace gt
