// The fault-line planet (seed 002 §2.5 after Elias and Bourke), GPU twin: votes per region from
// gpu/shaders/planet/fault_lines.comp.
//
// FaultLines() compiles the pass.
// votes(positions, normals) uploads the regions' positions and the fault normals (x, y, z each, float,
//   rounded once by the caller from core's doubles), dispatches one invocation per region and
//   returns one vote count per region; run() alone (after a first votes()) repeats the dispatch on
//   the uploaded buffers, for timing (bracket with glFinish).
//
// Inputs:  positions (3 per region), normals (3 per fault); both non-empty. Needs a current GlContext.
// Outputs: votes per region (elevation = Δ·votes, the caller's).
// Units:   positions and normals dimensionless (unit sphere); votes a count.
// Throws:  std::invalid_argument for empty inputs or sizes not a multiple of 3; std::runtime_error
//          when the shader does not compile or link or lacks its uniforms.
// Twin:    reference/planet/fault_lines.hpp (the spec: core/params/fault_planet.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class FaultLines {
 public:
  FaultLines();
  std::vector<std::int32_t> votes(const std::vector<float>& positions, const std::vector<float>& normals);
  void run() const;

 private:
  ComputeProgram program_;
  GLint region_count_location_;
  GLint fault_count_location_;
  std::size_t regions_ = 0;
  std::optional<StorageBuffer> positions_, normals_, votes_;
};

}  // namespace gt::gpu
