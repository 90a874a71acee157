// Cave normals from the density: central differences (seed 004 Listing 3.3) and the analytic
// simplex gradient; formulas and operation order in normals.hpp.
#include "reference/cave/normals.hpp"

#include <cmath>
#include <numbers>

#include "reference/cave/density.hpp"
#include "reference/noise/simplex.hpp"

namespace gt::reference {
namespace {

template <class Real>
std::array<Real, 3> normalised(const std::array<Real, 3>& v) {
  const Real length = std::sqrt((v[0] * v[0] + v[1] * v[1]) + v[2] * v[2]);
  if (length == Real(0)) return v;
  return {v[0] / length, v[1] / length, v[2] / length};
}

template <class Real>
std::array<Real, 3> central_difference(const Permutation& perm, const CaveParams& params,
                                       const std::array<Real, 3>& position, Real step) {
  std::array<Real, 3> difference{};
  for (int axis = 0; axis < 3; ++axis) {
    std::array<Real, 3> plus = position;
    std::array<Real, 3> minus = position;
    plus[axis] = position[axis] + step;
    minus[axis] = position[axis] - step;
    difference[axis] = cave_density_at<Real>(perm, params, plus[0], plus[1], plus[2]) -
                       cave_density_at<Real>(perm, params, minus[0], minus[1], minus[2]);
  }
  return difference;
}

}  // namespace

template <class Real>
std::vector<std::array<Real, 3>> central_differences(const TriangleMesh<Real>& mesh, const CaveParams& params,
                                                     double step) {
  const Permutation perm = seeded_permutation(params.seed);
  std::vector<std::array<Real, 3>> differences;
  differences.reserve(mesh.positions.size());
  for (const auto& position : mesh.positions) {
    differences.push_back(central_difference(perm, params, position, static_cast<Real>(step)));
  }
  return differences;
}

template <class Real>
std::vector<std::array<Real, 3>> unit_normals(std::vector<std::array<Real, 3>> vectors) {
  for (auto& vector : vectors) vector = normalised(vector);
  return vectors;
}

template <class Real>
std::vector<std::array<Real, 3>> central_difference_normals(const TriangleMesh<Real>& mesh, const CaveParams& params,
                                                            double step) {
  return unit_normals(central_differences(mesh, params, step));
}

template <class Real>
std::vector<std::array<Real, 3>> gradient_normals(const TriangleMesh<Real>& mesh, const CaveParams& params) {
  const Permutation perm = seeded_permutation(params.seed);
  const auto world_to_noise = static_cast<Real>(1.0 / params.scale);
  const auto kernel = static_cast<Real>(params.kernel_radius_squared);
  std::vector<std::array<Real, 3>> normals;
  normals.reserve(mesh.positions.size());
  for (const auto& p : mesh.positions) {
    const auto gradient =
        simplex3_gradient<Real>(perm, p[0] * world_to_noise, p[1] * world_to_noise, p[2] * world_to_noise, kernel);
    normals.push_back(normalised<Real>({gradient[1], gradient[2], gradient[3]}));
  }
  return normals;
}

template <class Real>
std::vector<double> normal_angles(const std::vector<std::array<Real, 3>>& a, const std::vector<std::array<Real, 3>>& b) {
  std::vector<double> angles(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::array<double, 3> u{a[i][0], a[i][1], a[i][2]};
    const std::array<double, 3> v{b[i][0], b[i][1], b[i][2]};
    const double cross_x = u[1] * v[2] - u[2] * v[1];
    const double cross_y = u[2] * v[0] - u[0] * v[2];
    const double cross_z = u[0] * v[1] - u[1] * v[0];
    const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    const double cross = std::sqrt(cross_x * cross_x + cross_y * cross_y + cross_z * cross_z);
    angles[i] = (dot == 0.0 && cross == 0.0) ? std::numbers::pi / 2 : std::atan2(cross, dot);
  }
  return angles;
}

#define GT_INSTANTIATE_CAVE_NORMALS(Real)                                                                          \
  template std::vector<std::array<Real, 3>> central_differences(const TriangleMesh<Real>&, const CaveParams&,        \
                                                                double);                                           \
  template std::vector<std::array<Real, 3>> unit_normals(std::vector<std::array<Real, 3>>);                         \
  template std::vector<std::array<Real, 3>> central_difference_normals(const TriangleMesh<Real>&, const CaveParams&, \
                                                                       double);                                    \
  template std::vector<std::array<Real, 3>> gradient_normals(const TriangleMesh<Real>&, const CaveParams&);        \
  template std::vector<double> normal_angles(const std::vector<std::array<Real, 3>>&,                              \
                                             const std::vector<std::array<Real, 3>>&);

GT_INSTANTIATE_CAVE_NORMALS(float)
GT_INSTANTIATE_CAVE_NORMALS(double)
#undef GT_INSTANTIATE_CAVE_NORMALS

}  // namespace gt::reference
