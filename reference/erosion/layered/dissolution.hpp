// Dissolution (regolith erosion) on seed 001's layered ground (digest 001 §3.9, §3.13; step 7 of §4), CPU reference.
//
// dissolution_step(ground, water, params): per column, with r = r_org + r_sand the regolith the water
//   holds and r_max = min(w, K_r) (eq. 2.3):
//   r < r_max: request K_re·(r_max − r), half from organic matter and half from sand, each removed
//     as force erosion removes (erode_component, column.hpp: top layer first, transparency to the
//     one below; thesis §3.13); the taken amounts join r_org and r_sand.
//   r > r_max: K_rd·(r − r_max) settles with the regolith's composition: each kind gives the share
//     f = K_rd·(r − r_max)/r of itself (all of it when less than negligible_amount would stay,
//     layered_water.hpp), laid down with reserve-then-deposit (§3.1).
//   Nothing when K_r = 0 (the code's switch). Bedrock never dissolves (§3.13).
//
// Inputs:  ground (LayeredGround<Real>), water (LayeredWater<Real>, core/layered/layered_water.hpp: w
//          and the regolith r_org, r_sand it carries), params (K_r, K_re, K_rd).
// Outputs: ground and water changed in place. Moving the material between the ground and the water
//          converts nothing.
// Units:   metres.
// Throws:  nothing.
// Twin:    gpu/shaders/erosion/layered/dissolution.comp, run as a LayeredWaterPass
//          (gpu/erosion/layered/water_buffers.hpp) by gpu/erosion/layered/iteration.hpp.
#pragma once

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

template <class Real>
void dissolution_step(LayeredGround<Real>& ground, LayeredWater<Real>& water, const LayeredParams& params);

}  // namespace gt::reference
