// The flow map of seed 000 (Hydra, §4.7, eqs. 4.12-4.13, digest 000 §4.7 and Appendix A's flow.glsl
// notes), CPU reference.
//
// flow_map(heights, constants) -> concentration after the plug pass, and what it did
//   heights     Grid<Real>, read only, in the units the erosion's constants are given in (cells with
//               valid == 0 read 0, as off the grid).
//   constants   core/params/particle.hpp's FlowConstants (Real = float rounds each once, as the GPU).
//   returns     concentration in [0, 1] per texel (the heights' geometry and mask; masked texels 0)
//               after the plug pass, the number of texels the plug pass filled, and the droplets run.
// Orderings: race and disjoint run the droplets of a pass one after the other in row-major order
// (the truth); batch counts weights in fixed point (core/params/particle.hpp's FlowConstants).
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
#pragma once

#include <cstddef>

#include "core/grid.hpp"
#include "core/params/particle.hpp"

namespace gt::reference {

template <class Real>
struct FlowMapRun {
  Grid<Real> concentration;    // after the plug pass
  std::size_t plugged = 0;     // open texels the plug pass filled (0 or NaN before it)
  std::size_t droplets = 0;
};

template <class Real>
FlowMapRun<Real> flow_map(const Grid<Real>& heights, const FlowConstants& constants);

}  // namespace gt::reference
