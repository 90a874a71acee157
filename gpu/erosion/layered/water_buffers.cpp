// Host side of the water on the layered ground: its parameter block and buffers (see
// water_buffers.hpp; shaders in gpu/shaders/erosion/layered/).
#include "gpu/erosion/layered/water_buffers.hpp"

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace gt::gpu {
namespace {

constexpr GLuint block_binding = 1, state_binding = 10, records_binding = 11;
// Sections of water.glsl.
constexpr std::size_t water_section = 0, previous_section = 1, wetness_section = 2, flux_section = 3,
                      carried_section = 7, surface_section = 14;

int first_sink_row(int height) {
  for (int y = 0; y < height; ++y) {
    if (river_sink_row(y, height)) return y;
  }
  return height;
}

LayeredWaterBlock make_block(const LayeredGround<float>& shape, const LayeredParams& params) {
  LayeredWaterBlock block{};
  const double area = shape.cell_size_x * shape.cell_size_y;
  for (int k = 0; k < water_pipe_count; ++k) {
    block.pipe_coefficient[k] = static_cast<float>(
        params.time_step * area * params.gravity / layered_neighbour_distance(shape.cell_size_x, shape.cell_size_y, k));
  }
  for (std::size_t j = 0; j < fragment_size_count; ++j) {
    for (std::size_t i = 0; i < fragment_size_count; ++i) {
      block.breakdown_slopes[j][i] = static_cast<float>(params.breakdown_slopes[j][i]);
      block.breakdown_thresholds[j][i] = static_cast<float>(params.breakdown_thresholds[j][i]);
    }
  }
  block.cell_area = static_cast<float>(area);
  block.rain_depth = static_cast<float>(params.time_step * params.rain_rate);
  block.river_depth = static_cast<float>(params.river_depth);
  block.river = params.river ? 1 : 0;
  block.river_source = static_cast<std::int32_t>(river_source_cell(shape.width, shape.height));
  block.sink_row_start = first_sink_row(shape.height);
  block.velocity_depth_floor = static_cast<float>(params.velocity_depth_floor);
  block.depth_ramp = static_cast<float>(params.depth_ramp);
  block.slope_floor = static_cast<float>(params.slope_floor);
  const bool thesis_slope = params.slope_form == SlopeForm::thesis;
  block.slope_scale_x = static_cast<float>(thesis_slope ? 0.5 / shape.cell_size_x : 1.0);
  block.slope_scale_y = static_cast<float>(thesis_slope ? 0.5 / shape.cell_size_y : 1.0);
  block.cell_size_x = static_cast<float>(shape.cell_size_x);
  block.cell_size_y = static_cast<float>(shape.cell_size_y);
  block.erosion_strength = static_cast<float>(params.erosion_strength);
  block.organic_capacity = static_cast<float>(params.organic_capacity);
  block.erosion_rate = static_cast<float>(params.erosion_rate);
  block.deposition_rate = static_cast<float>(params.deposition_rate);
  block.vegetation_protection = static_cast<float>(params.vegetation_protection);
  block.breakdown_code = params.breakdown_form == BreakdownForm::seed001_code ? 1 : 0;
  block.share_code = params.share_form == ShareForm::seed001_code ? 1 : 0;
  block.least_share = static_cast<float>(params.least_share);
  block.transparency_depth = static_cast<float>(params.transparency_depth);
  block.regolith_depth = static_cast<float>(params.regolith_depth);
  block.regolith_erosion = static_cast<float>(params.regolith_erosion);
  block.regolith_deposition = static_cast<float>(params.regolith_deposition);
  block.drying_factor = static_cast<float>(std::pow(params.drying, params.time_step));
  block.flood_wetness = static_cast<float>(params.flood_wetness);
  block.impact_scale = static_cast<float>(params.impact_rate * params.time_step / area);
  block.sediment_diffusion = static_cast<float>(params.sediment_diffusion);
  block.diffusion_water = params.diffusion_weighting == DiffusionWeighting::water ? 1 : 0;
  block.regolith_diffusion = params.regolith_diffusion ? 1 : 0;
  block.rain_steps = params.rain_steps;
  block.drain_step = params.drain_step;
  return block;
}

void put(std::vector<float>& state, std::size_t section, std::size_t cells, const std::vector<float>& values) {
  std::copy(values.begin(), values.end(), state.begin() + static_cast<std::ptrdiff_t>(section * cells));
}

std::vector<float> take(const std::vector<float>& state, std::size_t section, std::size_t cells, std::size_t count) {
  const auto first = state.begin() + static_cast<std::ptrdiff_t>(section * cells);
  return {first, first + static_cast<std::ptrdiff_t>(count)};
}

}  // namespace

LayeredWaterBuffers::LayeredWaterBuffers(const LayeredGroundBuffers& ground, const LayeredWater<float>& water)
    : cells_(ground.shape().cells()),
      block_(make_block(ground.shape(), ground.params())),
      block_buffer_(UniformBuffer::from(block_)),
      state_(2 * water_sections * cells_ * sizeof(float)),
      records_(water_record_floats * cells_ * sizeof(float)) {
  upload(water);
}

void LayeredWaterBuffers::upload(const LayeredWater<float>& water) {
  check_layered_water(water, cells_);
  std::vector<float> state(water_sections * cells_, 0.0f);
  put(state, water_section, cells_, water.water);
  put(state, previous_section, cells_, water.previous_water);
  put(state, wetness_section, cells_, water.wetness);
  put(state, flux_section, cells_, water.water_flux);
  put(state, carried_section, cells_, water.carried);
  state_.upload(state.data(), state.size() * sizeof(float));
}

LayeredWater<float> LayeredWaterBuffers::download() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto state = state_.download<float>(water_sections * cells_);
  LayeredWater<float> water;
  water.water = take(state, water_section, cells_, cells_);
  water.previous_water = take(state, previous_section, cells_, cells_);
  water.wetness = take(state, wetness_section, cells_, cells_);
  water.water_flux = take(state, flux_section, cells_, water_pipe_count * cells_);
  water.carried = take(state, carried_section, cells_, carried_kind_count * cells_);
  return water;
}

void LayeredWaterBuffers::bind() const {
  block_buffer_.bind(block_binding);
  state_.bind(state_binding);
  records_.bind(records_binding);
}

void LayeredWaterBuffers::snapshot() const {
  const auto half = static_cast<GLsizeiptr>(state_.size_bytes() / 2);
  glCopyNamedBufferSubData(state_.id(), state_.id(), 0, half, half);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void LayeredWaterBuffers::snapshot_surface(const LayeredGroundBuffers& ground) const {
  const auto bytes = static_cast<GLsizeiptr>(cells_ * sizeof(float));
  glCopyNamedBufferSubData(ground.surface_buffer().id(), state_.id(), 0,
                           static_cast<GLintptr>(surface_section * cells_ * sizeof(float)), bytes);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

std::vector<float> LayeredWaterBuffers::records(std::size_t floats_per_column) const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return records_.download<float>(floats_per_column * cells_);
}

void count_erosion_records(const std::vector<float>& records, std::size_t cells, double area,
                           const ErosionRecordLayout& layout, bool count_breakdown, LayeredConversions& conversions) {
  for (std::size_t c = 0; c < cells; ++c) {
    const float* record = records.data() + c * layout.floats;
    for (std::size_t i = 0; i < fragment_size_count; ++i) {
      for (std::size_t j = i + 1; j < fragment_size_count && count_breakdown; ++j) {
        const float broken = record[layout.broken_at + fragment_size_count * j + i];
        if (!(broken > 0.0f)) continue;
        conversions.broken_from[j + 1] += static_cast<double>(broken) * area;
        conversions.broken_into[i + 1] += static_cast<double>(broken) * area;
      }
      const float eroded = record[layout.bedrock_at + i];
      if (!(eroded > 0.0f)) continue;
      const auto type = static_cast<std::size_t>(record[layout.type_at + layout.type_stride * i]);
      conversions.bedrock_eroded_from.at(type) += static_cast<double>(eroded) * area;
      conversions.bedrock_eroded_into[i + 1] += static_cast<double>(eroded) * area;
    }
  }
}

ComputeProgram layered_water_program(const std::string& shader, const std::vector<std::string>& defines) {
  ComputeProgram program = layered_program(shader, defines);
  program.check_block("LayeredWaterBlock", sizeof(LayeredWaterBlock),
                      {{"pipe_coefficient", offsetof(LayeredWaterBlock, pipe_coefficient)},
                       {"breakdown_slopes", offsetof(LayeredWaterBlock, breakdown_slopes)},
                       {"breakdown_thresholds", offsetof(LayeredWaterBlock, breakdown_thresholds)},
                       {"cell_area", offsetof(LayeredWaterBlock, cell_area)},
                       {"rain_depth", offsetof(LayeredWaterBlock, rain_depth)},
                       {"river_depth", offsetof(LayeredWaterBlock, river_depth)},
                       {"river", offsetof(LayeredWaterBlock, river)},
                       {"river_source", offsetof(LayeredWaterBlock, river_source)},
                       {"sink_row_start", offsetof(LayeredWaterBlock, sink_row_start)},
                       {"velocity_depth_floor", offsetof(LayeredWaterBlock, velocity_depth_floor)},
                       {"depth_ramp", offsetof(LayeredWaterBlock, depth_ramp)},
                       {"slope_floor", offsetof(LayeredWaterBlock, slope_floor)},
                       {"slope_scale_x", offsetof(LayeredWaterBlock, slope_scale_x)},
                       {"slope_scale_y", offsetof(LayeredWaterBlock, slope_scale_y)},
                       {"cell_size_x", offsetof(LayeredWaterBlock, cell_size_x)},
                       {"cell_size_y", offsetof(LayeredWaterBlock, cell_size_y)},
                       {"erosion_strength", offsetof(LayeredWaterBlock, erosion_strength)},
                       {"organic_capacity", offsetof(LayeredWaterBlock, organic_capacity)},
                       {"erosion_rate", offsetof(LayeredWaterBlock, erosion_rate)},
                       {"deposition_rate", offsetof(LayeredWaterBlock, deposition_rate)},
                       {"vegetation_protection", offsetof(LayeredWaterBlock, vegetation_protection)},
                       {"breakdown_code", offsetof(LayeredWaterBlock, breakdown_code)},
                       {"share_code", offsetof(LayeredWaterBlock, share_code)},
                       {"least_share", offsetof(LayeredWaterBlock, least_share)},
                       {"transparency_depth", offsetof(LayeredWaterBlock, transparency_depth)},
                       {"regolith_depth", offsetof(LayeredWaterBlock, regolith_depth)},
                       {"regolith_erosion", offsetof(LayeredWaterBlock, regolith_erosion)},
                       {"regolith_deposition", offsetof(LayeredWaterBlock, regolith_deposition)},
                       {"drying_factor", offsetof(LayeredWaterBlock, drying_factor)},
                       {"flood_wetness", offsetof(LayeredWaterBlock, flood_wetness)},
                       {"impact_scale", offsetof(LayeredWaterBlock, impact_scale)},
                       {"sediment_diffusion", offsetof(LayeredWaterBlock, sediment_diffusion)},
                       {"diffusion_water", offsetof(LayeredWaterBlock, diffusion_water)},
                       {"regolith_diffusion", offsetof(LayeredWaterBlock, regolith_diffusion)},
                       {"rain_steps", offsetof(LayeredWaterBlock, rain_steps)},
                       {"drain_step", offsetof(LayeredWaterBlock, drain_step)}});
  return program;
}

LayeredWaterPass::LayeredWaterPass(const std::string& shader) : program_(layered_water_program(shader)) {}

void LayeredWaterPass::step(LayeredGroundBuffers& ground, const LayeredWaterBuffers& water, std::uint32_t step) const {
  water.bind();
  ground.dispatch_pass(program_, step);
}

}  // namespace gt::gpu
