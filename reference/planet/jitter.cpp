// Step 1 of the Earth-like generator; see jitter.hpp.
#include "reference/planet/jitter.hpp"

#include <cmath>
#include <type_traits>

#include "core/mutant.hpp"
#include "core/rng.hpp"

namespace gt::reference {
namespace {

// eq. 5.1: 0.5 + (U − 0.5)·j
template <class Real>
Real jittered_offset(const PlanetParams& params, std::size_t region, std::uint32_t axis) {
  const Real draw = static_cast<Real>(uniform01(random_u32(params.seed, static_cast<std::uint32_t>(region), axis,
                                                           planet_stream_jitter)));
  return Real(0.5) + (draw - Real(0.5)) * static_cast<Real>(params.jitter);
}

// The calibrated pair of the float position model (32u, planet_error_model.hpp), in both float
// twins (gpu/shaders/planet/jitter.comp alike): each component times 1 + 2^-17 (4 times the bound
// at |p| = 1) or 1 + 2^-23 (one rounding).
template <class Real>
Real calibrated(Real component) {
  if constexpr (std::is_same_v<Real, float>) {
    if (mutant_active("planet.jitter.float_off_above_bound")) return component * (1.0f + 0x1p-17f);
    if (mutant_active("planet.jitter.float_off_below_bound")) return component * (1.0f + 0x1p-23f);
  }
  return component;
}

// f(t) = tan(θt)/tan θ, with θ and tan θ rounded to Real once; t itself for no warp (θ = 0).
template <class Real>
Real warped(Real t, CubeWarp cube_warp) {
  if (cube_warp.angle == 0.0) return t;
  const Real angle = static_cast<Real>(cube_warp.angle);
  return std::tan(angle * t) / static_cast<Real>(std::tan(cube_warp.angle));
}

}  // namespace

template <class Real>
JitteredRegions<Real> jitter_regions(const CubeSphere& sphere, const PlanetParams& params) {
  const std::size_t count = sphere.region_count();
  const int resolution = sphere.resolution();
  const CubeWarp warp = cube_warp(params.warp);
  JitteredRegions<Real> regions;
  regions.offsets.resize(2 * count);
  regions.positions.resize(3 * count);
  for (std::size_t region = 0; region < count; ++region) {
    const Real offset_a = jittered_offset<Real>(params, region, 0);
    const Real offset_b = jittered_offset<Real>(params, region, 1);
    const std::size_t cell = region % (std::size_t(resolution) * resolution);
    const Real a = (static_cast<Real>(cell % resolution) + offset_a) / static_cast<Real>(resolution);
    const Real b = (static_cast<Real>(cell / resolution) + offset_b) / static_cast<Real>(resolution);
    const Vector3<Real> face_space{warped(Real(2) * a - Real(1), warp), warped(Real(1) - Real(2) * b, warp), Real(1)};
    const FaceMatrix& matrix = face_matrix(static_cast<CubeFace>(region / (std::size_t(resolution) * resolution)));
    Vector3<Real> cube{};
    for (int row = 0; row < 3; ++row) {
      for (int column = 0; column < 3; ++column) cube[row] += static_cast<Real>(matrix[row][column]) * face_space[column];
    }
    const Real inverse_length = Real(1) / std::sqrt(cube[0] * cube[0] + cube[1] * cube[1] + cube[2] * cube[2]);
    regions.offsets[2 * region] = offset_a;
    regions.offsets[2 * region + 1] = offset_b;
    for (int axis = 0; axis < 3; ++axis) regions.positions[3 * region + axis] = calibrated(cube[axis] * inverse_length);
  }
  return regions;
}

template JitteredRegions<double> jitter_regions(const CubeSphere&, const PlanetParams&);
template JitteredRegions<float> jitter_regions(const CubeSphere&, const PlanetParams&);

}  // namespace gt::reference
