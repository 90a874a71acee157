// Parameters of seed 000's particle (droplet) water erosion (Hydra, digest 000 §4.4, Appendix A)
// and the per-run constants both twins derive from them. Shared by reference/erosion/particle.cpp
// and gpu/erosion/particle.cpp (parameter structs are the only thing the twins share besides core
// data types and the RNG).
//
// Units: the kernel works in texels. Positions and velocities are in texels (per step), one step
// moves a droplet at most one texel; heights are seed 000's normalised heights in [0, 1] by
// default ((h - min)/(max - min) over valid cells), or the input's own heights taken as texel units
// when `normalised` is off (then drop_max, capacity and the amounts are in those units).
//
// Orderings of the droplets of a pass and the batch quantum: core/params/droplets.hpp.
//
// Colour transport (§4.5) is optional per run: the reference and the GPU twin transport a colour map
// only when given one; colour_mixing and interpolate_colour act on nothing otherwise.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/param_table.hpp"
#include "core/params/droplets.hpp"

namespace gt {

// The kernel's constants (Appendix A's uniforms), already mapped from the UI values of §4.4.1.
// Each twin rounds them to its own Real once (the GPU receives the float values).
struct ParticleConstants {
  int iterations = 10;         // outer iterations of Algorithm 7: each releases one droplet per texel
  int lifetime = 50;           // steps of one droplet (part_lifetime)
  int spacing = 4;             // subdiv: one droplet per spacing x spacing block and pass
  double acceleration = 0.5;   // a (part_acceleration)
  double bite = 0.25;          // erosion strength (part_fineness)
  double release = 0.25;       // deposition strength (part_deposition x 0.5)
  double max_velocity = 2.0;   // v_max, texels per step
  double drag = 0.8;           // the velocity multiplier 1 - part_drag
  double capacity_factor = 0.01;  // f_c (part_capacity x 1e-2)
  double max_jump = 0.1;       // drop_max (part_maxjump)
  bool interpolate = true;     // bilinear erosion over the 4 nearest texel centres (Algorithm 6)
  // Colour transport (§4.5, Algorithm 8, eq. 4.9), used only when a run is given a colour map.
  double colour_mixing = 0.2;     // f_col (color_mixing): share of the texel's colour a droplet picks up
  bool interpolate_colour = true;  // colour deposited over the 4 nearest texel centres (colorize4)
  DropletOrdering ordering = DropletOrdering::race;
  double quantum = 0.0;        // batch: the height of one fixed-point unit (a power of two)
};

// The flow map's constants (§4.7): the droplets move as the erosion's (Algorithm 4 without the
// drop_max limit, drag, the v_max clamp), one droplet per texel in spacing² passes (its own spacing),
// and leave a concentration F = F·(1 - factor) + factor (eq. 4.12) where they pass, factor = f_c·w
// over erode4's 4 corners (interpolate) or f_c at the droplet's texel.
// Batch ordering: the concentration is order-dependent in float, so each visit adds its weight w as
// an integer count of 2^-10 (flow_weight_quantum) and a texel's count n becomes
// F = 1 - Π over n's set bits i of (1 - f_c)^(2^i · 2^-10) (batch_powers[i], rounded once per Real):
// order-independent, (1 - f_c)^w in place of 1 - f_c·w per visit (equal for w = 1).
struct FlowConstants {
  int spacing = 8;             // flow_subdiv: one droplet per spacing x spacing block and pass
  int lifetime = 50;           // steps of one droplet (shared with erosion)
  double acceleration = 0.5;   // as ParticleConstants
  double max_velocity = 2.0;
  double drag = 0.8;
  double factor = 0.0;         // f_c of eq. 4.12: flow_contrast_factor(contrast), eq. 4.13
  bool interpolate = true;     // interpolate_flow: the concentration over the 4 nearest texel centres
  DropletOrdering ordering = DropletOrdering::race;
  std::array<double, 31> batch_powers{};  // (1 - factor)^(2^i · flow_weight_quantum), i = 0..30
};

// One unit of a batch flow weight count.
inline constexpr double flow_weight_quantum = 1.0 / 1024.0;

// Eq. 4.13: f_c = 0.2·exp(-6.61·contrast), the UI's contrast in [0, 1] to the flow contrast constant.
double flow_contrast_factor(double contrast);

// (1 - factor)^(2^i · flow_weight_quantum) for i = 0..30, in double.
std::array<double, 31> flow_batch_powers(double factor);

// The texels one droplet can touch beyond its start: lifetime unit steps, one more for the
// neighbour reads and one for the bilinear corners. Spacing must exceed twice this for `disjoint`.
int droplet_reach(int lifetime);

// The parameters of an erosion.particle case: the UI values of §4.4.1 (add-on 1a1a8c9), which
// particle_constants maps to the kernel's, and the case's pictures, colour map and flow map.
struct ParticleParams {
  int iterations = 10;
  int lifetime = 50;
  int spacing = 4;
  double acceleration = 0.5;
  double erosion_strength = 0.25;     // bite
  double deposition_strength = 0.25;  // release
  double max_velocity = 2.0;
  double drag = 0.2;                  // the kernel's drag is 1 - drag
  double capacity_factor = 0.01;
  double max_jump = 0.1;
  bool interpolate = true;
  double colour_mixing = 0.2;
  bool interpolate_colour = true;
  DropletOrdering ordering = DropletOrdering::batch;
  double erosion_contrast = 20.0;
  double deposition_contrast = 15.0;
  std::string colour = "none";
  bool flow_map = true;
  int flow_spacing = 8;
  double flow_contrast = 0.5;
  bool interpolate_flow = true;
  bool normalised = true;
};

// The declarations (core/param_table.hpp), their ParamSpecs, and the struct from resolve_params' output.
const ParamTable<ParticleParams>& particle_param_table();
const ParamSpecs& particle_param_specs();
ParticleParams particle_params_from_json(const nlohmann::json& resolved);

// Constants from resolved parameters (UI values mapped as §4.4.1 says) for `heights` (already
// normalised when the case asks for it; the quantum is taken from them). Throws InputError when
// `disjoint` is asked with a spacing that lets droplets meet.
ParticleConstants particle_constants(const nlohmann::json& resolved, const Heightmap& heights);

// The flow map's constants from resolved parameters and the erosion's constants (shared motion);
// nullopt when the case asks for no flow map. Throws InputError when `disjoint` is asked with a flow
// spacing that lets droplets meet.
std::optional<FlowConstants> flow_constants(const nlohmann::json& resolved, const ParticleConstants& erosion);

// What the case's output says about parameters run as asked though the thesis warns against them
// (erosion or deposition strength of 0.5 and more oscillates, §4.4.1): the run goes on.
std::vector<std::string> particle_warnings(const ParticleConstants& constants);

}  // namespace gt
