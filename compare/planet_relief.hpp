// A planet's relief as seed 002's cases report it, for any generator that gives an elevation per
// cube-sphere region (planet.earth_like, planet.fault_lines): beside the Earth's (ETOPO 1°, or the
// global grid a case gives), its spherical power spectrum, and its maps.
//
// reference_relief(grid, name) -> the relief, bimodality and spectrum of a global grid
// etopo_relief(dataset_dir, reason) -> ETOPO 1° when datasets/fetch.sh fetched it (read once), else
//   none and why
// add_fidelity_checks(planet, earth_like, given, options, result) -> fidelity.land_fraction,
//   .bimodality (graded, warn-only, for earth_like cases; informative otherwise), .mean,
//   .spectral_exponent, and the hypsometry and spectrum plots
// planet_map_directions() -> the directions of the equirectangular maps' pixel centres
// elevation_colour(e), elevation_scale(elevation) -> §4.3's palette and its colour bar
// write_elevation_maps(planet, nearest, options, result) -> elevation.png (each pixel its nearest
//   centroid's region), elevation_cpu.{exr,npy}, the cube map elevation_cube.png and its fields
//
// Units: elevations in the generator's units, sea level 0; positions on the unit sphere.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/descriptors/global_relief.hpp"
#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/io/global_grid.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/vec3.hpp"
#include "reference/planet/voronoi.hpp"

namespace gt {

// The relief a planet is set beside: ETOPO 1° (datasets/fetch.sh), or the global grid the case
// gives as its input.
struct ReferenceRelief {
  std::string name;
  GlobalRelief relief;
  double bimodality = 0.0;
  std::vector<double> spectrum;   // C_l, l = 0..128
  std::size_t no_data_cells = 0;  // set to the mean for the spectrum
};

ReferenceRelief reference_relief(const GlobalGrid& grid, const std::string& name);

// ETOPO 1° when datasets/fetch.sh has fetched it, read once per process; otherwise none and why.
const std::optional<ReferenceRelief>& etopo_relief(const std::filesystem::path& dataset_dir, std::string& reason);

// A planet's elevation per region of `sphere`, and the regions' centroids (x, y, z per region) that
// decide which region a direction falls in.
struct RegionRelief {
  const CubeSphere& sphere;
  const std::vector<double>& positions;
  const std::vector<double>& elevation;
  // Where every elevation is k·lattice_step + lattice_offset (the fault-line planet's integer
  // votes), the histogram's bins hold whole lattice steps and their edges lie halfway between
  // two values; 0: the elevation is continuous.
  double lattice_step = 0.0;
  double lattice_offset = 0.0;
  CubeWarp warp{};  // the cube sphere's warp, which sets the cells' areas
};

// Each cell's solid angle on the unit sphere through `cube_warp`: its two triangles between its
// corners' positions (Van Oosterom & Strackee 1983), region order; the cells sum to 4π.
std::vector<double> cell_solid_angles(const CubeSphere& sphere, CubeWarp cube_warp);

void add_fidelity_checks(const RegionRelief& planet, bool earth_like, const std::optional<ReferenceRelief>& given,
                         const RunOptions& options, CaseResult& result);

inline constexpr int planet_map_width = 512;
inline constexpr int planet_map_height = 256;

// The directions of an equirectangular map's pixel centres, row-major: row 0 at the north pole (+y),
// column 0 at longitude −180° (the −z side); longitude 0 faces +z (the front face).
std::vector<Vector3<double>> planet_map_directions();

// §4.3's palette (reference/planet/render.hpp) as a picture's pixel.
std::array<float, 3> elevation_colour(double elevation);

// The colour bar of the elevation maps: the §4.3 palette from the lowest region to the highest.
ColourScale elevation_scale(const std::vector<double>& elevation);

void write_elevation_maps(const RegionRelief& planet, const std::vector<reference::NearestSite>& nearest,
                          const RunOptions& options, CaseResult& result);

}  // namespace gt
