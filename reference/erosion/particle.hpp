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
// The ledger and the side maps: reference/erosion/droplets.hpp.
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/params/particle.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt::reference {

template <class Real>
DropletRun<Real> particle_erosion(const Grid<Real>& heights, const ParticleConstants& constants, int iterations,
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
