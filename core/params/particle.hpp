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

#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/params.hpp"
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

// The texels one droplet can touch beyond its start: lifetime unit steps, one more for the
// neighbour reads and one for the bilinear corners. Spacing must exceed twice this for `disjoint`.
int droplet_reach(int lifetime);

const ParamSpecs& particle_param_specs();

// Constants from resolved parameters (UI values mapped as §4.4.1 says) for `heights` (already
// normalised when the case asks for it; the quantum is taken from them). Throws InputError when
// `disjoint` is asked with a spacing that lets droplets meet.
ParticleConstants particle_constants(const nlohmann::json& resolved, const Heightmap& heights);

// What the case's output says about parameters run as asked though the thesis warns against them
// (erosion or deposition strength of 0.5 and more oscillates, §4.4.1): the run goes on.
std::vector<std::string> particle_warnings(const ParticleConstants& constants);

}  // namespace gt
