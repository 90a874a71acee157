// Vegetation growth on the layered ground (digest 001 §3.15), CPU reference.
//
// vegetation_step(ground, params, step, conversions, water = nullptr): every column's new density from
// one snapshot of the old densities (double-buffered, as the code's vegetation2), then written back:
//   - death: a column with no organic matter in either soil layer gets veg' = 0, and the flood
//     death: with `water`, a column whose wetness (wetness.hpp) exceeds flood_wetness gets veg' = 0
//     (the thesis's "critical threshold", the code's wet > 1.0).
//   - soil quality, from the soil sampled down to depth d (topsoil, then subsoil, a layer partly
//     sampled contributing the same share of each component), normalised by min(d, h_soil):
//       q(d) = (Σ_i K_v,i·V*_i(d)) / min(d, h_soil)      (0 where the soil is empty)
//     thesis: q_s = q(K_vd); seed001_code: q_s = (1 − veg)·q(K_vd) + veg·q(d_deep) − vegetation_base
//     (the code's 0.25 m and 2.0 m samples).
//   - nveg: the old densities of the 8 neighbours (thesis), or of the 3 × 3 including the column
//     (seed001_code); neighbours outside a closed border count 0.
//   - veg' = clamp(veg + rand(0,1)·K_veg·Δt·(q_s − K_eveg·veg + K_nveg·nveg), 0, 1); rand from the
//     counter-based RNG keyed (seed, c, step, vegetation_cell_stream).
// soil_quality(ground, params, c, depth) -> q(d) of column c, 0 for an empty soil.
// grown_vegetation(ground, params, x, y, step) -> column (x, y)'s density after one step, from
//   `ground` as it is.
//
// Inputs:  ground and params, valid (assumed, as talus_step, talus.hpp); step: the random draws'
//          counter; water: the ground's water for the flood death, or null.
// Outputs: the densities after the step. Vegetation is a density, not a volume: growth creates no
//          material and converts nothing, so `conversions` is left as it is (organic matter is made
//          only by weathering, weathering.hpp).
// Units:   K_veg in 1/s, Δt in s, depths in m; q_s, veg, nveg dimensionless.
// Throws:  nothing.
// Twin:    gpu/erosion/layered/vegetation.hpp (LayeredVegetation) with
//          gpu/shaders/erosion/layered/vegetation.comp.
// Decisions: the death without organic matter is the code's rule (the thesis is silent), taken for
//          both variants; the code's own normalisation "only if the thickness is > 1" is vague, the
//          thesis's min(d, h_soil) is used for both samples; the thesis writes no clamp, but
//          veg ∈ [0, 1] by definition (the code clamps).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt::reference {

// q(d) of column c: Σ_i K_v,i·V*_i(d) / min(d, h_soil), 0 for an empty soil.
template <class Real>
Real soil_quality(const LayeredGround<Real>& ground, const LayeredParams& params, std::size_t c, Real depth);

// Column (x, y)'s density after one step, from `ground` as it is.
template <class Real>
Real grown_vegetation(const LayeredGround<Real>& ground, const LayeredParams& params, int x, int y,
                      std::uint32_t step);

// One double-buffered step. Valid parameters and ground assumed, as talus_step (talus.hpp).
template <class Real>
void vegetation_step(LayeredGround<Real>& ground, const LayeredParams& params, std::uint32_t step,
                     LayeredConversions& conversions, const LayeredWater<Real>* water = nullptr);

}  // namespace gt::reference
