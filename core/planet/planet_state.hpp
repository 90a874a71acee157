// The state of seed 002's Earth-like generator (digest 002 §9.1) as both twins return it: core data
// types, shared by reference/planet/ and gpu/planet/. What each field holds and how it is computed:
// core/params/planet.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gt {

template <class Real>
using Vector3 = std::array<Real, 3>;

// Step 1.
template <class Real>
struct JitteredRegions {
  std::vector<Real> offsets;    // 2 per region: a, b in [0, 1] (cells)
  std::vector<Real> positions;  // 3 per region: x, y, z on the unit sphere
};

// Steps 2–3.
struct PlatePartition {
  std::vector<std::int32_t> plate;    // per region, 0..P−1
  std::vector<std::uint8_t> is_edge;  // per region: 1 when a valid neighbour has another plate
  int cycles = 0;                     // cycles of the flood fill until it stopped
};

// Steps 4–6, per plate.
template <class Real>
struct PlateMotion {
  std::vector<Vector3<Real>> centre;  // unit length, or 0 for a plate with an empty sum
  std::vector<Vector3<Real>> shift;   // s_k, |s_k| in [0.5, 1], or 0
  std::vector<Real> base;             // b_k in [−e_r, e_r]
};

// Steps 4–9.
template <class Real>
struct PlanetElevation {
  PlateMotion<Real> motion;
  std::vector<Real> noisy;     // E0 = base + S·fbm, per region
  std::vector<Real> collided;  // E1 = E0 + C·Σ pressure on edge regions
  std::vector<Real> smoothed;  // E2: the elevation (E1 when smoothing does not run)
};

}  // namespace gt
