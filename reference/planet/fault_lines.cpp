// The fault-line planet's votes, CPU reference (see fault_lines.hpp; the spec in
// core/params/fault_planet.hpp).
#include "reference/planet/fault_lines.hpp"

#include <cmath>
#include <type_traits>

#include "core/mutant.hpp"

namespace gt::reference {

template <class Real>
std::vector<std::int32_t> fault_votes(const std::vector<Real>& positions, const std::vector<Real>& normals) {
  const bool raise_only = mutant_active("planet.fault_lines.raise_only");
  const Real plane_offset = mutant_active("planet.fault_lines.plane_off_centre") ? Real(0.05) : Real(0);
  const bool nudged = std::is_same_v<Real, float> && mutant_active("planet.fault_lines.float_dot_nudged");
  const std::size_t regions = positions.size() / 3, faults = normals.size() / 3;
  std::vector<std::int32_t> votes(regions, 0);
  for (std::size_t region = 0; region < regions; ++region) {
    const Real* p = &positions[3 * region];
    std::int32_t count = 0;
    for (std::size_t fault = 0; fault < faults; ++fault) {
      const Real* n = &normals[3 * fault];
      Real dot = (n[0] * p[0] + n[1] * p[1]) + n[2] * p[2];
      if (nudged) dot = dot + Real(0x1p-12) * ((std::abs(n[0] * p[0]) + std::abs(n[1] * p[1])) + std::abs(n[2] * p[2]));
      if (dot > plane_offset) {
        ++count;
      } else if (!raise_only) {
        --count;
      }
    }
    votes[region] = count;
  }
  return votes;
}

double dot_error_bound(const std::array<double, 3>& normal, const double* position, double unit_roundoff) {
  double magnitude = 0.0;
  for (int c = 0; c < 3; ++c) magnitude += std::abs(normal[c] * position[c]);
  return 6.0 * unit_roundoff * magnitude;
}

template std::vector<std::int32_t> fault_votes(const std::vector<double>&, const std::vector<double>&);
template std::vector<std::int32_t> fault_votes(const std::vector<float>&, const std::vector<float>&);

}  // namespace gt::reference
