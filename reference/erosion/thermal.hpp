// Thermal erosion of seed 000 (Hydra, Vlček 2023 §4.4.3; digest 000 §4.6, Algorithms 9-11), CPU reference.
//
// thermal_erosion(heights, constants, iterations, neighbourhood, first_iteration = 0) -> eroded heights
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
//
// Inputs:  heights          Grid<Real>; cells with valid == 0 take no part: they neither give nor
//                           receive material and keep their value.
//          constants        from core/params/thermal.hpp: talus slope T, neighbour distances, f_s, clamp.
//          iterations       any count >= 0; iteration i uses the cardinal pipes when the neighbourhood
//                           is cardinal, or alternating with i even; the diagonal pipes otherwise.
//          neighbourhood    cardinal, diagonal or alternating (core/params/thermal.hpp).
//          first_iteration  the number of the first iteration run: `heights` is the state after that
//                           many iterations (0 = from the input). It only picks the pipes of an
//                           alternating run, so that a run stepped in pieces (the driver's shadow
//                           steps) equals one in one go.
// Outputs: the heights after the iterations, with the input's geometry, units and mask.
// Units:   heights in the units of `constants` (metres, or [0,1] when normalised), lengths in the same
//          unit; T dimensionless.
// Throws:  nothing.
// Twin:    gpu/erosion/thermal.hpp (ThermalErosion) with gpu/shaders/erosion/thermal_requests.comp,
//          thermal_transfer.comp and thermal_block.glsl.
// Decisions: in reference/erosion/thermal.cpp (0/0, borders and no-data, Algorithm 11, l_y, odd counts).
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> thermal_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations,
                           Neighbourhood neighbourhood, int first_iteration = 0);

}  // namespace gt::reference
