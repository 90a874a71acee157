// The layered ground's water on the GPU (seed 001, digest 001 §3.3-3.5, §3.12-3.15, §3.19) and its one-pass processes.
//
// GPU side of core/layered/layered_water.hpp, beside LayeredGroundBuffers.
// LayeredWaterBuffers(ground, water) validates `water` against the ground's size, builds the std140
//   LayeredWaterBlock of gpu/shaders/erosion/layered/water.glsl from the ground's parameters (every
//   real the reference<float>'s static_cast<float> of the double), allocates the water state (16
//   sections of `cells` floats, twice: the state, then the move pass's snapshot) and a scratch of
//   per-column records, and uploads `water`.
// upload(water), download(); bind() binds the block (uniform binding 1), the state (10) and the
//   records (11); snapshot() copies the state into its second half; snapshot_surface() copies the
//   ground's surface into SURFACE_BEFORE; records(count) reads the first count·cells record floats
//   back.
// count_erosion_records(records, cells, area, layout, count_breakdown, conversions): adds an erosion
//   pass's tallies to `conversions`.
// layered_water_program(shader, defines) -> a program of water.glsl with its blocks checked.
// LayeredWaterPass(shader) is a pass of one invocation per column that needs nothing but the bound
//   buffers (dissolution.comp, diffusion.comp, wetness.comp): step(ground, water, step) binds and dispatches it.
//
// Inputs:  ground (LayeredGroundBuffers), water (LayeredWater<float>). Needs a current GlContext.
// Outputs: the water state on the GPU; download(); records; conversions.
// Units:   m, m³/s; conversions in m³.
// Throws:  InputError ("erosion.layered: ...") from the constructor and upload() for water of another
//          size than the ground or with non-finite or negative depths, fluxes, carried amounts or
//          wetness (check_layered_water); std::runtime_error when a shader does not compile or link or
//          its LayeredWaterBlock does not match the C++ mirror.
// Twin:    the state: core/layered/layered_water.hpp; the passes: reference/erosion/layered/dissolution.hpp
//          (dissolution.comp), diffusion.hpp (diffusion.comp) and wetness.hpp (wetness.comp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/layered/layered_water.hpp"
#include "gpu/buffer.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"

namespace gt::gpu {

// Mirror of `LayeredWaterBlock` in water.glsl (std140; checked against each program by
// layered_water_program).
struct LayeredWaterBlock {
  float pipe_coefficient[4];
  float breakdown_slopes[4][4];
  float breakdown_thresholds[4][4];
  float cell_area;
  float rain_depth;
  float river_depth;
  std::int32_t river;
  std::int32_t river_source;
  std::int32_t sink_row_start;
  float velocity_depth_floor;
  float depth_ramp;
  float slope_floor;
  float slope_scale_x;
  float slope_scale_y;
  float cell_size_x;
  float cell_size_y;
  float erosion_strength;
  float organic_capacity;
  float erosion_rate;
  float deposition_rate;
  float vegetation_protection;
  std::int32_t breakdown_code;
  std::int32_t share_code;
  float least_share;
  float transparency_depth;
  float regolith_depth;
  float regolith_erosion;
  float regolith_deposition;
  float drying_factor;
  float flood_wetness;
  float impact_scale;
  float sediment_diffusion;
  std::int32_t diffusion_water;
  std::int32_t regolith_diffusion;
  std::int32_t rain_steps;
  std::int32_t drain_step;
  std::int32_t padding[3];  // std140 rounds the block up to 16 bytes
};

// Floats per column of the records scratch: the most any water pass writes (impact erosion's 48).
inline constexpr std::size_t water_record_floats = 48;
// Sections of the water state (water.glsl).
inline constexpr std::size_t water_sections = 16;

class LayeredWaterBuffers {
 public:
  LayeredWaterBuffers(const LayeredGroundBuffers& ground, const LayeredWater<float>& water);

  void upload(const LayeredWater<float>& water);
  LayeredWater<float> download() const;

  void bind() const;
  void snapshot() const;
  void snapshot_surface(const LayeredGroundBuffers& ground) const;
  std::vector<float> records(std::size_t floats_per_column) const;
  const LayeredWaterBlock& block() const { return block_; }

 private:
  std::size_t cells_;
  LayeredWaterBlock block_;
  UniformBuffer block_buffer_;
  StorageBuffer state_;
  StorageBuffer records_;
};

// Where an erosion pass (force_erosion.comp, impact_erosion.comp) writes its per-column tally in a
// record of `floats`: [broken_at + 4j + i] size j broken into size i (i < j), [bedrock_at + i]
// bedrock eroded into size i, its type at [type_at + type_stride·i] (stride 0: one type a column).
struct ErosionRecordLayout {
  std::size_t floats;
  std::size_t broken_at;
  std::size_t bedrock_at;
  std::size_t type_at;
  std::size_t type_stride;
};

// Adds the records' tallies to `conversions` in the reference's order — per column, for each result
// size i, the larger sizes broken into it (when `count_breakdown`), then the bedrock eroded into it —
// each float times `area` in double.
void count_erosion_records(const std::vector<float>& records, std::size_t cells, double area,
                           const ErosionRecordLayout& layout, bool count_breakdown, LayeredConversions& conversions);

// A program of water.glsl (`shader`, with `defines`): layered_program's checks, and its
// LayeredWaterBlock checked against the C++ mirror (std::runtime_error on a mismatch).
ComputeProgram layered_water_program(const std::string& shader, const std::vector<std::string>& defines = {});

class LayeredWaterPass {
 public:
  explicit LayeredWaterPass(const std::string& shader);
  void step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step) const;

 private:
  ComputeProgram program_;
};

}  // namespace gt::gpu
