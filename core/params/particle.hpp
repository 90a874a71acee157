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
// Ordering of the droplets of one pass (one draw of Algorithm 7: one droplet per spacing² block):
//   race      every droplet at once on one height buffer, as Hydra dispatches them (the GPU races:
//             droplets overwrite each other); the references run the droplets one after the other
//             in row-major order, the defined truth, and the GPU is compared statistically.
//   disjoint  the same dispatch with spacing > 2·(lifetime + 2), so no two droplets of a pass read
//             or write a common texel (a droplet moves at most one texel per step and touches texels
//             up to two beyond its path): the GPU equals the sequential reference within rounding.
//   batch     every droplet of a pass reads the heights as they were at the pass's start and adds
//             what it erodes and deposits, as fixed-point integers of `quantum`, into a delta that
//             is applied when the pass ends: order-independent, so the GPU equals ref<float> bit for
//             bit at any spacing. The droplet carries its sediment as an integer count of quanta.
#pragma once

#include <string>
#include <vector>

#include "core/grid.hpp"
#include "core/params.hpp"

namespace gt {

enum class DropletOrdering { race, disjoint, batch };

// "race", "disjoint", "batch": the names of the `ordering` parameter.
const char* droplet_ordering_name(DropletOrdering ordering);

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
  DropletOrdering ordering = DropletOrdering::race;
  double quantum = 0.0;        // batch: the height of one fixed-point unit (a power of two)
};

// The texels one droplet can touch beyond its start: lifetime unit steps, one more for the
// neighbour reads and one for the bilinear corners. Spacing must exceed twice this for `disjoint`.
int droplet_reach(int lifetime);

// The fixed-point unit for heights whose magnitude is at most `max_abs_height`: 2^-24 times the
// smallest power of two >= max(1, max_abs_height), about one float ulp at the top of the range, so
// an int32 delta holds ±128 times the heights' magnitude per pass.
double batch_quantum(double max_abs_height);

const ParamSpecs& particle_param_specs();

// Constants from resolved parameters (UI values mapped as §4.4.1 says) for `heights` (already
// normalised when the case asks for it; the quantum is taken from them). Throws InputError when
// `disjoint` is asked with a spacing that lets droplets meet.
ParticleConstants particle_constants(const nlohmann::json& resolved, const Heightmap& heights);

// What the case's output says about parameters run as asked though the thesis warns against them
// (erosion or deposition strength of 0.5 and more oscillates, §4.4.1): the run goes on.
std::vector<std::string> particle_warnings(const ParticleConstants& constants);

}  // namespace gt
