// Host side of the GPU central-difference normals: the parameter block, the buffers, one dispatch.
// The formula and its operation order are in gpu/shaders/cave/central_normals.comp.
#include "gpu/cave/normals.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "core/noise/permutation.hpp"
#include "gpu/buffer.hpp"
#include "gpu/cave/linear_dispatch.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {
namespace {

// Mirror of `CaveNormalsBlock` in gpu/shaders/cave/central_normals.comp (std140).
struct CaveNormalsBlock {
  std::uint32_t vertex_count;
  float step;
  float world_to_noise;
  float kernel_radius_squared;
};

constexpr int local_size = 256;
constexpr GLuint block_binding = 0, positions_binding = 1, normals_binding = 2, permutation_binding = 5;

ComputeProgram normals_program() {
  ComputeProgram program = ComputeProgram::load("cave/central_normals.comp");
  program.check_block("CaveNormalsBlock", sizeof(CaveNormalsBlock),
                      {{"vertex_count", offsetof(CaveNormalsBlock, vertex_count)},
                       {"step", offsetof(CaveNormalsBlock, step)},
                       {"world_to_noise", offsetof(CaveNormalsBlock, world_to_noise)},
                       {"kernel_radius_squared", offsetof(CaveNormalsBlock, kernel_radius_squared)}});
  return program;
}

}  // namespace

std::vector<std::array<float, 3>> central_difference_normals(const std::vector<std::array<float, 3>>& positions,
                                                             const CaveParams& params, double step) {
  if (positions.empty()) return {};
  const ComputeProgram program = normals_program();
  const CaveNormalsBlock block{.vertex_count = static_cast<std::uint32_t>(positions.size()),
                               .step = static_cast<float>(step),
                               .world_to_noise = static_cast<float>(1.0 / params.scale),
                               .kernel_radius_squared = static_cast<float>(params.kernel_radius_squared)};
  const UniformBuffer uniforms = UniformBuffer::from(block);
  const std::size_t bytes = positions.size() * sizeof(positions[0]);
  const std::int64_t limit = storage_block_limit();
  const std::string what = fmt::format("GPU cave normals: {} vertices", positions.size());
  StorageBuffer position_buffer = limited_storage(bytes, what, limit);
  position_buffer.upload(positions.data(), bytes);
  const StorageBuffer normal_buffer = limited_storage(bytes, what, limit);
  const StorageBuffer permutation = StorageBuffer::from(doubled_permutation(seeded_permutation(params.seed)));
  uniforms.bind(block_binding);
  position_buffer.bind(positions_binding);
  normal_buffer.bind(normals_binding);
  permutation.bind(permutation_binding);
  dispatch_linear(program, positions.size(), local_size);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const std::vector<float> flat = normal_buffer.download<float>(positions.size() * 3);
  std::vector<std::array<float, 3>> normals(positions.size());
  for (std::size_t v = 0; v < positions.size(); ++v) normals[v] = {flat[3 * v], flat[3 * v + 1], flat[3 * v + 2]};
  return normals;
}

}  // namespace gt::gpu
