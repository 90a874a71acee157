// Parameters of seed 000's particle (droplet) hydraulic erosion after Beyer 2015 (digest 000 §3.7,
// the thesis's §2.7, eqs. 2.35-2.45; Appendix B item 6) and the per-run constants both twins derive
// from them. Shared by reference/erosion/beyer.cpp and gpu/erosion/beyer.cpp (parameter structs are
// the only thing the twins share besides core data types and the RNG).
//
// Units: the kernel works in texels and steps. Heights are samples at integer points (sample (i, j)
// is cell (i, j) of the grid); a droplet's position is continuous, in texels, and one step moves it
// by its unit direction. Heights are seed 000's normalised heights in [0, 1] by default ((h - min) /
// (max - min) over valid cells, done by the driver), or the input's own heights taken as texel units
// when `normalised` is off (then min_slope, the capacity and the amounts are in those units).
//
// Decisions of this project where the thesis leaves it open (digest notes, Appendix B item 6):
//   - speed (eq. 2.44): `printed` v = sqrt(max(v² + Δh·c_g, 0)) as printed and as Beyer's
//     followers' code has it (slower downhill; the default), the radicand clamped at 0; `physical`
//     v = sqrt(max(v² - Δh·c_g, 0)), faster downhill as the digest reads the intent — without
//     friction the speed, and with it the capacity, then grows on every downhill step, and the
//     terrain runs away within a few iterations at the other defaults (measured on a 64² cone:
//     lowest height -0.89 after 5 iterations, -818 after 9);
//   - the evaporation constant of eq. 2.45 is its own parameter (Beyer's p_evaporation), not the
//     erosion constant c_e of eq. 2.41 that shares its symbol;
//   - the erosion brush of eq. 2.42 is centred at the droplet's old position (Beyer's choice);
//   - eq. 2.43's blend with a blurred map (c_b, `blur_blend`, off by default as in Beyer's own
//     path) follows each outer iteration, with a 3x3 box blur written as exchanges between
//     neighbours so that it conserves the volume (reference/erosion/blur_blend.hpp).
// Orderings of the droplets of a pass and the batch quantum: core/params/droplets.hpp.
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/param_table.hpp"
#include "core/params/droplets.hpp"

namespace gt {

// Eq. 2.44's sign: `physical` (v² - Δh·c_g, Δh = h_new - h_old, so downhill speeds up) or `printed`.
enum class BeyerSpeedRule { physical, printed };

// "physical", "printed": the names of the `speed_rule` parameter.
const char* beyer_speed_rule_name(BeyerSpeedRule rule);

// The kernel's constants, Beyer's names in the comments. Each twin rounds them to its own Real once
// (the GPU receives the float values).
struct BeyerConstants {
  int iterations = 10;            // outer iterations of Algorithm 7: each releases one droplet per texel
  int lifetime = 30;              // steps of one droplet (p_maxPath)
  int spacing = 4;                // one droplet per spacing x spacing block and pass
  double inertia = 0.05;          // c_i (p_inertia)
  double capacity_factor = 4.0;   // c_c (p_capacity)
  double min_slope = 0.01;        // c_min (p_minSlope), a height difference
  double deposition = 0.3;        // c_d (p_deposition)
  double erosion = 0.3;           // c_e of eq. 2.41 (p_erosion)
  double gravity = 4.0;           // c_g (p_gravity)
  double evaporation = 0.01;      // c_e of eq. 2.45 (p_evaporation)
  double radius = 3.0;            // c_r (p_radius), texels
  double initial_speed = 1.0;     // v_0, texels per step
  double initial_water = 1.0;     // w_0
  double blur_blend = 0.0;        // c_b of eq. 2.43: after each iteration h = c_b·blur(h) + (1 - c_b)·h
  BeyerSpeedRule speed_rule = BeyerSpeedRule::printed;
  std::uint32_t seed = 1;         // of the random directions taken where the new direction is 0
  DropletOrdering ordering = DropletOrdering::race;
  double quantum = 0.0;           // batch: the height of one fixed-point unit (a power of two)
};

// The texels one droplet can touch beyond its start: lifetime unit steps, ceil(radius) for the
// erosion brush, one for the bilinear corners and one to spare. Spacing must exceed twice this for
// `disjoint`.
int beyer_reach(const BeyerConstants& constants);

// The parameters of an erosion.beyer case: the kernel's constants, batch ordering by default (the
// kernel's own default is race), and whether the case normalises the heights.
struct BeyerParams {
  BeyerConstants kernel{.ordering = DropletOrdering::batch};
  bool normalised = true;
};

// The declarations (core/param_table.hpp), their ParamSpecs, and the struct from resolve_params' output.
const ParamTable<BeyerParams>& beyer_param_table();
const ParamSpecs& beyer_param_specs();
BeyerParams beyer_params_from_json(const nlohmann::json& resolved);

// Constants from resolved parameters for `heights` (already normalised when the case asks for it;
// the quantum is taken from them). Throws InputError when `disjoint` is asked with a spacing that
// lets droplets meet.
BeyerConstants beyer_constants(const nlohmann::json& resolved, const Heightmap& heights);

}  // namespace gt
