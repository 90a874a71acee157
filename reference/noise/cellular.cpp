// Cellular noise bases (Worley 1996, as Blender's noise bases; seed 001 §3.18); see cellular.hpp.
#include "reference/noise/cellular.hpp"

#include <cmath>

#include "core/mutant.hpp"
#include "reference/noise/lattice_floor.hpp"

namespace gt::reference {
namespace {

constexpr std::array<int, 3> jitter_entries = {0, 85, 170};  // o_a: the entries P[h + o_a]
constexpr int value_entry = 128;                            // cell noise's entry P[h + 128]
constexpr double far_away = 1e10;                            // F_k before any point is found

int permuted(const Permutation& permutation, int index) { return permutation[index & 255]; }

int cell_hash(const Permutation& permutation, int x, int y, int z) {
  return permuted(permutation, permuted(permutation, permuted(permutation, x) + (y & 255)) + (z & 255));
}

// The entry P[h + o] of the cell's hash as (P + 1/2)/256, exact in float.
double hashed_fraction(const Permutation& permutation, int hash, int entry) {
  return (permuted(permutation, hash + entry) + 0.5) / 256.0;
}

template <class Real>
struct Located {
  std::array<int, 3> cell;   // floor(p)
  std::array<Real, 3> local;  // p − floor(p), exact
};

template <class Real>
Located<Real> locate(Real x, Real y, Real z) {
  const std::array<Real, 3> point = {x, y, z};
  Located<Real> located{};
  for (int axis = 0; axis < 3; ++axis) {
    located.cell[axis] = lattice_floor(point[axis]);
    located.local[axis] = point[axis] - static_cast<Real>(located.cell[axis]);
  }
  return located;
}

// Mutant noise.voronoi.squared_distance (both twins): the squared distance where the distance
// belongs (Blender's "distance squared" metric taken for the Euclidean one).
template <class Real>
Real distance_of(Real squared) {
  return mutant_active("noise.voronoi.squared_distance") ? squared : std::sqrt(squared);
}

// `distance` inserted into the ascending four nearest.
template <class Real>
void keep_nearest(std::array<Real, 4>& nearest, Real distance) {
  if (!(distance < nearest[3])) return;
  int slot = 3;
  while (slot > 0 && distance < nearest[slot - 1]) {
    nearest[slot] = nearest[slot - 1];
    --slot;
  }
  nearest[slot] = distance;
}

}  // namespace

template <class Real>
std::array<Real, 4> voronoi_distances(const Permutation& permutation, Real x, Real y, Real z) {
  const Located<Real> located = locate(x, y, z);
  const Real far = static_cast<Real>(far_away);
  std::array<Real, 4> nearest = {far, far, far, far};
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const std::array<int, 3> offset = {dx, dy, dz};
        const int hash =
            cell_hash(permutation, located.cell[0] + dx, located.cell[1] + dy, located.cell[2] + dz);
        std::array<Real, 3> apart{};
        for (int axis = 0; axis < 3; ++axis) {
          const Real feature = static_cast<Real>(offset[axis] + hashed_fraction(permutation, hash, jitter_entries[axis]));
          apart[axis] = located.local[axis] - feature;
        }
        const Real squared = (apart[0] * apart[0] + apart[1] * apart[1]) + apart[2] * apart[2];
        keep_nearest(nearest, distance_of(squared));
      }
    }
  }
  return nearest;
}

template <class Real>
Real cellular(const Permutation& permutation, NoiseBasis basis, Real x, Real y, Real z) {
  if (basis == NoiseBasis::cell_noise) {
    const Located<Real> located = locate(x, y, z);
    const int hash = cell_hash(permutation, located.cell[0], located.cell[1], located.cell[2]);
    // Mutant noise.cell.value_from_jitter_hash (both twins): the value read from the entry of the
    // point's x jitter, P[h], instead of its own, P[h + 128].
    const int entry = mutant_active("noise.cell.value_from_jitter_hash") ? jitter_entries[0] : value_entry;
    return static_cast<Real>(2.0 * hashed_fraction(permutation, hash, entry) - 1.0);
  }
  const auto nearest = voronoi_distances(permutation, x, y, z);
  const Real gap = nearest[1] - nearest[0];
  switch (basis) {
    case NoiseBasis::voronoi_f1: return Real(2) * nearest[0] - Real(1);
    case NoiseBasis::voronoi_f2: return Real(2) * nearest[1] - Real(1);
    case NoiseBasis::voronoi_f3: return Real(2) * nearest[2] - Real(1);
    case NoiseBasis::voronoi_f4: return Real(2) * nearest[3] - Real(1);
    case NoiseBasis::voronoi_f2f1: return Real(2) * gap - Real(1);
    case NoiseBasis::voronoi_crackle: {
      const Real crackle = Real(10) * gap;
      return Real(2) * (crackle < Real(1) ? crackle : Real(1)) - Real(1);
    }
    default: return Real(0);
  }
}

template std::array<float, 4> voronoi_distances(const Permutation&, float, float, float);
template std::array<double, 4> voronoi_distances(const Permutation&, double, double, double);
template float cellular(const Permutation&, NoiseBasis, float, float, float);
template double cellular(const Permutation&, NoiseBasis, double, double, double);

}  // namespace gt::reference
