// Parameters of Beneš's dissolution erosion (Beneš 2002 as surveyed by seed 000 §2.3, digest 000
// §3.3, eqs. 2.1-2.9), the per-run constants both twins derive from them and the model's state.
// Shared by reference/erosion/dissolution.cpp and gpu/erosion/dissolution.cpp (parameter structs and
// core data types are the only things the twins share besides the RNG).
//
// Units: the thesis takes cells and time steps as 1. Heights, water and dissolved material are in
// the input's vertical unit (metres); rain is a depth per iteration; the evaporation constant K_e is
// per iteration (eq. 2.2 with t counted in iterations); K_s is material per unit of water (1). The
// transport compares heights only, so the horizontal cell size plays no part (as printed).
#pragma once

#include "core/grid.hpp"
#include "core/param_table.hpp"

namespace gt {

// How much water a cell gives to its lower neighbours before eq. 2.8 shares it (the thesis leaves
// Δw open): `pairwise`, the thesis's proposal, Σ_n min(d, Δh_n/2) clamped to d (eq. 2.9 for each
// pair, summed); `mean_level`, min(d, h − h̄) with h̄ the mean surface of the cell and its lower
// neighbours (Σ_n Δh_n/(n + 1)), which cannot overshoot the mean.
enum class DissolutionShare { pairwise, mean_level };

// "pairwise", "mean_level": the names of the `water_share` parameter.
const char* dissolution_share_name(DissolutionShare share);

struct DissolutionParams {
  int iterations = 100;
  double rain = 0.01;                    // K_r of eq. 2.1, m per iteration on every valid cell
  double evaporation = 0.05;             // K_e of eq. 2.2, per iteration
  double evaporation_threshold = 1e-4;   // T of eq. 2.3, m
  double saturation = 0.05;              // K_s of eq. 2.4, material a unit of water carries
  double dissolution_rate = 1.0;         // share of S - s taken from the terrain per iteration (1: eq. 2.5)
  double deposition_rate = 1.0;          // share of s - S laid down per iteration (1: eq. 2.5)
  DissolutionShare water_share = DissolutionShare::pairwise;
};

const ParamTable<DissolutionParams>& dissolution_param_table();
const ParamSpecs& dissolution_param_specs();
DissolutionParams dissolution_params_from_json(const nlohmann::json& resolved);

// What one iteration needs; each twin rounds these to its own Real once (the GPU gets the floats).
struct DissolutionConstants {
  double rain = 0.01;
  double retained = 0.0;             // e^{-K_e}: the share of the water kept by evaporation (eq. 2.2)
  double evaporation_threshold = 1e-4;
  double saturation = 0.05;
  double dissolution_rate = 1.0;
  double deposition_rate = 1.0;
  DissolutionShare water_share = DissolutionShare::pairwise;
};

DissolutionConstants dissolution_constants(const DissolutionParams& params);

// The model's state, one grid a field, all of one geometry and mask (the terrain's).
//   terrain     b: terrain height
//   water       d: water depth
//   dissolved   s: material carried by the water, as a height of terrain
//   evaporated  the water evaporated from the cell since the start, a depth (the water ledger's
//               term: what rain added is known before the run, what evaporation took is not)
template <class Real>
struct DissolutionState {
  Grid<Real> terrain;
  Grid<Real> water;
  Grid<Real> dissolved;
  Grid<Real> evaporated;
};

}  // namespace gt
