// The seed's central-difference normals of the cave (seed 004 Listing 3.3, digest §2.8), GPU twin.
//
// central_difference_normals(positions, params, step = 1.0) -> one normal per position:
//   gpu/shaders/cave/central_normals.comp, one invocation per vertex: for each axis
//   f(p + step·e_c) − f(p − step·e_c) of the seed's density f (the density pass's float arithmetic:
//   each world coordinate times float(1/scale)), normalised; the zero vector where all three
//   differences are 0. Waits for the GPU.
//
// Inputs:  positions in world units (a mesh's, float); params (CaveParams: seed, scale, kernel);
//          step, the seed's ND in world units (1.0), rounded once to float. Needs a current GlContext.
// Outputs: one unit normal (or the zero vector) per position, pointing from rock into air.
// Units:   world units; normals dimensionless.
// Throws:  std::runtime_error when the shader does not compile or link or its block does not match
//          the C++ mirror, or when the positions exceed GL_MAX_SHADER_STORAGE_BLOCK_SIZE.
// Twin:    reference/cave/normals.hpp central_difference_normals<float>.
#pragma once

#include <array>
#include <vector>

#include "core/params/cave.hpp"

namespace gt::gpu {

std::vector<std::array<float, 3>> central_difference_normals(const std::vector<std::array<float, 3>>& positions,
                                                             const CaveParams& params, double step = 1.0);

}  // namespace gt::gpu
