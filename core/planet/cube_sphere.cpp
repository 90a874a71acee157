// The cube-sphere surface; see cube_sphere.hpp.
#include "core/planet/cube_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"

namespace gt {
namespace {

// The code's facePermutationMatrix, rows as the digest's table (§3.4) lists them.
constexpr std::array<FaceMatrix, cube_face_count> face_matrices = {{
    {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},    // front: +z, +a toward +x, +b toward -y
    {{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}},   // right: +x, +a toward -z
    {{{-1, 0, 0}, {0, 1, 0}, {0, 0, -1}}},  // back: -z, +a toward -x
    {{{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}},   // left: -x, +a toward +z
    {{{1, 0, 0}, {0, 0, 1}, {0, -1, 0}}},   // north: +y, +a toward +x, +b toward +z
    {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}},   // south: -y, +a toward +x, +b toward -z
}};

// Neighbour steps (dx, dy) in the table's order: up, upLeft, left, downLeft, down, downRight,
// right, upRight.
constexpr std::array<std::array<int, 2>, 8> neighbour_steps = {
    {{0, -1}, {-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1}, {1, 0}, {1, -1}}};


// P·vector, or Pᵀ·vector (the inverse: P is a signed permutation) when transposed.
Vec3 apply(const FaceMatrix& matrix, const Vec3& vector, bool transposed) {
  Vec3 result{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) result[i] += (transposed ? matrix[j][i] : matrix[i][j]) * vector[j];
  }
  return result;
}

Vec3 to_cube(CubeFace face, const Vec3& face_space) { return apply(face_matrix(face), face_space, false); }

Vec3 to_face_space(CubeFace face, const Vec3& point) { return apply(face_matrix(face), point, true); }

// The face a direction meets: its component of largest magnitude, ties to z, then x, then y.
CubeFace face_of(const Vec3& direction) {
  const double x = std::abs(direction[0]), y = std::abs(direction[1]), z = std::abs(direction[2]);
  if (z >= x && z >= y) return direction[2] >= 0 ? CubeFace::front : CubeFace::back;
  if (x >= y) return direction[0] >= 0 ? CubeFace::right : CubeFace::left;
  return direction[1] >= 0 ? CubeFace::north : CubeFace::south;
}

// (u, v) of face space as local (a, b).
LocalPosition local_of_face_space(CubeFace face, double u, double v) { return {face, (u + 1.0) / 2.0, (1.0 - v) / 2.0}; }

}  // namespace

const FaceMatrix& face_matrix(CubeFace face) { return face_matrices[static_cast<std::size_t>(face)]; }

double warp(double t, CubeWarp cube_warp) {
  const double angle = cube_warp.angle;
  return angle == 0.0 ? t : std::tan(angle * t) / std::tan(angle);
}

// Mutant planet.cube_sphere.unwarp_over_tan (both twins share this): divided by tan θ instead of θ.
double unwarp(double u, CubeWarp cube_warp) {
  const double angle = cube_warp.angle;
  if (angle == 0.0) return u;
  const double divisor = mutant_active("planet.cube_sphere.unwarp_over_tan") ? std::tan(angle) : angle;
  return std::atan(u * std::tan(angle)) / divisor;
}

Vec3 cube_point(const LocalPosition& local) {
  return to_cube(local.face, {2.0 * local.a - 1.0, 1.0 - 2.0 * local.b, 1.0});
}

Vec3 sphere_position(const LocalPosition& local, CubeWarp cube_warp) {
  const double u = 2.0 * local.a - 1.0, v = 1.0 - 2.0 * local.b;
  return normalised(to_cube(local.face, Vec3{warp(u, cube_warp), warp(v, cube_warp), 1.0}));
}

LocalPosition local_position_of(const Vec3& direction, CubeWarp cube_warp) {
  const double largest = std::max({std::abs(direction[0]), std::abs(direction[1]), std::abs(direction[2])});
  if (!(largest > 0.0) || !std::isfinite(largest)) {
    throw std::invalid_argument(fmt::format("cube sphere: the direction ({}, {}, {}) names no point of the sphere",
                                            direction[0], direction[1], direction[2]));
  }
  const CubeFace face = face_of(direction);
  const Vec3 face_space = to_face_space(face, (1.0 / largest) * direction);
  return local_of_face_space(face, unwarp(face_space[0], cube_warp), unwarp(face_space[1], cube_warp));
}

std::optional<LocalPosition> wrap(const LocalPosition& local) {
  const double u = 2.0 * local.a - 1.0, v = 1.0 - 2.0 * local.b;
  const double u_clamped = std::clamp(u, -1.0, 1.0), v_clamped = std::clamp(v, -1.0, 1.0);
  const double u_over = std::abs(u_clamped - u), v_over = std::abs(v_clamped - v);
  if (u_over == 0.0 && v_over == 0.0) return local;
  if (u_over > 0.0 && v_over > 0.0) return std::nullopt;  // over a corner
  // Fold the overshoot down the edge onto the neighbouring face (an isometric unfolding). Mutant
  // planet.cube_sphere.overshoot_doubled (the table is shared): folded twice as far down.
  const double overshoot = (u_over + v_over) * (mutant_active("planet.cube_sphere.overshoot_doubled") ? 2.0 : 1.0);
  const Vec3 folded = to_cube(local.face, {u_clamped, v_clamped, 1.0 - overshoot});
  const CubeFace face = face_of(folded);
  const Vec3 face_space = to_face_space(face, folded);
  return local_of_face_space(face, face_space[0], face_space[1]);
}

CubeSphere::CubeSphere(int resolution) : resolution_(resolution) {
  if (resolution < 1 || resolution > max_cube_sphere_resolution) {
    throw InputError(fmt::format("cube sphere: resolution {} is outside 1..{} (6R² regions)", resolution,
                                 max_cube_sphere_resolution));
  }
  const auto per_face = static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution);
  neighbours_.resize(cube_face_count * per_face);
  for (std::size_t region = 0; region < neighbours_.size(); ++region) {
    const LocalPosition centre = local_position(region);
    for (std::size_t step = 0; step < neighbour_steps.size(); ++step) {
      const LocalPosition next{centre.face, centre.a + neighbour_steps[step][0] / double(resolution),
                               centre.b + neighbour_steps[step][1] / double(resolution)};
      // Mutant planet.cube_sphere.no_wrap (both twins: the table is shared): neighbours off the
      // face are left out, as if the cube's faces were not joined.
      const bool off_face = next.a < 0.0 || next.a > 1.0 || next.b < 0.0 || next.b > 1.0;
      const auto found = off_face && mutant_active("planet.cube_sphere.no_wrap") ? std::nullopt : region_at(next);
      neighbours_[region][step] = found ? static_cast<std::int32_t>(*found) : invalid_region;
    }
  }
}

std::vector<std::int32_t> CubeSphere::neighbour_table() const {
  std::vector<std::int32_t> table;
  table.reserve(8 * neighbours_.size());
  for (const auto& around : neighbours_) table.insert(table.end(), around.begin(), around.end());
  return table;
}

LocalPosition CubeSphere::local_position(std::size_t region, double offset_a, double offset_b) const {
  const auto side = static_cast<std::size_t>(resolution_);
  const std::size_t per_face = side * side;
  const std::size_t x = region % side, y = region / side % side;
  return {static_cast<CubeFace>(region / per_face), (double(x) + offset_a) / double(side),
          (double(y) + offset_b) / double(side)};
}

std::optional<std::size_t> CubeSphere::region_on_face(const LocalPosition& local) const {
  if (!(local.a >= 0.0 && local.a <= 1.0 && local.b >= 0.0 && local.b <= 1.0)) return std::nullopt;
  const auto cell = [this](double coordinate) {
    return std::min(static_cast<std::size_t>(coordinate * resolution_), static_cast<std::size_t>(resolution_ - 1));
  };
  const auto side = static_cast<std::size_t>(resolution_);
  return static_cast<std::size_t>(local.face) * side * side + cell(local.b) * side + cell(local.a);
}

std::optional<std::size_t> CubeSphere::region_at(const LocalPosition& local) const {
  const auto wrapped = wrap(local);
  return wrapped ? region_on_face(*wrapped) : std::nullopt;
}

}  // namespace gt
