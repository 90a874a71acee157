// Parameter tables and per-run constants of the two thermal-erosion models (see thermal.hpp).
#include "core/params/thermal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/mutant.hpp"

namespace gt {
namespace {

constexpr Choice<Neighbourhood> neighbourhood_choices[] = {{"cardinal", Neighbourhood::cardinal},
                                                           {"diagonal", Neighbourhood::diagonal},
                                                           {"alternating", Neighbourhood::alternating}};

// Range of valid heights; a field with no valid cell counts as flat at 0.
std::pair<double, double> height_range(const Heightmap& heights) {
  const auto [low, high] = valid_range(heights);
  return low > high ? std::pair{0.0, 0.0} : std::pair{low, high};
}

}  // namespace

const char* neighbourhood_name(Neighbourhood neighbourhood) { return choice_name(neighbourhood_choices, neighbourhood); }

const ParamTable<ThermalParams>& thermal_param_table() {
  using P = ThermalParams;
  static const ParamTable<P> table = {
      integer_param("iterations", &P::iterations, 0, 100000, "count", "iterations (two passes each); odd counts allowed"),
      real_param("talus_angle", &P::talus_angle_deg, 0.0, 85.0, "degree", "talus angle α; Hydra's UI range 0..85"),
      real_param("strength", &P::strength, 0.0, 2.0, "1", "Hydra's strength; request factor f_s = strength/2"),
      choice_param("neighbourhood", &P::neighbourhood, neighbourhood_choices, "",
                   "cardinal, diagonal (distance sqrt(lx²+ly²)), or alternating (even iterations cardinal, odd diagonal)"),
      boolean_param("normalised", &P::normalised,
                    "seed 000's [0,1] heights with T from eq. 4.10 instead of physical heights with T = tan α"),
      real_param("vertical_aspect", &P::vertical_aspect, 0.0, 1e6, "1",
                 "d_z of eq. 4.3 for normalised heights; 0 derives it from the grid (2·range/extent_x)"),
  };
  return table;
}

const ParamTable<ThermalJakoParams>& thermal_jako_param_table() {
  using P = ThermalJakoParams;
  static const ParamTable<P> table = {
      integer_param("iterations", &P::iterations, 0, 100000, "count", "iterations (outflow + gather each)"),
      real_param("talus_angle", &P::talus_angle_deg, 0.0, 85.0, "degree", "talus angle: tan = C_a·R + C_i of eq. 2.33"),
      real_param("rate", &P::rate, 0.0, 1.0, "1",
                 "Δt·C_t·R of eq. 2.32: the share of half the largest excess difference moved per iteration"),
  };
  return table;
}

const ParamSpecs& thermal_param_specs() {
  static const ParamSpecs specs = param_specs(thermal_param_table());
  return specs;
}

const ParamSpecs& thermal_jako_param_specs() {
  static const ParamSpecs specs = param_specs(thermal_jako_param_table());
  return specs;
}

ThermalParams thermal_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(thermal_param_table(), resolved);
}

ThermalJakoParams thermal_jako_params_from_json(const nlohmann::json& resolved) {
  return params_from_json(thermal_jako_param_table(), resolved);
}

// Mutant erosion.thermal.eq_4_10_unconverted_degrees: the angle passed to tan in degrees, as if
// radians; both twins take their talus slope from here.
double talus_threshold_eq_4_10(double angle_deg, int width, double vertical_aspect) {
  const double angle = mutant_active("erosion.thermal.eq_4_10_unconverted_degrees") ? angle_deg
                                                                                     : std::numbers::pi / 180.0 * angle_deg;
  return std::tan(angle) / (static_cast<double>(width) * vertical_aspect);
}

ThermalConstants thermal_constants(const ThermalParams& params, const Heightmap& original) {
  check_cell_size(original, "thermal erosion");
  ThermalConstants constants;
  constants.request_factor = params.strength * 0.5;
  if (params.normalised) {
    const auto [low, high] = height_range(original);
    const double extent_x = original.width * original.cell_size_x;
    const double derived_aspect = high > low ? 2.0 * (high - low) / extent_x : 1.0;
    const double aspect = params.vertical_aspect > 0.0 ? params.vertical_aspect : derived_aspect;
    constants.talus_slope = talus_threshold_eq_4_10(params.talus_angle_deg, original.width, aspect);
    constants.length_x = 1.0;
    constants.length_y = original.cell_size_y / original.cell_size_x;
    constants.clamp_unit = true;
  } else {
    constants.talus_slope = std::tan(std::numbers::pi / 180.0 * params.talus_angle_deg);
    constants.length_x = original.cell_size_x;
    constants.length_y = original.cell_size_y;
  }
  constants.length_diagonal = std::hypot(constants.length_x, constants.length_y);
  return constants;
}

ThermalConstants thermal_jako_constants(const ThermalJakoParams& params, const Heightmap& heights) {
  check_cell_size(heights, "thermal erosion (Jákó)");
  ThermalConstants constants;
  constants.talus_slope = std::tan(std::numbers::pi / 180.0 * params.talus_angle_deg);
  constants.length_x = heights.cell_size_x;
  constants.length_y = heights.cell_size_y;
  constants.length_diagonal = std::hypot(constants.length_x, constants.length_y);
  constants.request_factor = params.rate;
  return constants;
}

Heightmap normalise_heights(const Heightmap& heights) {
  Heightmap out = heights;
  const auto [low, high] = height_range(heights);
  const double range = high - low;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out.values[i] = heights.is_valid(i) && range > 0.0 ? (heights.values[i] - low) / range : 0.0;
  }
  out.vertical_unit = "1";
  return out;
}

}  // namespace gt
