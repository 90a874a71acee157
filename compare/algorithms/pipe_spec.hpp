// One step of the virtual-pipe model (Mei, Decaudin, Hu 2007; digest 000 §3.4, eqs. 2.10-2.23) on
// the host, written apart from both twins from the thesis's equations and the decisions that
// reference/erosion/pipes.cpp states in its header: the spec that spec.step.* holds ref<double> to,
// cell by cell (compare/algorithms/pipes.cpp). The twins' agreement cannot see a bug both share
// that conserves water and material (a capacity twice K_c, K_s and K_d exchanged, the tilt's
// central difference not halved); a spec of the erosion law can.
//
// Its constants come from HydraulicParams and the terrain's cell sizes alone, never from
// PipeConstants, which both twins read: a bug in those is a bug of both twins.
//
// It covers every parameter of erosion.pipe: 4 or 8 pipes, flux or semi-Lagrangian transport, both
// tilts (central differences and seed 001's code's raw ones), closed or open borders, the depth
// ramp, rain, a rain map, point sources, evaporation, seed 001's regolith and sediment diffusion
// (both weightings), and Jákó & Tóth's combined thermal step (the thermal spec of
// compare/algorithms/thermal_specs.hpp).
//
// Inputs:  start (every field as the twins' PipeState; no-data cells of the terrain's mask hold
//          nothing and send nothing), params, forcing (rain map in m/s, point sources in m³/s).
// Outputs: the state after one step: b, d, s, r after evaporation, u, v and the scaled outflows.
// Units:   core/params/hydraulic.hpp's (metres, seconds, m³/s).
// Real:    double, or core/rounding_interval.hpp's RoundingInterval for the spec's own rounding
//          bound (its value is the double computation).
#pragma once

#include "core/params/hydraulic.hpp"

namespace gt {

template <class Real>
PipeState<Real> pipe_spec_step(const PipeState<Real>& start, const HydraulicParams& params,
                               const HydraulicForcing& forcing);

}  // namespace gt
