// Beneš's dissolution erosion (digest 000 §3.3, eqs. 2.1-2.9), GPU twin.
//
// DissolutionErosion(width, height, constants) compiles gpu/shaders/erosion/dissolution_local.comp,
//   dissolution_outflow.comp and dissolution_gather.comp.
// load(state) uploads; step(count) dispatches `count` iterations (three passes each, not
//   synchronised); result() downloads.
//
// Inputs:  width, height, constants (dissolution_constants()); state: DissolutionState<float> of that
//          size, the terrain's mask for all four fields. Needs a current GlContext.
// Outputs: result(): the state with the geometry, units and mask of the last load.
// Units:   the terrain's vertical unit for every field (metres).
// Throws:  std::invalid_argument for a load of another size; std::runtime_error when a shader does not
//          compile or link or its block does not match the C++ mirror.
// Twin:    reference/erosion/dissolution.hpp.
#pragma once

#include <array>

#include "core/params/dissolution.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

class DissolutionErosion {
 public:
  DissolutionErosion(int width, int height, const DissolutionConstants& constants);
  void load(const DissolutionState<float>& state);
  void step(int count);
  DissolutionState<float> result() const;

 private:
  Grid<float> layout_;  // geometry, units and mask of the loaded state, values unused
  ComputeProgram local_program_;
  ComputeProgram outflow_program_;
  ComputeProgram gather_program_;
  UniformBuffer block_;
  StorageBuffer terrain_;
  StorageBuffer valid_;
  StorageBuffer outflows_;
  StorageBuffer evaporated_;
  std::array<StorageBuffer, 2> water_;      // [current_], and the gather's next
  std::array<StorageBuffer, 2> dissolved_;  // likewise
  int current_ = 0;
};

}  // namespace gt::gpu
