// The block size of the multi-level exclusive scan (gpu/cave/exclusive_scan.cpp mirrors it):
// 256 invocations per workgroup, 4 consecutive values each, so one workgroup scans 1024 values
// and leaves their sum for the next level. Guarded: both scan passes include it.
// Inputs:  none.
// Outputs: the block size constants.
// Twin:    none: the scan has no reference of its own (host: gpu/cave/exclusive_scan.cpp).
#ifndef GT_CAVE_SCAN_GLSL
#define GT_CAVE_SCAN_GLSL

const uint SCAN_GROUP_SIZE = 256u;
const uint SCAN_VALUES_PER_INVOCATION = 4u;
const uint SCAN_BLOCK_SIZE = SCAN_GROUP_SIZE * SCAN_VALUES_PER_INVOCATION;

#endif
