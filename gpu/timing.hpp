// Timing of GPU work, as DESIGN.md's "Timing" section asks: wall time bracketed by glFinish, and
// the driver's GL_TIME_ELAPSED where it fills it in.
//
// Conventions: milliseconds as double; `work` issues GL commands on the current context.
// Both functions wait for the GPU; they measure, they never assert a speed.
#pragma once

#include <functional>
#include <optional>

namespace gt {

// glFinish, start the steady clock, work(), glFinish, stop: the work's wall time in ms.
double gpu_wall_ms(const std::function<void()>& work);

// The GPU time of work() from a GL_TIME_ELAPSED query, or nullopt when the driver reports 0
// (llvmpipe does for compute dispatches).
std::optional<double> gpu_timer_query_ms(const std::function<void()>& work);

}  // namespace gt
