// The terrain-descriptor kit in one call: everything compare/descriptors/ measures on a heightmap,
// with what could not be measured and why (issue 16). Used by `groundtruth stats`, by every
// erosion and terrain case (input and each twin's result) and by the report's fidelity table.
//
// Input: a heightmap in metres (heights and cell sizes); no-data cells are left out of every
// statistic (the spectrum sets them to the detrended plane and says how many).
// Output (each part optional: absent with a note in `notes` when the grid is too small, flat or
// without drainage):
//   hypsometry         elevation histogram, hypsometric curve, integral (hypsometry.hpp)
//   slope_deg, laplacian_per_m, profile_per_m
//                      distributions over cells with a whole 3×3 window (surface_derivatives.hpp)
//   drainage           after Priority-Flood+ε filling: D8 streams above `stream_threshold_cells`
//                      cells of area, Strahler orders, Horton's R_B and R_L, drainage density, Hack's
//                      exponent, the drainage-area exceedance exponent from D8 and from D∞
//   spectrum, spectral_slope   radially averaged power spectrum (power_spectrum.hpp) and its slope β
//                      over default_spectral_band(), measured when that band spans two octaves
//                      (a shorter side of 128 cells or more)
// scalar_descriptors() flattens the result into named numbers with units and, for the comparison of
// two twins' results, the resolution at which each is quoted (see there).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/descriptors/distribution.hpp"
#include "compare/descriptors/fit.hpp"
#include "compare/descriptors/hypsometry.hpp"
#include "compare/descriptors/power_spectrum.hpp"
#include "core/grid.hpp"

namespace gt {

struct DescriptorOptions {
  // Cells of contributing area where a stream starts. 50 cells keeps a few Strahler orders on the
  // bundled DEMs (87×61 to 403×344) without calling single hillslope lines streams.
  double stream_threshold_cells = 50.0;
  int hypsometry_points = 21;
};

struct DrainageDescriptors {
  std::size_t raised_cells = 0;      // cells Priority-Flood+ε raised (pits and flats)
  double stream_threshold_m2 = 0.0;
  int max_order = 0;
  std::vector<int> streams_per_order;           // [0] unused
  std::vector<double> mean_length_per_order_m;  // [0] unused
  std::optional<double> bifurcation_ratio;      // Horton R_B
  std::optional<double> length_ratio;           // Horton R_L
  double drainage_density_per_m = 0.0;          // stream length per valid area
  std::optional<LineFit> hack;                  // log L against log A on stream cells: slope = h
  std::optional<LineFit> exceedance_d8;         // log P(A ≥ a) against log a: -slope = exponent
  std::optional<LineFit> exceedance_dinf;
};

struct TerrainDescriptors {
  int width = 0;
  int height = 0;
  double cell_size_x = 1.0;
  double cell_size_y = 1.0;
  std::size_t valid_cells = 0;
  std::optional<Hypsometry> hypsometry;
  std::optional<Distribution> slope_deg;
  std::optional<Distribution> laplacian_per_m;
  std::optional<Distribution> profile_per_m;
  std::optional<DrainageDescriptors> drainage;
  std::optional<RadialSpectrum> spectrum;
  std::optional<SpectralSlope> spectral_slope;
  std::vector<std::string> notes;  // what was not measured and why; decisions taken
};

// Throws InputError only when nothing at all can be measured (no valid cell).
TerrainDescriptors describe_terrain(const Heightmap& dem, const DescriptorOptions& options = {});

// A descriptor as one number, e.g. {"drainage.hack_exponent", 0.57, "", "Hack's exponent h"}.
struct ScalarDescriptor {
  std::string name;     // stable dotted identifier
  double value = 0.0;
  std::string unit;     // "" for dimensionless
  std::string label;    // what a table shows
  // For comparing two twins' results: the resolution at which the literature quotes the number
  // (HI to 0.01, slopes to 0.1°, β to 0.1). Two results agree on it when they differ by at most
  // half of that: a reader rounding both would see the same figure. Only statistics continuous in
  // the heights have one. Drainage statistics have none: a D8 receiver flips on an arbitrarily
  // small change of a height, so no bound on the fields bounds them (they are shown, not judged).
  std::optional<double> parity_resolution;
};

// Every measured scalar, in a fixed order (absent parts leave their names out).
std::vector<ScalarDescriptor> scalar_descriptors(const TerrainDescriptors& descriptors);

// {"grid", "scalars": [{name, label, unit, value}] (scalar_descriptors), "hypsometry", "slope_deg",
//  "laplacian_per_m", "profile_per_m", "drainage", "spectrum", "spectral_slope", "notes"}; parts not
// measured are null.
nlohmann::json to_json(const TerrainDescriptors& descriptors);

}  // namespace gt
