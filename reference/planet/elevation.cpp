// Steps 4–9 of the Earth-like generator; see elevation.hpp. The formulas and their order are the
// spec of core/params/planet.hpp; the comments here only name the step.
#include "reference/planet/elevation.hpp"

#include <cmath>
#include <stdexcept>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

#include "core/mutant.hpp"
#include "core/noise/permutation.hpp"
#include "core/params/noise_fractal.hpp"
#include "core/rng.hpp"
#include "reference/noise/fractal.hpp"
#include "reference/noise/perlin.hpp"

namespace gt::reference {
namespace {

// Every region's plate must name one of the P plates: the steps below index the plates by it.
void require_whole(const PlanetParams& params, const PlatePartition& partition) {
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    const std::int32_t plate = partition.plate[region];
    if (plate < 0 || plate >= params.plates) {
      throw std::invalid_argument(fmt::format("planet elevation: region {} has plate {}, not one of 0..{} (the "
                                              "partition is not whole: see partition.unassigned)",
                                              region, plate, params.plates - 1));
    }
  }
}

template <class Real>
Real dot3(const Vector3<Real>& a, const Vector3<Real>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class Real>
Vector3<Real> scaled(const Vector3<Real>& a, Real factor) {
  return {a[0] * factor, a[1] * factor, a[2] * factor};
}

template <class Real>
Vector3<Real> minus(const Vector3<Real>& a, const Vector3<Real>& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

template <class Real>
Vector3<Real> plus(const Vector3<Real>& a, const Vector3<Real>& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

template <class Real>
Real length3(const Vector3<Real>& a) {
  return std::sqrt(dot3(a, a));
}

// a·(1/|a|), or 0 for a zero vector.
template <class Real>
Vector3<Real> normalised3(const Vector3<Real>& a) {
  const Real squared = dot3(a, a);
  return squared > Real(0) ? scaled(a, Real(1) / std::sqrt(squared)) : Vector3<Real>{};
}

template <class Real>
Vector3<Real> position_of(const std::vector<Real>& positions, std::size_t region) {
  return {positions[3 * region], positions[3 * region + 1], positions[3 * region + 2]};
}

template <class Real>
Real draw(const PlanetParams& params, int plate, std::uint32_t step, PlanetStream stream) {
  return static_cast<Real>(uniform01(random_u32(params.seed, static_cast<std::uint32_t>(plate), step, stream)));
}

// Step 4: normalise(Σ pos) over the members (mean) or the edge members (edge_sum), in index order.
// The sums in double for either Real (core/params/planet.hpp), rounded to Real, then normalised.
template <class Real>
std::vector<Vector3<Real>> plate_centres(const PlanetParams& params, const std::vector<Real>& positions,
                                         const PlatePartition& partition) {
  std::vector<Vector3<double>> sums(static_cast<std::size_t>(params.plates), Vector3<double>{});
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    if (params.centre == PlateCentre::edge_sum && !partition.is_edge[region]) continue;
    for (int axis = 0; axis < 3; ++axis) sums[partition.plate[region]][axis] += positions[3 * region + axis];
  }
  std::vector<Vector3<Real>> centres;
  for (const auto& sum : sums) {
    centres.push_back(normalised3(Vector3<Real>{static_cast<Real>(sum[0]), static_cast<Real>(sum[1]), static_cast<Real>(sum[2])}));
  }
  return centres;
}

// Step 5, eq. 5.2: m·t/|t| with t = α·(c × x̂) + β·(c × ŷ) = (−β·c_z, α·c_z, β·c_x − α·c_y).
template <class Real>
Vector3<Real> plate_shift(const PlanetParams& params, int plate, const Vector3<Real>& centre) {
  const Real magnitude = Real(0.5) + Real(0.5) * draw<Real>(params, plate, 0, planet_stream_shift);
  const Real alpha = Real(2) * draw<Real>(params, plate, 1, planet_stream_shift) - Real(1);
  const Real beta = Real(2) * draw<Real>(params, plate, 2, planet_stream_shift) - Real(1);
  const Vector3<Real> tangent{-(beta * centre[2]), alpha * centre[2], beta * centre[0] - alpha * centre[1]};
  const Real tangent_length = length3(tangent);
  return tangent_length > Real(0) ? scaled(tangent, magnitude / tangent_length) : Vector3<Real>{};
}

// The calibrated pairs of the elevation's float error model (compare/checks/planet_error_model.hpp):
// the factor a float stage's result is multiplied by, 1 on an honest run. In both float twins
// (gpu/shaders/planet/elevation_*.comp alike), so that only the comparison with ref<double> sees
// it: 1 + 2^-above (a few times the stage's bound on the probe) or 1 + 2^-23 (one rounding).
template <class Real>
Real calibration_factor(std::string_view stage, int above) {
  if constexpr (std::is_same_v<Real, float>) {
    if (mutant_active(fmt::format("planet.{}.float_off_above_bound", stage))) return 1.0f + std::ldexp(1.0f, -above);
    if (mutant_active(fmt::format("planet.{}.float_off_below_bound", stage))) return 1.0f + 0x1p-23f;
  }
  return Real(1);
}
// The exponents `above` of the three stages, calibrated on planet.mutant_probe.r12 to 2–10 times the
// bound (the shaders hold the same): the noise's result, the collision's term C·Σ pressure (its bound
// carries the pressure's own, some 7 times the noise's on edge regions), the smoothed mean.
constexpr int noise_above_bound = 12;
constexpr int collision_above_bound = 9;
constexpr int smoothing_above_bound = 12;

// Step 6: uniform in [−e_r, e_r], or bimodal: oceanic in [−e_r, −e_r/2], continental in [0, e_r/4].
template <class Real>
Real plate_base(const PlanetParams& params, int plate) {
  const auto range = static_cast<Real>(params.elevation_range);
  const Real level = draw<Real>(params, plate, 0, planet_stream_elevation);
  if (params.plate_bases == PlateBases::uniform) return range * (Real(2) * level - Real(1));
  const bool oceanic = draw<Real>(params, plate, 1, planet_stream_elevation) < static_cast<Real>(params.ocean_share);
  return oceanic ? -(range * (Real(0.5) + Real(0.5) * level)) : (Real(0.25) * range) * level;
}

// Step 7: base + S·fbm(f·pos).
template <class Real>
std::vector<Real> noisy_elevation(const PlanetParams& params, const std::vector<Real>& positions,
                                  const PlatePartition& partition, const std::vector<Real>& base) {
  const Permutation permutation = seeded_permutation(params.seed);
  const auto basis = [&](Real x, Real y, Real z) { return perlin3<Real>(permutation, x, y, z); };
  FractalParams fractal;
  fractal.octaves = params.perlin_octaves;
  fractal.lacunarity = 2.0;
  fractal.gain = 0.5;
  const auto terms = fractal_terms<Real>(fractal);
  const auto frequency = static_cast<Real>(params.perlin_frequency);
  const auto strength = static_cast<Real>(params.perlin_strength);
  const Real drift = calibration_factor<Real>("noise", noise_above_bound);
  std::vector<Real> elevation(partition.plate.size());
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    elevation[region] = base[partition.plate[region]];
    if (!params.noise) continue;
    const Vector3<Real> point = scaled(position_of(positions, region), frequency);
    elevation[region] = (elevation[region] + strength * fbm(basis, terms, point[0], point[1], point[2])) * drift;
  }
  return elevation;
}

// Step 8: E0 + C·Σ pressure over neighbours of another plate, on edge regions.
template <class Real>
std::vector<Real> collided_elevation(const CubeSphere& sphere, const PlanetParams& params,
                                     const std::vector<Real>& positions, const PlatePartition& partition,
                                     const PlateMotion<Real>& motion, const std::vector<Real>& noisy) {
  if (!params.collisions) return noisy;
  std::vector<Real> elevation = noisy;
  const auto strength = static_cast<Real>(params.collision_strength);
  const Real drift = calibration_factor<Real>("collision", collision_above_bound);
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    if (!partition.is_edge[region]) continue;
    const std::int32_t own = partition.plate[region];
    Real total = 0;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region || partition.plate[neighbour] == own) continue;
      total = total + pressure(params.pressure, position_of(positions, region), motion.shift[own],
                               position_of(positions, neighbour), motion.shift[partition.plate[neighbour]]);
    }
    elevation[region] = elevation[region] + strength * total * drift;
  }
  return elevation;
}

// Step 9, jacobi: the mean of the region and its valid neighbours, self first.
template <class Real>
std::vector<Real> jacobi_smoothed(const CubeSphere& sphere, const std::vector<Real>& elevation) {
  std::vector<Real> smoothed(elevation.size());
  // Mutant planet.smoothing.float_in_place (ref<float> only): neighbours before the region read
  // from the smoothed output (Gauss-Seidel where the method is Jacobi).
  const bool in_place = std::is_same_v<Real, float> && mutant_active("planet.smoothing.float_in_place");
  const Real drift = calibration_factor<Real>("smoothing", smoothing_above_bound);
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    Real sum = elevation[region];
    int count = 1;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region) continue;
      sum = sum + (in_place && std::size_t(neighbour) < region ? smoothed[neighbour] : elevation[neighbour]);
      ++count;
    }
    // Mutant planet.smoothing.count_without_self (both twins): the region summed but not counted.
    smoothed[region] =
        sum / static_cast<Real>(mutant_active("planet.smoothing.count_without_self") ? count - 1 : count) * drift;
  }
  return smoothed;
}

// Step 9, legacy: the code's in-place sequential halving blend in index order.
template <class Real>
std::vector<Real> legacy_smoothed(const CubeSphere& sphere, std::vector<Real> elevation) {
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    Real blended = elevation[region];
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour != invalid_region) blended = Real(0.5) * (blended + elevation[neighbour]);
    }
    elevation[region] = blended;
  }
  return elevation;
}

}  // namespace

template <class Real>
PlateMotion<Real> plate_motion(const PlanetParams& params, const std::vector<Real>& positions,
                               const PlatePartition& partition) {
  PlateMotion<Real> motion;
  motion.centre = plate_centres(params, positions, partition);
  for (int plate = 0; plate < params.plates; ++plate) {
    motion.shift.push_back(plate_shift(params, plate, motion.centre[plate]));
    motion.base.push_back(plate_base<Real>(params, plate));
  }
  return motion;
}

template <class Real>
Real pressure(PressureFormula formula, const Vector3<Real>& position, const Vector3<Real>& shift,
              const Vector3<Real>& neighbour_position, const Vector3<Real>& neighbour_shift) {
  if (formula == PressureFormula::thesis) {
    const Vector3<Real> velocity = minus(shift, scaled(position, dot3(shift, position)));
    const Vector3<Real> neighbour_velocity =
        minus(neighbour_shift, scaled(neighbour_position, dot3(neighbour_shift, neighbour_position)));
    return length3(velocity) * dot3(velocity, minus(neighbour_position, position)) +
           length3(neighbour_velocity) * dot3(neighbour_velocity, minus(position, neighbour_position));
  }
  const Vector3<Real> direction = normalised3(minus(neighbour_position, position));
  const Vector3<Real> velocity = minus(normalised3(plus(position, shift)), position);
  const Vector3<Real> neighbour_velocity = minus(normalised3(plus(neighbour_position, neighbour_shift)), neighbour_position);
  // Mutant planet.collision.neighbour_sign (both twins): the neighbour's chord projected on d, not −d.
  const Real neighbour_sign = mutant_active("planet.collision.neighbour_sign") ? Real(1) : Real(-1);
  return length3(shift) * dot3(velocity, direction) +
         length3(neighbour_shift) * dot3(neighbour_velocity, scaled(direction, neighbour_sign));
}

template <class Real>
PlanetElevation<Real> planet_elevation(const CubeSphere& sphere, const PlanetParams& params,
                                       const std::vector<Real>& positions, const PlatePartition& partition) {
  require_whole(params, partition);
  PlanetElevation<Real> result;
  result.motion = plate_motion(params, positions, partition);
  result.noisy = noisy_elevation(params, positions, partition, result.motion.base);
  result.collided = collided_elevation(sphere, params, positions, partition, result.motion, result.noisy);
  result.smoothed = smoothed_elevation(sphere, params.smooths() ? params.smoothing : Smoothing::off, result.collided);
  return result;
}

template <class Real>
std::vector<Real> smoothed_elevation(const CubeSphere& sphere, Smoothing smoothing, std::vector<Real> elevation) {
  switch (smoothing) {
    case Smoothing::jacobi: return jacobi_smoothed(sphere, elevation);
    case Smoothing::legacy: return legacy_smoothed(sphere, std::move(elevation));
    case Smoothing::off: break;
  }
  return elevation;
}

#define GT_INSTANTIATE_PLANET_ELEVATION(Real)                                                                      \
  template PlateMotion<Real> plate_motion(const PlanetParams&, const std::vector<Real>&, const PlatePartition&); \
  template Real pressure(PressureFormula, const Vector3<Real>&, const Vector3<Real>&, const Vector3<Real>&,      \
                         const Vector3<Real>&);                                                                  \
  template std::vector<Real> smoothed_elevation(const CubeSphere&, Smoothing, std::vector<Real>);               \
  template PlanetElevation<Real> planet_elevation(const CubeSphere&, const PlanetParams&, const std::vector<Real>&, \
                                                  const PlatePartition&);
GT_INSTANTIATE_PLANET_ELEVATION(double)
GT_INSTANTIATE_PLANET_ELEVATION(float)
#undef GT_INSTANTIATE_PLANET_ELEVATION

}  // namespace gt::reference
