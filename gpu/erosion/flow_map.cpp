// Host side of seed 000's flow map on the GPU (§4.7): buffers, the std140 parameter block and the
// dispatch loop. The kernel and its decisions are described in gpu/shaders/erosion/
// flow_map_droplets.comp and flow_map_plug.comp; the CPU reference is reference/erosion/flow_map.cpp.
//
// For oy, ox in [0, S)²: one dispatch of flow_map_droplets.comp over the ceil(W/S) x ceil(H/S)
// droplets with pass_offset = (ox, oy), then a storage barrier; after the last pass one dispatch of
// flow_map_plug.comp over the grid. Constants are rounded to float once here, the batch powers
// each from their double value.
#include "gpu/erosion/flow_map.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "gpu/erosion/droplet_host.hpp"

namespace gt::gpu {
namespace {

// Mirror of `FlowBlock` in gpu/shaders/erosion/flow_map_block.glsl (std140).
struct FlowBlock {
  DropletBlockHead head;
  std::uint32_t interpolated_flow;
  float acceleration;
  float max_velocity;
  float drag;
  float flow_factor;
  float no_limit;
  float batch_powers[32];  // vec4[8]
};

enum Binding : GLuint { block_binding = 0, heights_binding = 1, valid_binding = 2, flow_binding = 3, plugged_binding = 4 };

std::vector<std::string> program_defines(const FlowConstants& constants) {
  if (constants.ordering == DropletOrdering::batch) return {"FLOW_BATCH"};
  return {};
}

// A program of flow_map_block.glsl, its FlowBlock checked against the mirror.
ComputeProgram flow_program(const char* shader, const FlowConstants& constants) {
  ComputeProgram program = ComputeProgram::load(shader, program_defines(constants));
  program.check_block(
      "FlowBlock", sizeof(FlowBlock),
      droplet_block_layout(offsetof(FlowBlock, head), {{"interpolated_flow", offsetof(FlowBlock, interpolated_flow)},
                                                       {"acceleration", offsetof(FlowBlock, acceleration)},
                                                       {"max_velocity", offsetof(FlowBlock, max_velocity)},
                                                       {"drag", offsetof(FlowBlock, drag)},
                                                       {"flow_factor", offsetof(FlowBlock, flow_factor)},
                                                       {"no_limit", offsetof(FlowBlock, no_limit)},
                                                       {"batch_powers", offsetof(FlowBlock, batch_powers)}}));
  return program;
}

FlowBlock make_block(const FlowConstants& constants, int width, int height) {
  FlowBlock block{};
  block.head = droplet_block_head(width, height, constants.spacing, constants.lifetime, "FlowMap");
  block.interpolated_flow = constants.interpolate ? 1u : 0u;
  block.acceleration = static_cast<float>(constants.acceleration);
  block.max_velocity = static_cast<float>(constants.max_velocity);
  block.drag = static_cast<float>(constants.drag);
  block.flow_factor = static_cast<float>(constants.factor);
  block.no_limit = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < constants.batch_powers.size(); ++i) {
    block.batch_powers[i] = static_cast<float>(constants.batch_powers[i]);
  }
  return block;
}

}  // namespace

FlowMap::FlowMap(int width, int height, const FlowConstants& constants)
    : spacing_(checked_droplet_spacing(constants.spacing, "FlowMap")),
      droplets_x_(droplet_count(width, spacing_)),
      droplets_y_(droplet_count(height, spacing_)),
      layout_(empty_layout(width, height)),
      droplets_program_(flow_program("erosion/flow_map_droplets.comp", constants)),
      plug_program_(flow_program("erosion/flow_map_plug.comp", constants)),
      offset_location_(droplets_program_.required_uniform("pass_offset")),
      block_(UniformBuffer::from(make_block(constants, width, height))),
      heights_(cell_count(width, height) * sizeof(float)),
      valid_(cell_count(width, height) * sizeof(GLuint)),
      flow_(cell_count(width, height) * sizeof(float)),
      plugged_(cell_count(width, height) * sizeof(float)) {}

void FlowMap::load(const Grid<float>& heights) {
  layout_ = load_heightfield(heights, layout_.width, layout_.height, heights_, valid_, "FlowMap");
  const std::vector<std::int32_t> zeros(heights.size(), 0);  // float 0 and int 0 share their bits
  flow_.upload(zeros.data(), zeros.size() * sizeof(std::int32_t));
}

void FlowMap::run() const {
  block_.bind(block_binding);
  heights_.bind(heights_binding);
  valid_.bind(valid_binding);
  flow_.bind(flow_binding);
  plugged_.bind(plugged_binding);
  for (int offset_y = 0; offset_y < spacing_; ++offset_y) {
    for (int offset_x = 0; offset_x < spacing_; ++offset_x) {
      dispatch_droplet_pass(droplets_program_, offset_location_, offset_x, offset_y, droplets_x_, droplets_y_);
    }
  }
  dispatch_cell_pass(plug_program_, layout_.width, layout_.height);
}

Grid<float> FlowMap::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  Grid<float> flow = layout_;
  flow.values = plugged_.download<float>(cell_count(layout_.width, layout_.height));
  return flow;
}

}  // namespace gt::gpu
