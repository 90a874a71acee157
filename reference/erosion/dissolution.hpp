// Beneš's dissolution erosion (Beneš 2002 via seed 000 §2.3; digest 000 §3.3, eqs. 2.1-2.9), CPU
// reference.
//
// dissolution_erosion(state, constants, iterations) -> the state after the iterations
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation;
// Real = RoundingInterval (core/rounding_interval.hpp) gives the shadow step's per-cell bounds.
//
// Inputs:  state       DissolutionState<Real> (core/params/dissolution.hpp): terrain, water,
//                      dissolved, evaporated; one geometry, the terrain's mask (cells with valid == 0
//                      take no part and keep their values).
//          constants   dissolution_constants(): K_r, e^{-K_e}, T, K_s, the two rates.
//          iterations  the number of iterations, each: rain and evaporation, dissolution or
//                      deposition (eq. 2.5), transport to the 8 neighbours (eqs. 2.6-2.9).
// Outputs: the state after the iterations, same geometry, units and mask.
// Units:   heights, depths and dissolved material in the terrain's vertical unit (metres).
// Throws:  nothing.
// Twin:    gpu/erosion/dissolution.hpp (DissolutionErosion) with gpu/shaders/erosion/dissolution_local.comp,
//          dissolution_outflow.comp, dissolution_gather.comp and dissolution_block.glsl.
// Decisions: in reference/erosion/dissolution.cpp.
#pragma once

#include "core/params/dissolution.hpp"

namespace gt::reference {

template <class Real>
DissolutionState<Real> dissolution_erosion(const DissolutionState<Real>& state, const DissolutionConstants& constants,
                                           int iterations);

}  // namespace gt::reference
