// Cellular noise bases as Blender offers them (seed 001 §3.18: VORONOI_F1..F4, VORONOI_F2F1,
// VORONOI_CRACKLE, CELLNOISE), after Worley 1996 ("A cellular texture basis function"), CPU reference.
//
// Feature points: one per lattice cell (X, Y, Z), at (X, Y, Z) + j, with the cell's hash
// h = P[P[P[X & 255] + (Y & 255)] + (Z & 255)] (Perlin's corner hash, the table doubled, as in
// perlin.cpp) and j_a = (P[h + o_a] + 1/2)/256 for o = (0, 85, 170): inside the cell, on a 1/256
// lattice (exact in float), period 256.
// voronoi_distances(perm, x, y, z) -> F1 <= F2 <= F3 <= F4, the Euclidean distances from p to the
//   four nearest feature points of the 27 cells around floor(p) (Blender's search: it is not the
//   true k-th nearest where that lies beyond distance 1 from p, and it jumps where p crosses a
//   lattice plane; every F_k <= sqrt(4.25) ≈ 2.06, from the own cell's point and the three nearest
//   face neighbours').
// cellular(perm, basis, x, y, z) -> the signed basis value, Blender's musgrave variants ("…S"):
//   voronoi_f1..f4: 2·F_k − 1, in [−1, 3.13];  voronoi_f2f1: 2·(F2 − F1) − 1, in [−1, 3.13];
//   voronoi_crackle: 2·min(1, 10·(F2 − F1)) − 1, in [−1, 1];
//   cell_noise: the cell's own value, (P[h + 128] + 1/2)/128 − 1, in (−1, 1), mean 0 over P.
// Decisions (Blender's tables and hash are its own; seed 001 says matching them is not required):
//   - The hash and jitter use the noise's permutation, so `seed` shuffles them as it does Perlin's.
//   - p − floor(p) first (exact in float, as perlin.cpp's local coordinates), then the offset to
//     each point, (local − (cell offset + j)): one rounding per axis, at any |p| below 2^31.
//   - Distances summed (d_x² + d_y²) + d_z², then sqrt; the four nearest kept by insertion in the
//     order z, y, x of the 27 cells, from −1 to +1.
//   - The single functions take the signed variant too, so every basis is centred as Perlin's is.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  perm (core/noise/permutation.hpp); coordinates in lattice units, |p| < 2^31.
// Outputs: the four distances; the value.
// Units:   lattice units; values dimensionless.
// Throws:  nothing.
// Twin:    gpu/shaders/noise/cellular.glsl.
#pragma once

#include <array>

#include "core/noise/permutation.hpp"
#include "core/params/noise.hpp"

namespace gt::reference {

template <class Real>
std::array<Real, 4> voronoi_distances(const Permutation& permutation, Real x, Real y, Real z);

// `basis` one of the cellular bases (is_cellular); the value of any other is 0.
template <class Real>
Real cellular(const Permutation& permutation, NoiseBasis basis, Real x, Real y, Real z);

}  // namespace gt::reference
