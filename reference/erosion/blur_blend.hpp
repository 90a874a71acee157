// Beyer's blend with a blurred map (seed 000 §2.7, eq. 2.43; digest 000 §3.7), CPU reference:
// map = c_b·map_blurred + (1 - c_b)·map, the thesis's other way to remove features too thin for
// droplets, applied by erosion.beyer after each outer iteration of Algorithm 7.
//
// blur_blend(heights, blend, algorithm) -> heights blended in place (in Real)
// blur_blend_quanta(heights, blend, inverse_quantum, delta, algorithm) -> the blend as quanta added to
//   a batch delta (reference/erosion/droplets.hpp), which the caller applies
//
// Decisions (the thesis names neither the blur nor the border):
//   - the blur is the 3x3 box, the smallest; inside the grid eq. 2.43 is then
//     h + c_b/9·Σ_n (h_n - h) over the 8 Moore neighbours n;
//   - it is written as exchanges between neighbours: cell a receives w·(h_b - h_a), w = Real(c_b/9)
//     rounded once, from each neighbour b that is inside the grid and valid (the border and no-data
//     cells exchange nothing: a mirror border), so the pairs cancel exactly and the blend conserves
//     the terrain's volume, which a box blur renormalised at the border would not;
//   - Jacobi: every cell reads the heights as the blend found them;
//   - each cell sums its exchanges in the order of core/grid.hpp's moore_offsets from 0, then adds
//     the sum to its height (two roundings orders the GPU repeats: gpu/shaders/erosion/blur_blend.comp);
//   - batch: each exchange becomes nearbyint(w·(h_b - h_a)·inverse_quantum) quanta (ties to even:
//     the count of b → a is exactly minus that of a → b), so the ledger's identity in quanta holds.
// Inputs:  heights Grid<Real> with its mask; blend c_b in [0, 1] (0 changes nothing); inverse_quantum
//          1/quantum (a power of two); `algorithm` names the caller's mutants ("erosion.beyer").
// Outputs: heights blended in place (blur_blend), or each open cell's quanta added to `delta`
//          (blur_blend_quanta); no-data cells unchanged, and their delta 0.
// Units:   heights in the caller's units; c_b dimensionless.
// Throws:  nothing (BatchDelta::apply, the caller's, refuses a delta beyond int32).
// Mutant:  <algorithm>.blur_renormalised_at_border (both twins): the box blur renormalised over the
//          samples it finds, w = c_b/(1 + open neighbours): the border's exchanges lose their pairs and
//          the volume drifts (ledger.closure).
// Twin:    gpu/erosion/blur_blend.hpp with gpu/shaders/erosion/blur_blend.comp.
#pragma once

#include <string>

#include "core/grid.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt::reference {

template <class Real>
void blur_blend(Grid<Real>& heights, double blend, const std::string& algorithm);

template <class Real>
void blur_blend_quanta(const Grid<Real>& heights, double blend, Real inverse_quantum, BatchDelta<Real>& delta,
                       const std::string& algorithm);

}  // namespace gt::reference
