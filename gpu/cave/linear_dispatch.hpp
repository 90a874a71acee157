// One-dimensional dispatches of the cave passes, the host side of
// gpu/shaders/cave/linear_dispatch.glsl: ceil(items / local_size) workgroups spread over x (at most
// 65535, the GL 4.5 minimum of GL_MAX_COMPUTE_WORK_GROUP_COUNT) and y, so that blocks of 256³
// cubes and more fit. The shader reads its item as linear_invocation() and ignores those past the
// end. Needs a current GlContext.
#pragma once

#include <algorithm>
#include <cstddef>

#include "gpu/shader_program.hpp"

namespace gt::gpu {

inline constexpr std::size_t max_workgroups_per_row = 65535;

// Dispatches `program` (local size local_size x 1 x 1) over `items` invocations; none when 0.
inline void dispatch_linear(const ComputeProgram& program, std::size_t items, int local_size) {
  const std::size_t groups = (items + static_cast<std::size_t>(local_size) - 1) / static_cast<std::size_t>(local_size);
  if (groups == 0) return;
  const std::size_t row = std::min(groups, max_workgroups_per_row);
  const std::size_t rows = (groups + row - 1) / row;
  program.dispatch(static_cast<int>(row) * local_size, static_cast<int>(rows), local_size, 1);
}

}  // namespace gt::gpu
