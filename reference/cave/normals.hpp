// Cave mesh normals from the density (central differences, analytic gradient), seed 004 digest §2.8, CPU reference.
//
// central_difference_normals<Real>(mesh, params, step = 1.0): the seed's central differences (Listing 3.3)
//   n_c = f(p + step·e_c) - f(p - step·e_c) for c = x, y, z (the seed's 6 noise calls, ND = step
//   world units, 1.0 as NORMAL_DISTANCE = 0.1 noise units at scale 10), f = cave_density_at, each
//   shifted coordinate computed in Real as p_c ± Real(step). The seed drops the factor 1/(2·step)
//   and does not normalise (its shader does); here the result is normalised, n / sqrt((n_x² + n_y²)
//   + n_z²), so the two kinds compare directly. A zero difference gives the zero vector.
// central_differences<Real>(mesh, params, step = 1.0): those n before normalising (the error model of
//   the GPU twin's normals reads their lengths); unit_normals(vectors): each normalised as above.
// gradient_normals<Real>(mesh, params): the analytic gradient of the simplex noise,
//   ∇f from simplex3_gradient at p·Real(1/scale) (the chain factor 1/scale > 0 does not change the
//   direction), normalised the same way.
// Both point along +∇f, from rock (f < threshold) into air, like the meshes' winding.
// normal_angles(a, b): per vertex the angle between a[i] and b[i] in radians, atan2(|a×b|, a·b) in
//   double (accurate for small angles); π/2 when either vector is zero.
//
// Inputs:  mesh (positions in world units), params (the cave's CaveParams: seed, scale, kernel);
//          normal_angles: b at least as long as a (one angle per entry of a).
// Outputs: one unit normal per vertex (or the zero vector); one angle per vertex.
// Units:   step in world units; angles in radians; normals dimensionless.
// Throws:  nothing.
// Twin:    none: the normals are computed once on the CPU and given to both render twins
//          (reference/render/cave_look.hpp cave_scene, gpu/render/phong.hpp).
// Error of central differences (used by the tests' bound): with h = step/scale noise units,
// D_h f - ∇f = h²/6·f''' per axis for smooth f; the seed's kernel r² = 0.6 also makes f jump across
// simplex faces (digest §2.2.5), adding up to (jump)/h per axis.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.hpp"
#include "core/params/cave.hpp"

namespace gt::reference {

template <class Real>
std::vector<std::array<Real, 3>> central_difference_normals(const TriangleMesh<Real>& mesh, const CaveParams& params,
                                                            double step = 1.0);

template <class Real>
std::vector<std::array<Real, 3>> central_differences(const TriangleMesh<Real>& mesh, const CaveParams& params,
                                                     double step = 1.0);

template <class Real>
std::vector<std::array<Real, 3>> unit_normals(std::vector<std::array<Real, 3>> vectors);

template <class Real>
std::vector<std::array<Real, 3>> gradient_normals(const TriangleMesh<Real>& mesh, const CaveParams& params);

template <class Real>
std::vector<double> normal_angles(const std::vector<std::array<Real, 3>>& a, const std::vector<std::array<Real, 3>>& b);

}  // namespace gt::reference
