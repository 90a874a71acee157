// The cube-sphere surface of seed 002 (digest 002_planets.md §2.7, §3.3–3.4, §9.1, §9.4): the six
// faces of the cube [-1, 1]³, each an R×R grid of cells holding one region, projected onto the unit
// sphere through a warp (the optimised tangent warp unless the planet asks for another). A core type: both planet twins index regions this way,
// and the neighbour table is computed once here and uploaded (§9.1), so that the wrap arithmetic
// stays off the parity surface.
//
// Indexing (§3.3): faces FRONT 0 (+z), RIGHT 1 (+x), BACK 2 (-z), LEFT 3 (-x), NORTH 4 (+y), SOUTH 5
// (-y); region i = face·R² + y·R + x, cells row-major from the face's top-left.
// Local coordinates (§3.4) (face, a, b): a, b in [0, 1], (0, 0) the face's top-left corner, b growing
// downward. The face-space point is (u, v, 1) = (2a - 1, 1 - 2b, 1) (the code's y flip) and the
// cube point P_face·(u, v, 1), with the code's signed permutations P (facePermutationMatrix; the
// thesis's illustrative P differs, §3.4).
// Warp (eq. 3.5): f(t) = tan(θt)/tan θ, θ = 0.868734829276, inverse atan(u·tan θ)/θ (the thesis
// prints a wrong inverse, §2.7 [E]); position = normalise(P·(f(u), f(v), 1)) (eq. 4.3, 4.4). The
// same formula with θ = π/4 is the plain tangent warp (eq. 3.4), and θ = 0 stands for no warp, the
// identity (the limit of both formulas, which are 0/0 there, so it is written as such).
// Direction -> local (eq. 4.5, 4.6): the face is the component of largest magnitude, ties to z, then
// x, then y (one rule where the code compares == ±1 and its shader > 0.99999, §9.4); (u, v, 1) =
// Pᵀ·(p / max|p|), then unwarped (the code's CPU path forgot the unwarp, §3.4 [C]).
// Wrap (Algorithm 2 as corrected in §3.4): a point at most one edge beyond its face folds
// isometrically onto the neighbouring face (front a = 1 + e/2 lands on right a = e/2); beyond a
// corner (both coordinates outside) there is none.
// Neighbours (§3.4 [C], §9.1): the cells around a cell in the order up (0, -1), upLeft, left,
// downLeft, down, downRight, right, upRight, found by wrapping the neighbour cell's centre; the one
// diagonal over a cube corner is invalid_region, so the 24 corner cells have 7 and the rest 8.
// A cell of a coordinate of exactly 1 is R - 1 (§9.4).
// Units: positions on the unit sphere (dimensionless); angles in radians.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/vec3.hpp"

namespace gt {

enum class CubeFace : int { front = 0, right = 1, back = 2, left = 3, north = 4, south = 5 };
inline constexpr int cube_face_count = 6;
inline constexpr int max_cube_sphere_resolution = 300;  // §9.1: 540,000 regions
inline constexpr double warp_angle = 0.868734829276;    // θ of eq. 3.5 (WARP_MAGIC_ANGLE)
inline constexpr std::int32_t invalid_region = -1;

struct LocalPosition {
  CubeFace face = CubeFace::front;
  double a = 0.5;
  double b = 0.5;
};

// The 8 neighbours of a cell, in the order up, upLeft, left, downLeft, down, downRight, right, upRight.
using RegionNeighbours = std::array<std::int32_t, 8>;

// The code's facePermutationMatrix P of a face: cube point = P·(u, v, 1); rows as §3.4 lists them.
using FaceMatrix = std::array<std::array<int, 3>, 3>;
const FaceMatrix& face_matrix(CubeFace face);

// The warp's θ: warp_angle (eq. 3.5) by default, π/4 the plain tangent warp (eq. 3.4), 0 none.
struct CubeWarp {
  double angle = warp_angle;
};
inline constexpr CubeWarp no_warp{0.0};

double warp(double t, CubeWarp cube_warp = {});    // f(t) = tan(θt) / tan θ: [-1, 1] -> [-1, 1]
double unwarp(double u, CubeWarp cube_warp = {});  // f⁻¹(u) = atan(u tan θ) / θ

// The point on the cube [-1, 1]³ of a local position (no warp).
Vec3 cube_point(const LocalPosition& local);
// The unit-sphere position of a local position, through the warp.
Vec3 sphere_position(const LocalPosition& local, CubeWarp cube_warp = {});
// The local position of a direction (any non-zero vector), through the warp's inverse.
LocalPosition local_position_of(const Vec3& direction, CubeWarp cube_warp = {});
// Algorithm 2: the position on its own face when a or b lies outside [0, 1] by at most one edge
// crossing; none over a corner. A position inside its face is returned unchanged.
std::optional<LocalPosition> wrap(const LocalPosition& local);

class CubeSphere {
 public:
  // Throws InputError for a resolution outside 1..max_cube_sphere_resolution.
  explicit CubeSphere(int resolution);

  int resolution() const { return resolution_; }
  std::size_t region_count() const { return neighbours_.size(); }

  // eq. 4.1, corrected: the position of `region` at offset (offset_a, offset_b) in [0, 1]² inside its
  // cell ((0.5, 0.5): the centre).
  LocalPosition local_position(std::size_t region, double offset_a = 0.5, double offset_b = 0.5) const;
  // eq. 4.2: the region whose cell holds the position, wrapped once when off its face; none over a
  // corner.
  std::optional<std::size_t> region_at(const LocalPosition& local) const;
  const RegionNeighbours& neighbours(std::size_t region) const { return neighbours_[region]; }
  // The whole table flat, 8 entries per region in region order: what the shaders receive (§9.1).
  std::vector<std::int32_t> neighbour_table() const;

 private:
  std::optional<std::size_t> region_on_face(const LocalPosition& local) const;

  int resolution_;
  std::vector<RegionNeighbours> neighbours_;
};

}  // namespace gt
