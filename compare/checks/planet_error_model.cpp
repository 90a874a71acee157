// The planet twins' error model; see planet_error_model.hpp for the derivation.
#include "compare/checks/planet_error_model.hpp"

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"

namespace gt {
namespace {

constexpr double unit_roundoff = 0x1p-24;
const double root3 = std::sqrt(3.0);
constexpr double perlin_lipschitz = 3.9;  // compare/algorithms/noise.cpp's traits for perlin3

using Vector = Vector3<double>;

double norm(const Vector& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }
Vector difference(const Vector& a, const Vector& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vector position_at(const std::vector<double>& positions, std::size_t region) {
  return {positions[3 * region], positions[3 * region + 1], positions[3 * region + 2]};
}

double draw(const PlanetParams& params, int plate, std::uint32_t step) {
  return uniform01(random_u32(params.seed, static_cast<std::uint32_t>(plate), step, planet_stream_shift));
}

// δs per plate (shift error), from the centre's conditioning.
std::vector<double> shift_errors(const PlanetParams& params, const std::vector<double>& positions,
                                 const PlatePartition& partition, const PlanetErrorModel& model) {
  const double u = model.operation_error;
  std::vector<Vector> sums(static_cast<std::size_t>(params.plates), Vector{});
  std::vector<double> counts(sums.size(), 0.0);
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    if (params.centre == PlateCentre::edge_sum && !partition.is_edge[region]) continue;
    for (int axis = 0; axis < 3; ++axis) sums[partition.plate[region]][axis] += positions[3 * region + axis];
    counts[partition.plate[region]] += 1.0;
  }
  std::vector<double> errors;
  for (int plate = 0; plate < params.plates; ++plate) {
    const double sum_length = norm(sums[plate]);
    const double magnitude = 0.5 + 0.5 * draw(params, plate, 0);
    const double alpha = 2.0 * draw(params, plate, 1) - 1.0, beta = 2.0 * draw(params, plate, 2) - 1.0;
    if (!(sum_length > 0.0)) {
      errors.push_back(0.0);
      continue;
    }
    const Vector centre{sums[plate][0] / sum_length, sums[plate][1] / sum_length, sums[plate][2] / sum_length};
    const double centre_error = 2.0 * counts[plate] * (root3 * model.position_error + 0x1p-30) / sum_length + 6.0 * u;
    const double tangent = norm({-beta * centre[2], alpha * centre[2], beta * centre[0] - alpha * centre[1]});
    errors.push_back(tangent > 0.0 ? 2.0 * magnitude * (3.0 * centre_error + 4.0 * u) / tangent + 4.0 * u * magnitude
                                   : 0.0);
  }
  return errors;
}

// δ of one side's term of the code's pressure: |s|·(t·d).
double code_term_error(const Vector& position, const Vector& shift, double shift_error, double direction_error,
                       const PlanetErrorModel& model) {
  const double u = model.operation_error, e = model.position_error;
  const Vector moved{position[0] + shift[0], position[1] + shift[1], position[2] + shift[2]};
  const double moved_length = norm(moved);
  const double shift_length = norm(shift);
  if (!(moved_length > 0.0)) return 0.0;
  const Vector chord = difference(Vector{moved[0] / moved_length, moved[1] / moved_length, moved[2] / moved_length}, position);
  const double chord_length = norm(chord);
  const double chord_error = 2.0 * ((e + shift_error) * root3 + 2.0 * u) / moved_length + 4.0 * u + root3 * e + 2.0 * u;
  return root3 * shift_error * chord_length + shift_length * (chord_error + chord_length * direction_error) +
         4.0 * u * shift_length * chord_length;
}

// δ of one side's term of eq. 5.3: |v|·(v·Δ).
double thesis_term_error(const Vector& position, const Vector& shift, double shift_error, double distance,
                         const PlanetErrorModel& model) {
  const double u = model.operation_error, e = model.position_error;
  const double along = shift[0] * position[0] + shift[1] * position[1] + shift[2] * position[2];
  const double velocity = norm(difference(shift, Vector{along * position[0], along * position[1], along * position[2]}));
  const double velocity_error = root3 * shift_error + 2.0 * root3 * norm(shift) * e + 6.0 * u;
  return 2.0 * velocity * distance * velocity_error + velocity * velocity * (2.0 * root3 * e + 2.0 * u) +
         6.0 * u * velocity * velocity * distance;
}

double pair_error(const PlanetParams& params, const Vector& position, const Vector& shift, double shift_error,
                  const Vector& neighbour, const Vector& neighbour_shift, double neighbour_shift_error,
                  const PlanetErrorModel& model) {
  const double u = model.operation_error, e = model.position_error;
  const double distance = norm(difference(neighbour, position));
  if (params.pressure == PressureFormula::thesis) {
    return thesis_term_error(position, shift, shift_error, distance, model) +
           thesis_term_error(neighbour, neighbour_shift, neighbour_shift_error, distance, model);
  }
  const double direction_error = distance > 0.0 ? 2.0 * (2.0 * root3 * e + 2.0 * u) / distance + 4.0 * u : 2.0;
  return code_term_error(position, shift, shift_error, direction_error, model) +
         code_term_error(neighbour, neighbour_shift, neighbour_shift_error, direction_error, model);
}

std::vector<double> noise_bounds(const PlanetParams& params, const PlatePartition& partition,
                                 const PlanetElevation<double>& reference, const PlanetErrorModel& model) {
  const double u = model.operation_error;
  double octave_gain = 0.0, weights = 0.0, weight = 1.0;
  for (int octave = 0; octave < params.perlin_octaves; ++octave, weight *= 0.5) {
    octave_gain += 1.0;  // (g·2)^k = 1 for g = 0.5, lacunarity 2
    weights += weight;
  }
  const double strength = params.noise ? params.perlin_strength : 0.0;
  const double noise = strength * (perlin_lipschitz * params.perlin_frequency * root3 * (model.position_error + u) *
                                       (octave_gain / weights) +
                                   64.0 * u) +
                       3.0 * u * strength;
  std::vector<double> bounds(partition.plate.size());
  for (std::size_t region = 0; region < bounds.size(); ++region) {
    bounds[region] = 4.0 * u * std::abs(reference.motion.base[partition.plate[region]]) + noise;
  }
  return bounds;
}

std::vector<double> collision_bounds(const CubeSphere& sphere, const PlanetParams& params,
                                     const std::vector<double>& positions, const PlatePartition& partition,
                                     const PlanetElevation<double>& reference, const PlanetErrorModel& model,
                                     const std::vector<double>& noisy_bounds) {
  if (!params.collisions) return noisy_bounds;
  const auto shift_error = shift_errors(params, positions, partition, model);
  const auto& shifts = reference.motion.shift;
  std::vector<double> bounds = noisy_bounds;
  for (std::size_t region = 0; region < bounds.size(); ++region) {
    if (!partition.is_edge[region]) continue;
    const std::int32_t own = partition.plate[region];
    double pairs = 0.0, pressures = 0.0;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region || partition.plate[neighbour] == own) continue;
      const std::int32_t other = partition.plate[neighbour];
      pairs += pair_error(params, position_at(positions, region), shifts[own], shift_error[own],
                          position_at(positions, neighbour), shifts[other], shift_error[other], model);
    }
    pressures = std::abs(reference.collided[region] - reference.noisy[region]);
    bounds[region] += params.collision_strength * pairs +
                      3.0 * model.operation_error * (std::abs(reference.noisy[region]) + pressures);
  }
  return bounds;
}

std::vector<double> smoothing_bounds(const CubeSphere& sphere, const PlanetParams& params,
                                     const PlanetElevation<double>& reference, const std::vector<double>& collided_bounds,
                                     const PlanetErrorModel& model) {
  if (!params.smooths() || params.smoothing == Smoothing::off) return collided_bounds;
  const double u = model.operation_error;
  if (params.smoothing == Smoothing::legacy) {
    double largest_magnitude = 0.0;
    for (const double value : reference.collided) largest_magnitude = std::max(largest_magnitude, std::abs(value));
    const double bound = *std::max_element(collided_bounds.begin(), collided_bounds.end()) + 11.0 * u * largest_magnitude;
    return std::vector<double>(collided_bounds.size(), bound);
  }
  std::vector<double> bounds(collided_bounds.size());
  for (std::size_t region = 0; region < bounds.size(); ++region) {
    double error = collided_bounds[region], magnitude = std::abs(reference.collided[region]);
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region) continue;
      error = std::max(error, collided_bounds[neighbour]);
      magnitude = std::max(magnitude, std::abs(reference.collided[neighbour]));
    }
    bounds[region] = error + 11.0 * u * magnitude;
  }
  return bounds;
}

}  // namespace

double float_position_error() { return 32.0 * unit_roundoff; }

double gpu_position_error() { return 4.0 * float_position_error(); }

ElevationBounds elevation_bounds(const CubeSphere& sphere, const PlanetParams& params,
                                 const std::vector<double>& positions, const PlatePartition& partition,
                                 const PlanetElevation<double>& reference, const PlanetErrorModel& model) {
  ElevationBounds bounds;
  bounds.noisy = noise_bounds(params, partition, reference, model);
  bounds.collided = collision_bounds(sphere, params, positions, partition, reference, model, bounds.noisy);
  bounds.smoothed = smoothing_bounds(sphere, params, reference, bounds.collided, model);
  return bounds;
}

}  // namespace gt
