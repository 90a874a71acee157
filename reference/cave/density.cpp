// Seed 004's density on the lattice; see density.hpp for the formula and the operation order.
#include "reference/cave/density.hpp"

#include <type_traits>

#include "core/mutant.hpp"
#include "reference/noise/simplex.hpp"

namespace gt::reference {

template <class Real>
Real cave_density_at(const Permutation& perm, const CaveParams& params, Real x, Real y, Real z) {
  const auto kernel = static_cast<Real>(params.kernel_radius_squared);
  if constexpr (std::is_same_v<Real, float>) {
    // The calibrated pair of the float density's error model (compare/mutants/cave.cpp): ref<float>'s
    // samples, which the GPU meshes too, off by 2^-5, or divided by the scale (an honest variant).
    if (mutant_active("cave.marching_tetrahedra.float_density_off_above_bound")) {
      const auto world_to_noise = static_cast<Real>(1.0 / params.scale);
      return simplex3<Real>(perm, x * world_to_noise, y * world_to_noise, z * world_to_noise, kernel) + 0.03125f;
    }
    if (mutant_active("cave.marching_tetrahedra.float_density_divided_below_bound")) {
      const auto scale = static_cast<Real>(params.scale);
      return simplex3<Real>(perm, x / scale, y / scale, z / scale, kernel);
    }
  }
  const auto world_to_noise = static_cast<Real>(1.0 / params.scale);
  return simplex3<Real>(perm, x * world_to_noise, y * world_to_noise, z * world_to_noise, kernel);
}

template <class Real>
Volume<Real> cave_density(const CaveParams& params) {
  Volume<Real> density(params.size[0] + 1, params.size[1] + 1, params.size[2] + 1);
  density.origin = {static_cast<double>(params.origin[0]), static_cast<double>(params.origin[1]),
                    static_cast<double>(params.origin[2])};
  density.spacing = 1.0;
  const Permutation perm = seeded_permutation(params.seed);
  for (int k = 0; k < density.nz; ++k) {
    for (int j = 0; j < density.ny; ++j) {
      for (int i = 0; i < density.nx; ++i) {
        density.at(i, j, k) = cave_density_at<Real>(perm, params, static_cast<Real>(params.origin[0] + i),
                                                    static_cast<Real>(params.origin[1] + j),
                                                    static_cast<Real>(params.origin[2] + k));
      }
    }
  }
  return density;
}

template Volume<float> cave_density(const CaveParams&);
template Volume<double> cave_density(const CaveParams&);
template float cave_density_at(const Permutation&, const CaveParams&, float, float, float);
template double cave_density_at(const Permutation&, const CaveParams&, double, double, double);

}  // namespace gt::reference
