#version 450
// First half of one level of the exclusive scan (uint, in place): each workgroup replaces its
// block of 1024 values (cave/scan.glsl) by their exclusive prefix sums within the block and
// writes the block's total to block_sums[block]. Each invocation sums its 4 values serially, the
// 256 partial sums are scanned in shared memory by Blelloch's work-efficient up-sweep and
// down-sweep, then each invocation writes its 4 results. Integer sums: the same bits in any order.
// Values past value_count read as 0 and are not written; the host scans the block sums with the
// next level and adds them back with scan_add.comp.
// Inputs:  values (binding 0), the uniform value_count.
// Outputs: values (0), in place; block_sums (1).
// Twin:    none: the scan has no reference of its own (host: gpu/cave/exclusive_scan.cpp).
layout(local_size_x = 256) in;

#include "cave/linear_dispatch.glsl"
#include "cave/scan.glsl"

layout(std430, binding = 0) buffer Values { uint values[]; };
layout(std430, binding = 1) writeonly buffer BlockSums { uint block_sums[]; };

uniform uint value_count;

shared uint partial_sums[SCAN_GROUP_SIZE];

void scan_partial_sums(uint invocation) {
  for (uint stride = 1u; stride < SCAN_GROUP_SIZE; stride *= 2u) {
    uint right = (invocation + 1u) * 2u * stride - 1u;
    if (right < SCAN_GROUP_SIZE) partial_sums[right] += partial_sums[right - stride];
    memoryBarrierShared();
    barrier();
  }
  if (invocation == 0u) partial_sums[SCAN_GROUP_SIZE - 1u] = 0u;
  memoryBarrierShared();
  barrier();
  for (uint stride = SCAN_GROUP_SIZE / 2u; stride >= 1u; stride /= 2u) {
    uint right = (invocation + 1u) * 2u * stride - 1u;
    if (right < SCAN_GROUP_SIZE) {
      uint left_sum = partial_sums[right - stride];
      partial_sums[right - stride] = partial_sums[right];
      partial_sums[right] += left_sum;
    }
    memoryBarrierShared();
    barrier();
  }
}

void main() {
  uint block = linear_workgroup();
  if (block * SCAN_BLOCK_SIZE >= value_count) return;  // a spare group of the last row: all leave
  uint invocation = gl_LocalInvocationID.x;
  uint first = block * SCAN_BLOCK_SIZE + invocation * SCAN_VALUES_PER_INVOCATION;
  uint own[SCAN_VALUES_PER_INVOCATION];
  uint own_sum = 0u;
  for (uint k = 0u; k < SCAN_VALUES_PER_INVOCATION; ++k) {
    own[k] = first + k < value_count ? values[first + k] : 0u;
    own_sum += own[k];
  }
  partial_sums[invocation] = own_sum;
  memoryBarrierShared();
  barrier();
  scan_partial_sums(invocation);
  uint running = partial_sums[invocation];
  if (invocation == SCAN_GROUP_SIZE - 1u) block_sums[block] = running + own_sum;
  for (uint k = 0u; k < SCAN_VALUES_PER_INVOCATION; ++k) {
    if (first + k < value_count) values[first + k] = running;
    running += own[k];
  }
}
