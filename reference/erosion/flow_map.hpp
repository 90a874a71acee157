// The flow map of seed 000 (Hydra, §4.7, eqs. 4.12-4.13; digest 000 §4.7, Appendix A's flow.glsl notes), CPU reference.
//
// flow_map(heights, constants) -> FlowMapRun: the concentration after the plug pass, and what it did
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  heights     Grid<Real>, read only (cells with valid == 0 read 0, as off the grid).
//          constants   core/params/particle.hpp's FlowConstants (Real = float rounds each once, as the GPU).
//                      Orderings: race and disjoint run the droplets of a pass one after the other in
//                      row-major order (the truth); batch counts weights in fixed point.
// Outputs: concentration in [0, 1] per texel (the heights' geometry and mask; masked texels 0) after
//          the plug pass, the number of open texels the plug pass filled (0 or NaN before it), and the
//          droplets run.
// Units:   heights in the units the erosion's constants are given in; concentration dimensionless.
// Throws:  std::invalid_argument when constants.spacing < 1; std::runtime_error in batch ordering when
//          a texel's weight count exceeds the GPU's 32-bit counter.
// Twin:    gpu/erosion/flow_map.hpp (FlowMap) with gpu/shaders/erosion/flow_map_droplets.comp,
//          flow_map_plug.comp, flow_map_block.glsl and hydra_motion.glsl.
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
