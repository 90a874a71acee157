// One-dimensional work on a two-dimensional grid of workgroups, the shader side of
// gpu/cave/linear_dispatch.hpp: the host spreads ceil(items / local size) groups over x (at most
// 65535, the smallest GL_MAX_COMPUTE_WORK_GROUP_COUNT the GL 4.5 spec allows) and y, so that
// 256³-cube blocks (16.8M items) fit. Items past the end belong to the last row's spare groups:
// callers compare the index with their item count. Local size: x only (y = z = 1).
// Guarded: several cave programs include it.
// Inputs:  gl_WorkGroupID, gl_NumWorkGroups.
// Outputs: linear_workgroup(), linear_invocation().
// Twin:    none: dispatch arithmetic (host: gpu/cave/linear_dispatch.hpp).
#ifndef GT_CAVE_LINEAR_DISPATCH_GLSL
#define GT_CAVE_LINEAR_DISPATCH_GLSL

uint linear_workgroup() { return gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x; }

uint linear_invocation() { return linear_workgroup() * gl_WorkGroupSize.x + gl_LocalInvocationID.x; }

#endif
