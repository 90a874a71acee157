// Thermal erosion of Jákó & Tóth 2011 (digest 000 §3.6, eqs. 2.30-2.34), CPU reference.
//
// thermal_jako_erosion(heights, constants, iterations) -> eroded heights
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  heights     Grid<Real> on the 8-neighbourhood pipe system; cells with valid == 0 take no part.
//          constants   thermal_jako_constants(): talus slope C_i = tan(angle), C_a, neighbour
//                      distances, request_factor = rate = Δt·C_t of eq. 2.32, and the hardness map
//                      R (empty: 1 everywhere; same size as heights).
//          iterations  the number of iterations (two synchronous passes each: outflow, gather).
// Outputs: the heights after the iterations, with the input's geometry, units and mask.
// Units:   heights and lengths in metres; rate dimensionless in [0, 1].
// Throws:  nothing.
// Twin:    gpu/erosion/thermal_jako.hpp (ThermalJakoErosion) with gpu/shaders/erosion/thermal_jako_outflow.comp,
//          thermal_jako_gather.comp and thermal_jako_block.glsl.
// Decisions: in reference/erosion/thermal_jako.cpp (H over the set A, height differences in eq. 2.34).
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> thermal_jako_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations);

}  // namespace gt::reference
