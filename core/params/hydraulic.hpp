// Hydraulic erosion with virtual pipes (Mei, Decaudin, Hu 2007; digest 000 §3.4 and Appendix B):
// the parameters, the per-run constants both twins derive from them, the forcing (rain map, point
// sources), the state the twins advance and the water/material ledger they fill. Algorithm name
// `erosion.pipe`. Shared by reference/erosion/pipes.cpp and (later) the GPU twin.
//
// Units (SI throughout, so a parameter keeps its meaning across grid sizes):
//   lengths and heights in metres (cell size from the terrain grid), Δt in seconds, rain in m/s,
//   point sources in m³/s, fluxes in m³/s, velocities in m/s, rates (evaporation K_e, dissolving
//   K_s, deposition K_d) in 1/s. Suspended sediment s is a height of material in metres over the
//   cell (Mei's convention), so material volume = (b + s)·l_x·l_y. The capacity constant K_c is in
//   seconds: C = K_c · sin α · |v| is a height in metres.
// Decisions where Mei is silent or per-step:
//   - Mei's K_s and K_d are fractions per step; here they are rates: the fraction of the gap to the
//     capacity closed in one step is min(1, K·Δt), so results do not depend on how time is cut.
//   - Evaporation d ← d·(1 − K_e·Δt) needs K_e·Δt ≤ 1; larger products are refused, not clamped.
//   - Pipe cross-section A: a parameter in m²; 0 takes the cell area l_x·l_y (Šťava's A = l²).
//   - Point sources and the rain map are inputs (HydraulicForcing), not JSON parameters.
//   - Seed 001's regolith rates K_re, K_rd are "usually 1" per step in the thesis; here rates in 1/s
//     like K_s, K_d, with defaults (20/s) that close the whole gap at Δt ≥ 0.05 s.
//   - Jákó & Tóth's combined step (digest 000 §3.6): after each pipe step, one iteration of their
//     8-neighbour thermal erosion (reference/erosion/thermal_jako.hpp) on the terrain, with its own
//     talus angle and rate; the rate is per iteration, so it does not scale with Δt (as theirs).
//   - Seed 001's sediment diffusion (§3.8): `uniform` is the thesis's weight w per neighbour;
//     `water` is its code's weighting by water depth (centre d, neighbours ½·d_n), in which w only
//     switches the stage on.
//   - Seed 001's regolith (§3.9): `regolith_diffusion` = true diffuses r like s (the thesis); false
//     is its code, where r moves with the water but stage 6b diffuses only s.
//   - `tilt_differences` (seed 001 §3.5, §5): `central` = sin α from central differences over 2l
//     (the true slope); `seed001_code` = its code's get_steepness, the raw differences
//     |b(x−1) − b(x+1)| (as if l = 1 and without halving) in the same sqrt(q/(1 + q)); at an exterior
//     neighbour both take the one-sided difference, the code variant over 1 too (not doubled: the
//     seed's code wraps periodically and never meets a border), and 0 with both sides exterior.
//   - Šťava et al. 2008's layers (digest 000 §3.5, eqs. 2.27-2.29, Algorithm 1): `layers` = N ≤ 3
//     layers of thickness b_1..b_N (state field, m) lie on the bedrock, layer N on top; the terrain
//     b stays the ground's height (eq. 2.27: the bedrock's surface plus Σ b_k), so the flow, the
//     tilt and the material ledger are unchanged. Layer k's capacity constant is C_k
//     (`layer_capacity_k`, s), the bedrock's K_c (`capacity`). The law and its decisions are at the
//     top of reference/erosion/pipes.cpp. `layer_erosion` = as_printed takes Algorithm 1's printed
//     condition T̂_k < s. With layers, regolith and the thermal step are refused: the seeds do not
//     say which layer they loosen or move.
//   - `pipes` (issue 3): 4 pipes (Mei) or 8, the diagonal pipes of length l_d = sqrt(l_x² + l_y²)
//     with the same cross-section A. A choice of the names "4" and "8" (JSON case files write
//     "pipes": "8"), so the parameter system itself refuses any other count.
#pragma once

#include <array>
#include <vector>

#include "core/grid.hpp"
#include "core/param_table.hpp"
#include "core/params/diffusion_weighting.hpp"
#include "core/params/thermal.hpp"
#include "core/sum.hpp"

namespace gt {

enum class SedimentTransport { semi_lagrangian, flux, maccormack };
enum class PipeBoundary { closed, open };
// Seed 001 §3.5: sin α from central differences over the distance, or its code's raw differences.
enum class TiltDifferences { central, seed001_code };
// Algorithm 1's condition to erode layer k: T̂_k > s (the prose: the water has capacity left) or as
// the thesis prints it, T̂_k < s (digest 000 §3.5's note).
enum class LayerErosion { capacity_above_sediment, as_printed };
// The most layers above the bedrock (state fields layer_1 .. layer_3).
inline constexpr int max_pipe_layers = 3;

// "semi_lagrangian", "flux", "maccormack", "closed", "open", "central", "seed001_code": the names of
// the `transport`, `boundary` and `tilt_differences` parameters (diffusion_weighting_name: core/params/diffusion_weighting.hpp).
const char* sediment_transport_name(SedimentTransport transport);
const char* pipe_boundary_name(PipeBoundary boundary);
const char* tilt_differences_name(TiltDifferences differences);
const char* layer_erosion_name(LayerErosion erosion);  // "capacity_above_sediment", "as_printed"

// Pipe k of a cell leads to (x + dx, y + dy): L, R, T, B = 0..3 (Mei: T is +y), then the diagonals
// TL, BR, TR, BL = 4..7 (used with 8 pipes only); pipe k and pipe k^1 are opposite.
struct PipeOffset {
  int dx;
  int dy;
};
inline constexpr std::array<PipeOffset, 8> pipe_offsets{{{-1, 0}, {1, 0}, {0, 1}, {0, -1},
                                                         {-1, 1}, {1, -1}, {1, 1}, {-1, -1}}};
// "L", "R", "T", "B", "TL", "BR", "TR", "BL" for pipes 0..7.
const char* pipe_name(int pipe);

struct HydraulicParams {
  int steps = 200;
  double time_step = 0.05;              // Δt, s
  double gravity = 9.81;                // g, m/s²
  double pipe_area = 0.0;               // A, m²; 0 = cell area l_x·l_y
  double rain_rate = 0.0;               // uniform rain, m/s
  double evaporation_rate = 0.0;        // K_e, 1/s
  double capacity = 0.1;                // K_c, s
  double min_tilt_sine = 0.05;          // lower bound of sin α (Mei's T_α, seed 001's 0.05)
  TiltDifferences tilt_differences = TiltDifferences::central;
  double depth_ramp = 0.0;              // K_w of l(d) = min(1, d/K_w), m; 0 = no ramp (Mei)
  double dissolving_rate = 0.5;         // K_s, 1/s
  double deposition_rate = 0.5;         // K_d, 1/s
  double velocity_depth_floor = 1e-3;   // the mean depth in u = ΔW_X/(l_y·d̄) is at least this, m
  int pipe_count = 4;                   // 4 (L, R, T, B) or 8 (and the diagonals)
  SedimentTransport transport = SedimentTransport::flux;
  PipeBoundary boundary = PipeBoundary::closed;
  // Seed 001's variant (digest 001 §3.8-3.9); 0 switches a stage off.
  double sediment_diffusion = 0.0;      // w, share of s (and r) sent to each neighbour per step, ≤ 1/4
  DiffusionWeighting diffusion_weighting = DiffusionWeighting::uniform;
  double regolith_depth = 0.0;          // K_r, the most water can loosen of the bed, m
  double regolith_dissolving_rate = 20.0;   // K_re, 1/s: a step closes min(1, K_re·Δt) of r_max − r
  double regolith_deposition_rate = 20.0;   // K_rd, 1/s: a step closes min(1, K_rd·Δt) of r − r_max
  bool regolith_diffusion = true;       // r diffused like s (the thesis) or not (seed 001's code)
  // Jákó & Tóth 2011's combined step: one iteration of their thermal erosion after each pipe step.
  bool thermal_step = false;
  double thermal_talus_angle = 30.0;    // degrees
  double thermal_rate = 0.5;            // Jákó's rate = Δt·C_t·R per iteration, in [0, 1]
  // Šťava et al. 2008's layers above the bedrock (0 = Mei's single material).
  int layers = 0;
  std::array<double, max_pipe_layers> layer_capacity{0.2, 0.4, 0.8};  // C_1..C_3, s (layer 1 lowest)
  LayerErosion layer_erosion = LayerErosion::capacity_above_sediment;
};

// The declarations (core/param_table.hpp), their ParamSpecs, and the struct from resolve_params' output.
const ParamTable<HydraulicParams>& hydraulic_param_table();
const ParamSpecs& hydraulic_param_specs();
HydraulicParams hydraulic_params_from_json(const nlohmann::json& resolved);

// A point source pours `rate` m³/s into cell (x, y).
struct PointSource {
  int x = 0;
  int y = 0;
  double rate = 0.0;
};

// Water added besides the uniform rain: rain_map (m/s, same size as the terrain, empty = none) is
// added to rain_rate cell by cell; each source adds rate·Δt/(l_x·l_y) metres to its cell.
struct HydraulicForcing {
  Grid<double> rain_map;
  std::vector<PointSource> sources;
};

// Everything one step needs, in double; the twins round each to their scalar once.
struct PipeConstants {
  double time_step = 0.05;
  double gravity = 9.81;
  double pipe_area = 1.0;             // A, resolved (never 0)
  double length_x = 1.0;              // l_x = cell_size_x, m
  double length_y = 1.0;              // l_y = cell_size_y, m
  double length_diagonal = 1.0;       // l_d = sqrt(l_x² + l_y²), m: the diagonal pipes' length
  double cell_area = 1.0;             // l_x·l_y, m²
  double rain_rate = 0.0;             // m/s
  double evaporation_kept = 1.0;      // 1 − K_e·Δt, in [0, 1]
  double capacity = 0.1;              // K_c, s
  double min_tilt_sine = 0.05;
  TiltDifferences tilt_differences = TiltDifferences::central;
  double depth_ramp = 0.0;            // K_w, m; 0 = off
  double dissolving_fraction = 0.0;   // min(1, K_s·Δt)
  double deposition_fraction = 0.0;   // min(1, K_d·Δt)
  double velocity_depth_floor = 1e-3; // m
  int pipe_count = 4;                 // 4 or 8
  SedimentTransport transport = SedimentTransport::flux;
  PipeBoundary boundary = PipeBoundary::closed;
  double sediment_diffusion = 0.0;             // w; 0 = off
  DiffusionWeighting diffusion_weighting = DiffusionWeighting::uniform;
  double regolith_depth = 0.0;                 // K_r, m; 0 = off
  double regolith_dissolving_fraction = 1.0;   // min(1, K_re·Δt)
  double regolith_deposition_fraction = 1.0;   // min(1, K_rd·Δt)
  bool regolith_diffusion = true;              // stage 6b diffuses r too (with w > 0 and K_r > 0)
  bool thermal_step = false;
  ThermalConstants thermal;                    // thermal_jako_constants() on the terrain's grid
  int layer_count = 0;                         // N layers above the bedrock, 0..max_pipe_layers
  std::array<double, max_pipe_layers> layer_capacity{};  // C_1..C_N, s
  LayerErosion layer_erosion = LayerErosion::capacity_above_sediment;
};

// Constants for `params` on the grid of `terrain` (its cell sizes). Throws InputError for values a
// struct built in code can hold but the declared ranges refuse (check_param_ranges: Δt ≤ 0,
// negative rates, non-finite values, a pipe count other than 4 or 8, ...), for K_e·Δt > 1 and for
// a cell size ≤ 0.
PipeConstants pipe_constants(const HydraulicParams& params, const Heightmap& terrain);

// What the tilt divides a height difference across `sides` (1: one-sided, 2: central) cells of size
// `length` by: sides·length (central, the slope), or 1 (seed001_code: the raw difference).
double tilt_span(TiltDifferences differences, int sides, double length);

// The state of a pipe-model run. Pipes are indexed as pipe_offsets: L, R, T, B = 0..3, pointing to
// (x−1, y), (x+1, y), (x, y+1), (x, y−1) (Mei: T is +y), then TL, BR, TR, BL = 4..7; pipe k and
// pipe k^1 are opposite. With 4 pipes the diagonal fluxes are 0 (the twins refuse others).
template <class Real>
struct PipeState {
  Grid<Real> terrain;                       // b, m
  Grid<Real> water;                         // d, m
  Grid<Real> sediment;                      // s, m of material over the cell
  std::vector<std::array<Real, 8>> outflow; // f per pipe as pipe_offsets, m³/s (scaled, ≥ 0)
  Grid<Real> velocity_x;                    // u, m/s, +x
  Grid<Real> velocity_y;                    // v, m/s, +y
  Grid<Real> regolith;                      // r, m of loosened bed material (seed 001 §3.9)
  std::vector<Grid<Real>> layers;           // b_1..b_N, m: layer thicknesses, bottom first (Šťava 2008)
};

// A state with the geometry and mask of `terrain`, dry, no sediment or regolith, no flux, at rest,
// and `layers` layers of thickness 0.
template <class Real>
PipeState<Real> dry_pipe_state(const Grid<Real>& terrain, int layers = 0);

// Every field and flux of `state` rounded once to To.
template <class To, class From>
PipeState<To> cast_pipe_state(const PipeState<From>& state);

// Every field and flux v of `state` as value(v), the grids' geometry and mask kept.
template <class To, class From, class Value>
PipeState<To> map_pipe_state(const PipeState<From>& state, Value value) {
  PipeState<To> mapped{state.terrain.template map<To>(value),    state.water.template map<To>(value),
                       state.sediment.template map<To>(value),   {},
                       state.velocity_x.template map<To>(value), state.velocity_y.template map<To>(value),
                       state.regolith.template map<To>(value)};
  for (const auto& layer : state.layers) mapped.layers.push_back(layer.template map<To>(value));
  mapped.outflow.reserve(state.outflow.size());
  for (const auto& fluxes : state.outflow) {
    auto& mapped_fluxes = mapped.outflow.emplace_back();
    for (std::size_t k = 0; k < fluxes.size(); ++k) mapped_fluxes[k] = value(fluxes[k]);
  }
  return mapped;
}

// What both twins refuse before they run (InputError, "erosion.pipe: ..."): fields of another size
// than the terrain, a mask without a valid cell, non-finite values on valid cells (in Real: a value
// that rounds to infinity is refused too), negative water, sediment, regolith, layer or flux, another
// number of layers than the constants' layer_count, flux through
// diagonal pipes with 4 pipes, a rain map of another size or with negative or non-finite rates, and
// sources off the grid, on no-data cells or with a negative or non-finite rate or depth.
template <class Real>
void check_pipe_input(const PipeState<Real>& state, const HydraulicForcing& forcing, const PipeConstants& constants);

// One line of the ledger: volumes in m³, summed over valid cells in double with compensated
// sums. State totals are after the step; the flows are cumulative since the initial state (entry 0).
struct PipeLedgerEntry {
  int step = 0;
  double water = 0.0;                  // W_t = Σ d·l_x·l_y
  double terrain = 0.0;                // Σ b·l_x·l_y
  double sediment = 0.0;               // Σ s·l_x·l_y
  double regolith = 0.0;               // Σ r·l_x·l_y
  double rain_in = 0.0;                // uniform rain and rain map, Σ Δt·r·l_x·l_y as asked for
  double source_in = 0.0;              // point sources, Σ Δt·rate as asked for
  // What the steps added to the depths, Σ (d_A − d)·l_x·l_y as the scalar rounded each addition. In
  // float, adding the same small rain depth to many similar depths rounds the same way every step,
  // so the water received drifts from rain_in + source_in by about 1e-6 over hundreds of steps; the
  // balance uses what was added (it measures what the flow does with the water), and
  // rain_rounding() reports the difference.
  double water_added = 0.0;
  double evaporated = 0.0;
  double boundary_out_water = 0.0;     // through open borders and into no-data cells
  double boundary_out_sediment = 0.0;
  double boundary_out_regolith = 0.0;
  double max_cfl = 0.0;                // this step: max of Δt·|u|/l_x and Δt·|v|/l_y over valid cells
};

// The cumulative flows of a run, each a compensated sum in double, as both twins keep them;
// write_to copies them into a ledger entry.
struct PipeFlows {
  CompensatedSum rain_in, source_in, water_added, evaporated, boundary_out_water, boundary_out_sediment,
      boundary_out_regolith;
  void write_to(PipeLedgerEntry& entry) const;
};

// W_t − W_0 − water_added + evaporated + boundary_out_water: 0 for exact arithmetic, m³.
double water_balance(const PipeLedgerEntry& entry, const PipeLedgerEntry& initial);

// (rain_in + source_in) − water_added: the rain and source water the additions' rounding lost, m³.
double rain_rounding(const PipeLedgerEntry& entry);

// (terrain + sediment + regolith + boundary_out_sediment + boundary_out_regolith) − (terrain_0 +
// sediment_0 + regolith_0): 0 when material is conserved, m³.
double material_drift(const PipeLedgerEntry& entry, const PipeLedgerEntry& initial);

}  // namespace gt
