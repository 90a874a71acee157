// Slope and curvature of a terrain from each cell's 3×3 window.
//
// Input: a heightmap (heights and cell sizes in metres, or any one length unit for both).
// Output: grids of the same size; a cell is valid only when its whole 3×3 window is valid, so the
// outer ring and every neighbour of a no-data cell are no-data (gdaldem's default without
// -compute_edges: no slope is made up at an edge).
//   slope_deg        atan(|∇z|) in degrees, ∇z by Horn 1981's weighted differences (gdaldem's
//                    default): ∂z/∂x = ((c + 2f + i) - (a + 2d + g)) / (8·dx),
//                    ∂z/∂y = ((a + 2b + c) - (g + 2h + i)) / (8·dy), with the window
//                        a b c     (row above = north = +y, column right = east = +x)
//                        d e f
//                        g h i
//   laplacian_per_m  z_xx + z_yy (1/m for metre heights), Zevenbergen & Thorne 1987's second
//                    differences: z_xx = (d - 2e + f)/dx², z_yy = (b - 2e + h)/dy² (their 2(D + E)).
//   profile_per_m    the second derivative along the gradient,
//                    (z_xx·p² + 2·z_xy·p·q + z_yy·q²) / (p² + q²), with Zevenbergen & Thorne's
//                    central p = (f - d)/(2dx), q = (b - h)/(2dy) and z_xy = (c + g - a - i)/(4·dx·dy);
//                    positive where the slope steepens uphill (concave), negative on convex
//                    shoulders. Undefined (no-data) where p = q = 0.
// All differences are exact for quadratic surfaces, which the tests use (a paraboloid
// z = k(x² + y²) has slope atan(2kr), laplacian 4k and profile 2k in every valid cell).
#pragma once

#include "core/grid.hpp"

namespace gt {

struct SurfaceDerivatives {
  Grid<double> slope_deg;
  Grid<double> laplacian_per_m;
  Grid<double> profile_per_m;
};

// Throws InputError for a grid narrower or shorter than 3 cells.
SurfaceDerivatives surface_derivatives(const Heightmap& dem);

}  // namespace gt
