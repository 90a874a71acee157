// Parameter tables and per-run constants of the two thermal-erosion models (see thermal.hpp).
#include "core/params/thermal.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
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
      real_param("talus_angle", &P::talus_angle_deg, 0.0, 85.0, "degree",
                 "talus angle: C_i = its tan, the talus slope where R = 0 (eq. 2.33; R = 1 without a hardness map)"),
      real_param("hardness_talus", &P::hardness_talus, 0.0, 100.0, "1",
                 "C_a of eq. 2.33: the talus slope toward neighbour n is C_a·R(n) + C_i"),
      real_param("rate", &P::rate, 0.0, 1.0, "1",
                 "Δt·C_t of eq. 2.32: the share of half the largest excess difference moved per iteration, times R"),
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
  constants.hardness_talus = params.hardness_talus;
  return constants;
}

std::vector<std::array<double, 9>> jako_cell_constants(const ThermalConstants& constants, int width, int height) {
  // Mutant erosion.thermal_jako.talus_degree_off (both twins): the slope of an angle one degree
  // steeper than asked.
  const double talus_slope = mutant_active("erosion.thermal_jako.talus_degree_off")
                                 ? std::tan(std::atan(constants.talus_slope) + std::numbers::pi / 180.0)
                                 : constants.talus_slope;
  const auto hardness = [&](int x, int y) {
    return constants.hardness.empty() ? 1.0 : constants.hardness[std::size_t(y) * std::size_t(width) + std::size_t(x)];
  };
  // Mutant erosion.thermal_jako.hardness_of_the_cell (both twins): the talus below a cell read from
  // its own hardness, not the lower neighbour's.
  const bool own_hardness = mutant_active("erosion.thermal_jako.hardness_of_the_cell");
  std::vector<std::array<double, 9>> cells(std::size_t(width) * std::size_t(height));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      auto& cell = cells[std::size_t(y) * std::size_t(width) + std::size_t(x)];
      for (int k = 0; k < 8; ++k) {
        const int nx = x + moore_offsets[k].dx, ny = y + moore_offsets[k].dy;
        const bool inside = nx >= 0 && ny >= 0 && nx < width && ny < height;
        const double neighbour_hardness = !inside ? 0.0 : own_hardness ? hardness(x, y) : hardness(nx, ny);
        const double length = k >= 4 ? constants.length_diagonal : (k % 2 == 0 ? constants.length_x : constants.length_y);
        cell[std::size_t(k)] = (constants.hardness_talus * neighbour_hardness + talus_slope) * length;
      }
      cell[8] = constants.request_factor * hardness(x, y);
    }
  }
  return cells;
}

std::vector<double> jako_hardness(const std::vector<double>& map, const std::vector<std::uint8_t>& valid, int width,
                                  double rate, const std::string& who) {
  std::vector<double> hardness = map;
  for (std::size_t c = 0; c < hardness.size(); ++c) {
    if (!valid.empty() && valid[c] == 0) {
      hardness[c] = 1.0;
    } else if (!std::isfinite(hardness[c]) || hardness[c] < 0.0 || rate * hardness[c] > 1.0) {
      throw InputError(fmt::format("{}: the hardness field holds {} at cell ({}, {}); R must be finite, >= 0 and "
                                   "rate·R at most 1 (rate = {}: a cell moves rate·R of half its largest drop)",
                                   who, hardness[c], c % std::size_t(width), c / std::size_t(width), rate));
    }
  }
  return hardness;
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
