// Runs every descriptor of compare/descriptors/ on one heightmap and gathers what could not be
// measured. Each part is measured on its own: a grid too small for a spectrum still gets its
// hypsometry, and the note says which statistic is missing and why.
#include "compare/descriptors/terrain_descriptors.hpp"

#include <cmath>

#include <fmt/format.h>

#include "compare/descriptors/drainage_laws.hpp"
#include "compare/descriptors/flow_d8.hpp"
#include "compare/descriptors/flow_dinf.hpp"
#include "compare/descriptors/priority_flood.hpp"
#include "compare/descriptors/stream_network.hpp"
#include "compare/descriptors/surface_derivatives.hpp"
#include "core/errors.hpp"

namespace gt {

namespace {

// Runs one part; an InputError (too small, flat, no cell) becomes a note naming the part.
template <class Measure>
void measure_part(const std::string& part, TerrainDescriptors& out, Measure&& measure) {
  try {
    measure();
  } catch (const InputError& error) {
    out.notes.push_back(fmt::format("{} not measured: {}", part, error.what()));
  }
}

void measure_derivatives(const Heightmap& dem, TerrainDescriptors& out) {
  const auto derivatives = surface_derivatives(dem);
  const auto slopes = valid_values(derivatives.slope_deg);
  if (slopes.empty()) throw InputError("no cell has a whole 3x3 window of valid cells");
  out.slope_deg = distribution_of(slopes);
  out.laplacian_per_m = distribution_of(valid_values(derivatives.laplacian_per_m));
  const auto profile = valid_values(derivatives.profile_per_m);
  if (!profile.empty()) out.profile_per_m = distribution_of(profile);
}

void measure_drainage(const Heightmap& dem, const DescriptorOptions& options, TerrainDescriptors& out) {
  if (dem.width < 3 || dem.height < 3) {
    throw InputError(fmt::format("a {}x{} grid has no interior cell to route flow through", dem.width, dem.height));
  }
  DrainageDescriptors drainage;
  const Heightmap filled = fill_depressions(dem, &drainage.raised_cells);
  const D8Flow d8 = d8_flow(filled);
  const double cell_area = dem.cell_size_x * dem.cell_size_y;
  drainage.stream_threshold_m2 = options.stream_threshold_cells * cell_area;
  const StreamNetwork network = stream_network(d8, filled, drainage.stream_threshold_m2);
  if (network.max_order == 0) {
    throw InputError(fmt::format("no cell drains {} cells or more, so there is no stream",
                                 options.stream_threshold_cells));
  }
  drainage.max_order = network.max_order;
  drainage.streams_per_order = network.streams_per_order;
  drainage.mean_length_per_order_m = network.mean_length_per_order_m;
  drainage.bifurcation_ratio = network.bifurcation_ratio;
  drainage.length_ratio = network.length_ratio;
  drainage.drainage_density_per_m = network.drainage_density_per_m;
  const double total_area = static_cast<double>(out.valid_cells) * cell_area;
  drainage.hack = hack_fit(d8, drainage.stream_threshold_m2);
  drainage.exceedance_d8 = exceedance_fit(d8.area_m2, 10.0 * cell_area, 0.01 * total_area);
  drainage.exceedance_dinf = exceedance_fit(dinf_flow(filled).area_m2, 10.0 * cell_area, 0.01 * total_area);
  if (drainage.raised_cells > 0) {
    out.notes.push_back(fmt::format("drainage: Priority-Flood+ε raised {} cells (pits and flats) before routing",
                                    drainage.raised_cells));
  }
  out.drainage = drainage;
}

// Two octaves at least between the band's edges (default_spectral_band: from 4 cycles per side to
// wavelengths of 8 cells, a factor of side/32). Over less, β is the scatter of a handful of bins:
// a 45-row window of ETOPO 20' gave β = 9 from three bins.
constexpr double minimum_band_ratio = 4.0;

void measure_spectrum(const Heightmap& dem, TerrainDescriptors& out) {
  out.spectrum = radial_power_spectrum(dem);
  if (out.spectrum->masked_cells > 0) {
    out.notes.push_back(fmt::format("spectrum: {} no-data cells set to the fitted plane before the transform",
                                    out.spectrum->masked_cells));
  }
  const auto [low, high] = default_spectral_band(dem);
  if (high < minimum_band_ratio * low) {
    out.notes.push_back(fmt::format(
        "spectral slope not measured: its band [{:.3g}, {:.3g}] cycles/m spans less than a factor {} (the shorter "
        "side needs 128 cells or more); a slope over fewer octaves is the scatter of a few bins",
        low, high, minimum_band_ratio));
    return;
  }
  out.spectral_slope = spectral_slope(*out.spectrum, low, high);
  if (!out.spectral_slope) {
    out.notes.push_back(fmt::format("spectral slope not measured: fewer than two frequency bins between {:.3g} and "
                                    "{:.3g} cycles/m", low, high));
  }
}

}  // namespace

TerrainDescriptors describe_terrain(const Heightmap& dem, const DescriptorOptions& options) {
  TerrainDescriptors out;
  out.width = dem.width;
  out.height = dem.height;
  out.cell_size_x = dem.cell_size_x;
  out.cell_size_y = dem.cell_size_y;
  out.valid_cells = count_valid(dem);
  if (out.valid_cells == 0) throw InputError("no valid cell: nothing can be measured");
  measure_part("hypsometry", out, [&] { out.hypsometry = hypsometry(dem, options.hypsometry_points); });
  if (!out.hypsometry) return out;  // flat: no slope, no drainage, no spectrum either
  measure_part("slope and curvature", out, [&] { measure_derivatives(dem, out); });
  measure_part("drainage", out, [&] { measure_drainage(dem, options, out); });
  measure_part("power spectrum", out, [&] { measure_spectrum(dem, out); });
  return out;
}

namespace {

void add_distribution(const std::string& name, const std::string& label, const std::string& unit,
                      const std::optional<Distribution>& distribution, std::optional<double> resolution,
                      std::vector<ScalarDescriptor>& out) {
  if (!distribution) return;
  out.push_back({name + ".mean", distribution->mean, unit, label + ", mean", resolution});
  out.push_back({name + ".p10", distribution->quantile(0.10), unit, label + ", 10th percentile", resolution});
  out.push_back({name + ".p50", distribution->quantile(0.50), unit, label + ", median", resolution});
  out.push_back({name + ".p90", distribution->quantile(0.90), unit, label + ", 90th percentile", resolution});
}

void add_drainage(const DrainageDescriptors& drainage, std::vector<ScalarDescriptor>& out) {
  out.push_back({"drainage.max_order", static_cast<double>(drainage.max_order), "", "highest Strahler order", {}});
  if (drainage.bifurcation_ratio) {
    out.push_back({"drainage.bifurcation_ratio", *drainage.bifurcation_ratio, "", "Horton's bifurcation ratio R_B", {}});
  }
  if (drainage.length_ratio) {
    out.push_back({"drainage.length_ratio", *drainage.length_ratio, "", "Horton's length ratio R_L", {}});
  }
  out.push_back({"drainage.density", drainage.drainage_density_per_m * 1000.0, "1/km", "drainage density", {}});
  if (drainage.hack) out.push_back({"drainage.hack_exponent", drainage.hack->slope, "", "Hack's exponent h", {}});
  if (drainage.exceedance_d8) {
    out.push_back({"drainage.exceedance_exponent_d8", -drainage.exceedance_d8->slope, "",
                   "drainage-area exceedance exponent (D8)", {}});
  }
  if (drainage.exceedance_dinf) {
    out.push_back({"drainage.exceedance_exponent_dinf", -drainage.exceedance_dinf->slope, "",
                   "drainage-area exceedance exponent (D∞)", {}});
  }
}

}  // namespace

std::vector<ScalarDescriptor> scalar_descriptors(const TerrainDescriptors& descriptors) {
  std::vector<ScalarDescriptor> out;
  if (descriptors.hypsometry) {
    out.push_back({"hypsometric_integral", descriptors.hypsometry->integral, "", "hypsometric integral HI", 0.01});
    out.push_back({"relief", descriptors.hypsometry->max - descriptors.hypsometry->min, "m", "relief (max - min)", {}});
  }
  add_distribution("slope", "slope", "deg", descriptors.slope_deg, 0.1, out);
  add_distribution("laplacian", "curvature (Laplacian)", "1/m", descriptors.laplacian_per_m, std::nullopt, out);
  if (descriptors.drainage) add_drainage(*descriptors.drainage, out);
  if (descriptors.spectral_slope) {
    out.push_back({"spectrum.beta", descriptors.spectral_slope->beta, "", "power-spectrum slope β", 0.1});
  }
  return out;
}

namespace {

// Declared first: optional_json's lookup of to_json happens where the template is defined.
nlohmann::json to_json(const Distribution& distribution);
nlohmann::json to_json(const LineFit& fit);
nlohmann::json to_json(const Hypsometry& hypsometry);
nlohmann::json to_json(const DrainageDescriptors& drainage);
nlohmann::json to_json(const RadialSpectrum& spectrum);
nlohmann::json to_json(const SpectralSlope& slope);

nlohmann::json to_json(const Distribution& distribution) {
  return {{"count", distribution.count}, {"mean", distribution.mean}, {"quantile_levels", quantile_levels()},
          {"quantiles", distribution.quantiles}};
}

template <class T>
nlohmann::json optional_json(const std::optional<T>& value) {
  return value ? nlohmann::json(to_json(*value)) : nlohmann::json(nullptr);
}

nlohmann::json to_json(const LineFit& fit) {
  return {{"slope", fit.slope}, {"intercept", fit.intercept}, {"r_squared", fit.r_squared}, {"points", fit.points}};
}

nlohmann::json to_json(const Hypsometry& hypsometry) {
  return {{"min", hypsometry.min}, {"max", hypsometry.max}, {"mean", hypsometry.mean},
          {"integral", hypsometry.integral}, {"relative_height", hypsometry.relative_height},
          {"relative_area", hypsometry.relative_area}, {"histogram", hypsometry.histogram}};
}

nlohmann::json to_json(const DrainageDescriptors& drainage) {
  return {{"raised_cells", drainage.raised_cells},
          {"stream_threshold_m2", drainage.stream_threshold_m2},
          {"max_order", drainage.max_order},
          {"streams_per_order", drainage.streams_per_order},
          {"mean_length_per_order_m", drainage.mean_length_per_order_m},
          {"bifurcation_ratio", drainage.bifurcation_ratio ? nlohmann::json(*drainage.bifurcation_ratio) : nullptr},
          {"length_ratio", drainage.length_ratio ? nlohmann::json(*drainage.length_ratio) : nullptr},
          {"drainage_density_per_m", drainage.drainage_density_per_m},
          {"hack", optional_json(drainage.hack)},
          {"exceedance_d8", optional_json(drainage.exceedance_d8)},
          {"exceedance_dinf", optional_json(drainage.exceedance_dinf)}};
}

nlohmann::json to_json(const RadialSpectrum& spectrum) {
  return {{"frequency_per_m", spectrum.frequency_per_m}, {"power", spectrum.power},
          {"coefficients", spectrum.coefficients}, {"masked_cells", spectrum.masked_cells}};
}

nlohmann::json to_json(const SpectralSlope& slope) {
  return {{"beta", slope.beta}, {"fit", to_json(slope.fit)}, {"low_frequency_per_m", slope.low_frequency_per_m},
          {"high_frequency_per_m", slope.high_frequency_per_m}};
}

}  // namespace

nlohmann::json to_json(const TerrainDescriptors& descriptors) {
  nlohmann::json scalars = nlohmann::json::array();
  for (const auto& scalar : scalar_descriptors(descriptors)) {
    scalars.push_back({{"name", scalar.name}, {"label", scalar.label}, {"unit", scalar.unit}, {"value", scalar.value}});
  }
  return {{"grid", {{"width", descriptors.width}, {"height", descriptors.height},
                    {"cell_size_x", descriptors.cell_size_x}, {"cell_size_y", descriptors.cell_size_y},
                    {"valid_cells", descriptors.valid_cells}}},
          {"scalars", scalars},
          {"hypsometry", optional_json(descriptors.hypsometry)},
          {"slope_deg", optional_json(descriptors.slope_deg)},
          {"laplacian_per_m", optional_json(descriptors.laplacian_per_m)},
          {"profile_per_m", optional_json(descriptors.profile_per_m)},
          {"drainage", optional_json(descriptors.drainage)},
          {"spectrum", optional_json(descriptors.spectrum)},
          {"spectral_slope", optional_json(descriptors.spectral_slope)},
          {"notes", descriptors.notes}};
}

}  // namespace gt
