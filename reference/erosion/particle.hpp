// Particle (droplet) water erosion of seed 000 (Hydra; digest 000 §4.4, Appendix A, Algorithms 4-8), CPU reference.
//
// particle_erosion(heights, constants, iterations, ordering[, colour]) -> heights, droplet maps,
//   ledger and colour (DropletRun, reference/erosion/droplets.hpp)
// run_one_droplet(heights, constants, base_x, base_y[, colour]) -> DropletPath: one droplet started at
//   texel `base` on `heights` (sequential ordering), for spec vectors: the positions it occupied after
//   each step (the start first) and the sediment it carried at the end. With `colour` (the heights'
//   size) the droplet transports it, and it is changed in place.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  heights     Grid<Real>; cells with valid == 0 behave as outside the grid: they read 0 and a
//                      write to them is lost (GLSL's image semantics, which Hydra's kernel relies on).
//          constants   core/params/particle.hpp; Real = float rounds each constant once, as the GPU does.
//          iterations  outer iterations of Algorithm 7, each spacing² passes, one droplet per texel.
//          ordering    race and disjoint: the droplets of a pass run one after the other in row-major
//                      order of their block, each on the heights its predecessors left (the defined
//                      truth); batch: every droplet of a pass reads the heights of the pass's start and
//                      its erosion and deposition are integer quanta added into a delta applied at the end.
//          colour      optional: a colour map of the heights' size (reference/erosion/droplets.hpp) that
//                      the droplets transport (§4.5: picked up on erosion, deposited on deposition). Null:
//                      no colour is transported and everything else is as with it. Batch ordering: colour
//                      frozen during a pass, the deposits' weighted mean applied at its end
//                      (reference/erosion/particle.cpp).
// Outputs: DropletRun: the heights; the ledger and the side maps (reference/erosion/droplets.hpp), the
//          side maps Real sums (batch: quanta) stored as double, twins of the GPU's eroded_at_droplet() /
//          deposited_at_droplet(); the transported colour in DropletRun::colour (empty without `colour`).
// Units:   heights in the units of `constants` (seed 000's normalised [0,1] heights by default);
//          positions in texels.
// Throws:  std::invalid_argument when `colour`'s size differs from the heights'; in batch ordering,
//          RunawayRun (core/errors.hpp) when a cell's delta in one pass exceeds the GPU's 32-bit counter,
//          std::runtime_error when a colour term or sum, or a side map's count of quanta does.
// Twin:    gpu/erosion/particle.hpp (ParticleErosion) with gpu/shaders/erosion/particle_droplets.comp,
//          particle_apply.comp, particle_block.glsl and hydra_motion.glsl.
// Decisions: in reference/erosion/particle.cpp (pass order, batch quanta, colour transport).
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/params/particle.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt::reference {

template <class Real>
DropletRun<Real> particle_erosion(const Grid<Real>& heights, const ParticleConstants& constants, int iterations,
                                   DropletOrdering ordering, const ColourMap<Real>* colour = nullptr);

// One droplet started at texel `base` on `heights` (sequential ordering), for spec vectors: the
// positions it occupied after each step (the start first) and the sediment it carried at the end.
// With `colour` (the heights' size) the droplet transports it, and it is changed in place.
template <class Real>
struct DropletPath {
  std::vector<std::pair<Real, Real>> positions;
  Real sediment = 0;
};
template <class Real>
DropletPath<Real> run_one_droplet(Grid<Real>& heights, const ParticleConstants& constants, int base_x, int base_y,
                                  ColourMap<Real>* colour = nullptr);

}  // namespace gt::reference
