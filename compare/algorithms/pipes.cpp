// `erosion.pipe`: hydraulic erosion with virtual pipes (Mei 2007, digest 000 §3.4; seed 001's
// variant by its parameters: depth ramp, sediment diffusion, regolith) on a heightmap, run by the
// CPU reference in double (the truth) and in float, and by the GPU twin, each with its per-step
// water and material ledger (core/params/hydraulic.hpp).
//
// Scenario parameters (besides hydraulic_param_table(); PipeCaseParams in pipes.hpp):
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
//   layer_thickness_k   with `layers` ≥ k: layer k's initial thickness on every valid cell, m, unless
//                  the input carries a field layer_k (m, ≥ 0), which gives it cell by cell.
//
// The state (compare/stepper.hpp): terrain b, water d, sediment s, regolith r (m), velocity_x u
// and velocity_y v (m/s), outflow f per pipe (m³/s, cell × pipe), with layers layer_1 .. layer_N (m;
// Šťava 2008, part of b: the material ledger holds them); compare/stepped_case.hpp runs the
// three twins over it (checkpoints, shadow steps, end-of-run distances, determinism, field files,
// pictures of every field, descriptors) and grades each field's one-step shadow value by value
// (the shadow_length steps' distance shown, not graded) against pipe_shadow_bounds
// (compare/checks/pipe_error_model.hpp):
// the step in rounding-interval arithmetic from ref<float>'s state before it, one bound per cell and pipe
// (tellable: the bounds' 90th percentile within a tenth of the field's own size).
// Decision on the terrain: the GPU stores b = b0 + Δb (the float trap fix); loading takes
// ref<float>'s floats as the base b0 with Δb = 0, so both twins start from the same heights bit for
// bit and differ only where later roundings land, which the bound's surface term allows.
// Ledger terms, on each backend's run (cpu = ref<double>, cpu_float = ref<float>, gpu), each bound
// fixed before the run from an error model; none grades a run against its own measurements:
//   mass.water_added               max over steps of |water the twin's additions put into its depths −
//                  asked| / (W_0 + asked), asked = step × (rain × valid area × Δt + rain map + sources
//                  × Δt) computed on the host from the parameters and forcing; bound
//                  u·((1 + sources)·steps + 4): the additions' rounding.
//   mass.evaporation               max over steps of |evaporated − K/(1 − K)·Σ W_t| / (Σ W_t/(1 − K)),
//                  K = K_e·Δt from the parameters, W_t the water held after step t; bound 3u.
//   mass.water_balance             max over steps of |W_t − W_0 − added + evaporated + out| divided by
//                  the water handled, W_0 + rain_in + source_in: bound 1e-12 (cpu) and 1e-6 (gpu),
//                  issue 3's figures (cpu: each step rounds a cell's depth in at most 6 operations of
//                  relative error 2^-53, so n steps move the total by at most 6n·2^-53 of it: 3.3e-13
//                  at n = 500). It catches water lost inside a step; the two checks above catch water
//                  added or evaporated at the wrong rate, which this balance cannot see. cpu_float:
//                  informative.
//   mass.material_drift            max over steps of |material_drift| divided by the material present,
//                  M_0 = Σ(|b_0| + s_0 + r_0)·l_x·l_y. Flux transport conserves: bounds 1e-12 (cpu, as
//                  the water) and 1e-6 (gpu); cpu_float informative (the float trap of plain float
//                  storage: the GPU stores heights as base + change, gpu/erosion/pipes.hpp).
//                  Semi-Lagrangian and MacCormack transport do not conserve (the methods' property, no
//                  model of how much): informative, so the ledger shows what each creates or destroys.
//   mass.material_drift_of_moved   the same drift divided by the material moved (Σ|b_T − b_0|·l_x·l_y +
//                  what is suspended or left): informative.
//   stability.max_cfl              the largest Δt·|u|/l_x or Δt·|v|/l_y of the run: at most 1 by the K
//                  scaling (max_cfl_bound), plus 24 float roundings; no warn band.
// spec.step.<field>.cpu: ref<double>'s step 11 value by value against a host spec of one step
// (compare/algorithms/pipe_spec.hpp, compare/checks/pipe_spec_check.hpp): the erosion law, which no
// ledger sees (a conserving bug of both twins).
// And, from the parameters alone, stability.pipe_wave_number: the stability number of the pipe
// scheme's gravity waves (see pipe_wave_number below), at most 1, no warn band.
// Mutants: compare/mutants/pipe.cpp (killed on the erosion.pipe.mutant_probe.* cases).
// A state that turns NaN or negative makes the reference (or the GPU's check) throw InputError,
// and the case ends as an error naming the step, the cell and the CFL number.
// Plots: the ledger error over the steps (water balance and material drift, each backend) and the
// ledger's volumes (water, rain and sources in, evaporated, out through the borders).
// Timings: one whole run each (ref<double>'s walk through the checkpoints; the GPU without ledger
// downloads, bracketed by glFinish).
#include "compare/algorithms/pipes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/algorithms/pipe_spec.hpp"
#include "compare/benchmark.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/field_twin.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/pipe_error_model.hpp"
#include "compare/checks/pipe_spec_check.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/report/plots.hpp"
#include "compare/steppers/pipe.hpp"
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

constexpr Choice<InitialWater> initial_water_choices[] = {
    {"dry", InitialWater::dry}, {"depth", InitialWater::depth}, {"sea_level", InitialWater::sea_level}};
constexpr Choice<RainMap> rain_map_choices[] = {{"none", RainMap::none}, {"orographic", RainMap::orographic}};

const ParamSpecs& pipe_specs() {
  static const ParamSpecs specs = param_specs(pipe_case_param_table());
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

void set_initial_water(const PipeCaseParams& given, PipeScenario& scenario) {
  auto& state = scenario.initial;
  for (std::size_t cell = 0; cell < state.terrain.size(); ++cell) {
    if (!state.terrain.is_valid(cell)) continue;
    if (given.initial_water == InitialWater::depth) state.water.values[cell] = given.initial_depth;
    if (given.initial_water == InitialWater::sea_level) {
      state.water.values[cell] = std::max(0.0, given.sea_level - state.terrain.values[cell]);
    }
  }
  if (given.initial_water == InitialWater::depth) {
    scenario.notes.push_back(fmt::format("initial water: {} m on every valid cell", given.initial_depth));
  }
  if (given.initial_water == InitialWater::sea_level) {
    scenario.notes.push_back(fmt::format("initial water: cells below {} m filled up to it (the sea from the start)",
                                         given.sea_level));
  }
}

void set_forcing(const PipeCaseParams& given, PipeScenario& scenario) {
  const auto& terrain = scenario.initial.terrain;
  if (given.rain_map == RainMap::orographic) {
    const FieldTotals totals = field_totals(terrain);
    const double range = totals.high - totals.low;
    const double rate = given.rain_map_rate;
    Grid<double> rain = terrain;
    for (std::size_t cell = 0; cell < rain.size(); ++cell) {
      rain.values[cell] = terrain.is_valid(cell) && range > 0.0 ? rate * (terrain.values[cell] - totals.low) / range : 0.0;
    }
    scenario.forcing.rain_map = std::move(rain);
    scenario.notes.push_back(fmt::format("orographic rain map: 0 to {} m/s from {:.4g} m to {:.4g} m", rate,
                                         totals.low, totals.high));
  }
  if (given.source_rate > 0.0) {
    const int x = static_cast<int>(std::lround(given.source_x * (terrain.width - 1)));
    const int y = static_cast<int>(std::lround(given.source_y * (terrain.height - 1)));
    scenario.forcing.sources.push_back({x, y, given.source_rate});
    scenario.notes.push_back(fmt::format("point source: {} m³/s at cell (x={}, y={})", given.source_rate, x, y));
  }
}

// Šťava's layers: each layer_k input field (make_scenario checks its values), or layer_thickness_k
// on every valid cell.
void set_layers(const PipeCaseParams& given, const std::map<std::string, Heightmap>& fields, PipeScenario& scenario) {
  auto& state = scenario.initial;
  for (int k = 1; k <= given.hydraulic.layers; ++k) {
    const std::string name = fmt::format("layer_{}", k);
    Grid<double>& layer = state.layers[static_cast<std::size_t>(k - 1)];
    const auto field = fields.find(name);
    if (field == fields.end()) {
      const double thickness = given.layer_thickness[static_cast<std::size_t>(k - 1)];
      for (std::size_t cell = 0; cell < layer.size(); ++cell) {
        if (state.terrain.is_valid(cell)) layer.values[cell] = thickness;
      }
      scenario.notes.push_back(fmt::format("{}: {} m on every valid cell (layer_thickness_{}; no input field {})", name,
                                           thickness, k, name));
      continue;
    }
    for (std::size_t cell = 0; cell < layer.size(); ++cell) {
      if (state.terrain.is_valid(cell)) layer.values[cell] = field->second.values[cell];
    }
    const FieldTotals totals = field_totals(layer);
    scenario.notes.push_back(fmt::format("{} from the input field {}: {:.4g} to {:.4g} m", name, name, totals.low,
                                         totals.high));
  }
  for (int k = given.hydraulic.layers + 1; k <= max_pipe_layers; ++k) {
    const std::string name = fmt::format("layer_{}", k);
    if (fields.contains(name)) {
      throw InputError(fmt::format("erosion.pipe: the input field {} names a layer above layers = {}", name,
                                   given.hydraulic.layers));
    }
  }
}

PipeScenario make_scenario(const nlohmann::json& resolved, const Heightmap& input,
                           const std::map<std::string, Heightmap>& fields = {}) {
  if (input.size() == 0) throw InputError("erosion.pipe erodes a heightmap: the case needs an input");
  if (count_valid(input) == 0) throw InputError("erosion.pipe: the terrain's mask covers every cell");
  check_finite(input, "erosion.pipe: terrain");
  const auto given = params_from_json(pipe_case_param_table(), resolved);
  PipeScenario scenario;
  scenario.params = given.hydraulic;
  scenario.constants = pipe_constants(scenario.params, input);
  scenario.initial = dry_pipe_state(input, scenario.params.layers);
  scenario.checkpoints = std::min(given.checkpoints, std::max(scenario.params.steps, 1));
  set_layers(given, fields, scenario);
  set_initial_water(given, scenario);
  set_forcing(given, scenario);
  // The twins' own refusals (a negative layer from an input field among them), before any runs.
  check_pipe_input(scenario.initial, scenario.forcing, scenario.constants);
  return scenario;
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
double material_moved(const State& initial, const State& final, const PipeLedgerEntry& last) {
  CompensatedSum sum;
  const auto& before = initial.fields[0];
  const auto& after = final.fields[0];
  for (std::size_t cell = 0; cell < before.size(); ++cell) {
    if (initial.grid.is_valid(cell)) sum.add(std::abs(after[cell] - before[cell]));
  }
  return sum.value() * initial.grid.cell_size_x * initial.grid.cell_size_y + last.sediment + last.regolith +
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

// The CFL number's bound. |ΔW_X| ≤ ½(Σf_out + Σf_in) (a diagonal's share l_x/l_d ≤ 1), K makes
// Σf_out·Δt ≤ d_A·l_x·l_y and the inflows arrive in d_B, so |u| = |ΔW_X|/(l_y·d̄) ≤ l_x/Δt:
// Δt·|u|/l_x ≤ 1 in exact arithmetic, a property of the scheme (the cap sits at 1 where a cell
// drains in one step). The float twins round K's quotient and product, the flux sums, ΔW_X, d̄
// and the quotient: about 13 roundings, with GLSL's 2.5-ulp division 4u more; 24u covers them.
// Above that bound something moved water faster than the K scaling allows: a failure, no warn band.
constexpr double max_cfl_bound = 1.0 + 24.0 * pipe_float_roundoff;

// The ledger terms (see the top of this file), each evaluated on every backend's run.
std::vector<LedgerTerm> pipe_ledger_terms(const PipeScenario& scenario) {
  const double asked = pipe_asked_volume_per_step(scenario.constants, scenario.forcing, scenario.initial.terrain);
  const std::size_t sources = scenario.forcing.sources.size();
  const double share = scenario.params.evaporation_rate * scenario.params.time_step;
  const double material = material_present(scenario.initial);
  const bool conserving = conservative(scenario);
  const auto errors = [material](const LedgerRun& run) { return ledger_errors(entries_of(run.records), material); };
  const std::string material_detail =
      "max over steps of |Δ(terrain + sediment + regolith) + out| / Σ(|b_0| + s_0 + r_0)·l_x·l_y";
  return {
      {"mass.water_added",
       [=](const LedgerRun& run) {
         const auto ledger = entries_of(run.records);
         const int steps = ledger.back().step;
         return bounded_check(
             "", pipe_water_added_error(ledger, asked), pipe_water_added_bound(unit_roundoff_of(run.backend), steps, sources),
             std::nullopt,
             fmt::format("max over steps of |water the additions added - asked| / (W_0 + asked); asked = step x {:.6g} "
                         "m³ (rain x valid area x Δt + rain map + sources x Δt, on the host); bound: the additions' "
                         "rounding, u·((1 + {} sources)·{} steps + 4)",
                         asked, sources, steps));
       }},
      {"mass.evaporation",
       [=](const LedgerRun& run) {
         return bounded_check(
             "", pipe_evaporation_error(entries_of(run.records), share),
             pipe_evaporation_bound(unit_roundoff_of(run.backend), share), std::nullopt,
             fmt::format("max over steps of |evaporated - K/(1 - K)·Σ W_t| / (Σ W_t/(1 - K)), K = K_e·Δt = {:.6g} from "
                         "the parameters; bound 3u (rounding of the kept share, the product, the difference)",
                         share));
       }},
      {"stability.max_cfl",
       [=](const LedgerRun& run) {
         return bounded_check("", errors(run).max_cfl, max_cfl_bound, std::nullopt,
                              "largest Δt·|u|/l_x or Δt·|v|/l_y of the run: at most 1 by the K scaling, plus 24 float "
                              "roundings");
       }},
      {"mass.water_balance",
       [=](const LedgerRun& run) {
         const std::string detail =
             "max over steps of |W_t - W_0 - added + evaporated + out| / (W_0 + rain + sources) (issue 3's figure)";
         if (run.backend == "cpu_float") {
           return informative_check("", errors(run).max_water,
                                    "ref<float>: the water balance of plain float arithmetic, for comparison with the "
                                    "GPU's; " + detail);
         }
         return bounded_check("", errors(run).max_water, run.backend == "gpu" ? gpu_water_bound : cpu_water_bound,
                              std::nullopt, detail);
       }},
      {"mass.material_drift",
       [=](const LedgerRun& run) {
         if (run.backend == "cpu_float") {
           return informative_check("", errors(run).max_material,
                                    "ref<float>, heights stored as plain floats: the float trap (erosion below the "
                                    "height's float spacing lost); " + material_detail);
         }
         // Semi-Lagrangian transport creates and destroys material by construction (bilinear
         // backtrace of a field that is not divergence-free), and MacCormack's correction on top of
         // it (and its limiter) too; how much depends on the flow, and no error model bounds it, so
         // the drift is reported, not graded.
         if (!conserving) {
           return informative_check("", errors(run).max_material,
                                    fmt::format("{}; {} transport is not conservative", material_detail,
                                                sediment_transport_name(scenario.constants.transport)));
         }
         return bounded_check("", errors(run).max_material, run.backend == "gpu" ? gpu_material_bound : cpu_material_bound,
                              std::nullopt, material_detail + "; flux transport conserves");
       }},
      {"mass.material_drift_of_moved",
       [=](const LedgerRun& run) {
         const auto ledger = entries_of(run.records);
         const double moved = std::max(material_moved(run.initial, run.final, ledger.back()), drift_floor);
         return informative_check(
             "", std::abs(material_drift(ledger.back(), ledger.front())) / moved,
             conserving ? "final drift / material moved (eroded, deposited, suspended, out)"
                        : fmt::format("final drift / material moved; {} transport creates or destroys material (the "
                                      "method's property)",
                                      sediment_transport_name(scenario.constants.transport)));
       }},
  };
}

Series ledger_series(const std::string& label, const std::vector<double>& steps, const std::vector<double>& values,
                     bool dashed = false, const std::string& group = "") {
  return {.label = label, .x = steps, .y = values, .dashed = dashed, .group = group};
}

// The ledger error of every backend over the steps, and ref<double>'s volumes.
void plot_ledgers(const std::vector<BackendEnd>& ends, double material, const RunOptions& options, CaseResult& result) {
  SeriesPlot error_plot{.title = "Ledger error over the steps",
                        .x_label = "step",
                        .y_label = "relative error (exact zeros at 1e-18)",
                        .log_y = true};
  for (const BackendEnd& end : ends) {
    const LedgerErrors error = ledger_errors(entries_of(end.records), material);
    error_plot.series.push_back(ledger_series("water balance " + end.backend, error.steps, error.water, false, end.backend));
    error_plot.series.push_back(ledger_series("material drift " + end.backend, error.steps, error.material, true, end.backend));
  }
  std::vector<double> steps, water, inflow, evaporated, out;
  for (const auto& entry : entries_of(ends.front().records)) {
    steps.push_back(entry.step);
    water.push_back(entry.water);
    inflow.push_back(entry.rain_in + entry.source_in);
    evaporated.push_back(entry.evaporated);
    out.push_back(entry.boundary_out_water);
  }
  // One panel each, on its own scale: the water held (53,000 m³ on the topobathy) would flatten
  // what came in and went out onto 0 in a shared one.
  const auto panel = [&](const std::string& title, const std::vector<double>& values) {
    return SeriesPlot{.title = title, .x_label = "step", .y_label = "m³", .series = {ledger_series(title, steps, values)}};
  };
  attach_plot({error_plot}, options, "ledger_error.png",
              "water balance (solid) and material drift (dashed), relative", result);
  attach_plot({panel("water held W_t", water), panel("rain and sources in", inflow), panel("evaporated", evaporated),
               panel("out through borders", out)},
              options, "ledger_volumes.png",
              "ref<double>'s water ledger, m³, each on its own scale: held, and what came in and went out", result);
}

// A bound wider than this share of the field's size (its 90th percentile over the cells, against
// the field's largest size over the checkpoints) cannot tell a bug that changes the field by a
// tenth from rounding: the check is then inconclusive.
constexpr double tellable_share_of_field = 0.1;

// pipe_shadow_bounds of ref<float>'s state before the step, one bound per value of each field as
// pipe_fields declares them, with the field's own size as its scale. One step is graded. Over
// shadow_length steps the distance is shown, neither bounded nor graded: a branch that jumps (the
// thermal step's talus threshold, a cell dry by an ulp) moves a whole transfer, which the next steps
// of an unstable run amplify (honest run specificity.erosion.pipe.topobathy.set_09 of `groundtruth
// specificity --seed 1`: every one-step distance within its bound, 431 m of terrain apart after
// four steps, in a run whose velocities reach 1e5 m/s), so no bound is computed for them.
const std::string multi_step_not_graded =
    "over several steps a branch that jumps (a talus threshold, a dry cell) moves a whole transfer, which an "
    "unstable run amplifies; the one-step shadow is graded";

std::vector<ShadowBound> pipe_field_bounds(const State& from, int steps, const PipeScenario& scenario) {
  const PipeConstants& constants = scenario.constants;
  const auto start = pipe_state_of<double>(from, constants.pipe_count);
  const PipeShadowScales scales = pipe_shadow_scales(start, constants);
  std::vector<double> scale_of_field{scales.relief, scales.depth, scales.sediment, scales.regolith,
                                     scales.speed,  scales.speed, scales.flux};
  scale_of_field.insert(scale_of_field.end(), scales.layers.begin(), scales.layers.end());
  if (steps > 1) {
    std::vector<ShadowBound> shown;
    for (double scale : scale_of_field) shown.push_back({.scale = scale, .graded = false, .why_not_graded = multi_step_not_graded});
    return shown;
  }
  const State bounds = pipe_state(pipe_shadow_bounds(start, constants, scenario.forcing, steps), constants.pipe_count);
  const std::string model =
      "pipe_shadow_bounds: the step in rounding-interval arithmetic from that state, cell by cell "
      "(compare/checks/pipe_error_model.hpp)";
  std::vector<ShadowBound> field_bounds;
  for (std::size_t f = 0; f < bounds.fields.size(); ++f) {
    field_bounds.push_back({.per_value = bounds.fields[f], .scale = scale_of_field.at(f),
                            .tellable_share = tellable_share_of_field, .model = model});
  }
  return field_bounds;
}

// Strict, no warn band: the number comes from the case's parameters alone (no rounding in it worth
// a margin), and above 1 the scheme's checkerboard mode grows every step — a case that asks for
// that is a failed case, not a doubtful one.
CaseRun wave_number_check(const PipeScenario& scenario) {
  return [wave = pipe_wave_number(scenario.constants), notes = scenario.notes](const nlohmann::json&, const RunOptions&,
                                                                                CaseResult& result) {
    result.notes.insert(result.notes.end(), notes.begin(), notes.end());
    result.checks.push_back(bounded_check(
        "stability.pipe_wave_number", wave, 1.0, std::nullopt,
        "Δt·sqrt(A·g/(l_x·l_y)·λ), λ = 1/l_x + 1/l_y with 4 pipes (more with 8): the explicit pipe scheme's gravity "
        "waves are stable up to 1"));
  };
}

// spec.step.*.cpu (compare/checks/pipe_spec_check.hpp) from ref<double>'s state after
// `spec_start_step` steps: flows and suspended sediment established.
constexpr int spec_start_step = 10;

CaseRun spec_step_check(std::shared_ptr<const PipeScenario> scenario) {
  return [scenario](const nlohmann::json&, const RunOptions&, CaseResult& result) {
    const HydraulicParams& params = scenario->params;
    if (params.steps < 1) return;
    const int from = std::min(params.steps - 1, spec_start_step);
    reference::PipeErosion<double> truth(scenario->initial, scenario->constants, scenario->forcing);
    truth.run(from);
    for (Check& check : pipe_spec_checks(truth.state(), scenario->constants, params, scenario->forcing, from + 1)) {
      result.checks.push_back(std::move(check));
    }
  };
}

PreparedTwin prepare_pipe(const nlohmann::json& resolved, const LoadedInput& input) {
  auto scenario = std::make_shared<const PipeScenario>(make_scenario(resolved, input.heights, input.fields));
  const PipeConstants& constants = scenario->constants;
  SteppedTwin twin{.algorithm = "erosion.pipe",
                   .fields = pipe_fields(constants),
                   .initial = pipe_state(scenario->initial, constants.pipe_count),
                   .iterations = scenario->params.steps,
                   .checkpoints = scenario->checkpoints,
                   .time_walks = true};
  twin.reference_double = [scenario] { return pipe_reference_stepper<double>(scenario->constants, scenario->forcing); };
  twin.reference_float = [scenario] { return pipe_reference_stepper<float>(scenario->constants, scenario->forcing); };
  twin.make_gpu = [scenario] { return pipe_gpu_stepper(scenario->initial, scenario->constants, scenario->forcing, true); };
  twin.make_timed_gpu = [scenario] { return pipe_gpu_stepper(scenario->initial, scenario->constants, scenario->forcing, false); };
  twin.shadow_bounds = [scenario](const State& from, int steps) { return pipe_field_bounds(from, steps, *scenario); };
  twin.ledger = pipe_ledger_terms(*scenario);
  twin.finish = [material = material_present(scenario->initial)](const std::vector<BackendEnd>& ends,
                                                                   const nlohmann::json&, const RunOptions& options,
                                                                   CaseResult& result) {
    plot_ledgers(ends, material, options, result);
  };
  return {.kind = std::move(twin), .extra_checks = in_turn(wave_number_check(*scenario), spec_step_check(scenario))};
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

const ParamTable<PipeCaseParams>& pipe_case_param_table() {
  using C = PipeCaseParams;
  static const ParamTable<C> table = [] {
    ParamTable<C> rows = nested(&C::hydraulic, hydraulic_param_table());
    const ParamTable<C> scenario = {
        choice_param("initial_water", &C::initial_water, initial_water_choices, "",
                     "dry; depth: initial_depth on every cell (seed 001's set water level); "
                     "sea_level: fill up to sea_level"),
        real_param("initial_depth", &C::initial_depth, 0.0, 1e3, "m", "water depth of initial_water = depth"),
        real_param("sea_level", &C::sea_level, -1e4, 1e4, "m", "initial_water = sea_level fills cells below it"),
        choice_param("rain_map", &C::rain_map, rain_map_choices, "",
                     "orographic: rain_map_rate·(b − b_min)/(b_max − b_min) more rain on high ground"),
        real_param("rain_map_rate", &C::rain_map_rate, 0.0, 1.0, "m/s", "the orographic rain on the highest cell"),
        real_param("source_rate", &C::source_rate, 0.0, 1e6, "m³/s", "one point source; 0 = none"),
        real_param("source_x", &C::source_x, 0.0, 1.0, "1", "the source's column as a share of the width"),
        real_param("source_y", &C::source_y, 0.0, 1.0, "1", "the source's row as a share of the height"),
        integer_param("checkpoints", &C::checkpoints, 1, 1000, "count",
                      "states along the run from which the GPU takes shadow steps beside ref<float>, "
                      "and at which it is compared with ref<double>"),
        real_param("layer_thickness_1", element(&C::layer_thickness, 0), 0.0, 1e4, "m",
                   "layer 1's initial thickness on every cell (with layers >= 1), unless the input field layer_1 "
                   "gives it"),
        real_param("layer_thickness_2", element(&C::layer_thickness, 1), 0.0, 1e4, "m",
                   "layer 2's initial thickness (layers >= 2), unless the input field layer_2 gives it"),
        real_param("layer_thickness_3", element(&C::layer_thickness, 2), 0.0, 1e4, "m",
                   "layer 3's initial thickness (layers = 3), unless the input field layer_3 gives it"),
    };
    rows.insert(rows.end(), scenario.begin(), scenario.end());
    return rows;
  }();
  return table;
}

Algorithm pipe_algorithm() {
  return {.name = "erosion.pipe",
          .summary = "virtual-pipe hydraulic erosion with a water and material ledger (Mei 2007; seed 001's variant)",
          .source = "seed 000 §3.4 and Appendix B (Mei, Decaudin, Hu 2007, eqs. 2.10-2.25); seed 001 §3.3-3.9",
          .params = &pipe_specs(),
          .prepare = prepare_pipe,
          .kind = CaseKind::stepped,
          .input_fields = {{"layer_1", "m", "Šťava's layer 1 (on the bedrock): initial thickness, >= 0 (layers >= 1)"},
                           {"layer_2", "m", "layer 2's initial thickness, >= 0 (layers >= 2)"},
                           {"layer_3", "m", "layer 3's initial thickness, >= 0 (layers = 3, the top)"}},
          .benchmark = benchmark_pipes,
          // Counted in reference/erosion/pipes.cpp (step() as the table times it, ledger included)
          // and gpu/erosion/pipes.cpp, at the benchmark's parameters (4 pipes, flux transport).
          .traffic = {.cpu = 607.0, .gpu = 308.0},
          .expect_shape = field_spec_shape(),
          // Measured on 1024² (both backends, report included): 959 B a cell with 1 checkpoint; each
          // further one keeps ref<double>'s and ref<float>'s states there, 6 + pipes doubles a cell
          // each: 160 B a cell with 4 pipes, as measured (the peak RSS of 256² runs with 8 and 64
          // checkpoints), rounded up by 20 B. The shadow bounds' step in rounding intervals
          // (pipe_shadow_bounds: three doubles a value) holds its state, scratch and sent amounts,
          // about 25 such values a cell (600 B), while the GPU's and the references' states are
          // held too: counted, not measured (the 384² run of tests/memory_estimates_test.cpp peaked
          // 35 B a cell above the estimate without it).
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const double cells = static_cast<double>(input.heights.size());
            const auto given = params_from_json(pipe_case_param_table(), resolved);
            // Each of Šťava's layers: a double in the three twins' states, the GPU's float, the
            // interval model's three doubles and the field files' copy, 120 B a cell (counted).
            const double layers = given.hydraulic.layers;
            return memory_for(cells, "cells", 1100 + 600 + 120.0 * layers + descriptor_bytes_per_cell) +
                   memory_for(cells * given.checkpoints, "cell-checkpoints",
                              2.0 * 8.0 * (6.0 + given.hydraulic.pipe_count + layers) + 20.0);
          }};
}

}  // namespace gt
