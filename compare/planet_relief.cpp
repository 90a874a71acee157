// A planet's relief beside the Earth's, its spectrum and its maps (see planet_relief.hpp).
#include "compare/planet_relief.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "compare/checks/threshold.hpp"
#include "compare/descriptors/spherical_spectrum.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "core/io/global_grid.hpp"
#include "reference/planet/render.hpp"

namespace gt {
namespace {

constexpr double earth_land_fraction = 0.290;  // ETOPO 1°, area-weighted (tests/global_relief_test.cpp)
constexpr double land_fraction_tolerance = 0.1;  // issue 13: within ±0.1 of the Earth's
constexpr double bimodal_threshold = 5.0 / 9.0;  // Sarle's coefficient of a uniform distribution
// Spherical power spectra (compare/descriptors/spherical_spectrum.hpp) on a HEALPix map of ~0.9°
// pixels, ETOPO 1°'s own resolution, to degree 128 (< 3·nside); the exponent is fitted from l = 2
// (l = 0 is the mean, l = 1 a hemisphere's offset) to l = R, a wavelength of 4 cells at the
// equator's 4R: the smallest features the planet's regions can draw, and the same band for both.
constexpr int spectrum_nside = 64;
constexpr int spectrum_lmax = 128;
constexpr int spectrum_low_degree = 2;
// The exponents' allowed gap, a judgement fixed before any run: half a unit, against the exponent's
// range from 0 (independent regions: white noise) to 4 and above (smooth blobs); the Earth's own
// exponent moves by 0.7 as the band's upper end goes from l = 10 to 128, which is why both are fitted
// over the same band. Warn-only, like the other fidelity checks.
constexpr double spectral_exponent_tolerance = 0.5;


// Solid angle of a cell: its two triangles on the sphere (Van Oosterom & Strackee 1983).
double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double numerator = dot(a, cross(b, c));
  const double denominator = 1.0 + dot(a, b) + dot(b, c) + dot(c, a);
  return 2.0 * std::abs(std::atan2(numerator, denominator));
}

std::vector<AreaSample> planet_samples(const RegionRelief& planet) {
  const auto areas = cell_solid_angles(planet.sphere, planet.warp);
  std::vector<AreaSample> samples;
  for (std::size_t region = 0; region < areas.size(); ++region) samples.push_back({planet.elevation[region], areas[region]});
  return samples;
}

}  // namespace

std::vector<double> cell_solid_angles(const CubeSphere& sphere, CubeWarp cube_warp) {
  std::vector<double> areas;
  areas.reserve(sphere.region_count());
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    Vec3 corners[4];
    for (int corner = 0; corner < 4; ++corner) {
      corners[corner] = sphere_position(sphere.local_position(region, corner % 2, corner / 2), cube_warp);
    }
    areas.push_back(triangle_solid_angle(corners[0], corners[1], corners[3]) +
                    triangle_solid_angle(corners[0], corners[3], corners[2]));
  }
  return areas;
}

ReferenceRelief reference_relief(const GlobalGrid& grid, const std::string& name) {
  const auto samples = area_samples(grid);
  ReferenceRelief reference{name, weighted_relief(samples), bimodality_coefficient(samples), {}, 0};
  const auto& valid = grid.elevation.valid;
  reference.no_data_cells = std::size_t(std::count(valid.begin(), valid.end(), std::uint8_t{0}));
  reference.spectrum =
      angular_power_spectrum(nearest_cell_sampler(grid, reference.relief.mean), spectrum_nside, spectrum_lmax);
  return reference;
}

const std::optional<ReferenceRelief>& etopo_relief(const std::filesystem::path& dataset_dir, std::string& reason) {
  static std::optional<ReferenceRelief> earth;
  static std::string why;
  static bool read = false;
  if (!read) {
    read = true;
    const auto path = dataset_dir / "real" / "etopo60.cdf";
    if (std::filesystem::exists(path)) {
      earth = reference_relief(read_global_grid(path.string()), "Earth (ETOPO 1°)");
    } else {
      why = fmt::format("{} is missing: datasets/fetch.sh fetches it", path.string());
    }
  }
  reason = why;
  return earth;
}

namespace {

// The hypsometric curves (elevation over its largest magnitude against the share of the surface
// above) and the histograms of the planet and the Earth on one plot each.
void plot_relief(const GlobalRelief& planet, const std::optional<ReferenceRelief>& earth, const RunOptions& options,
                 CaseResult& result) {
  const auto curve = [](const GlobalRelief& relief, const std::string& label) {
    Series series{label, {}, {}, false, {}};
    const double scale = std::max(std::abs(relief.min), std::abs(relief.max));
    for (std::size_t point = 0; point < relief.hypsometry.size(); ++point) {
      series.x.push_back(1.0 - double(point) / double(relief.hypsometry.size() - 1));
      series.y.push_back(relief.hypsometry[point] / scale);
    }
    return series;
  };
  SeriesPlot hypsometry{"hypsometric curves", "share of the surface above", "elevation / largest |elevation|", false,
                        false, {curve(planet, "planet")}};
  if (earth) hypsometry.series.push_back(curve(earth->relief, earth->name));
  hypsometry.series.push_back({"sea level", {0.0, 1.0}, {0.0, 0.0}, true, {}});
  // Area density over the scaled elevation: each bin's area share over its scaled width.
  const auto density = [](const GlobalRelief& relief, const std::string& label) {
    Series series{label, {}, {}, false, {}};
    const double scale = std::max(std::abs(relief.min), std::abs(relief.max));
    for (std::size_t bin = 0; bin < relief.histogram.size(); ++bin) {
      series.x.push_back((relief.histogram_start + (double(bin) + 0.5) * relief.bin_width) / scale);
      series.y.push_back(relief.histogram[bin] / (relief.bin_width / scale));
    }
    return series;
  };
  SeriesPlot histogram{"elevation histograms", "elevation / largest |elevation|", "area density", false, false,
                       {density(planet, "planet")}};
  if (earth) histogram.series.push_back(density(earth->relief, earth->name));
  attach_plot({hypsometry, histogram}, options, "hypsometry.png",
              earth ? fmt::format("hypsometric curves and histograms of the planet and {}, each scaled by its largest "
                                  "|elevation|",
                                  earth->name)
                    : std::string("hypsometric curve and histogram of the planet (no global grid to set it beside)"),
              result);
}

// The planet's relief as the picture shows it (each direction its nearest centroid's region) on the
// HEALPix map, its exponent beside the Earth's over the same band, and both spectra on one plot,
// each as its share of the variance per degree, (2l + 1)·C_l / Σ_{l>=1} (2l + 1)·C_l.
void add_spectrum_checks(const RegionRelief& planet, bool earth_like, const std::optional<ReferenceRelief>& earth,
                         const RunOptions& options, CaseResult& result) {
  const reference::VoronoiSearch search(planet.positions);
  const auto& elevation = planet.elevation;
  const auto spectrum = angular_power_spectrum(
      [&](const std::array<double, 3>& direction) {
        return elevation[static_cast<std::size_t>(search.nearest({direction[0], direction[1], direction[2]}).region)];
      },
      spectrum_nside, spectrum_lmax);
  const int high_degree = std::min(planet.sphere.resolution(), spectrum_lmax);
  const double exponent = spectral_exponent(spectrum, spectrum_low_degree, high_degree);
  if (!earth) {
    result.checks.push_back(informative_check(
        "fidelity.spectral_exponent", exponent,
        fmt::format("β of C_l ∝ l^-β over l = {}..{} (no global grid to set it beside)", spectrum_low_degree, high_degree)));
  } else {
    const double earth_exponent = spectral_exponent(earth->spectrum, spectrum_low_degree, high_degree);
    if (earth->no_data_cells > 0) {
      result.notes.push_back(fmt::format("{}'s {} no-data cells were set to its mean elevation for its spectrum",
                                         earth->name, earth->no_data_cells));
    }
    const std::string detail = fmt::format("|β − {}'s β| of C_l ∝ l^-β over l = {}..{}: planet {:.2f}, {} {:.2f}",
                                           earth->name, spectrum_low_degree, high_degree, exponent, earth->name,
                                           earth_exponent);
    const double gap = std::abs(exponent - earth_exponent);
    result.checks.push_back(earth_like ? bounded_check("fidelity.spectral_exponent", gap, spectral_exponent_tolerance,
                                                       std::numeric_limits<double>::infinity(), detail)
                                       : informative_check("fidelity.spectral_exponent", gap, detail));
  }
  if (options.report_dir.empty()) return;
  const auto shares = [&](const std::vector<double>& power, const std::string& label) {
    double total = 0.0;
    for (int degree = 1; degree <= spectrum_lmax; ++degree) total += (2.0 * degree + 1.0) * power[std::size_t(degree)];
    Series series{label, {}, {}, false, {}};
    for (int degree = 1; degree <= spectrum_lmax; ++degree) {
      series.x.push_back(degree);
      series.y.push_back((2.0 * degree + 1.0) * power[std::size_t(degree)] / total);
    }
    return series;
  };
  SeriesPlot plot{"spherical power spectra", "degree l", "share of the variance at degree l", true, true,
                  {shares(spectrum, "planet")}};
  if (earth) plot.series.push_back(shares(earth->spectrum, earth->name));
  attach_plot({plot}, options, "spectrum.png",
              fmt::format("angular power spectra (HEALPix nside {}), each degree's share of the variance; the exponent "
                          "is fitted over l = {}..{}",
                          spectrum_nside, spectrum_low_degree, high_degree),
              result);
}

}  // namespace

void add_fidelity_checks(const RegionRelief& planet, bool earth_like, const std::optional<ReferenceRelief>& given,
                         const RunOptions& options, CaseResult& result) {
  const auto samples = planet_samples(planet);
  constexpr double bin_width = 0.1;  // elevation units
  const double step = planet.lattice_step;
  const GlobalRelief relief =
      step > 0.0 ? weighted_relief(samples, 0.0, 101, step * std::ceil(bin_width / step), planet.lattice_offset - step / 2)
                 : weighted_relief(samples, 0.0, 101, bin_width);
  const double bimodality = bimodality_coefficient(samples);
  std::string reason;
  const auto& earth = given ? given : etopo_relief(options.dataset_dir, reason);
  if (!earth) result.notes.push_back("no global grid to set the planet beside: " + reason);
  const double target_land = earth ? earth->relief.land_fraction : earth_land_fraction;
  const std::string target = earth ? earth->name : "the Earth (ETOPO 1°, data-sources.md)";
  const std::string land_detail = fmt::format("|land share − {}'s {:.3f}|: land (not below 0) {:.3f} of the area",
                                              target, target_land, relief.land_fraction);
  const std::string bimodal_detail =
      fmt::format("5/9 − Sarle's bimodality coefficient {:.3f} (above 5/9 suggests two modes){}", bimodality,
                  earth ? fmt::format("; {}'s {:.3f}", earth->name, earth->bimodality) : std::string());
  const double land_gap = std::abs(relief.land_fraction - target_land);
  if (earth_like) {
    const double unbounded = std::numeric_limits<double>::infinity();
    result.checks.push_back(bounded_check("fidelity.land_fraction", land_gap, land_fraction_tolerance, unbounded, land_detail));
    result.checks.push_back(bounded_check("fidelity.bimodality", bimodal_threshold - bimodality, 0.0, unbounded, bimodal_detail));
  } else {
    result.checks.push_back(informative_check("fidelity.land_fraction", land_gap, land_detail));
    result.checks.push_back(informative_check("fidelity.bimodality", bimodal_threshold - bimodality, bimodal_detail));
  }
  result.checks.push_back(informative_check(
      "fidelity.mean", relief.mean,
      fmt::format("area-weighted mean elevation; range {:.3f} .. {:.3f} (generator units, sea level 0)", relief.min,
                  relief.max)));
  add_spectrum_checks(planet, earth_like, earth, options, result);
  if (!options.report_dir.empty()) plot_relief(relief, earth, options, result);
}


std::vector<Vector3<double>> planet_map_directions() {
  std::vector<Vector3<double>> directions;
  for (int row = 0; row < planet_map_height; ++row) {
    const double latitude = std::numbers::pi / 2 - (row + 0.5) / planet_map_height * std::numbers::pi;
    for (int column = 0; column < planet_map_width; ++column) {
      const double longitude = (column + 0.5) / planet_map_width * 2 * std::numbers::pi - std::numbers::pi;
      directions.push_back({std::cos(latitude) * std::sin(longitude), std::sin(latitude),
                            std::cos(latitude) * std::cos(longitude)});
    }
  }
  return directions;
}

std::array<float, 3> elevation_colour(double elevation) {
  const Vec3 colour = reference::elevation_colour(elevation);
  return {static_cast<float>(colour[0]), static_cast<float>(colour[1]), static_cast<float>(colour[2])};
}

ColourScale elevation_scale(const std::vector<double>& elevation) {
  const auto [lowest, highest] = std::minmax_element(elevation.begin(), elevation.end());
  return sampled_scale("§4.3 elevation", static_cast<double>(*lowest), static_cast<double>(*highest), "generator units",
                       [](double elevation) { return elevation_colour(elevation); });
}

namespace {

struct ElevationPicture {
  std::string file;         // <file>.png beside the case
  std::string caption;
  std::string field;        // its EXR/NPY fields' name
  std::string description;  // theirs
};

// A grid of elevations as a PNG in §4.3's palette with the planet's colour bar, and as EXR/NPY fields.
void write_elevation_grid(const Grid<double>& grid, const std::vector<double>& elevation, const ElevationPicture& picture,
                          const RunOptions& options, CaseResult& result) {
  std::vector<std::array<float, 3>> pixels;
  pixels.reserve(grid.values.size());
  for (const double value : grid.values) pixels.push_back(elevation_colour(value));
  write_colour_image(grid.width, grid.height, pixels, options.report_dir / result.name / (picture.file + ".png"));
  add_picture(result, picture.file + ".png", picture.caption, elevation_scale(elevation));
  write_field_files(grid, {picture.field, "elevation", "cpu", "1", picture.description}, options, result);
}

// The cube map: the six faces side by side in index order (front, right, back, left, north, south),
// each R×R cells row-major from its top-left as the regions are numbered: region i is pixel
// (face·R + x, y).
Grid<double> cube_map(const RegionRelief& planet) {
  const auto side = static_cast<std::size_t>(planet.sphere.resolution());
  Grid<double> cube(cube_face_count * planet.sphere.resolution(), planet.sphere.resolution());
  for (std::size_t region = 0; region < planet.elevation.size(); ++region) {
    const std::size_t face = region / (side * side), y = region / side % side, x = region % side;
    cube.values[y * cube_face_count * side + face * side + x] = planet.elevation[region];
  }
  return cube;
}

}  // namespace

void write_elevation_maps(const RegionRelief& planet, const std::vector<reference::NearestSite>& nearest,
                          const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  std::filesystem::create_directories(options.report_dir / result.name);
  Grid<double> map(planet_map_width, planet_map_height);
  for (std::size_t pixel = 0; pixel < nearest.size(); ++pixel) {
    map.values[pixel] = planet.elevation[static_cast<std::size_t>(nearest[pixel].region)];
  }
  write_elevation_grid(map, planet.elevation,
                       {"elevation",
                        "elevation, ref<double>, equirectangular, each pixel its nearest centroid's region (§4.3 palette: "
                        "blue below sea level, brown above)",
                        "elevation_cpu",
                        "elevation (sea level 0) of the region under each pixel of an equirectangular map, ref<double>"},
                       options, result);
  write_elevation_grid(cube_map(planet), planet.elevation,
                       {"elevation_cube",
                        "cube map of the elevation: the faces front, right, back, left, north, south, a cell a pixel",
                        "elevation_cube_cpu",
                        "elevation per region as a cube map: faces in index order side by side, each R×R row-major"},
                       options, result);
}

}  // namespace gt
