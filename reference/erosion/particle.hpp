// Particle (droplet) water erosion of seed 000 (Hydra), CPU reference.
//
// particle_erosion(heights, constants, iterations, ordering) -> heights, droplet maps and ledger
//   heights     Grid<Real> in the units of `constants` (seed 000's normalised [0,1] heights by
//               default); cells with valid == 0 behave as outside the grid: they read 0 and a write
//               to them is lost (GLSL's image semantics, which Hydra's kernel relies on).
//   constants   core/params/particle.hpp; Real = float rounds each constant once, as the GPU does.
//   iterations  outer iterations of Algorithm 7, each spacing² passes, one droplet per texel.
//   ordering    race and disjoint: the droplets of a pass run one after the other in row-major
//               order of their block, each on the heights its predecessors left (the defined truth);
//               batch: every droplet of a pass reads the heights of the pass's start and its
//               erosion and deposition are integer quanta added into a delta applied at the end.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// The ledger (double, summed over every pass) names every place where material enters or leaves
// the terrain, so that
//   Σ heights after + sediment_at_end + sediment_left + deposited_outside
//     = Σ heights before + eroded_outside + clamp_created + apply_rounding      (up to rounding)
// and in batch ordering the same identity holds exactly in quanta (the *_quanta fields).
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/params/particle.hpp"

namespace gt::reference {

struct DropletLedger {
  double eroded = 0.0;             // taken from terrain cells (inside the grid, valid)
  double deposited = 0.0;          // given to terrain cells
  double eroded_outside = 0.0;     // picked up at texels outside the grid or masked: created from nothing
  double deposited_outside = 0.0;  // dropped at texels outside the grid or masked: lost
  double clamp_created = 0.0;      // unbilinear erosion stored as max(h - add, 0): add - removed
  double sediment_at_end = 0.0;    // carried by droplets whose lifetime ran out: lost with them
  double sediment_left = 0.0;      // carried by droplets that left across x <= 0 or y <= 0
  double apply_rounding = 0.0;     // batch: what rounding the heights + delta to Real added
  long long droplets = 0;
  long long droplets_left = 0;     // of them, ended by the position check
  long long steps = 0;             // droplet steps taken (a droplet's steps up to its end)
  // Batch ordering, in quanta: exact integers.
  long long eroded_quanta = 0, deposited_quanta = 0, eroded_outside_quanta = 0, deposited_outside_quanta = 0,
            clamp_created_quanta = 0, sediment_end_quanta = 0;
  long long applied_quanta = 0;  // Σ of the deltas applied to terrain cells: the terrain's change in quanta
  long long largest_cell_delta_quanta = 0;  // the largest |delta| of one cell in one pass (int32 on the GPU)
};

template <class Real>
struct ParticleRun {
  Grid<Real> heights;
  // Hydra's side maps before their contrasts: at the droplet's texel (ipos), what it eroded in all
  // (the depth map) and what it deposited (the sediment map), as the upstream kernel writes them.
  Grid<double> eroded_at_droplet;
  Grid<double> deposited_at_droplet;
  DropletLedger ledger;
};

template <class Real>
ParticleRun<Real> particle_erosion(const Grid<Real>& heights, const ParticleConstants& constants, int iterations,
                                   DropletOrdering ordering);

// One droplet started at texel `base` on `heights` (sequential ordering), for spec vectors: the
// positions it occupied after each step (the start first) and the sediment it carried at the end.
template <class Real>
struct DropletPath {
  std::vector<std::pair<Real, Real>> positions;
  Real sediment = 0;
};
template <class Real>
DropletPath<Real> run_one_droplet(Grid<Real>& heights, const ParticleConstants& constants, int base_x, int base_y);

}  // namespace gt::reference
