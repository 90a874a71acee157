// `erosion.pipe`: hydraulic erosion with virtual pipes (Mei 2007, digest 000 §3.4; seed 001's
// variant by its parameters: depth ramp, sediment diffusion, regolith) on a heightmap, run by the
// CPU reference in double (the truth) and in float, and by the GPU twin, each with its per-step
// water and material ledger (core/params/hydraulic.hpp).
//
// Scenario parameters (besides hydraulic_param_specs()):
//   initial_water  dry; depth: initial_depth metres on every valid cell (seed 001's one-shot "set
//                  water level", 0.1 m); sea_level: cells below sea_level start filled up to it
//                  (topobathy: the sea is there from the start; with closed borders it stays, with
//                  open borders it drains off the grid and the ledger counts it).
//   rain_map       none; orographic: rain_map_rate·(b − b_min)/(b_max − b_min) m/s more rain on
//                  high ground (a rain map in m/s, added to the uniform rain_rate).
//   source_rate    one point source of that many m³/s at (source_x, source_y) (shares of the grid's
//                  width and height); 0 = none. A source on a no-data cell is refused.
//   checkpoints    how many states along the run the shadow steps start from and the GPU is
//                  compared with ref<double> at.
//
// Checks (backend cpu = ref<double>, cpu_float = ref<float>, gpu = the GPU twin). Every bound is
// fixed before the run from an error model (compare/checks/pipe_error_model.hpp); no check grades
// a run against its own measurements.
//   mass.water_added.{cpu,cpu_float,gpu}  max over steps of |water the twin's additions put into
//                  its depths − asked| / (W_0 + asked), asked = step × (rain × valid area × Δt +
//                  rain map + sources × Δt) computed on the host from the parameters and forcing;
//                  bound u·((1 + sources)·steps + 4): the additions' rounding.
//   mass.evaporation.{cpu,cpu_float,gpu}  max over steps of |evaporated − K/(1 − K)·Σ W_t| /
//                  (Σ W_t/(1 − K)), K = K_e·Δt from the parameters, W_t the water held after step t:
//                  the rate the twin evaporated at; bound 3u.
//   mass.water_balance.{cpu,gpu}   max over steps of |W_t − W_0 − added + evaporated + out| divided
//                  by the water handled, W_0 + rain_in + source_in: bound 1e-12 (cpu) and 1e-6 (gpu),
//                  issue 3's figures (cpu: each step rounds a cell's depth in at most 6 operations of
//                  relative error 2^-53, so n steps move the total by at most 6n·2^-53 of it: 3.3e-13
//                  at n = 500). It catches water lost inside a step; the two checks above catch water
//                  added or evaporated at the wrong rate, which this balance (booking what was
//                  added and taken) cannot see. cpu_float: informative.
//   mass.material_drift.{cpu,gpu}  max over steps of |material_drift| divided by the material
//                  present, M_0 = Σ(|b_0| + s_0 + r_0)·l_x·l_y. Flux transport conserves: bounds
//                  1e-12 (cpu, as the water) and 1e-6 (gpu). Semi-Lagrangian transport does not
//                  (the method's property, no model of how much): informative.
//   mass.material_drift_of_moved.{cpu,gpu}  the same drift divided by the material moved
//                  (Σ|b_T − b_0|·l_x·l_y + what is suspended or left): informative.
//   mass.material_drift.cpu_float  informative: the float trap of plain float storage (the GPU
//                  stores heights as base + change, gpu/erosion/pipes.hpp).
//   stability.pipe_wave_number     the stability number of the pipe scheme's gravity waves (see
//                  pipe_wave_number below), from the parameters: at most 1, no warn band.
//   stability.max_cfl.{cpu,cpu_float,gpu}  the largest Δt·|u|/l_x or Δt·|v|/l_y of the run: at most
//                  1 by the K scaling (max_cfl_bound), plus 24 float roundings; no warn band.
//   parity.shadow.{terrain_change,water,sediment,regolith,velocity,flux}.gpu_vs_float  at every
//                  checkpoint ref<float>'s state is loaded into the GPU and both take one step:
//                  max |gpu − ref<float>| against pipe_shadow_bounds of that state (add_shadow_parity;
//                  regolith only with K_r > 0). …four_steps…: the same after 4 steps, informative.
//   parity.{terrain_change,water,sediment}.gpu_vs_double  informative: max |gpu − ref<double>| of
//                  b_T − b_0, d and s at the end, its RMS, and the divergence rate (e-folding per
//                  step) between the first and last checkpoint; a plot shows GPU and ref<float> at
//                  every checkpoint. The flow is chaotic: no a-priori bound exists for long runs.
//   determinism.gpu                cells whose terrain, water or sediment differ in any bit between
//                  two GPU runs (the second without the ledger's downloads, timed): bound 0.
// Mutants: compare/mutants/pipe.cpp (killed on the erosion.pipe.mutant_probe.* cases).
// A state that turns NaN or negative makes the reference (or the GPU's check) throw InputError,
// and the case ends as an error naming the step, the cell and the CFL number.
// Pictures: terrain before and after, erosion (blue) and deposition (red), water depth, sediment,
// velocity magnitude (ref<double>), and the GPU's terrain change minus the reference's. Plots: the
// ledger error over the steps (water balance and material drift, each backend) and the ledger's
// volumes (water, rain and sources in, evaporated, out through the borders).
// Timings: one whole run each (the reference in double; the GPU without ledger downloads,
// bracketed by glFinish).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <functional>
#include <memory>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/benchmark.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/pipe_error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/hydraulic.hpp"
#include "core/sum.hpp"
#include "gpu/erosion/pipes.hpp"
#include "gpu/timing.hpp"
#include "reference/erosion/pipes.hpp"

namespace gt {
namespace {

constexpr double cpu_water_bound = 1e-12;
constexpr double gpu_water_bound = 1e-6;
constexpr double cpu_material_bound = 1e-12;
constexpr double gpu_material_bound = 1e-6;
constexpr double drift_floor = 1e-18;  // log plots: exact zeros drawn here

const ParamSpecs& pipe_specs() {
  static const ParamSpecs specs = [] {
    ParamSpecs all = hydraulic_param_specs();
    const ParamSpecs scenario = {
        {"initial_water", ParamKind::choice, "depth", 0, 0, {"dry", "depth", "sea_level"}, "",
         "dry; depth: initial_depth on every cell (seed 001's set water level); sea_level: fill up to sea_level"},
        {"initial_depth", ParamKind::real, 0.1, 0.0, 1e3, {}, "m", "water depth of initial_water = depth"},
        {"sea_level", ParamKind::real, 0.0, -1e4, 1e4, {}, "m", "initial_water = sea_level fills cells below it"},
        {"rain_map", ParamKind::choice, "none", 0, 0, {"none", "orographic"}, "",
         "orographic: rain_map_rate·(b − b_min)/(b_max − b_min) more rain on high ground"},
        {"rain_map_rate", ParamKind::real, 0.0, 0.0, 1.0, {}, "m/s", "the orographic rain on the highest cell"},
        {"source_rate", ParamKind::real, 0.0, 0.0, 1e6, {}, "m³/s", "one point source; 0 = none"},
        {"source_x", ParamKind::real, 0.5, 0.0, 1.0, {}, "1", "the source's column as a share of the width"},
        {"source_y", ParamKind::real, 0.5, 0.0, 1.0, {}, "1", "the source's row as a share of the height"},
        {"checkpoints", ParamKind::integer, 16, 1, 1000, {}, "count",
         "states along the run from which the GPU takes shadow steps beside ref<float>, and at which it is "
         "compared with ref<double>"},
    };
    all.insert(all.end(), scenario.begin(), scenario.end());
    return all;
  }();
  return specs;
}

struct PipeScenario {
  HydraulicParams params;
  PipeConstants constants;
  PipeState<double> initial;
  HydraulicForcing forcing;
  int checkpoints = 16;
  std::vector<std::string> notes;
};

void set_initial_water(const nlohmann::json& resolved, PipeScenario& scenario) {
  auto& state = scenario.initial;
  const auto mode = resolved.at("initial_water").get<std::string>();
  const double depth = resolved.at("initial_depth");
  const double sea_level = resolved.at("sea_level");
  for (std::size_t cell = 0; cell < state.terrain.size(); ++cell) {
    if (!state.terrain.is_valid(cell)) continue;
    if (mode == "depth") state.water.values[cell] = depth;
    if (mode == "sea_level") state.water.values[cell] = std::max(0.0, sea_level - state.terrain.values[cell]);
  }
  if (mode == "depth") scenario.notes.push_back(fmt::format("initial water: {} m on every valid cell", depth));
  if (mode == "sea_level") {
    scenario.notes.push_back(fmt::format("initial water: cells below {} m filled up to it (the sea from the start)",
                                         sea_level));
  }
}

void set_forcing(const nlohmann::json& resolved, PipeScenario& scenario) {
  const auto& terrain = scenario.initial.terrain;
  if (resolved.at("rain_map") == "orographic") {
    const FieldTotals totals = field_totals(terrain);
    const double range = totals.high - totals.low;
    const double rate = resolved.at("rain_map_rate");
    Grid<double> rain = terrain;
    for (std::size_t cell = 0; cell < rain.size(); ++cell) {
      rain.values[cell] = terrain.is_valid(cell) && range > 0.0 ? rate * (terrain.values[cell] - totals.low) / range : 0.0;
    }
    scenario.forcing.rain_map = std::move(rain);
    scenario.notes.push_back(fmt::format("orographic rain map: 0 to {} m/s from {:.4g} m to {:.4g} m", rate,
                                         totals.low, totals.high));
  }
  const double source_rate = resolved.at("source_rate");
  if (source_rate > 0.0) {
    const int x = static_cast<int>(std::lround(resolved.at("source_x").get<double>() * (terrain.width - 1)));
    const int y = static_cast<int>(std::lround(resolved.at("source_y").get<double>() * (terrain.height - 1)));
    if (!terrain.is_valid(x, y)) {
      throw InputError(fmt::format("erosion.pipe: the point source at cell (x={}, y={}) lies on a no-data cell", x, y));
    }
    scenario.forcing.sources.push_back({x, y, source_rate});
    scenario.notes.push_back(fmt::format("point source: {} m³/s at cell (x={}, y={})", source_rate, x, y));
  }
}

PipeScenario make_scenario(const nlohmann::json& resolved, const Heightmap& input) {
  if (input.size() == 0) throw InputError("erosion.pipe erodes a heightmap: the case needs an input");
  if (count_valid(input) == 0) throw InputError("erosion.pipe: the terrain's mask covers every cell");
  check_finite(input, "erosion.pipe: terrain");
  PipeScenario scenario;
  scenario.params = hydraulic_params_from_json(resolved);
  scenario.constants = pipe_constants(scenario.params, input);
  scenario.initial = dry_pipe_state(input);
  scenario.checkpoints = std::min(resolved.at("checkpoints").get<int>(), std::max(scenario.params.steps, 1));
  set_initial_water(resolved, scenario);
  set_forcing(resolved, scenario);
  return scenario;
}

// The fields compared between backends, in double; the terrain as its change b − b_0.
struct Snapshot {
  int step = 0;
  Grid<double> terrain_change, water, sediment;
};

template <class Real>
Snapshot snapshot(const PipeState<Real>& state, const Grid<double>& initial_terrain, int step) {
  Snapshot shot{step, state.terrain.template cast<double>(), state.water.template cast<double>(),
                state.sediment.template cast<double>()};
  for (std::size_t cell = 0; cell < shot.terrain_change.size(); ++cell) {
    shot.terrain_change.values[cell] -= initial_terrain.values[cell];
  }
  return shot;
}

std::vector<int> checkpoint_steps(int steps, int checkpoints) {
  std::vector<int> at;
  for (int i = 1; i <= checkpoints; ++i) {
    const int step = static_cast<int>((static_cast<long long>(steps) * i) / checkpoints);
    if (step > 0 && (at.empty() || step != at.back())) at.push_back(step);
  }
  return at;
}

struct BackendRun {
  std::vector<PipeLedgerEntry> ledger;
  std::vector<Snapshot> checkpoints;
  PipeState<double> final_state;
  std::vector<PipeState<float>> float_states;  // ref<float> only: its whole state at each checkpoint
};

// Runs `erosion` (reference or GPU) step by step, taking snapshots at `at`.
template <class Erosion, class StateOf>
void step_through(Erosion& erosion, int steps, const std::vector<int>& at, const Grid<double>& initial_terrain,
                  StateOf state_of, std::vector<Snapshot>& snapshots) {
  auto next = at.begin();
  for (int step = 1; step <= steps; ++step) {
    erosion.step();
    if (next != at.end() && *next == step) {
      snapshots.push_back(snapshot(state_of(erosion), initial_terrain, step));
      ++next;
    }
  }
}

BackendRun run_reference_double(const PipeScenario& scenario, const std::vector<int>& at, CaseResult& result) {
  BackendRun run;
  reference::PipeErosion<double> erosion(scenario.initial, scenario.constants, scenario.forcing);
  const auto state_of = [](const reference::PipeErosion<double>& e) { return e.state(); };
  result.timings.cpu_ms = cpu_wall_ms([&] {
    step_through(erosion, scenario.params.steps, at, scenario.initial.terrain, state_of, run.checkpoints);
  });
  result.timings.cpu_reps = 1;
  run.ledger = erosion.ledger();
  run.final_state = erosion.state();
  return run;
}

BackendRun run_reference_float(const PipeScenario& scenario, const std::vector<int>& at) {
  BackendRun run;
  reference::PipeErosion<float> erosion(cast_pipe_state<float>(scenario.initial), scenario.constants, scenario.forcing);
  const auto state_of = [&run](const reference::PipeErosion<float>& e) {
    run.float_states.push_back(e.state());
    return e.state();
  };
  step_through(erosion, scenario.params.steps, at, scenario.initial.terrain, state_of, run.checkpoints);
  run.ledger = erosion.ledger();
  run.final_state = cast_pipe_state<double>(erosion.state());
  return run;
}

// The ledger's yardsticks: the water handled up to an entry, and the material present at the start.
double water_handled(const PipeLedgerEntry& entry, const PipeLedgerEntry& initial) {
  return initial.water + entry.rain_in + entry.source_in;
}

double material_present(const PipeState<double>& initial) {
  CompensatedSum sum;
  const auto& terrain = initial.terrain;
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    sum.add(std::abs(terrain.values[cell]) + initial.sediment.values[cell] + initial.regolith.values[cell]);
  }
  return sum.value() * terrain.cell_size_x * terrain.cell_size_y;
}

// Σ|b_T − b_0|·l_x·l_y plus what is suspended, loosened or gone through the borders at the end.
double material_moved(const Grid<double>& terrain_change, const PipeLedgerEntry& last) {
  CompensatedSum sum;
  for (std::size_t cell = 0; cell < terrain_change.size(); ++cell) {
    if (terrain_change.is_valid(cell)) sum.add(std::abs(terrain_change.values[cell]));
  }
  return sum.value() * terrain_change.cell_size_x * terrain_change.cell_size_y + last.sediment + last.regolith +
         last.boundary_out_sediment + last.boundary_out_regolith;
}

struct LedgerErrors {
  std::vector<double> steps, water, material;  // relative, per entry
  double max_water = 0.0, max_material = 0.0, max_cfl = 0.0;
};

LedgerErrors ledger_errors(const std::vector<PipeLedgerEntry>& ledger, double material) {
  LedgerErrors errors;
  const auto& initial = ledger.front();
  for (const auto& entry : ledger) {
    const double handled = water_handled(entry, initial);
    const double water = handled > 0.0 ? std::abs(water_balance(entry, initial)) / handled : 0.0;
    const double drift = material > 0.0 ? std::abs(material_drift(entry, initial)) / material : 0.0;
    errors.steps.push_back(entry.step);
    errors.water.push_back(std::max(water, drift_floor));
    errors.material.push_back(std::max(drift, drift_floor));
    errors.max_water = std::max(errors.max_water, water);
    errors.max_material = std::max(errors.max_material, drift);
    errors.max_cfl = std::max(errors.max_cfl, entry.max_cfl);
  }
  return errors;
}

// The pipe model's gravity waves: the flux gains Δt·A·g/l_k per metre of head and the depth loses
// Δt/(l_x·l_y) per m³/s, a forward-backward scheme for waves whose speed does not depend on the
// depth (the pipe's cross-section A stands for the depth of the shallow-water equations). It is
// stable while Δt²·(A·g/(l_x·l_y))·λ ≤ 1, λ the largest eigenvalue of the pipes' Laplacian over 4:
// 1/l_x + 1/l_y with 4 pipes (the checkerboard mode); with 8 pipes the diagonals add 2/l_d to the
// modes that alternate along one axis only, so λ = max(1/l_x + 1/l_y, 1/l_x + 2/l_d, 1/l_y + 2/l_d).
// Beyond 1 the surface oscillates from step to step (the K scaling keeps water non-negative, so
// nothing blows up, but the flow is noise and float and double runs part ways).
double pipe_wave_number(const PipeConstants& c) {
  double largest = 1.0 / c.length_x + 1.0 / c.length_y;
  if (c.pipe_count == 8) {
    largest = std::max({largest, 1.0 / c.length_x + 2.0 / c.length_diagonal, 1.0 / c.length_y + 2.0 / c.length_diagonal});
  }
  return c.time_step * std::sqrt(c.pipe_area * c.gravity / c.cell_area * largest);
}

bool conservative(const PipeScenario& scenario) { return scenario.constants.transport == SedimentTransport::flux; }

double unit_roundoff_of(const std::string& backend) {
  return backend == "cpu" ? pipe_double_roundoff : pipe_float_roundoff;
}

// The ledger terms pinned against what was asked, computed on the host from the parameters and
// the forcing (pipe_error_model.hpp derives both bounds).
void add_asked_ledger_checks(const PipeScenario& scenario, const BackendRun& run, const std::string& backend,
                             CaseResult& result) {
  const double u = unit_roundoff_of(backend);
  const int steps = run.ledger.back().step;
  const double asked = pipe_asked_volume_per_step(scenario.constants, scenario.forcing, scenario.initial.terrain);
  const std::size_t sources = scenario.forcing.sources.size();
  result.checks.push_back(bounded_check(
      "mass.water_added." + backend, pipe_water_added_error(run.ledger, asked), pipe_water_added_bound(u, steps, sources),
      std::nullopt,
      fmt::format("max over steps of |water the additions added - asked| / (W_0 + asked); asked = step x {:.6g} m³ "
                  "(rain x valid area x Δt + rain map + sources x Δt, on the host); bound: the additions' rounding, "
                  "u·((1 + {} sources)·{} steps + 4)",
                  asked, sources, steps)));
  const double share = scenario.params.evaporation_rate * scenario.params.time_step;
  result.checks.push_back(bounded_check(
      "mass.evaporation." + backend, pipe_evaporation_error(run.ledger, share), pipe_evaporation_bound(u, share),
      std::nullopt,
      fmt::format("max over steps of |evaporated - K/(1 - K)·Σ W_t| / (Σ W_t/(1 - K)), K = K_e·Δt = {:.6g} from the "
                  "parameters; bound 3u (rounding of the kept share, the product, the difference)",
                  share)));
}

// The CFL number's bound. |ΔW_X| ≤ ½(Σf_out + Σf_in) (a diagonal's share l_x/l_d ≤ 1), K makes
// Σf_out·Δt ≤ d_A·l_x·l_y and the inflows arrive in d_B, so |u| = |ΔW_X|/(l_y·d̄) ≤ l_x/Δt:
// Δt·|u|/l_x ≤ 1 in exact arithmetic, a property of the scheme (the cap sits at 1 where a cell
// drains in one step). The float twins round K's quotient and product, the flux sums, ΔW_X, d̄
// and the quotient: about 13 roundings, with GLSL's 2.5-ulp division 4u more; 24u covers them.
// Above that bound something moved water faster than the K scaling allows: a failure, no warn band.
constexpr double max_cfl_bound = 1.0 + 24.0 * pipe_float_roundoff;

// The ledger checks of one backend (cpu_float: the water balance and material drift are
// informative, the asked-for ledger and the CFL bound strict); returns the errors per step for
// the plot.
LedgerErrors add_ledger_checks(const PipeScenario& scenario, const BackendRun& run, double material,
                               const std::string& backend, CaseResult& result) {
  const LedgerErrors errors = ledger_errors(run.ledger, material);
  const auto& first = run.ledger.front();
  const auto& last = run.ledger.back();
  add_asked_ledger_checks(scenario, run, backend, result);
  result.checks.push_back(bounded_check("stability.max_cfl." + backend, errors.max_cfl, max_cfl_bound, std::nullopt,
                                        "largest Δt·|u|/l_x or Δt·|v|/l_y of the run: at most 1 by the K scaling, "
                                        "plus 24 float roundings"));
  if (backend == "cpu_float") {
    result.checks.push_back(informative_check(
        "mass.water_balance.cpu_float", errors.max_water,
        "ref<float>: the water balance of plain float arithmetic, for comparison with the GPU's"));
    result.checks.push_back(informative_check(
        "mass.material_drift.cpu_float", errors.max_material,
        "ref<float>, heights stored as plain floats: the float trap (erosion below the height's float spacing lost)"));
    return errors;
  }
  const bool gpu = backend == "gpu";
  result.checks.push_back(bounded_check(
      "mass.water_balance." + backend, errors.max_water, gpu ? gpu_water_bound : cpu_water_bound, std::nullopt,
      "max over steps of |W_t - W_0 - added + evaporated + out| / (W_0 + rain + sources) (issue 3's figure)"));
  const Snapshot end = snapshot(run.final_state, scenario.initial.terrain, last.step);
  const double drift_of_moved =
      std::abs(material_drift(last, first)) / std::max(material_moved(end.terrain_change, last), drift_floor);
  const std::string material_detail =
      "max over steps of |Δ(terrain + sediment + regolith) + out| / Σ(|b_0| + s_0 + r_0)·l_x·l_y";
  if (conservative(scenario)) {
    result.checks.push_back(bounded_check("mass.material_drift." + backend, errors.max_material,
                                          gpu ? gpu_material_bound : cpu_material_bound, std::nullopt,
                                          material_detail + "; flux transport conserves"));
    result.checks.push_back(informative_check("mass.material_drift_of_moved." + backend, drift_of_moved,
                                              "final drift / material moved (eroded, deposited, suspended, out)"));
  } else {
    // Semi-Lagrangian transport creates and destroys material by construction (bilinear backtrace
    // of a field that is not divergence-free); how much depends on the flow, and no error model
    // bounds it, so the drift is reported, not graded.
    result.checks.push_back(informative_check("mass.material_drift." + backend, errors.max_material,
                                              material_detail + "; semi-Lagrangian transport is not conservative"));
    result.checks.push_back(informative_check("mass.material_drift_of_moved." + backend, drift_of_moved,
                                              "final drift / material moved; semi-Lagrangian transport creates or "
                                              "destroys material (the method's property)"));
  }
  return errors;
}

// The fields compared between backends: the terrain as its change b − b_0, water, sediment.
struct ComparedField {
  const char* name;
  Grid<double> Snapshot::*field;
};

constexpr ComparedField compared_fields[] = {{"terrain_change", &Snapshot::terrain_change},
                                             {"water", &Snapshot::water},
                                             {"sediment", &Snapshot::sediment}};

// Shadow steps: the GPU loaded with ref<float>'s state at each checkpoint, stepped beside a
// ref<float> started from the same state.
struct ShadowDistances {
  double terrain = 0.0, water = 0.0, sediment = 0.0, regolith = 0.0, velocity = 0.0, flux = 0.0;
};

double cell_distance(double a, double b) {
  const double distance = std::abs(a - b);
  return std::isnan(distance) ? std::numeric_limits<double>::infinity() : distance;
}

ShadowDistances shadow_distances(const PipeState<double>& gpu, const PipeState<float>& reference, int pipes) {
  ShadowDistances d;
  const auto& mask = reference.terrain;
  for (std::size_t cell = 0; cell < mask.size(); ++cell) {
    if (!mask.is_valid(cell)) continue;
    const auto field = [&](const Grid<double>& a, const Grid<float>& b) {
      return cell_distance(a.values[cell], static_cast<double>(b.values[cell]));
    };
    d.terrain = std::max(d.terrain, field(gpu.terrain, reference.terrain));
    d.water = std::max(d.water, field(gpu.water, reference.water));
    d.sediment = std::max(d.sediment, field(gpu.sediment, reference.sediment));
    d.regolith = std::max(d.regolith, field(gpu.regolith, reference.regolith));
    d.velocity = std::max({d.velocity, field(gpu.velocity_x, reference.velocity_x), field(gpu.velocity_y, reference.velocity_y)});
    for (int k = 0; k < pipes; ++k) {
      d.flux = std::max(d.flux, cell_distance(gpu.outflow[cell][k], static_cast<double>(reference.outflow[cell][k])));
    }
  }
  return d;
}

// Steps of each shadow run: the distance after one is graded, after shadow_steps reported.
constexpr int shadow_steps = 4;

struct ShadowField {
  const char* name;
  double ShadowDistances::*distance;
  double PipeShadowBounds::*bound;
  double PipeShadowScales::*scale;  // the field's own size: the terrain's relief, the largest depth, ...
  const char* unit;
};

constexpr ShadowField shadow_fields[] = {
    {"terrain_change", &ShadowDistances::terrain, &PipeShadowBounds::terrain, &PipeShadowScales::relief, "m"},
    {"water", &ShadowDistances::water, &PipeShadowBounds::water, &PipeShadowScales::depth, "m"},
    {"sediment", &ShadowDistances::sediment, &PipeShadowBounds::sediment, &PipeShadowScales::sediment, "m"},
    {"regolith", &ShadowDistances::regolith, &PipeShadowBounds::regolith, &PipeShadowScales::regolith, "m"},
    {"velocity", &ShadowDistances::velocity, &PipeShadowBounds::velocity, &PipeShadowScales::speed, "m/s"},
    {"flux", &ShadowDistances::flux, &PipeShadowBounds::flux, &PipeShadowScales::flux, "m³/s"},
};

// A one-step bound wider than this share of the field's size (over the checkpoints) cannot tell a
// bug that changes the field by a tenth from rounding: the check is then inconclusive. On the real
// DEMs the first-order model (worst cases of global maxima) is that wide for the sediment and the
// velocity, while the measured distances stay orders of magnitude below it.
constexpr double tellable_share_of_field = 0.1;

// The worst shadow distance of one field over the checkpoints, as a share of its bound.
struct ShadowWorst {
  double distance = 0.0, bound = 0.0, ratio = -1.0;
  double scale = 0.0;  // the field's largest size over the checkpoints
  int checkpoint = 0;
  bool all_exact = true;  // every distance 0: bit for bit
};

void keep_worst(ShadowWorst& worst, double distance, double bound, int checkpoint) {
  worst.all_exact = worst.all_exact && distance == 0.0;
  const double ratio = std::isnan(distance) || (bound <= 0.0 && distance > 0.0) ? std::numeric_limits<double>::infinity()
                       : bound > 0.0                                           ? distance / bound
                                                                               : 0.0;
  if (ratio > worst.ratio) {
    worst.distance = std::isnan(distance) ? std::numeric_limits<double>::infinity() : distance;
    worst.bound = bound;
    worst.ratio = ratio;
    worst.checkpoint = checkpoint;
  }
}

// Shadow-step parity. At each checkpoint ref<float>'s whole state (terrain, water, sediment,
// regolith, fluxes, velocity) is loaded into the GPU twin and both are stepped from it; every field
// is compared cell by cell with a bound fixed from that state before stepping (pipe_shadow_bounds,
// compare/checks/pipe_error_model.hpp).
// Decision on the terrain: the GPU stores b = b0 + Δb (the float trap fix); loading takes
// ref<float>'s floats as the base b0 with Δb = 0, the state a run starts from, so both twins start
// from the same heights bit for bit and differ only where later roundings land (ref<float> rounds
// b + d and b − moved at the height's float spacing, the GPU at the change's), which the bound's
// surface term allows.
// Graded: one step (parity.shadow.<field>.gpu_vs_float, the worst checkpoint against its own
// bound), where the model is sharp. After shadow_steps steps the first-order worst case grows by
// about 10× a step (depth and flux feed each other through K and the heads) and is too wide to
// grade: that distance is reported (…four_steps…) with the bound in the detail.
void add_shadow_parity(const PipeScenario& scenario, const BackendRun& float_run, CaseResult& result) {
  gpu::PipeErosion gpu_twin(scenario.initial, scenario.constants, scenario.forcing, false);
  std::vector<ShadowWorst> one_step(std::size(shadow_fields)), several(std::size(shadow_fields));
  for (std::size_t i = 0; i < float_run.float_states.size(); ++i) {
    const auto& start = float_run.float_states[i];
    const int checkpoint = float_run.checkpoints[i].step;
    const PipeShadowScales scales = pipe_shadow_scales(start, scenario.constants);
    gpu_twin.upload(cast_pipe_state<double>(start));
    reference::PipeErosion<float> reference_twin(start, scenario.constants, scenario.forcing);
    for (int step = 1; step <= shadow_steps; ++step) {
      reference_twin.step();
      gpu_twin.step();
      if (step != 1 && step != shadow_steps) continue;
      const ShadowDistances distances =
          shadow_distances(gpu_twin.state(), reference_twin.state(), scenario.constants.pipe_count);
      const PipeShadowBounds bounds = pipe_shadow_bounds(scales, scenario.constants, step);
      auto& worst = step == 1 ? one_step : several;
      for (std::size_t f = 0; f < std::size(shadow_fields); ++f) {
        keep_worst(worst[f], distances.*shadow_fields[f].distance, bounds.*shadow_fields[f].bound, checkpoint);
        worst[f].scale = std::max(worst[f].scale, scales.*shadow_fields[f].scale);
      }
    }
  }
  const bool regolith = scenario.constants.regolith_depth > 0.0;
  const std::size_t states = float_run.float_states.size();
  for (std::size_t f = 0; f < std::size(shadow_fields); ++f) {
    const auto& field = shadow_fields[f];
    if (!regolith && std::string(field.name) == "regolith") continue;
    const auto& one = one_step[f];
    result.checks.push_back(decisive_check(
        fmt::format("parity.shadow.{}.gpu_vs_float", field.name), one.distance, one.bound, std::nullopt, one.scale,
        tellable_share_of_field,
        fmt::format("GPU loaded with ref<float>'s state at {} checkpoints, one step beside it: max |gpu - ref<float>| "
                    "{}{}; worst against its bound at the checkpoint after step {}; bound from that state before "
                    "stepping (compare/checks/pipe_error_model.hpp)",
                    states, field.unit, one.all_exact ? ", bit for bit (0) at every checkpoint" : "",
                    one.checkpoint)));
    const auto& four = several[f];
    result.checks.push_back(informative_check(
        fmt::format("parity.shadow.{}.four_steps.gpu_vs_float", field.name), four.distance,
        fmt::format("the same after {} steps, {}{}; the first-order worst case there is {:.3g}, too wide to grade",
                    shadow_steps, field.unit, four.all_exact ? ", bit for bit (0) at every checkpoint" : "",
                    four.bound)));
  }
}

// The e-folding rate of a distance that grows from `first` at step `from` to `last` at step
// `to`: ln(last/first)/(to − from) per step; 0 when either is 0 or there is one checkpoint.
double divergence_rate(double first, double last, int from, int to) {
  if (!(first > 0.0) || !(last > 0.0) || to <= from) return 0.0;
  return std::log(last / first) / (to - from);
}

// N steps, GPU and ref<float> vs ref<double>: informative. The flow's thresholds (K scaling,
// capacity above or below s, max(0, ·)) switch on single roundings and carry the switch on, so
// two float runs part from the double one at a rate set by the flow (0.1-0.3 m after ~130 steps on
// the volcano), for which there is no a-priori bound; the twins' agreement is graded by the
// shadow steps instead. Reported: the distance at the end, its RMS, and the rate at which the
// GPU's distance grew between the first and the last checkpoint; the plot shows both runs.
void add_parity_vs_double(const BackendRun& truth, const BackendRun& float_run, const BackendRun& gpu_run,
                          const RunOptions& options, CaseResult& result) {
  SeriesPlot plot{.title = "Distance from ref<double> along the run",
                  .x_label = "step",
                  .y_label = "max |· - ref<double>| (m; exact zeros at 1e-18)",
                  .log_y = true};
  const std::size_t shots = std::min({truth.checkpoints.size(), float_run.checkpoints.size(), gpu_run.checkpoints.size()});
  if (shots == 0) return;
  for (const auto& [name, field] : compared_fields) {
    Series gpu_series{.label = std::string(name) + " gpu", .group = name};
    Series float_series{.label = std::string(name) + " ref<float>", .dashed = true, .group = name};
    FieldDifference gpu_first, gpu_last, float_last;
    for (std::size_t i = 0; i < shots; ++i) {
      gpu_last = field_difference(truth.checkpoints[i].*field, gpu_run.checkpoints[i].*field);
      float_last = field_difference(truth.checkpoints[i].*field, float_run.checkpoints[i].*field);
      if (i == 0) gpu_first = gpu_last;
      const double step = truth.checkpoints[i].step;
      gpu_series.x.push_back(step);
      gpu_series.y.push_back(std::max(gpu_last.max_abs, drift_floor));
      float_series.x.push_back(step);
      float_series.y.push_back(std::max(float_last.max_abs, drift_floor));
    }
    const int from = truth.checkpoints.front().step;
    const int to = truth.checkpoints[shots - 1].step;
    result.checks.push_back(informative_check(
        fmt::format("parity.{}.gpu_vs_double", name), gpu_last.max_abs,
        fmt::format("max |gpu - ref<double>| after {} steps, m (ref<float>: {:.3g} m); chaotic flow, no bound: the "
                    "shadow steps grade the twins",
                    to, float_last.max_abs)));
    result.checks.push_back(informative_check(fmt::format("parity.{}.rms.gpu_vs_double", name), gpu_last.rms,
                                              "RMS of gpu - ref<double> after the run, m"));
    result.checks.push_back(informative_check(
        fmt::format("parity.{}.divergence_rate.gpu_vs_double", name),
        divergence_rate(gpu_first.max_abs, gpu_last.max_abs, from, to),
        fmt::format("ln(distance at step {} / distance at step {}) per step: how fast the GPU run parts from "
                    "ref<double>",
                    to, from)));
    plot.series.push_back(std::move(gpu_series));
    plot.series.push_back(std::move(float_series));
  }
  attach_plot({plot}, options.report_dir, "parity.png",
              "distance from ref<double> at the checkpoints: GPU (solid), ref<float> (dashed)", result);
}

std::size_t differing_cells(const PipeState<double>& a, const PipeState<double>& b) {
  return field_difference(a.terrain, b.terrain).differing_bits + field_difference(a.water, b.water).differing_bits +
         field_difference(a.sediment, b.sediment).differing_bits;
}

BackendRun run_gpu(const PipeScenario& scenario, const std::vector<int>& at, CaseResult& result) {
  BackendRun run;
  {
    gpu::PipeErosion erosion(scenario.initial, scenario.constants, scenario.forcing, true);
    const auto state_of = [](const gpu::PipeErosion& e) { return e.state(); };
    step_through(erosion, scenario.params.steps, at, scenario.initial.terrain, state_of, run.checkpoints);
    run.ledger = erosion.ledger();
    run.final_state = erosion.state();
  }
  gpu::PipeErosion timed(scenario.initial, scenario.constants, scenario.forcing, false);
  result.timings.gpu_ms = gpu_wall_ms([&] { timed.run(scenario.params.steps); });
  result.timings.gpu_reps = 1;
  result.checks.push_back(bounded_check("determinism.gpu", double(differing_cells(run.final_state, timed.state())),
                                        0.0, std::nullopt,
                                        "terrain, water and sediment cells differing in any bit between two GPU runs"));
  result.notes.push_back(fmt::format("GPU: {} compute passes per step", timed.passes_per_step()));
  return run;
}

Series ledger_series(const std::string& label, const std::vector<double>& steps, const std::vector<double>& values,
                     bool dashed = false, const std::string& group = "") {
  return {.label = label, .x = steps, .y = values, .dashed = dashed, .group = group};
}

void plot_ledgers(const BackendRun& truth, const std::vector<std::pair<std::string, LedgerErrors>>& errors,
                  const RunOptions& options, CaseResult& result) {
  SeriesPlot error_plot{.title = "Ledger error over the steps",
                        .x_label = "step",
                        .y_label = "relative error (exact zeros at 1e-18)",
                        .log_y = true};
  for (const auto& [backend, error] : errors) {
    error_plot.series.push_back(ledger_series("water balance " + backend, error.steps, error.water, false, backend));
    error_plot.series.push_back(ledger_series("material drift " + backend, error.steps, error.material, true, backend));
  }
  SeriesPlot volume_plot{.title = "Water ledger (ref<double>)", .x_label = "step", .y_label = "m³"};
  std::vector<double> steps, water, inflow, evaporated, out;
  for (const auto& entry : truth.ledger) {
    steps.push_back(entry.step);
    water.push_back(entry.water);
    inflow.push_back(entry.rain_in + entry.source_in);
    evaporated.push_back(entry.evaporated);
    out.push_back(entry.boundary_out_water);
  }
  volume_plot.series = {ledger_series("water held W_t", steps, water), ledger_series("rain and sources in", steps, inflow),
                        ledger_series("evaporated", steps, evaporated), ledger_series("out through borders", steps, out)};
  attach_plot({error_plot}, options.report_dir, "ledger_error.png",
              "water balance (solid) and material drift (dashed), relative", result);
  attach_plot({volume_plot}, options.report_dir, "ledger_volumes.png", "water held and what came in and went out, m³",
              result);
}

Grid<double> speed(const PipeState<double>& state) {
  Grid<double> magnitude = state.velocity_x;
  for (std::size_t cell = 0; cell < magnitude.size(); ++cell) {
    magnitude.values[cell] = std::hypot(state.velocity_x.values[cell], state.velocity_y.values[cell]);
  }
  return magnitude;
}

Grid<double> zeros_like(const Grid<double>& field) {
  Grid<double> zero = field;
  std::fill(zero.values.begin(), zero.values.end(), 0.0);
  return zero;
}

void write_pictures(const PipeScenario& scenario, const BackendRun& truth, const BackendRun* gpu_run,
                    const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  const auto add = [&](const std::string& file, const std::string& caption) {
    result.artifacts.push_back({result.name + "/" + file, "image", caption});
  };
  const auto& before = scenario.initial.terrain;
  const auto& after = truth.final_state;
  const FieldTotals totals = field_totals(before);
  const double exaggeration = write_height_image(before, totals.low, totals.high, folder / "before.png");
  add("before.png", "terrain before");
  write_height_image(after.terrain, totals.low, totals.high, folder / "after_cpu.png", exaggeration);
  add("after_cpu.png", "terrain after, ref<double>");
  const auto change = write_difference_image(before, after.terrain, folder / "erosion_cpu.png");
  add("erosion_cpu.png", fmt::format("b_T - b_0, ref<double>: blue eroded, red deposited, full colour at {:.3g} m",
                                     change.scale_used));
  const Grid<double> zero = zeros_like(before);
  const auto water = write_difference_image(zero, after.water, folder / "water_cpu.png");
  add("water_cpu.png", fmt::format("water depth, ref<double>: white dry, full red at {:.3g} m", water.scale_used));
  const auto sediment = write_difference_image(zero, after.sediment, folder / "sediment_cpu.png");
  add("sediment_cpu.png", fmt::format("suspended sediment, ref<double>: full red at {:.3g} m", sediment.scale_used));
  const auto velocity = write_difference_image(zero, speed(after), folder / "speed_cpu.png");
  add("speed_cpu.png", fmt::format("|v|, ref<double>: full red at {:.3g} m/s", velocity.scale_used));
  if (!gpu_run) return;
  const auto gpu_vs_cpu = write_difference_image(after.terrain, gpu_run->final_state.terrain, folder / "gpu_vs_cpu.png");
  add("gpu_vs_cpu.png", fmt::format("terrain, GPU - ref<double>: max {:.3g} m", gpu_vs_cpu.max_abs));
}

// Every state field of the pipe model (core/params/hydraulic.hpp's PipeState) as field files:
// <field>_<backend>.exr/.npy for the initial state, ref<double>'s last state, ref<float>'s and the GPU's, units
// as the state declares them; the outflow as one field per pipe in use, outflow_<pipe>_<backend>
// (L, R, T, B, then the diagonals).
void write_state_fields(const PipeState<double>& state, int pipe_count, const std::string& backend,
                        const std::string& when, const RunOptions& options, CaseResult& result) {
  struct StateField {
    const Grid<double>& values;
    const char* field;
    const char* unit;
    const char* meaning;
  };
  const StateField fields[] = {{state.terrain, "terrain", "m", "terrain height b"},
                               {state.water, "water", "m", "water depth d"},
                               {state.sediment, "sediment", "m", "suspended sediment s, as material over the cell"},
                               {state.velocity_x, "velocity_x", "m/s", "water velocity u, +x"},
                               {state.velocity_y, "velocity_y", "m/s", "water velocity v, +y"},
                               {state.regolith, "regolith", "m", "loosened bed material r (seed 001 §3.9)"}};
  for (const StateField& field : fields) {
    write_field_files(field.values,
                      {fmt::format("{}_{}", field.field, backend), field.field, backend, field.unit,
                       fmt::format("{}, {}", field.meaning, when)},
                      options, result);
  }
  Grid<double> outflow = state.terrain;
  for (int pipe = 0; pipe < pipe_count; ++pipe) {
    for (std::size_t cell = 0; cell < outflow.size(); ++cell) outflow.values[cell] = state.outflow[cell][pipe];
    const std::string field = fmt::format("outflow_{}", pipe_name(pipe));
    write_field_files(outflow,
                      {fmt::format("{}_{}", field, backend), field, backend, "m³/s",
                       fmt::format("flux f through pipe {} (towards ({:+d}, {:+d})), {}", pipe_name(pipe),
                                   pipe_offsets[pipe].dx, pipe_offsets[pipe].dy, when)},
                      options, result);
  }
}

void run_pipe_case(const PipeScenario& scenario, const nlohmann::json& expect, const RunOptions& options,
                   CaseResult& result) {
  const auto& terrain = scenario.initial.terrain;
  result.width = terrain.width;
  result.height = terrain.height;
  for (const auto& note : scenario.notes) result.notes.push_back(note);
  if (!options.report_dir.empty()) std::filesystem::create_directories(options.report_dir / result.name);
  const auto at = checkpoint_steps(scenario.params.steps, scenario.checkpoints);
  const double material = material_present(scenario.initial);
  // Strict, no warn band: the number comes from the case's parameters alone (no rounding in it
  // worth a margin), and above 1 the scheme's checkerboard mode grows every step — a case that
  // asks for that is a failed case, not a doubtful one.
  result.checks.push_back(bounded_check(
      "stability.pipe_wave_number", pipe_wave_number(scenario.constants), 1.0, std::nullopt,
      "Δt·sqrt(A·g/(l_x·l_y)·λ), λ = 1/l_x + 1/l_y with 4 pipes (more with 8): the explicit pipe scheme's "
      "gravity waves are stable up to 1"));

  if (options.progress) options.progress->stage("CPU reference (double)");
  const BackendRun truth = run_reference_double(scenario, at, result);
  std::vector<std::pair<std::string, LedgerErrors>> errors;
  errors.emplace_back("cpu", add_ledger_checks(scenario, truth, material, "cpu", result));

  if (options.progress) options.progress->stage("CPU reference (float)");
  const BackendRun float_run = run_reference_float(scenario, at);
  errors.emplace_back("cpu_float", add_ledger_checks(scenario, float_run, material, "cpu_float", result));

  std::optional<BackendRun> gpu_run;
  if (options.gpu_available) {
    if (options.progress) options.progress->stage("GPU");
    gpu_run = run_gpu(scenario, at, result);
    errors.emplace_back("gpu", add_ledger_checks(scenario, *gpu_run, material, "gpu", result));
    add_shadow_parity(scenario, float_run, result);
    add_parity_vs_double(truth, float_run, *gpu_run, options, result);
  } else {
    for (const char* name : {"mass.water_balance.gpu", "mass.material_drift.gpu", "parity.gpu", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
  }
  plot_ledgers(truth, errors, options, result);
  write_pictures(scenario, truth, gpu_run ? &*gpu_run : nullptr, options, result);
  const int pipes = scenario.constants.pipe_count;
  write_state_fields(scenario.initial, pipes, "input", "before the first step", options, result);
  write_state_fields(truth.final_state, pipes, "cpu", "after the last step, ref<double>", options, result);
  write_state_fields(float_run.final_state, pipes, "cpu_float", "after the last step, ref<float>", options, result);
  if (gpu_run) write_state_fields(gpu_run->final_state, pipes, "gpu", "after the last step, GPU", options, result);
  if (options.progress) options.progress->stage("terrain descriptors");
  add_case_descriptors({&terrain, &truth.final_state.terrain, &float_run.final_state.terrain,
                        gpu_run ? &gpu_run->final_state.terrain : nullptr},
                       expect, options, result);
}

PreparedTwin prepare_pipe(const nlohmann::json& resolved, const LoadedInput& input) {
  PreparedTwin prepared;
  prepared.run = [scenario = make_scenario(resolved, input.heights)](const nlohmann::json& expect,
                                                                     const RunOptions& options, CaseResult& result) {
    run_pipe_case(scenario, expect, options, result);
  };
  return prepared;
}

// Mei, Decaudin, Hu 2007's simulation time per step on a GeForce 8800 GTX (as quoted by issue 3).
constexpr std::pair<int, double> mei_2007_ms_per_step[] = {{256, 1.29}, {512, 2.38}, {1024, 6.65}, {2048, 22.88}};

BenchmarkRow step_row(const std::string& backend, int size, int reps, double ms_per_step, const std::string& device) {
  BenchmarkRow row{.algorithm = "erosion.pipe", .backend = backend, .size = size, .iterations = 1, .reps = reps,
                   .median_ms = ms_per_step, .device = device};
  row.mcell_iterations_per_s = double(size) * size / (ms_per_step * 1e-3) / 1e6;
  return row;
}

// A cone with slopes of about 0.1 and 0.1 m of water on every cell under light rain: every cell is
// wet, so every stage does its full work.
PipeScenario benchmark_scenario(int size) {
  const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                {"peak", 0.05 * size}, {"noise", 0.1}, {"seed", 7}};
  const auto params = resolve_params("erosion.pipe", pipe_specs(), {{"rain_rate", 1e-4}, {"capacity", 0.01}});
  return make_scenario(params, load_input(input, nullptr, {}).heights);
}

// ms per step: the median over `reps` runs of `steps` steps, divided by `steps`, after one warm-up step.
template <class Erosion>
double median_ms_per_step(Erosion& erosion, int reps, int steps, double (*clock)(const std::function<void()>&)) {
  erosion.step();
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) times.push_back(clock([&] { erosion.run(steps); }) / steps);
  return median(times);
}

// Rows per grid side: the reference in double (fewer steps: it is slow by design), the GPU without
// ledger downloads, and Mei 2007's published time, each in ms per step.
std::vector<BenchmarkRow> benchmark_pipes(const BenchmarkOptions& options, bool gpu_available,
                                          const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  const int gpu_steps = std::max(1, options.iterations);
  const int cpu_steps = std::max(1, options.iterations / 5);
  for (const int size : options.sizes) {
    const PipeScenario scenario = benchmark_scenario(size);
    reference::PipeErosion<double> reference_run(scenario.initial, scenario.constants, scenario.forcing);
    BenchmarkRow cpu_row = step_row("cpu", size, options.reps,
                                    median_ms_per_step(reference_run, options.reps, cpu_steps, cpu_wall_ms), environment.cpu);
    cpu_row.detail = "ref<double> with its ledger";
    rows.push_back(cpu_row);
    if (gpu_available) {
      gpu::PipeErosion gpu_run(scenario.initial, scenario.constants, scenario.forcing, false);
      BenchmarkRow row = step_row("gpu", size, options.reps,
                                  median_ms_per_step(gpu_run, options.reps, gpu_steps, gpu_wall_ms),
                                  environment.gl_renderer);
      row.detail = fmt::format("{} compute passes per step, without ledger downloads", gpu_run.passes_per_step());
      rows.push_back(row);
    }
    for (const auto& [side, ms] : mei_2007_ms_per_step) {
      if (side != size) continue;
      BenchmarkRow row = step_row("published", size, 0, ms, "NVIDIA GeForce 8800 GTX (Mei et al. 2007)");
      row.detail = "Mei, Decaudin, Hu 2007's simulation time per step, as quoted by issue 3";
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace

Algorithm pipe_algorithm() {
  return {.name = "erosion.pipe",
          .summary = "virtual-pipe hydraulic erosion with a water and material ledger (Mei 2007; seed 001's variant)",
          .source = "seed 000 §3.4 and Appendix B (Mei, Decaudin, Hu 2007, eqs. 2.10-2.25); seed 001 §3.3-3.9",
          .params = &pipe_specs(),
          .prepare = prepare_pipe,
          .iterates = false,
          .has_field_twin = false,
          .benchmark = benchmark_pipes,
          // Counted in reference/erosion/pipes.cpp (step() as the table times it, ledger included)
          // and gpu/erosion/pipes.cpp, at the benchmark's parameters (4 pipes, flux transport).
          .traffic = {.cpu = 607.0, .gpu = 308.0},
          .expect_shape = descriptor_expect_shape(),
          // Measured on 1024² (both backends, report included): 959 B a cell with 1 checkpoint, and
          // 133 B a cell for each further one (the states kept for shadow steps and ref<double>).
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const double cells = static_cast<double>(input.heights.size());
            return memory_for(cells, "cells", 1100 + descriptor_bytes_per_cell) +
                   memory_for(cells * resolved.at("checkpoints").get<double>(), "cell-checkpoints", 150);
          }};
}

}  // namespace gt
