// Host side of Jákó & Tóth's thermal erosion on the GPU: buffers, the std140 parameter block and
// the two dispatches per iteration. The algorithm and its decisions are described in
// reference/erosion/thermal_jako.cpp.
//
// Memory traffic per cell and iteration (the performance table's floor column): 2 dispatches,
// 84 B read + 36 B written = 120 B (heights f32 and valid u32 read by both, the cell's 9 constants
// f32 by the outflow pass, outflows 2 × vec4 written then read, next heights f32 written).
#include "gpu/erosion/thermal_jako.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gt::gpu {
namespace {

// Mirror of `ThermalJakoBlock` in gpu/shaders/erosion/thermal_jako_block.glsl (std140).
struct ThermalJakoBlock {
  std::int32_t grid_size[2];
  std::int32_t padding[2];
};

// A program of thermal_jako_block.glsl, its ThermalJakoBlock checked against the mirror.
ComputeProgram thermal_jako_program(const char* shader) {
  ComputeProgram program = ComputeProgram::load(shader);
  program.check_block("ThermalJakoBlock", sizeof(ThermalJakoBlock), {{"grid_size", offsetof(ThermalJakoBlock, grid_size)}});
  return program;
}

constexpr int local_size = 16;  // local_size_x/y of thermal_jako_block.glsl
constexpr GLuint block_binding = 0, outflows_binding = 3, cell_constants_binding = 5;  // heights: HeightfieldBuffers
constexpr std::size_t floats_per_cell = 9;  // 8 thresholds, the rate (thermal_jako_block.glsl)

UniformBuffer block_buffer(int width, int height) {
  ThermalJakoBlock block{};
  block.grid_size[0] = width;
  block.grid_size[1] = height;
  UniformBuffer buffer(sizeof(ThermalJakoBlock));
  buffer.upload(&block, sizeof(ThermalJakoBlock));
  return buffer;
}

// Every cell's thresholds and rate, each rounded once from double, as the reference rounds them.
std::vector<float> rounded_cell_constants(const ThermalConstants& constants, int width, int height) {
  const auto exact = jako_cell_constants(constants, width, height);
  std::vector<float> rounded;
  rounded.reserve(exact.size() * floats_per_cell);
  for (const auto& cell : exact) {
    for (const double value : cell) rounded.push_back(static_cast<float>(value));
  }
  return rounded;
}

}  // namespace

ThermalJakoErosion::ThermalJakoErosion(int width, int height, const ThermalConstants& constants, int iterations)
    : width_(width),
      height_(height),
      iterations_(iterations),
      outflow_program_(thermal_jako_program("erosion/thermal_jako_outflow.comp")),
      gather_program_(thermal_jako_program("erosion/thermal_jako_gather.comp")),
      block_(block_buffer(width, height)),
      constants_(constants),
      cell_constants_(static_cast<std::size_t>(width) * height * floats_per_cell * sizeof(float)),
      outflows_(static_cast<std::size_t>(width) * height * 8 * sizeof(float)),
      heights_(width, height) {
  set_hardness(constants.hardness);
}

void ThermalJakoErosion::set_hardness(const std::vector<double>& hardness) {
  constants_.hardness = hardness;
  const std::vector<float> rounded = rounded_cell_constants(constants_, width_, height_);
  cell_constants_.upload(rounded.data(), rounded.size() * sizeof(float));
}

void ThermalJakoErosion::load(const Grid<float>& heights) { heights_.load(heights); }

void ThermalJakoErosion::run() { step(iterations_); }

void ThermalJakoErosion::step(int count) {
  block_.bind(block_binding);
  outflows_.bind(outflows_binding);
  cell_constants_.bind(cell_constants_binding);
  for (int iteration = 0; iteration < count; ++iteration) {
    heights_.iterate(outflow_program_, gather_program_, local_size);
  }
}

Grid<float> ThermalJakoErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return heights_.current();
}

}  // namespace gt::gpu
