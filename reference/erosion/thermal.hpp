// Thermal erosion of seed 000 (Hydra), CPU reference.
//
// thermal_erosion(heights, constants, iterations, neighbourhood) -> eroded heights
//   heights       Grid<Real>, values in the units of `constants` (metres, or [0,1] when normalised);
//                 cells with valid == 0 take no part: they neither give nor receive material and
//                 keep their value.
//   constants     from core/params/thermal.hpp: talus slope T, neighbour distances, f_s, clamp.
//   iterations    any count >= 0; iteration i uses the cardinal pipes when the neighbourhood is
//                 cardinal, or alternating with i even; the diagonal pipes otherwise.
//   first_iteration  the number of the first iteration run: `heights` is the state after that many
//                 iterations (0 = from the input). It only picks the pipes of an alternating run, so
//                 that a run stepped in pieces (the driver's shadow steps) equals one in one go.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> thermal_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations,
                           Neighbourhood neighbourhood, int first_iteration = 0);

}  // namespace gt::reference
