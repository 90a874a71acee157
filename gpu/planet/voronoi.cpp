// The GPU spherical Voronoi; see voronoi.hpp.
#include "gpu/planet/voronoi.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include <cstddef>

namespace gt::gpu {
namespace {

// Mirror of VoronoiBlock in voronoi.comp (std140).
struct VoronoiBlock {
  std::int32_t face_rows[18][4];
  std::int32_t resolution;
  std::int32_t direction_count;
  float warp_angle;
  float tan_warp_angle;
};

constexpr int local_size = 64;

ComputeProgram voronoi_program(int rings) {
  if (rings < 1 || rings > 2) throw std::invalid_argument(fmt::format("Voronoi search of {} rings: 1 or 2", rings));
  ComputeProgram program = ComputeProgram::load("planet/voronoi.comp", {fmt::format("SEARCH_RINGS={}", rings)});
  check_voronoi_block(program);
  return program;
}

}  // namespace

std::vector<float> padded_xyz(const std::vector<float>& xyz) {
  std::vector<float> result(xyz.size() / 3 * 4, 0.0f);
  for (std::size_t item = 0; item < xyz.size() / 3; ++item) {
    for (std::size_t axis = 0; axis < 3; ++axis) result[4 * item + axis] = xyz[3 * item + axis];
  }
  return result;
}

void check_voronoi_block(const GlProgram& program) {
  program.check_block("VoronoiBlock", sizeof(VoronoiBlock),
                      {{"face_rows", offsetof(VoronoiBlock, face_rows)},
                       {"resolution", offsetof(VoronoiBlock, resolution)},
                       {"direction_count", offsetof(VoronoiBlock, direction_count)},
                       {"warp_angle", offsetof(VoronoiBlock, warp_angle)},
                       {"tan_warp_angle", offsetof(VoronoiBlock, tan_warp_angle)}});
}

UniformBuffer voronoi_block(int resolution, std::size_t direction_count, CubeWarp cube_warp) {
  VoronoiBlock block{};
  for (int face = 0; face < cube_face_count; ++face) {
    const FaceMatrix& matrix = face_matrix(static_cast<CubeFace>(face));
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column) block.face_rows[3 * face + row][column] = matrix[row][column];
    }
  }
  block.resolution = resolution;
  block.direction_count = static_cast<std::int32_t>(direction_count);
  block.warp_angle = static_cast<float>(cube_warp.angle);
  block.tan_warp_angle = static_cast<float>(std::tan(cube_warp.angle));
  return UniformBuffer::from(block);
}

PlanetVoronoi::PlanetVoronoi(const CubeSphere& sphere, int rings, CubeWarp cube_warp)
    : resolution_(sphere.resolution()),
      warp_(cube_warp),
      region_count_(sphere.region_count()),
      program_(voronoi_program(rings)),
      neighbours_(StorageBuffer::from(sphere.neighbour_table())) {}

std::vector<std::int32_t> PlanetVoronoi::labels(const std::vector<float>& positions,
                                                const std::vector<Vector3<float>>& directions) {
  if (positions.size() != 3 * region_count_) {
    throw std::invalid_argument(fmt::format("Voronoi: {} position values for {} regions", positions.size(), region_count_));
  }
  if (directions.empty()) return {};
  const auto uniforms = voronoi_block(resolution_, directions.size(), warp_);
  std::vector<float> direction_values;
  for (const auto& direction : directions) direction_values.insert(direction_values.end(), direction.begin(), direction.end());
  const auto position_buffer = StorageBuffer::from(padded_xyz(positions));
  const auto direction_buffer = StorageBuffer::from(padded_xyz(direction_values));
  StorageBuffer label_buffer(directions.size() * sizeof(std::int32_t));
  uniforms.bind(0);
  neighbours_.bind(0);
  position_buffer.bind(1);
  direction_buffer.bind(2);
  label_buffer.bind(3);
  program_.dispatch(static_cast<int>(directions.size()), 1, local_size, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return label_buffer.download<std::int32_t>(directions.size());
}

}  // namespace gt::gpu
