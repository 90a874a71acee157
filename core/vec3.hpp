// Three-component vectors of doubles (positions, normals, camera directions) and the few
// operations the render code needs on them, written once: sums, differences, scaling, dot and cross
// products, length and normalisation. Plain std::array so that meshes and matrices share the type.
#pragma once

#include <array>
#include <cmath>

namespace gt {

using Vec3 = std::array<double, 3>;

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
// a / |a|, computed as (1/|a|)·a.
inline Vec3 normalised(const Vec3& a) { return (1.0 / std::sqrt(dot(a, a))) * a; }

}  // namespace gt
