// Wetness of seed 001's layered ground (digest 001 §3.15, eq. 3.12; step 9 of §4), CPU reference.
//
// wetness_step(water, params): per column, wet ← wet + Δt·w where the column holds water,
//   wet ← wet·K_dry^Δt where it is dry (K_dry^Δt computed once in double, then rounded to Real, as the
//   GPU twin receives it); a wetness below negligible_amount (layered_water.hpp) becomes 0.
//
// Inputs:  water (LayeredWater<Real>: w and the wetness), params (Δt, K_dry).
// Outputs: the wetness, in place. The flood death it causes is the vegetation step's (vegetation.hpp).
// Units:   wetness in m·s, w in m, Δt in s.
// Throws:  nothing.
// Twin:    gpu/shaders/erosion/layered/wetness.comp, run as a LayeredWaterPass
//          (gpu/erosion/layered/water_buffers.hpp) by gpu/erosion/layered/iteration.hpp.
#pragma once

#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void wetness_step(LayeredWater<Real>& water, const LayeredParams& params);

}  // namespace gt::reference
