// Host side of Jákó & Tóth's thermal erosion on the GPU: buffers, the std140 parameter block and
// the two dispatches per iteration. The algorithm and its decisions are described in
// reference/erosion/thermal_jako.cpp.
//
// Memory traffic per cell and iteration (the performance table's floor column): 2 dispatches,
// 48 B read + 36 B written = 84 B (heights f32 and valid u32 read by both, outflows 2 × vec4
// written then read, next heights f32 written).
#include "gpu/erosion/thermal_jako.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

// Mirror of `ThermalJakoBlock` in gpu/shaders/erosion/thermal_jako_block.glsl (std140).
struct ThermalJakoBlock {
  float talus_limit_cardinal[4];
  float talus_limit_diagonal[4];
  std::int32_t grid_size[2];
  float rate;
  float padding;
};

// A program of thermal_jako_block.glsl, its ThermalJakoBlock checked against the mirror.
ComputeProgram thermal_jako_program(const char* shader) {
  ComputeProgram program = ComputeProgram::load(shader);
  program.check_block("ThermalJakoBlock", sizeof(ThermalJakoBlock),
                      {{"talus_limit_cardinal", offsetof(ThermalJakoBlock, talus_limit_cardinal)},
                       {"talus_limit_diagonal", offsetof(ThermalJakoBlock, talus_limit_diagonal)},
                       {"grid_size", offsetof(ThermalJakoBlock, grid_size)},
                       {"rate", offsetof(ThermalJakoBlock, rate)}});
  return program;
}

constexpr int local_size = 16;  // local_size_x/y of thermal_jako_block.glsl
constexpr GLuint block_binding = 0, outflows_binding = 3;  // heights: see HeightfieldBuffers

// T, or under mutant erosion.thermal_jako.talus_degree_off the slope of an angle one degree steeper
// (a parameter misapplied in both twins: the shader receives T·l from here).
double applied_talus_slope(const ThermalConstants& constants) {
  if (!mutant_active("erosion.thermal_jako.talus_degree_off")) return constants.talus_slope;
  return std::tan(std::atan(constants.talus_slope) + std::numbers::pi / 180.0);
}

// T·l rounded once from double, as the reference does.
UniformBuffer block_buffer(const ThermalConstants& constants, int width, int height) {
  ThermalJakoBlock block{};
  const double talus_slope = applied_talus_slope(constants);
  const float limit_x = static_cast<float>(talus_slope * constants.length_x);
  const float limit_y = static_cast<float>(talus_slope * constants.length_y);
  const float limit_diagonal = static_cast<float>(talus_slope * constants.length_diagonal);
  for (int k = 0; k < 4; ++k) {
    block.talus_limit_cardinal[k] = k % 2 == 0 ? limit_x : limit_y;
    block.talus_limit_diagonal[k] = limit_diagonal;
  }
  block.grid_size[0] = width;
  block.grid_size[1] = height;
  block.rate = static_cast<float>(constants.request_factor);
  UniformBuffer buffer(sizeof(ThermalJakoBlock));
  buffer.upload(&block, sizeof(ThermalJakoBlock));
  return buffer;
}

}  // namespace

ThermalJakoErosion::ThermalJakoErosion(int width, int height, const ThermalConstants& constants, int iterations)
    : iterations_(iterations),
      outflow_program_(thermal_jako_program("erosion/thermal_jako_outflow.comp")),
      gather_program_(thermal_jako_program("erosion/thermal_jako_gather.comp")),
      block_(block_buffer(constants, width, height)),
      outflows_(static_cast<std::size_t>(width) * height * 8 * sizeof(float)),
      heights_(width, height) {}

void ThermalJakoErosion::load(const Grid<float>& heights) { heights_.load(heights); }

void ThermalJakoErosion::run() { step(iterations_); }

void ThermalJakoErosion::step(int count) {
  block_.bind(block_binding);
  outflows_.bind(outflows_binding);
  for (int iteration = 0; iteration < count; ++iteration) {
    heights_.iterate(outflow_program_, gather_program_, local_size);
  }
}

Grid<float> ThermalJakoErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return heights_.current();
}

}  // namespace gt::gpu
