// A multi-level exclusive prefix sum of uint values on the GPU, in place: the compaction step of the GPU mesher.
//
// The GPU marching tetrahedra classify, prefix-sum and emit; this is the prefix sum.
// Level l: gpu/shaders/cave/scan_blocks.comp scans blocks of 1024 values (256 invocations x 4, a
// Blelloch scan in shared memory) and writes each block's total to block sums l; when there is
// more than one block, the block sums are scanned the same way (level l + 1, recursively), then
// gpu/shaders/cave/scan_add.comp adds them back. 256³ values take three levels (16.8M -> 16,384 ->
// 16 -> 1). Integer addition, so the result is the same in any order: deterministic.
// ExclusiveScan(max_count) compiles both programs and allocates the block sums of every level for
//   up to max_count values.
// run(values, count) scans the first `count` uints of `values` without synchronising at the end:
//   callers issue glMemoryBarrier before reading.
//
// Inputs:  values: a storage buffer of uint, count <= max_count. Needs a current GlContext.
// Outputs: the exclusive prefix sums in place; sums wrap modulo 2^32.
// Units:   counts (dimensionless).
// Throws:  std::invalid_argument from run() for count > max_count; std::runtime_error when a shader
//          does not compile or link.
// Twin:    none: no reference of its own; the mesh it builds is compared with
//          reference/cave/marching_tetrahedra.hpp (gpu/cave/marching_tetrahedra.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "gpu/buffer.hpp"
#include "gpu/shader_program.hpp"

namespace gt::gpu {

// Values one workgroup of scan_blocks.comp scans (SCAN_BLOCK_SIZE of gpu/shaders/cave/scan.glsl).
inline constexpr std::size_t scan_block_size = 1024;

class ExclusiveScan {
 public:
  explicit ExclusiveScan(std::size_t max_count);
  void run(const StorageBuffer& values, std::size_t count) const;

 private:
  void scan_level(const StorageBuffer& values, std::size_t count, std::size_t level) const;

  std::size_t max_count_;
  ComputeProgram blocks_program_;
  ComputeProgram add_program_;
  std::vector<StorageBuffer> block_sums_;  // level l: one uint per block of level l
};

}  // namespace gt::gpu
