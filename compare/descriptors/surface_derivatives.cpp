// Slope (Horn 1981, "Hill shading and the reflectance map", eq. for the 3×3 weighted gradient) and
// curvature (Zevenbergen & Thorne 1987, "Quantitative analysis of land surface topography", the
// partial-quartic coefficients D, E, F, G, H) over a 3×3 window. Decisions: the window must be
// whole (no edge extrapolation); dx and dy are kept apart (both papers assume square cells); the
// profile curvature is the plain second derivative along the gradient, without the (1 + p² + q²)
// normalisation some GIS add, so that it is exact on quadratics and comparable between twins.
// Units: degrees for slope, 1/length for curvatures (heights and cells in the same unit).
#include "compare/descriptors/surface_derivatives.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {

namespace {

// The 3×3 window around a cell, named as in the header (north row first).
struct Window {
  double a, b, c, d, e, f, g, h, i;
};

bool window_valid(const Heightmap& dem, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (!dem.is_valid(x + dx, y + dy)) return false;
    }
  }
  return true;
}

// Row y - 1 is north in the grid's convention (row 0 first in the file = north).
Window window_at(const Heightmap& dem, int x, int y) {
  return {dem.at(x - 1, y - 1), dem.at(x, y - 1), dem.at(x + 1, y - 1),
          dem.at(x - 1, y),     dem.at(x, y),     dem.at(x + 1, y),
          dem.at(x - 1, y + 1), dem.at(x, y + 1), dem.at(x + 1, y + 1)};
}

Grid<double> empty_like(const Heightmap& dem) {
  Grid<double> grid(dem.width, dem.height, 0.0);
  grid.cell_size_x = dem.cell_size_x;
  grid.cell_size_y = dem.cell_size_y;
  grid.horizontal_unit = dem.horizontal_unit;
  grid.valid.assign(dem.size(), 0);
  return grid;
}

void set(Grid<double>& grid, int x, int y, double value) {
  grid.at(x, y) = value;
  grid.valid[grid.index(x, y)] = 1;
}

}  // namespace

SurfaceDerivatives surface_derivatives(const Heightmap& dem) {
  if (dem.width < 3 || dem.height < 3) {
    throw InputError(fmt::format("slope and curvature need a 3x3 window: the grid is {}x{}", dem.width, dem.height));
  }
  const double dx = dem.cell_size_x, dy = dem.cell_size_y;
  SurfaceDerivatives out{empty_like(dem), empty_like(dem), empty_like(dem)};
  out.slope_deg.vertical_unit = "deg";
  out.laplacian_per_m.vertical_unit = "1/" + dem.horizontal_unit;
  out.profile_per_m.vertical_unit = "1/" + dem.horizontal_unit;
  for (int y = 1; y + 1 < dem.height; ++y) {
    for (int x = 1; x + 1 < dem.width; ++x) {
      if (!window_valid(dem, x, y)) continue;
      const Window w = window_at(dem, x, y);
      const double horn_x = ((w.c + 2.0 * w.f + w.i) - (w.a + 2.0 * w.d + w.g)) / (8.0 * dx);
      const double horn_y = ((w.a + 2.0 * w.b + w.c) - (w.g + 2.0 * w.h + w.i)) / (8.0 * dy);
      set(out.slope_deg, x, y, std::atan(std::hypot(horn_x, horn_y)) * 180.0 / std::numbers::pi);

      const double z_xx = (w.d - 2.0 * w.e + w.f) / (dx * dx);
      const double z_yy = (w.b - 2.0 * w.e + w.h) / (dy * dy);
      const double z_xy = (w.c + w.g - w.a - w.i) / (4.0 * dx * dy);
      set(out.laplacian_per_m, x, y, z_xx + z_yy);

      const double p = (w.f - w.d) / (2.0 * dx), q = (w.b - w.h) / (2.0 * dy);
      const double gradient_squared = p * p + q * q;
      if (gradient_squared > 0.0) {
        set(out.profile_per_m, x, y, (z_xx * p * p + 2.0 * z_xy * p * q + z_yy * q * q) / gradient_squared);
      }
    }
  }
  return out;
}

}  // namespace gt
