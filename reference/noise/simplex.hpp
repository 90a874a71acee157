// Simplex noise in 2, 3 and 4 dimensions, gradients in 2-D and 3-D (seed 004, digest §2.2.3-2.2.4), CPU reference.
//
// Eshelman's port of Gustavson 2005, the code the Endless Cave thesis calls as raw_noise_3d.
// simplex2(perm, x, y)                  kernel radius² 0.5, scale 70
// simplex3(perm, x, y, z, r2)           r2 = 0.6 as the seed (slightly discontinuous across
//                                       simplex faces, digest §2.2.5) or 0.5 (Gustavson's
//                                       correction, continuous), scale 32
// simplex4(perm, x, y, z, w, r2)        the same choice of r2, scale 27
// simplex2_gradient -> {value, d/dx, d/dy}; simplex3_gradient -> {value, d/dx, d/dy, d/dz}; the
// value is bit for bit the one simplex2/simplex3 return.
// SimplexLattice simplex_lattice2/3/4: skew and unskew factors (below).
// Real = double is the truth; Real = float repeats gpu/shaders/noise/simplex.glsl operation by
// operation (the constants below are rounded once from these decimals, as the shader's literals).
//
// Inputs:  perm (core/noise/permutation.hpp); coordinates in noise units. The lattice is hashed with
//          `& 255`, so the noise has period 256 on every lattice axis. Coordinates must keep
//          |x + skew| below 2^31 (the cell index is an int).
// Outputs: values dimensionless, inside [-1, 1] (largest found: 0.998 in 2-D, 0.979 / 0.992 in
//          3-D / 4-D with r2 = 0.6, only 0.416 / 0.430 with r2 = 0.5, since the scales were fitted to
//          0.6); derivatives per noise unit.
// Units:   coordinates in noise units (one lattice cell = 1; seed 004 divides world units by 10
//          before calling, digest §2.2.2).
// Throws:  nothing.
// Twin:    gpu/shaders/noise/simplex.glsl (with permutation.glsl).
#pragma once

#include <array>

#include "core/noise/permutation.hpp"

namespace gt::reference {

// Skew factor F = (sqrt(n + 1) - 1) / n and unskew factor G = (1 - 1/sqrt(n + 1)) / n of the
// n-dimensional simplex lattice; corner m of a simplex lies at offset m·G in unskewed space, each
// m·G written out and rounded once (in float, 3·G4 rounded once differs from 3·float(G4)).
struct SimplexLattice {
  double skew;
  std::array<double, 5> corner_unskew;  // m·G for corners m = 0..n; [1] is G; unused tail 0
};

inline constexpr SimplexLattice simplex_lattice2{
    0.36602540378443865, {0.0, 0.2113248654051871, 0.4226497308103742}};
inline constexpr SimplexLattice simplex_lattice3{
    0.3333333333333333, {0.0, 0.16666666666666666, 0.3333333333333333, 0.5}};
inline constexpr SimplexLattice simplex_lattice4{
    0.30901699437494745, {0.0, 0.1381966011250105, 0.276393202250021, 0.41458980337503154, 0.552786404500042}};

template <class Real>
Real simplex2(const Permutation& perm, Real x, Real y);

template <class Real>
Real simplex3(const Permutation& perm, Real x, Real y, Real z, Real kernel_radius_squared);

template <class Real>
Real simplex4(const Permutation& perm, Real x, Real y, Real z, Real w, Real kernel_radius_squared);

template <class Real>
std::array<Real, 3> simplex2_gradient(const Permutation& perm, Real x, Real y);

template <class Real>
std::array<Real, 4> simplex3_gradient(const Permutation& perm, Real x, Real y, Real z, Real kernel_radius_squared);

}  // namespace gt::reference
