// The layered ground of seed 001 (digest 001 §3.1) on the GPU, and the compute-then-apply step of talus and creep.
//
// GPU side of core/layered/layered_ground.hpp; the apply step is shared by talus collapse (§3.10) and
// soil creep (§3.11).
// LayeredGroundBuffers(ground, params) allocates one storage buffer per array of LayeredGround<float>
//   (soil and bedrock twice as long: the current state, then the step's snapshot), the bedrock types,
//   the 8 outflows per column, the per-column conversions and the std140 parameter block of
//   gpu/shaders/erosion/layered/layered.glsl, and uploads `ground`.
// upload(ground) replaces the state; download() returns the current state.
// compute_then_apply(outflow, apply, step, conversions) runs one step: snapshot copy, the process's
//   outflow pass, the apply pass (gpu/shaders/erosion/layered/apply.comp), then adds the step's
//   fragmentation to `conversions`.
// dispatch_pass(pass, step) runs one pass of a local process (vegetation.hpp, weathering.hpp).
// LayeredSlopeProcess(outflow_shader, clear_vegetation) is one such process (talus.hpp, creep.hpp
//   make them): its outflow program and the apply program, with LAYERED_CLEAR_VEGETATION when asked.
// layered_program(shader, defines) -> a program of layered.glsl with its blocks checked.
//
// Inputs:  ground (LayeredGround<float>) and params (LayeredParams). Needs a current GlContext.
// Outputs: the ground on the GPU; download(); conversions (per-column floats summed here in double in
//          column order).
// Units:   metres; conversions in m³.
// Throws:  InputError from the constructor for invalid params or ground (validate_layered_params,
//          check_layered_ground) and from upload() for an invalid ground; std::invalid_argument from
//          upload() for a ground of another size or bedrock layer count; std::runtime_error when a
//          shader does not compile or link or its LayeredBlock, BedrockTypes or Conversions records do
//          not match their C++ mirrors.
// Twin:    reference/erosion/layered/transfer.hpp (apply_outflows); the state: core/layered/layered_ground.hpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"
#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// Mirror of `LayeredBlock` in gpu/shaders/erosion/layered/layered.glsl (std140; checked against
// each program by layered_program). Every real is the reference<float>'s static_cast<float> of the
// double.
struct LayeredBlock {
  float repose_tan_a[4];
  float distance[8];
  std::int32_t grid_size[2];
  std::int32_t bedrock_layer_count;
  std::int32_t periodic;
  float repose_boulders;
  float time_step;
  float vegetation_repose;
  float depth_factor;
  float topsoil_max;
  float creep_rate;
  float critical_slope;
  float creep_denominator_floor;
  float random_base;
  float random_span;
  std::uint32_t seed;
  std::uint32_t step_number;
  std::int32_t talus_thesis_amount;
  std::int32_t talus_random;
  std::int32_t creep_random;
  std::int32_t creep_floored;
  float vegetation_quality_a[4];
  float weathering_shares[4];
  float vegetation_quality_boulders;
  float vegetation_rate;
  float vegetation_equilibrium;
  float vegetation_neighbours;
  float root_depth;
  float root_depth_deep;
  float vegetation_base;
  std::int32_t vegetation_code;
  float weathering_rate;
  float weathering_reach;
  std::int32_t padding[2];
};

// A program of layered.glsl (`shader` under the shader root, with `defines`), its LayeredBlock and
// BedrockTypes records checked against their C++ mirrors (GlProgram::check_block: std::runtime_error
// on a mismatch). Every layered pass loads its programs through this or layered_water_program.
ComputeProgram layered_program(const std::string& shader, const std::vector<std::string>& defines = {});

class LayeredGroundBuffers {
 public:
  // Validates `params` and `ground` (InputError) and uploads it.
  LayeredGroundBuffers(const LayeredGround<float>& ground, const LayeredParams& params);

  // A ground of the constructed size and bedrock layer count (else std::invalid_argument).
  void upload(const LayeredGround<float>& ground);
  LayeredGround<float> download() const;

  void compute_then_apply(const ComputeProgram& outflow, const ComputeProgram& apply, std::uint32_t step,
                          LayeredConversions& conversions);
  // One pass of a local process (vegetation, weathering): the block with `step`, every buffer bound
  // (the outflows as its scratch), one invocation per column, then a barrier. No snapshot copy.
  void dispatch_pass(const ComputeProgram& pass, std::uint32_t step);
  // Sizes and cell sizes of the ground (its arrays empty); the parameters.
  const LayeredGround<float>& shape() const { return shape_; }
  const LayeredParams& params() const { return params_; }
  // The surface heights (for the water's snapshot of them, water_buffers.hpp).
  const StorageBuffer& surface_buffer() const { return surface_; }

 private:
  void bind() const;
  void add_conversions(LayeredConversions& conversions) const;

  LayeredParams params_;
  LayeredGround<float> shape_;  // sizes and cell sizes; its arrays stay empty
  LayeredBlock block_;
  UniformBuffer block_buffer_;
  StorageBuffer surface_;
  StorageBuffer soil_;
  StorageBuffer bedrock_;
  StorageBuffer bedrock_type_;
  StorageBuffer vegetation_;
  StorageBuffer bedrock_types_;
  StorageBuffer outflows_;
  StorageBuffer conversions_;
};

class LayeredSlopeProcess {
 public:
  LayeredSlopeProcess(const std::string& outflow_shader, bool clear_vegetation);
  void step(LayeredGroundBuffers& ground, std::uint32_t step, LayeredConversions& conversions) const;

 private:
  ComputeProgram outflow_;
  ComputeProgram apply_;
};

}  // namespace gt::gpu
