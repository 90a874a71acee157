// Host side of Beneš's dissolution erosion on the GPU: buffers, the std140 parameter block and the
// three dispatches per iteration. The algorithm and its decisions are described in
// reference/erosion/dissolution.cpp.
//
// Memory traffic per cell and iteration (the performance table's floor column): the local pass
// reads 5 and writes 4 words (36 B), the outflow pass reads 3 and writes 8 (44 B), the gather reads
// 11 (valid, water, dissolved, 8 outflows) and writes 2 (52 B): 132 B, neighbours' values taken as
// cached.
#include "gpu/erosion/dissolution.hpp"

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "gpu/heightfield_buffers.hpp"

namespace gt::gpu {
namespace {

// Mirror of `DissolutionBlock` in gpu/shaders/erosion/dissolution_block.glsl (std140).
struct DissolutionBlock {
  std::int32_t grid_size[2];
  float rain;
  float retained;
  float threshold;
  float saturation;
  float dissolution_rate;
  float deposition_rate;
  std::int32_t mean_level;
  std::int32_t padding[3];  // std140 rounds the block up to a multiple of 16 bytes
};

// A program of dissolution_block.glsl, its DissolutionBlock checked against the mirror.
ComputeProgram dissolution_program(const char* shader) {
  ComputeProgram program = ComputeProgram::load(shader);
  program.check_block("DissolutionBlock", sizeof(DissolutionBlock),
                      {{"grid_size", offsetof(DissolutionBlock, grid_size)},
                       {"rain", offsetof(DissolutionBlock, rain)},
                       {"retained", offsetof(DissolutionBlock, retained)},
                       {"threshold", offsetof(DissolutionBlock, threshold)},
                       {"saturation", offsetof(DissolutionBlock, saturation)},
                       {"dissolution_rate", offsetof(DissolutionBlock, dissolution_rate)},
                       {"deposition_rate", offsetof(DissolutionBlock, deposition_rate)},
                       {"mean_level", offsetof(DissolutionBlock, mean_level)}});
  return program;
}

constexpr int local_size = 16;  // local_size_x/y of dissolution_block.glsl
constexpr GLuint block_binding = 0, terrain_binding = 1, valid_binding = 2, outflows_binding = 3,
                 water_binding = 4, dissolved_binding = 5, evaporated_binding = 6, next_water_binding = 7,
                 next_dissolved_binding = 8;

// The constants rounded once from double, as the reference does.
UniformBuffer block_buffer(const DissolutionConstants& constants, int width, int height) {
  const DissolutionBlock block{.grid_size = {width, height},
                               .rain = static_cast<float>(constants.rain),
                               .retained = static_cast<float>(constants.retained),
                               .threshold = static_cast<float>(constants.evaporation_threshold),
                               .saturation = static_cast<float>(constants.saturation),
                               .dissolution_rate = static_cast<float>(constants.dissolution_rate),
                               .deposition_rate = static_cast<float>(constants.deposition_rate),
                               .mean_level = constants.water_share == DissolutionShare::mean_level ? 1 : 0};
  UniformBuffer buffer(sizeof(DissolutionBlock));
  buffer.upload(&block, sizeof(DissolutionBlock));
  return buffer;
}

std::size_t float_bytes(int width, int height) { return static_cast<std::size_t>(width) * height * sizeof(float); }

void upload(StorageBuffer& buffer, const Grid<float>& field) {
  buffer.upload(field.values.data(), field.values.size() * sizeof(float));
}

Grid<float> download(const StorageBuffer& buffer, const Grid<float>& layout) {
  Grid<float> field = layout;
  field.values = buffer.download<float>(static_cast<std::size_t>(layout.width) * layout.height);
  return field;
}

}  // namespace

DissolutionErosion::DissolutionErosion(int width, int height, const DissolutionConstants& constants)
    : layout_(width, height),
      local_program_(dissolution_program("erosion/dissolution_local.comp")),
      outflow_program_(dissolution_program("erosion/dissolution_outflow.comp")),
      gather_program_(dissolution_program("erosion/dissolution_gather.comp")),
      block_(block_buffer(constants, width, height)),
      terrain_(float_bytes(width, height)),
      valid_(static_cast<std::size_t>(width) * height * sizeof(GLuint)),
      outflows_(float_bytes(width, height) * 8),
      evaporated_(float_bytes(width, height)),
      water_{StorageBuffer(float_bytes(width, height)), StorageBuffer(float_bytes(width, height))},
      dissolved_{StorageBuffer(float_bytes(width, height)), StorageBuffer(float_bytes(width, height))} {}

void DissolutionErosion::load(const DissolutionState<float>& state) {
  const Grid<float>& terrain = state.terrain;
  for (const Grid<float>* field : {&state.terrain, &state.water, &state.dissolved, &state.evaporated}) {
    if (field->width != layout_.width || field->height != layout_.height) {
      throw std::invalid_argument("DissolutionErosion::load: grid size differs from the buffers'");
    }
  }
  layout_ = terrain;
  layout_.values.clear();
  current_ = 0;
  upload(terrain_, terrain);
  upload(water_[0], state.water);
  upload(dissolved_[0], state.dissolved);
  upload(evaporated_, state.evaporated);
  upload_validity(valid_, terrain);
}

void DissolutionErosion::step(int count) {
  block_.bind(block_binding);
  terrain_.bind(terrain_binding);
  valid_.bind(valid_binding);
  outflows_.bind(outflows_binding);
  evaporated_.bind(evaporated_binding);
  for (int iteration = 0; iteration < count; ++iteration) {
    const int next = 1 - current_;
    water_[current_].bind(water_binding);
    dissolved_[current_].bind(dissolved_binding);
    water_[next].bind(next_water_binding);
    dissolved_[next].bind(next_dissolved_binding);
    for (const ComputeProgram* pass : {&local_program_, &outflow_program_, &gather_program_}) {
      pass->dispatch(layout_.width, layout_.height, local_size, local_size);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    current_ = next;
  }
}

DissolutionState<float> DissolutionErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return {.terrain = download(terrain_, layout_),
          .water = download(water_[current_], layout_),
          .dissolved = download(dissolved_[current_], layout_),
          .evaporated = download(evaporated_, layout_)};
}

}  // namespace gt::gpu
