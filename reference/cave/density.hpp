// The cave's density: 3-D simplex noise on the integer lattice (seed 004, digest §2.2.2, §2.4), CPU reference.
//
// Seed 004's single octave of simplex noise, sampled at the lattice points.
// cave_density<Real>(params) -> Volume<Real> of (size + 1)³ samples (per axis), origin = params.origin,
//   spacing 1 world unit; sample (i, j, k) holds
//     simplex3(perm, Real(ox + i)·r, Real(oy + j)·r, Real(oz + k)·r, Real(kernel))   with r = Real(1/scale)
//   where perm = seeded_permutation(params.seed), ox + i is the exact integer world coordinate
//   converted to Real once, and r is 1/scale computed in double and rounded to Real once.
// cave_density_at<Real>(perm, params, x, y, z) -> the density at a world point, in Real with the same
//   operations as a sample: each world coordinate multiplied by Real(1/scale). Used by the normals
//   (normals.hpp).
// Real = double is the truth; Real = float repeats the shader's arithmetic.
//
// Inputs:  params (CaveParams, core/params/cave.hpp: origin, size, scale, kernel, seed); a world point.
// Outputs: the sampled volume; one density value.
// Units:   world units (the lattice spacing 1); densities dimensionless (rock where below the threshold).
// Throws:  nothing.
// Twin:    gpu/shaders/cave/density.comp, pass 1 of gpu/cave/marching_tetrahedra.hpp (MarchingTetrahedra).
// Decisions: the seed divides by SCALE_FACTOR (Listing 3.1); both twins multiply by the rounded
//   reciprocal instead, because GLSL's float division is only accurate to 2.5 ulp and cannot be
//   reproduced, while a multiplication is correctly rounded on both sides. In double the two differ
//   by at most one rounding (for scale 10: 10·0.1 = 1 exactly, 30·0.1 = 3.0000000000000004).
//   The `solid` padding is not applied here: the meshers pad (marching_tetrahedra.hpp).
#pragma once

#include "core/noise/permutation.hpp"
#include "core/params/cave.hpp"
#include "core/volume.hpp"

namespace gt::reference {

template <class Real>
Volume<Real> cave_density(const CaveParams& params);

// The density at a world point, in Real with the same operations as a sample: each world
// coordinate multiplied by Real(1/scale). Used by the normals (normals.hpp).
template <class Real>
Real cave_density_at(const Permutation& perm, const CaveParams& params, Real x, Real y, Real z);

}  // namespace gt::reference
