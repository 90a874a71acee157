// Host side of the multi-level exclusive scan: block-sum buffers per level and the recursion of
// scan_blocks / scan_add dispatches; see exclusive_scan.hpp.
#include "gpu/cave/exclusive_scan.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "gpu/cave/linear_dispatch.hpp"

namespace gt::gpu {
namespace {

constexpr int local_size = 256;  // local_size_x of scan_blocks.comp and scan_add.comp (SCAN_GROUP_SIZE)
constexpr GLuint values_binding = 0, block_sums_binding = 1;

std::size_t block_count(std::size_t count) { return (count + scan_block_size - 1) / scan_block_size; }

// One buffer per level until a level fits in one block.
std::vector<StorageBuffer> block_sum_buffers(std::size_t max_count) {
  std::vector<StorageBuffer> levels;
  std::size_t count = max_count;
  do {
    count = std::max<std::size_t>(block_count(count), 1);
    levels.emplace_back(count * sizeof(GLuint));
  } while (count > 1);
  return levels;
}

void set_value_count(const ComputeProgram& program, std::size_t count) {
  glProgramUniform1ui(program.id(), program.uniform("value_count"), static_cast<GLuint>(count));
}

}  // namespace

ExclusiveScan::ExclusiveScan(std::size_t max_count)
    : max_count_(max_count),
      blocks_program_(ComputeProgram::load("cave/scan_blocks.comp")),
      add_program_(ComputeProgram::load("cave/scan_add.comp")),
      block_sums_(block_sum_buffers(max_count)) {}

void ExclusiveScan::run(const StorageBuffer& values, std::size_t count) const {
  if (count > max_count_) {
    throw std::invalid_argument(fmt::format("exclusive scan of {} values, set up for at most {}", count, max_count_));
  }
  if (count > 0) scan_level(values, count, 0);
}

void ExclusiveScan::scan_level(const StorageBuffer& values, std::size_t count, std::size_t level) const {
  const std::size_t blocks = block_count(count);
  const StorageBuffer& sums = block_sums_[level];
  values.bind(values_binding);
  sums.bind(block_sums_binding);
  set_value_count(blocks_program_, count);
  dispatch_linear(blocks_program_, blocks * static_cast<std::size_t>(local_size), local_size);
  if (blocks == 1) return;
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  scan_level(sums, blocks, level + 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  values.bind(values_binding);
  sums.bind(block_sums_binding);
  set_value_count(add_program_, count);
  dispatch_linear(add_program_, count, local_size);
}

}  // namespace gt::gpu
