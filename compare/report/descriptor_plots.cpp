// Turns TerrainDescriptors into SeriesPlot panels; drawing is plots.cpp's.
#include "compare/report/descriptor_plots.hpp"

#include <cmath>

#include <fmt/format.h>

namespace gt {

namespace {

SeriesPlot hypsometry_panel(const std::vector<DescribedTerrain>& terrains) {
  SeriesPlot plot{"hypsometric curve", "share of area above, a/A", "relative height, h/H", false, false, {}};
  for (const auto& terrain : terrains) {
    if (!terrain.descriptors->hypsometry) continue;
    const auto& curve = *terrain.descriptors->hypsometry;
    plot.series.push_back({fmt::format("{} (HI {:.3f})", terrain.label, curve.integral),
                           curve.relative_area, curve.relative_height});
  }
  return plot;
}

SeriesPlot slope_panel(const std::vector<DescribedTerrain>& terrains) {
  SeriesPlot plot{"slope distribution", "slope, degrees", "share of cells at or below", false, false, {}};
  for (const auto& terrain : terrains) {
    if (!terrain.descriptors->slope_deg) continue;
    plot.series.push_back({terrain.label, terrain.descriptors->slope_deg->quantiles, quantile_levels()});
  }
  return plot;
}

SeriesPlot spectrum_panel(const std::vector<DescribedTerrain>& terrains) {
  SeriesPlot plot{"power spectrum", "frequency, cycles/m", "mean power, m²/(cycles/m)²", true, true, {}};
  for (const auto& terrain : terrains) {
    const auto& descriptors = *terrain.descriptors;
    if (!descriptors.spectrum) continue;
    plot.series.push_back({terrain.label, descriptors.spectrum->frequency_per_m, descriptors.spectrum->power,
                           false, terrain.label});
    if (!descriptors.spectral_slope) continue;
    const auto& slope = *descriptors.spectral_slope;
    std::vector<double> band{slope.low_frequency_per_m, slope.high_frequency_per_m}, fitted;
    for (double frequency : band) fitted.push_back(std::pow(10.0, slope.fit.intercept + slope.fit.slope * std::log10(frequency)));
    plot.series.push_back({fmt::format("{}: β = {:.2f} fit", terrain.label, slope.beta), band, fitted, true, terrain.label});
  }
  return plot;
}

SeriesPlot horton_panel(const std::vector<DescribedTerrain>& terrains) {
  SeriesPlot plot{"Horton plot", "Strahler order", "streams of that order", false, true, {}};
  for (const auto& terrain : terrains) {
    if (!terrain.descriptors->drainage) continue;
    const auto& counts = terrain.descriptors->drainage->streams_per_order;
    Series series{terrain.label, {}, {}};
    for (std::size_t order = 1; order < counts.size(); ++order) {
      series.x.push_back(static_cast<double>(order));
      series.y.push_back(counts[order]);
    }
    plot.series.push_back(series);
  }
  return plot;
}

}  // namespace

std::vector<SeriesPlot> descriptor_panels(const std::vector<DescribedTerrain>& terrains) {
  std::vector<SeriesPlot> panels;
  for (auto&& panel : {hypsometry_panel(terrains), slope_panel(terrains), spectrum_panel(terrains),
                       horton_panel(terrains)}) {
    if (!panel.series.empty()) panels.push_back(panel);
  }
  return panels;
}

}  // namespace gt
