// Droplet hydraulic erosion after Beyer 2015 (seed 000 §2.7, eqs. 2.35-2.45; digest 000 §3.7), CPU reference.
//
// beyer_erosion(heights, constants, iterations, ordering[, first_iteration]) -> heights, droplet maps and
//   ledger (DropletRun)
// beyer_brush_weights(heights, x, y, radius) -> eq. 2.42's brush for a droplet at (x, y), as the
//   kernel computes it in Real
// beyer_one_droplet(heights, constants, x, y, droplet_id) -> BeyerPath: one droplet (spec vectors)
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  heights     Grid<Real>, samples at integer points; cells with valid == 0 are no data: a
//                      droplet whose bilinear cell touches one is off the map, and the brush skips them.
//          constants   core/params/beyer.hpp; Real = float rounds each constant once, as the GPU does.
//          iterations  outer iterations of Algorithm 7, each spacing² passes, one droplet per texel.
//          ordering    race and disjoint: the droplets of a pass run one after the other in row-major
//                      order of their block, each on the heights its predecessors left (the defined
//                      truth); batch: every droplet of a pass reads the heights of the pass's start and
//                      its erosion and deposition are integer quanta added into a delta applied at the end.
//          droplet_id  the RNG counter of a single droplet's random directions.
// Outputs: DropletRun: the heights, the ledger and the side maps (reference/erosion/droplets.hpp).
//          Beyer's droplets never touch a sample off the map, so the ledger's *_outside and clamp
//          terms stay 0; the side maps get each step's eroded or deposited total at the droplet's old
//          cell. The brush: at each sample (sx, sy) with sx in [ceil(x - radius), floor(x + radius)]
//          (sy alike) that lies inside the grid and is valid, w / Σw with w = max(radius - |(sx, sy) -
//          (x, y)|, 0); 0 at every other cell; all zeros when Σw is 0 (the kernel then erodes nothing).
//          BeyerPath: the positions the droplet occupied after each step it completed (the start
//          first), what it carried when it ended, and whether it ended by leaving the map.
// Units:   heights in the units of `constants` (seed 000's normalised [0,1] heights by default);
//          positions in texels.
// Throws:  RunawayRun (core/errors.hpp) in batch ordering when a cell's delta in one pass exceeds the
//          GPU's 32-bit counter.
// Twin:    gpu/erosion/beyer.hpp (BeyerErosion) with gpu/shaders/erosion/beyer_droplets.comp,
//          beyer_apply.comp and beyer_block.glsl.
// Decisions: in reference/erosion/beyer.cpp and gpu/shaders/erosion/beyer_droplets.comp (shared).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/grid.hpp"
#include "core/params/beyer.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt::reference {

template <class Real>
DropletRun<Real> beyer_erosion(const Grid<Real>& heights, const BeyerConstants& constants, int iterations,
                               DropletOrdering ordering, int first_iteration = 0);

// Eq. 2.42's brush for a droplet at (x, y) on `heights`, as the kernel computes it in Real: at each
// sample (sx, sy) with sx in [ceil(x - radius), floor(x + radius)] (sy alike) that lies inside the
// grid and is valid, w / Σw with w = max(radius - |(sx, sy) - (x, y)|, 0); 0 at every other cell.
// All zeros when Σw is 0 (the kernel then erodes nothing).
template <class Real>
Grid<double> beyer_brush_weights(const Grid<Real>& heights, Real x, Real y, Real radius);

// One droplet started at (x, y) on `heights` (sequential ordering), for spec vectors: the positions
// it occupied after each step it completed (the start first), what it carried when it ended, and
// whether it ended by leaving the map. `droplet_id` is the RNG counter of its random directions.
template <class Real>
struct BeyerPath {
  std::vector<std::pair<Real, Real>> positions;
  Real sediment = 0;
  Real speed = 0;
  Real water = 0;
  bool left = false;
};
template <class Real>
BeyerPath<Real> beyer_one_droplet(Grid<Real>& heights, const BeyerConstants& constants, Real x, Real y,
                                  std::uint32_t droplet_id);

}  // namespace gt::reference
