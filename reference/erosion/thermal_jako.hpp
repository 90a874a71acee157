// Thermal erosion of Jákó & Tóth 2011 (digest 000 §3.6), CPU reference.
//
// thermal_jako_erosion(heights, constants, iterations) -> eroded heights
//   heights     Grid<Real> in metres; cells with valid == 0 take no part.
//   constants   thermal_jako_constants(): talus slope T = tan(angle), neighbour distances,
//               request_factor = rate = Δt·C_t·R of eq. 2.32.
// Real = double is the truth; Real = float repeats the shader's arithmetic operation by operation.
#pragma once

#include "core/grid.hpp"
#include "core/params/thermal.hpp"

namespace gt::reference {

template <class Real>
Grid<Real> thermal_jako_erosion(const Grid<Real>& heights, const ThermalConstants& constants, int iterations);

}  // namespace gt::reference
