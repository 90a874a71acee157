// Material conversion (weathering) on the layered ground (digest 001 §3.16), CPU reference.
//
// weathering_step(ground, params, step, conversions): per column c, in place (a purely local process:
// no column reads another), with v = veg_c and nothing done where v = 0:
//   1. Roots break rock in each soil layer j (topsoil, subsoil), every amount from the layer as it
//      was before this step:
//        a_0 = min(K_conv·Δt·v·K_org, V_sand)       sand → org
//        a_1 = min(K_conv·Δt·v·K_1,0, V_gravel)     gravel → sand
//        a_2 = min(K_conv·Δt·v·K_2,1, V_stones)     stones → gravel
//        a_3 = min(K_conv·Δt·v·K_3,2, V_boulders)   boulders → stones
//        V_org += a_0; V_sand += a_1 − a_0; V_gravel += a_2 − a_1; V_stones += a_3 − a_2; V_boulders −= a_3.
//      Each amount is a thickness (m): K_conv is in m/s.
//   2. Bedrock → soil: when the soil (topsoil + subsoil) is thinner than the reach (4.0 m, the
//      code's "maximum reach of vegetation"), the top non-empty bedrock layer k, of type t, gives
//      q = min(K_t·Δt·v, h_k) (the code's clamp) to the subsoil, the lowest soil layer, split by
//      K_t,i: org, sand, gravel, stones by their shares, boulders the remainder q − (their sum), so
//      the parts sum to q whatever the rounding of ΣK_t,i (as fragments(), column.hpp).
//      The volume is conserved: q m of bedrock becomes q m of soil in the same column, so the
//      surface stays where it is (it is not touched).
// weather_column(ground, params, c, conversions): weathers column c (steps 1 and 2 above) and counts
//   what it converted.
//
// Inputs:  ground and params, valid (assumed, as talus_step, talus.hpp). `step` is unused (weathering
//          draws no random numbers); it is there for the common step protocol.
// Outputs: the ground after the step. Every amount is a conversion between ledger lines, counted in
//          `conversions` (m³: thickness × l_x·l_y): weathered_from/into per component,
//          soil_formed_from per bedrock type, soil_formed_into per component.
// Units:   metres, Δt in seconds, K_conv and K_t in m/s.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/weathering.hpp (LayeredWeathering) with
//          gpu/shaders/erosion/layered/weathering.comp.
// Decisions: the thesis gives no clamp in step 1; the code clamps each amount to its source. Decision:
//          always clamp (so no component goes negative).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

// Weathers column c (steps 1 and 2 above) and counts what it converted.
template <class Real>
void weather_column(LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c,
                    LayeredConversions& conversions);

// One step over every column. Valid parameters and ground assumed, as talus_step (talus.hpp).
template <class Real>
void weathering_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                     LayeredConversions& conversions);

}  // namespace gt::reference
