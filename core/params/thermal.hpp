// Parameters of the two thermal-erosion models and the per-run constants both twins derive from
// them. Shared by reference/erosion/thermal*.cpp and gpu/erosion/thermal*.cpp (parameter structs
// are the only thing the twins share besides core data types and the RNG).
//
// erosion.thermal (seed 000, Hydra, digest 000 §4.6): talus angle α in degrees, strength in
// Hydra's UI units (0..2; the request factor f_s = strength/2), neighbourhood cardinal |
// diagonal | alternating (even iterations cardinal, odd diagonal), heights physical (metres, the
// default: T = tan α, lengths in metres) or normalised (seed 000's [0,1] heights, T from eq. 4.10).
//
// erosion.thermal_jako (Jákó & Tóth 2011, digest 000 §3.6): 8 neighbours, the talus angle (C_i =
// tan of it), `hardness_talus` C_a and the fraction `rate` = Δt·C_t of eq. 2.32, with a hardness
// map R(x, y) (the case's "hardness" input field; R = 1 everywhere without one): a cell moves
// rate·R(x, y)·H/2 (eq. 2.32) to the neighbours n whose drop exceeds (C_a·R(n) + C_i)·l (eq. 2.33).
// Decision: R is taken as printed, a factor of both: eq. 2.32 moves more where R is larger (the
// thesis calls R a "hardness" but multiplies by it), eq. 2.33 steepens the talus below a hard
// neighbour.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/param_table.hpp"

namespace gt {

enum class Neighbourhood { cardinal, diagonal, alternating };

// "cardinal", "diagonal", "alternating": the names of the `neighbourhood` parameter.
const char* neighbourhood_name(Neighbourhood neighbourhood);

struct ThermalParams {
  int iterations = 100;
  double talus_angle_deg = 45.0;
  double strength = 1.0;
  Neighbourhood neighbourhood = Neighbourhood::alternating;
  bool normalised = false;
  double vertical_aspect = 0.0;  // d_z of eq. 4.3 for normalised heights; 0 = derived from the grid
};

struct ThermalJakoParams {
  int iterations = 100;
  double talus_angle_deg = 30.0;
  double rate = 0.5;
  double hardness_talus = 0.0;  // C_a of eq. 2.33
};

// The declarations (core/param_table.hpp), their ParamSpecs, and the structs from resolve_params'
// output.
const ParamTable<ThermalParams>& thermal_param_table();
const ParamTable<ThermalJakoParams>& thermal_jako_param_table();
const ParamSpecs& thermal_param_specs();
const ParamSpecs& thermal_jako_param_specs();
ThermalParams thermal_params_from_json(const nlohmann::json& resolved);
ThermalJakoParams thermal_jako_params_from_json(const nlohmann::json& resolved);

// Everything one iteration needs, in the units of the heights it is applied to.
struct ThermalConstants {
  double talus_slope = 0.0;      // T: largest stable height difference per unit length
  double length_x = 1.0;         // distance to the x neighbours
  double length_y = 1.0;         // distance to the y neighbours
  double length_diagonal = 1.0;  // distance to the diagonal neighbours, sqrt(lx² + ly²)
  double request_factor = 0.5;   // f_s of Algorithm 10 (Hydra) or `rate` (Jákó)
  bool clamp_unit = false;       // clamp results to [0, 1] (Hydra, normalised heights only)
  // Jákó only: C_a of eq. 2.33, and R per cell (row-major; empty: R = 1 everywhere).
  double hardness_talus = 0.0;
  std::vector<double> hardness;
};

// Jákó's per-cell constants on a width × height grid, in double, both twins rounding each once to
// their type: [k] for the Moore pipes k = 0..7 (core/grid.hpp's moore_offsets) the threshold
// (C_a·R(n) + C_i)·l_k of eq. 2.33 with C_i = constants.talus_slope and n the neighbour through k (a
// pipe out of the grid is closed: its threshold is C_i·l_k), and [8] the fraction rate·R(c) of eq.
// 2.32. Both twins take their thresholds from here, so the mutants of Jákó's parameters
// (talus_degree_off, hardness_of_the_cell) live here too.
std::vector<std::array<double, 9>> jako_cell_constants(const ThermalConstants& constants, int width, int height);

// Jákó's R per cell from a hardness map on a grid of `valid` cells (empty: all valid): the map's
// values where valid, each checked (finite, >= 0 and rate·R <= 1: a cell moves at most half its largest
// drop), and R = 1 at no-data cells, whose values are unspecified (an outside model hands NaN).
// Throws InputError naming the first cell that fails, and `who`.
std::vector<double> jako_hardness(const std::vector<double>& map, const std::vector<std::uint8_t>& valid, int width,
                                  double rate, const std::string& who);

// T_α = tan(π/180·α) / (width·d_z), eq. 4.10 of seed 000 taken literally. The digest shows it is a
// factor 2 steeper than the geometry implies (effective angle atan(tan α / 2)); kept for parity.
double talus_threshold_eq_4_10(double angle_deg, int width, double vertical_aspect);

// Constants for Hydra's model on `heights` (already normalised when params.normalised).
// Physical: T = tan α, lengths = cell sizes. Normalised: l_x = 1, l_y = cell_y/cell_x (eq. 4.3),
// d_z = 2·range/(width·cell_x) unless given, T from eq. 4.10.
ThermalConstants thermal_constants(const ThermalParams& params, const Heightmap& original);
ThermalConstants thermal_jako_constants(const ThermalJakoParams& params, const Heightmap& heights);

// Seed 000's normalised heights: (h - min) / (max - min) over valid cells (a flat field maps to 0).
Heightmap normalise_heights(const Heightmap& heights);

}  // namespace gt
