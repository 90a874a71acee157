// Host side of seed 000's thermal erosion on the GPU: buffers, the std140 parameter block and the
// two dispatches per iteration. The algorithm and its decisions are described in
// reference/erosion/thermal.cpp and gpu/shaders/erosion/thermal_requests.comp.
//
// Memory traffic per cell and iteration (the performance table's floor column): 2 dispatches,
// 32 B read + 20 B written = 52 B (heights f32 and valid u32 read by both, requests vec4 written
// then read, next heights f32 written).
#include "gpu/erosion/thermal.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "core/mutant.hpp"

namespace gt::gpu {
namespace {

// Mirror of `ThermalBlock` in gpu/shaders/erosion/thermal_block.glsl (std140).
struct ThermalBlock {
  float talus_limit[4];
  std::int32_t pipe_dx[4];
  std::int32_t pipe_dy[4];
  std::int32_t grid_size[2];
  float request_factor;
  std::uint32_t clamp_unit;
};

// A program of thermal_block.glsl, its ThermalBlock checked against the mirror.
ComputeProgram thermal_program(const char* shader) {
  ComputeProgram program = ComputeProgram::load(shader);
  program.check_block("ThermalBlock", sizeof(ThermalBlock),
                      {{"talus_limit", offsetof(ThermalBlock, talus_limit)},
                       {"pipe_dx", offsetof(ThermalBlock, pipe_dx)},
                       {"pipe_dy", offsetof(ThermalBlock, pipe_dy)},
                       {"grid_size", offsetof(ThermalBlock, grid_size)},
                       {"request_factor", offsetof(ThermalBlock, request_factor)},
                       {"clamp_unit", offsetof(ThermalBlock, clamp_unit)}});
  return program;
}

constexpr int local_size = 16;  // local_size_x/y of thermal_block.glsl
constexpr GLuint block_binding = 0, requests_binding = 3;  // heights: see HeightfieldBuffers

// T, or under mutant erosion.thermal.talus_degree_off the slope of an angle one degree steeper
// (a parameter misapplied in both twins: the shader receives T·l from here).
double applied_talus_slope(const ThermalConstants& constants) {
  if (!mutant_active("erosion.thermal.talus_degree_off")) return constants.talus_slope;
  return std::tan(std::atan(constants.talus_slope) + std::numbers::pi / 180.0);
}

// T·l rounded once from double, as the reference does.
ThermalBlock make_block(const ThermalConstants& constants, bool cardinal, int width, int height) {
  ThermalBlock block{};
  const double talus_slope = applied_talus_slope(constants);
  const float limit_x = static_cast<float>(talus_slope * constants.length_x);
  const float limit_y = static_cast<float>(talus_slope * constants.length_y);
  const float limit_diagonal = static_cast<float>(talus_slope * constants.length_diagonal);
  const int cardinal_dx[4] = {-1, 0, 1, 0}, cardinal_dy[4] = {0, 1, 0, -1};
  const int diagonal_dx[4] = {-1, -1, 1, 1}, diagonal_dy[4] = {-1, 1, 1, -1};
  for (int k = 0; k < 4; ++k) {
    block.talus_limit[k] = cardinal ? (k % 2 == 0 ? limit_x : limit_y) : limit_diagonal;
    block.pipe_dx[k] = cardinal ? cardinal_dx[k] : diagonal_dx[k];
    block.pipe_dy[k] = cardinal ? cardinal_dy[k] : diagonal_dy[k];
  }
  block.grid_size[0] = width;
  block.grid_size[1] = height;
  block.request_factor = static_cast<float>(constants.request_factor);
  block.clamp_unit = constants.clamp_unit ? 1u : 0u;
  return block;
}

UniformBuffer block_buffer(const ThermalBlock& block) {
  UniformBuffer buffer(sizeof(ThermalBlock));
  buffer.upload(&block, sizeof(ThermalBlock));
  return buffer;
}

}  // namespace

ThermalErosion::ThermalErosion(int width, int height, const ThermalConstants& constants, Neighbourhood neighbourhood,
                               int iterations)
    : neighbourhood_(neighbourhood),
      iterations_(iterations),
      requests_program_(thermal_program("erosion/thermal_requests.comp")),
      transfer_program_(thermal_program("erosion/thermal_transfer.comp")),
      cardinal_block_(block_buffer(make_block(constants, true, width, height))),
      diagonal_block_(block_buffer(make_block(constants, false, width, height))),
      requests_(static_cast<std::size_t>(width) * height * 4 * sizeof(float)),
      heights_(width, height) {}

void ThermalErosion::load(const Grid<float>& heights) { heights_.load(heights); }

void ThermalErosion::run() { step(0, iterations_); }

void ThermalErosion::step(int first_iteration, int count) {
  requests_.bind(requests_binding);
  for (int iteration = first_iteration; iteration < first_iteration + count; ++iteration) {
    const bool cardinal = neighbourhood_ == Neighbourhood::cardinal ||
                          (neighbourhood_ == Neighbourhood::alternating && iteration % 2 == 0);
    (cardinal ? cardinal_block_ : diagonal_block_).bind(block_binding);
    heights_.iterate(requests_program_, transfer_program_, local_size);
  }
}

Grid<float> ThermalErosion::result() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return heights_.current();
}

}  // namespace gt::gpu
