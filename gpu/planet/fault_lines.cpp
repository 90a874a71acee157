// Host side of the fault-line planet: buffers, uniforms and one dispatch of fault_lines.comp.
#include "gpu/planet/fault_lines.hpp"

#include <stdexcept>
#include <string>

namespace gt::gpu {
namespace {

constexpr const char* shader = "planet/fault_lines.comp";
constexpr int local_size = 64;

enum Binding : GLuint { positions_binding = 1, normals_binding = 2, votes_binding = 3 };

void check_xyz(const std::vector<float>& values, const char* what) {
  if (values.empty() || values.size() % 3 != 0) {
    throw std::invalid_argument(std::string("FaultLines::votes: ") + what + " must be x, y, z per item, at least one");
  }
}

}  // namespace

FaultLines::FaultLines()
    : program_(ComputeProgram::load(shader)),
      region_count_location_(program_.required_uniform("region_count")),
      fault_count_location_(program_.required_uniform("fault_count")) {}

std::vector<std::int32_t> FaultLines::votes(const std::vector<float>& positions, const std::vector<float>& normals) {
  check_xyz(positions, "positions");
  check_xyz(normals, "normals");
  regions_ = positions.size() / 3;
  positions_.emplace(StorageBuffer::from(positions));
  normals_.emplace(StorageBuffer::from(normals));
  votes_.emplace(regions_ * sizeof(std::int32_t));
  glProgramUniform1ui(program_.id(), region_count_location_, static_cast<GLuint>(regions_));
  glProgramUniform1ui(program_.id(), fault_count_location_, static_cast<GLuint>(normals.size() / 3));
  run();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  return votes_->download<std::int32_t>(regions_);
}

void FaultLines::run() const {
  positions_->bind(positions_binding);
  normals_->bind(normals_binding);
  votes_->bind(votes_binding);
  program_.dispatch(static_cast<int>(regions_), 1, local_size, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace gt::gpu
