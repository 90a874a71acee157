#include "gpu/memory/copy_bandwidth.hpp"

#include <numeric>
#include <stdexcept>

#include "gpu/cave/linear_dispatch.hpp"

namespace gt::gpu {
namespace {

constexpr int local_size = 256;

StorageBuffer indices(std::size_t elements) {
  std::vector<float> values(elements);
  std::iota(values.begin(), values.end(), 0.0f);
  return StorageBuffer::from(values);
}

std::size_t checked(std::size_t elements) {
  if (elements == 0 || elements % 4 != 0) {
    throw std::invalid_argument("CopyKernel: the element count must be a positive multiple of 4 (vec4 copies)");
  }
  return elements;
}

}  // namespace

CopyKernel::CopyKernel(std::size_t elements)
    : elements_(checked(elements)),
      program_(ComputeProgram::load("memory/copy.comp")),
      source_(indices(elements)),
      target_(elements * sizeof(float)) {}

void CopyKernel::run() const {
  program_.use();
  glUniform1ui(program_.uniform("vector_count"), static_cast<GLuint>(elements_ / 4));
  source_.bind(0);
  target_.bind(1);
  dispatch_linear(program_, elements_ / 4, local_size);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace gt::gpu
