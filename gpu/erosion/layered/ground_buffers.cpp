// Host side of the layered ground on the GPU: buffers, the parameter block, one compute-then-apply
// step, the conversion sums and the slope processes' programs (see ground_buffers.hpp; shaders in
// gpu/shaders/erosion/layered/).
#include "gpu/erosion/layered/ground_buffers.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

// Mirror of `BedrockTypeRecord` (std430: a vec4, two floats, three vec4 from 32; 80 bytes).
struct BedrockTypeRecord {
  float fragments[4];
  float repose_tan;
  float soil_rate;
  float padding[2];
  float soil_composition_a[4];
  float erosion_slopes[4];
  float erosion_thresholds[4];
};

// Mirror of `ColumnConversion` in apply.comp (std430: a vec4, a float, an int, padded to 32 bytes).
struct ColumnConversion {
  float fragmented_into[4];  // sand .. boulders, m
  float fragmented_from;     // m
  std::int32_t from_type;
  std::int32_t padding[2];
};

// apply.comp: a program of layered.glsl whose Conversions records are also checked.
ComputeProgram apply_program(bool clear_vegetation) {
  ComputeProgram program = layered_program(
      "erosion/layered/apply.comp",
      clear_vegetation ? std::vector<std::string>{"LAYERED_CLEAR_VEGETATION"} : std::vector<std::string>{});
  program.check_block("Conversions", sizeof(ColumnConversion),
                      {{"conversions[0].fragmented_into", offsetof(ColumnConversion, fragmented_into)},
                       {"conversions[0].fragmented_from", offsetof(ColumnConversion, fragmented_from)},
                       {"conversions[0].from_type", offsetof(ColumnConversion, from_type)}});
  return program;
}

constexpr int local_size = 16;  // local_size_x/y of layered.glsl
// Bindings of layered.glsl and apply.comp: the block, then the storage buffers.
constexpr GLuint block_binding = 0, surface_binding = 1, soil_binding = 2, bedrock_binding = 3,
                 bedrock_type_binding = 4, vegetation_binding = 5, bedrock_types_binding = 6, outflows_binding = 7,
                 conversions_binding = 8;

LayeredBlock make_block(const LayeredGround<float>& ground, const LayeredParams& params) {
  LayeredBlock block{};
  for (int i = 0; i < 4; ++i) block.repose_tan_a[i] = static_cast<float>(params.repose_tan[static_cast<std::size_t>(i)]);
  for (int k = 0; k < layered_neighbour_count; ++k) {
    block.distance[k] = static_cast<float>(layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k));
  }
  block.grid_size[0] = ground.width;
  block.grid_size[1] = ground.height;
  block.bedrock_layer_count = ground.bedrock_layer_count;
  block.periodic = params.border == LayeredBorder::periodic ? 1 : 0;
  block.repose_boulders = static_cast<float>(params.repose_tan[4]);
  block.time_step = static_cast<float>(params.time_step);
  block.vegetation_repose = static_cast<float>(params.vegetation_repose);
  block.depth_factor = static_cast<float>(params.depth_factor);
  block.topsoil_max = static_cast<float>(params.topsoil_max);
  block.creep_rate = static_cast<float>(params.creep_rate);
  block.critical_slope = static_cast<float>(params.critical_slope);
  block.creep_denominator_floor = static_cast<float>(params.creep_denominator_floor);
  block.random_base = static_cast<float>(0.9);
  block.random_span = static_cast<float>(0.1);
  block.seed = params.seed;
  block.talus_thesis_amount = params.talus_amount == TalusAmount::thesis ? 1 : 0;
  block.talus_random = params.talus_random ? 1 : 0;
  block.creep_random = params.creep_random ? 1 : 0;
  block.creep_floored = params.creep_denominator == CreepDenominator::seed001_code ? 1 : 0;
  for (int i = 0; i < 4; ++i) {
    block.vegetation_quality_a[i] = static_cast<float>(params.vegetation_soil_quality[static_cast<std::size_t>(i)]);
    block.weathering_shares[i] = static_cast<float>(params.weathering_shares[static_cast<std::size_t>(i)]);
  }
  block.vegetation_quality_boulders = static_cast<float>(params.vegetation_soil_quality[4]);
  block.vegetation_rate = static_cast<float>(params.vegetation_rate);
  block.vegetation_equilibrium = static_cast<float>(params.vegetation_equilibrium);
  block.vegetation_neighbours = static_cast<float>(params.vegetation_neighbours);
  block.root_depth = static_cast<float>(params.root_depth);
  block.root_depth_deep = static_cast<float>(params.root_depth_deep);
  block.vegetation_base = static_cast<float>(params.vegetation_base);
  block.vegetation_code = params.vegetation_quality == VegetationQuality::seed001_code ? 1 : 0;
  block.weathering_rate = static_cast<float>(params.weathering_rate);
  block.weathering_reach = static_cast<float>(params.weathering_reach);
  return block;
}

std::vector<BedrockTypeRecord> type_records(const LayeredParams& params) {
  std::vector<BedrockTypeRecord> records;
  for (const auto& type : params.bedrock_types) {
    BedrockTypeRecord record{};
    for (int size = 0; size < fragment_size_count; ++size) {
      record.fragments[size] = static_cast<float>(type.fragments[static_cast<std::size_t>(size)]);
    }
    record.repose_tan = static_cast<float>(type.repose_tan);
    record.soil_rate = static_cast<float>(type.soil_rate);
    for (int i = 0; i < 4; ++i) {
      const auto k = static_cast<std::size_t>(i);
      record.soil_composition_a[i] = static_cast<float>(type.soil_composition[k]);
      record.erosion_slopes[i] = static_cast<float>(type.erosion_slopes[k]);
      record.erosion_thresholds[i] = static_cast<float>(type.erosion_thresholds[k]);
    }
    records.push_back(record);
  }
  return records;
}

LayeredGround<float> validated_shape(const LayeredGround<float>& ground, const LayeredParams& params) {
  validate_layered_params(params);
  check_layered_ground(ground, params);
  LayeredGround<float> shape;
  shape.width = ground.width;
  shape.height = ground.height;
  shape.cell_size_x = ground.cell_size_x;
  shape.cell_size_y = ground.cell_size_y;
  shape.bedrock_layer_count = ground.bedrock_layer_count;
  return shape;
}

template <class T>
std::size_t bytes_of(const std::vector<T>& values) {
  return values.size() * sizeof(T);
}

// The bedrock types layer-major with the bottom layer first (the ground holds the top one first):
// mutant erosion.layered.gpu_types_layers_reversed's upload.
std::vector<std::int32_t> types_bottom_layer_first(const LayeredGround<float>& ground) {
  std::vector<std::int32_t> reversed;
  reversed.reserve(ground.bedrock_type.size());
  for (int layer = ground.bedrock_layer_count - 1; layer >= 0; --layer) {
    for (std::size_t c = 0; c < ground.cells(); ++c) reversed.push_back(ground.bedrock_type_at(layer, c));
  }
  return reversed;
}

}  // namespace

ComputeProgram layered_program(const std::string& shader, const std::vector<std::string>& defines) {
  ComputeProgram program = ComputeProgram::load(shader, defines);
  program.check_block("LayeredBlock", sizeof(LayeredBlock),
                      {{"repose_tan_a", offsetof(LayeredBlock, repose_tan_a)},
                       {"distance_a", offsetof(LayeredBlock, distance)},
                       {"distance_b", offsetof(LayeredBlock, distance) + 4 * sizeof(float)},
                       {"grid_size", offsetof(LayeredBlock, grid_size)},
                       {"bedrock_layer_count", offsetof(LayeredBlock, bedrock_layer_count)},
                       {"periodic", offsetof(LayeredBlock, periodic)},
                       {"repose_boulders", offsetof(LayeredBlock, repose_boulders)},
                       {"time_step", offsetof(LayeredBlock, time_step)},
                       {"vegetation_repose", offsetof(LayeredBlock, vegetation_repose)},
                       {"depth_factor", offsetof(LayeredBlock, depth_factor)},
                       {"topsoil_max", offsetof(LayeredBlock, topsoil_max)},
                       {"creep_rate", offsetof(LayeredBlock, creep_rate)},
                       {"critical_slope", offsetof(LayeredBlock, critical_slope)},
                       {"creep_denominator_floor", offsetof(LayeredBlock, creep_denominator_floor)},
                       {"random_base", offsetof(LayeredBlock, random_base)},
                       {"random_span", offsetof(LayeredBlock, random_span)},
                       {"seed", offsetof(LayeredBlock, seed)},
                       {"step_number", offsetof(LayeredBlock, step_number)},
                       {"talus_thesis_amount", offsetof(LayeredBlock, talus_thesis_amount)},
                       {"talus_random", offsetof(LayeredBlock, talus_random)},
                       {"creep_random", offsetof(LayeredBlock, creep_random)},
                       {"creep_floored", offsetof(LayeredBlock, creep_floored)},
                       {"vegetation_quality_a", offsetof(LayeredBlock, vegetation_quality_a)},
                       {"weathering_shares", offsetof(LayeredBlock, weathering_shares)},
                       {"vegetation_quality_boulders", offsetof(LayeredBlock, vegetation_quality_boulders)},
                       {"vegetation_rate", offsetof(LayeredBlock, vegetation_rate)},
                       {"vegetation_equilibrium", offsetof(LayeredBlock, vegetation_equilibrium)},
                       {"vegetation_neighbours", offsetof(LayeredBlock, vegetation_neighbours)},
                       {"root_depth", offsetof(LayeredBlock, root_depth)},
                       {"root_depth_deep", offsetof(LayeredBlock, root_depth_deep)},
                       {"vegetation_base", offsetof(LayeredBlock, vegetation_base)},
                       {"vegetation_code", offsetof(LayeredBlock, vegetation_code)},
                       {"weathering_rate", offsetof(LayeredBlock, weathering_rate)},
                       {"weathering_reach", offsetof(LayeredBlock, weathering_reach)}});
  program.check_block("BedrockTypes", sizeof(BedrockTypeRecord),
                      {{"bedrock_types[0].fragments", offsetof(BedrockTypeRecord, fragments)},
                       {"bedrock_types[0].repose_tan", offsetof(BedrockTypeRecord, repose_tan)},
                       {"bedrock_types[0].soil_rate", offsetof(BedrockTypeRecord, soil_rate)},
                       {"bedrock_types[0].soil_composition_a", offsetof(BedrockTypeRecord, soil_composition_a)},
                       {"bedrock_types[0].erosion_slopes", offsetof(BedrockTypeRecord, erosion_slopes)},
                       {"bedrock_types[0].erosion_thresholds", offsetof(BedrockTypeRecord, erosion_thresholds)}});
  return program;
}

LayeredGroundBuffers::LayeredGroundBuffers(const LayeredGround<float>& ground, const LayeredParams& params)
    : params_(params),
      shape_(validated_shape(ground, params)),
      block_(make_block(ground, params)),
      block_buffer_(UniformBuffer::from(block_)),
      surface_(bytes_of(ground.surface)),
      soil_(2 * bytes_of(ground.soil)),
      bedrock_(2 * bytes_of(ground.bedrock)),
      bedrock_type_(bytes_of(ground.bedrock_type)),
      vegetation_(bytes_of(ground.vegetation)),
      bedrock_types_(StorageBuffer::from(type_records(params))),
      outflows_(ground.cells() * layered_neighbour_count * sizeof(float)),
      conversions_(ground.cells() * sizeof(ColumnConversion)) {
  upload(ground);
}

void LayeredGroundBuffers::upload(const LayeredGround<float>& ground) {
  if (ground.width != shape_.width || ground.height != shape_.height ||
      ground.bedrock_layer_count != shape_.bedrock_layer_count) {
    throw std::invalid_argument("LayeredGroundBuffers::upload: the ground's size differs from the buffers'");
  }
  check_layered_ground(ground, params_);
  surface_.upload(ground.surface.data(), bytes_of(ground.surface));
  soil_.upload(ground.soil.data(), bytes_of(ground.soil));
  bedrock_.upload(ground.bedrock.data(), bytes_of(ground.bedrock));
  if (mutant_active("erosion.layered.gpu_types_layers_reversed")) {
    const std::vector<std::int32_t> reversed = types_bottom_layer_first(ground);
    bedrock_type_.upload(reversed.data(), bytes_of(reversed));
  } else {
    bedrock_type_.upload(ground.bedrock_type.data(), bytes_of(ground.bedrock_type));
  }
  vegetation_.upload(ground.vegetation.data(), bytes_of(ground.vegetation));
}

LayeredGround<float> LayeredGroundBuffers::download() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  LayeredGround<float> ground = shape_;
  const std::size_t cells = ground.cells();
  const auto bedrock_cells = cells * static_cast<std::size_t>(ground.bedrock_layer_count);
  ground.surface = surface_.download<float>(cells);
  ground.soil = soil_.download<float>(cells * soil_layer_count * soil_component_count);
  ground.bedrock = bedrock_.download<float>(bedrock_cells);
  ground.bedrock_type = bedrock_type_.download<std::int32_t>(bedrock_cells);
  ground.vegetation = vegetation_.download<float>(cells);
  return ground;
}

void LayeredGroundBuffers::bind() const {
  block_buffer_.bind(block_binding);
  surface_.bind(surface_binding);
  soil_.bind(soil_binding);
  bedrock_.bind(bedrock_binding);
  bedrock_type_.bind(bedrock_type_binding);
  vegetation_.bind(vegetation_binding);
  bedrock_types_.bind(bedrock_types_binding);
  outflows_.bind(outflows_binding);
  conversions_.bind(conversions_binding);
}

void LayeredGroundBuffers::compute_then_apply(const ComputeProgram& outflow, const ComputeProgram& apply,
                                              std::uint32_t step, LayeredConversions& conversions) {
  block_.step_number = step;
  block_buffer_.upload(block_);
  const auto soil_half = static_cast<GLsizeiptr>(soil_.size_bytes() / 2);
  const auto bedrock_half = static_cast<GLsizeiptr>(bedrock_.size_bytes() / 2);
  glCopyNamedBufferSubData(soil_.id(), soil_.id(), 0, soil_half, soil_half);
  glCopyNamedBufferSubData(bedrock_.id(), bedrock_.id(), 0, bedrock_half, bedrock_half);
  bind();
  outflow.dispatch(shape_.width, shape_.height, local_size, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  apply.dispatch(shape_.width, shape_.height, local_size, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  add_conversions(conversions);
}

void LayeredGroundBuffers::dispatch_pass(const ComputeProgram& pass, std::uint32_t step) {
  block_.step_number = step;
  block_buffer_.upload(block_);
  bind();
  pass.dispatch(shape_.width, shape_.height, local_size, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void LayeredGroundBuffers::add_conversions(LayeredConversions& conversions) const {
  conversions.fragmented_from.resize(std::max(conversions.fragmented_from.size(), params_.bedrock_types.size()), 0.0);
  const double area = shape_.cell_size_x * shape_.cell_size_y;
  for (const ColumnConversion& column : conversions_.download<ColumnConversion>(shape_.cells())) {
    if (column.fragmented_from > 0.0f) {
      conversions.fragmented_from.at(static_cast<std::size_t>(column.from_type)) +=
          static_cast<double>(column.fragmented_from) * area;
    }
    for (int size = 0; size < fragment_size_count; ++size) {
      conversions.fragmented_into[static_cast<std::size_t>(size + 1)] +=
          static_cast<double>(column.fragmented_into[size]) * area;
    }
  }
}

LayeredSlopeProcess::LayeredSlopeProcess(const std::string& outflow_shader, bool clear_vegetation)
    : outflow_(layered_program(outflow_shader)), apply_(apply_program(clear_vegetation)) {}

void LayeredSlopeProcess::step(LayeredGroundBuffers& ground, std::uint32_t step,
                               LayeredConversions& conversions) const {
  ground.compute_then_apply(outflow_, apply_, step, conversions);
}

}  // namespace gt::gpu
