// Drainage scaling laws measured on a flow routing (D8 for Hack; D8 or D∞ areas for the exceedance).
//   Hack 1957, "Studies of longitudinal stream profiles in Virginia and Maryland", USGS
//     Professional Paper 294-B: main-stream length L ∝ A^h, h ≈ 0.6 (0.57 in later compilations).
//     L here is the longest D8 flow path to the cell (upstream_length_m), the usual DEM reading of
//     "main-stream length"; every cell of the band is a point, as in DEM studies.
//   Rodríguez-Iturbe & Rinaldo 1997, "Fractal River Basins", ch. 1 (after Rodríguez-Iturbe et al.
//     1992): P(A ≥ a) ∝ a^−β with β ≈ 0.43 over the cells of real networks.
// The bands and the sampling are documented in the header; both fits are least-squares lines in
// natural logarithms (compare/descriptors/fit.hpp). Units: areas in m², lengths in m.
// Cost: O(n) for Hack, O(n log n) for the exceedance (one sort of the areas).
#include "compare/descriptors/drainage_laws.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

constexpr double exceedance_points_per_decade = 10.0;

std::vector<double> sorted_valid_areas(const std::vector<double>& area_m2) {
  std::vector<double> areas;
  for (const double area : area_m2) {
    if (area > 0.0) areas.push_back(area);
  }
  std::sort(areas.begin(), areas.end());
  return areas;
}

std::vector<double> log_spaced_areas(double min_area_m2, double max_area_m2) {
  const double decades = std::log10(max_area_m2 / min_area_m2);
  const int count = std::max(2, static_cast<int>(std::lround(exceedance_points_per_decade * decades)) + 1);
  std::vector<double> areas(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    areas[static_cast<std::size_t>(i)] = min_area_m2 * std::pow(max_area_m2 / min_area_m2, i / (count - 1.0));
  }
  return areas;
}

}  // namespace

std::optional<LineFit> hack_fit(const D8Flow& flow, double min_area_m2) {
  if (!std::isfinite(min_area_m2) || min_area_m2 < 0.0) {
    throw InputError(fmt::format("hack_fit: minimum area {} m² is not a finite area >= 0", min_area_m2));
  }
  if (flow.upstream_length_m.size() != flow.area_m2.size()) {
    throw InputError(fmt::format("hack_fit: {} lengths for {} areas", flow.upstream_length_m.size(),
                                 flow.area_m2.size()));
  }
  std::vector<double> log_area, log_length;
  for (std::size_t i = 0; i < flow.area_m2.size(); ++i) {
    const double area = flow.area_m2[i], length = flow.upstream_length_m[i];
    if (area < min_area_m2 || area <= 0.0 || length <= 0.0) continue;
    log_area.push_back(std::log(area));
    log_length.push_back(std::log(length));
  }
  return fit_line(log_area, log_length);
}

std::optional<LineFit> exceedance_fit(const std::vector<double>& area_m2, double min_area_m2, double max_area_m2) {
  if (!std::isfinite(min_area_m2) || !std::isfinite(max_area_m2) || min_area_m2 <= 0.0 ||
      max_area_m2 <= min_area_m2) {
    throw InputError(fmt::format("exceedance_fit: area band [{}, {}] m² is not 0 < min < max", min_area_m2,
                                 max_area_m2));
  }
  const std::vector<double> areas = sorted_valid_areas(area_m2);
  const auto cells = static_cast<double>(areas.size());
  std::vector<double> log_a, log_p;
  for (const double a : log_spaced_areas(min_area_m2, max_area_m2)) {
    const auto at_least_a = areas.end() - std::lower_bound(areas.begin(), areas.end(), a);
    if (at_least_a == 0) continue;
    log_a.push_back(std::log(a));
    log_p.push_back(std::log(static_cast<double>(at_least_a) / cells));
  }
  return fit_line(log_a, log_p);
}

}  // namespace gt
