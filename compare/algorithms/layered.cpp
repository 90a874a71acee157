// erosion.layered: seed 001's layered ground (digest 001 §3.1, §3.3-3.5, §3.10–3.17, §3.19, §4): a
// heightmap given a stated soil–rock profile in every column (compare/layered_case.hpp), then `steps`
// iterations of reference/erosion/layered/iteration.hpp (creep, talus, vegetation, weathering and,
// when water is given — initial_water, rain_rate or the river — sources and sinks, the pipe flow,
// force erosion, dissolution, sediment diffusion and wetness) in ref<double> and ref<float>, beside the GPU twin
// gpu/erosion/layered/iteration.hpp, run by the stepped runner (compare/stepped_case.hpp).
//
// Inputs:  a surface without no-data cells (m), the profile and LayeredParams.
// Outputs: the declared state and its steppers (compare/steppers/layered.hpp): terrain (the
//          surface h), soil (each component's thickness in topsoil and subsoil), bedrock and
//          bedrock_type per layer, vegetation; with water also water, previous_water, water_flux,
//          carried and wetness.
// Units:   m, m³/s (flux), m·s (wetness), 1 (vegetation, types); volumes in the ledger m³.
// Twin:    gpu/erosion/layered/ (the same float operations in the same order, every division
//          rounded to nearest by gt_div): every shadow step is graded bit for bit (bound 0), and so
//          is the whole run's end against ref<float> (SteppedTwin::gpu_bit_exact).
// Ledger (terms on every backend; V the volume of all materials at the start, S the steps, u the
// unit roundoff of the backend's type; records: the conversions a step, cumulative):
//   ledger.materials  the largest |V_m(end) − V_m(start) − converted into m + converted out of m +
//                     sunk| / V over the materials (5 components in the ground and in the water;
//                     each bedrock type)
//   ledger.total      |ΣV(end) + sunk − ΣV(start)| / V: conversions move volume between materials
//   ledger.conversions  |volume converted out of all materials − into them| / V; bound
//                     (32u + A·u_double)·(out + in)/V: most conversions book one float amount both
//                     ways; fragmentation books the rock removed (a float sum of 8 outflows, 7u)
//                     against its fragments (three products and a remainder, 3u; the GPU sums a
//                     column's 8 arrivals in float, 7u more), soil formation the amount formed
//                     against its parts (4 products and a remainder, 5u): 17u at most, 32u with
//                     room. Each total is a double sum of at most A = 64·cells·S addends (γ_A).
//                     A leak of a share above 32u of the converted volume fails, where a bound on
//                     the whole volume V would hide one 10^5 times larger.
//     Bound of the other two: S·R·2u (tests/layered_reference_test.cpp's model: each stored thickness
//     passes through at most R = 36 roundings an iteration, each within u of what the cell holds of
//     the material, and what moved is at most V). With water R = 64: the flow rounds a carried amount
//     13 times (4 shares sent, their sum, the rest, 4 arrivals and their sums), force erosion and
//     dissolution a stored amount up to 15 more; sediment diffusion (when on) 13 more, as the flow.
//     The GPU's fragments are summed per column in float before the host's double sum (γ_7 of the
//     total, far inside R·2u).
//   ledger.water      (with water) |W(end) − W(start) − added + sunk| / (W(start) + added): rain and
//                     the river's rise in, the sinks out; bound S·13·2u
//   layers.invalid    columns with a negative or non-finite thickness, or a topsoil above
//                     topsoil_max·(1 + 64u), or (with water) a negative or non-finite depth, flux,
//                     carried amount or wetness: bound 0
//   layers.surface    the largest |surface − Σ thicknesses − its start value| over columns: bound
//                     S·R·2u·(|surface| + Σ thickness), the largest over the columns at the start
// And on ref<double>'s run:
//   spec.courant.cpu  (with water; informative) Δt·sqrt(g·w_max)/l at its largest over the steps;
//                     above 1/√2 a note warns that the water oscillates
//   spec.repose.cpu   (expect {"at_rest": true}) the largest slope to a lower neighbour over the
//                     column's repose slope, written out here from eq. 3.1, over columns with soil:
//                     below 1 at rest (eq. 3.3 moves Δt·Δh/2 whenever a slope reaches tan φ)
// Pictures (compare/layered_pictures.hpp): the surface material, the cross-section, the material
// masks; the ledger per material over the steps.
// Performance: ms an iteration by grid side, dry and under rain, beside Šťava et al. 2008's figure.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/benchmark.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/inputs.hpp"
#include "compare/layered_case.hpp"
#include "compare/layered_pictures.hpp"
#include "compare/report/plots.hpp"
#include "compare/stepped_case.hpp"
#include "compare/steppers/layered.hpp"
#include "compare/timing.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"

namespace gt {
namespace {

// ---- the declared state ---------------------------------------------------------------------

// ---- the ledger terms -----------------------------------------------------------------------

// tests/layered_reference_test.cpp's ledger model: creep and talus round a stored value at most 32
// times an iteration, weathering 4 more; with water, the flow, force erosion and dissolution up to 28
// more (see the header). A depth of water: 13 roundings an iteration.
constexpr double roundings_per_step = 36.0;
constexpr double roundings_per_step_with_water = 64.0;
constexpr double diffusion_roundings_per_step = 13.0;
constexpr double water_roundings_per_step = 13.0;

// What the terms read beside a run: the setup's counts and limits.
struct LedgerModel {
  int steps = 0;
  std::size_t types = 0;
  int bedrock_layers = 0;
  bool wet = false;
  bool diffusing = false;  // wet, with sediment diffusion on
  double topsoil_max = 0.0;
  double roundings() const {
    if (!wet) return roundings_per_step;
    return roundings_per_step_with_water + (diffusing ? diffusion_roundings_per_step : 0.0);
  }
  double bound(const std::string& backend) const { return steps * roundings() * 2.0 * unit_roundoff_of(backend); }
};

std::vector<double> volumes_of(const State& state, const LedgerModel& model) {
  return layered_volumes(state, model.bedrock_layers, model.types);
}

double total_of(const std::vector<double>& volumes) { return std::accumulate(volumes.begin(), volumes.end(), 0.0); }

Check materials_term(const LedgerRun& run, const LedgerModel& model) {
  const auto start = volumes_of(run.initial, model), end = volumes_of(run.final, model);
  const auto& converted = run.records.back().totals;
  const double total = total_of(start);
  double worst = 0.0;
  std::size_t worst_material = 0;
  for (std::size_t m = 0; m < start.size(); ++m) {
    const double drift = std::abs(end[m] - start[m] - converted.at(layered_converted_key(m))) / total;
    // A material whose volume is NaN is the worst drift there is: a comparison would skip it.
    if (std::isnan(drift)) {
      worst = drift, worst_material = m;
      break;
    }
    if (drift > worst) worst = drift, worst_material = m;
  }
  return bounded_check("", worst, model.bound(run.backend), std::nullopt,
                       fmt::format("largest |V_end − V_start − converted + sunk| / V over the materials ({}; components "
                                   "in the ground and in the water), V = {:.6g} m³; bound S·R·2u with S = {} steps, R = {}",
                                   layered_material_name(worst_material), total, model.steps, model.roundings()));
}

Check total_term(const LedgerRun& run, const LedgerModel& model) {
  const double start = total_of(volumes_of(run.initial, model)), end = total_of(volumes_of(run.final, model));
  const double sunk = run.records.back().totals.at("sunk");
  return bounded_check("", std::abs(end + sunk - start) / start, model.bound(run.backend), std::nullopt,
                       fmt::format("|ΣV_end + sunk − ΣV_start| / V: {:.6g} m³ and {:.6g} m³ sunk against {:.6g} m³", end,
                                   sunk, start));
}

// The conversions' model (see the header): 32 roundings of the backend's type per converted amount,
// and the double sums of at most 64 addends a cell and step.
constexpr double conversion_roundings = 32.0;
constexpr double conversion_addends_per_cell_step = 64.0;

Check conversions_term(const LedgerRun& run, const LedgerModel& model) {
  const auto& totals = run.records.back().totals;
  const double out = totals.at("converted_out"), in = totals.at("converted_in");
  const double total = total_of(volumes_of(run.initial, model));
  const double addends = conversion_addends_per_cell_step * double(run.initial.grid.cells()) * model.steps;
  const double relative = conversion_roundings * unit_roundoff_of(run.backend) + addends * unit_roundoff_of("cpu");
  return bounded_check("", std::abs(out - in) / total, relative * (out + in) / total, std::nullopt,
                       fmt::format("|converted out of all materials − converted into them| / V: {:.6g} m³ out (bedrock "
                                   "fragmented, eroded or turned to soil, rock weathered or broken by water), {:.6g} m³ "
                                   "in; bound (32u + A·u_double)·(out + in)/V, A = 64·cells·steps",
                                   out, in));
}

Check water_term(const LedgerRun& run, const LedgerModel& model) {
  const double start = layered_water_volume(run.initial), end = layered_water_volume(run.final);
  const auto& totals = run.records.back().totals;
  const double added = totals.at("water_added"), sunk = totals.at("water_sunk");
  const double scale = std::max(start + added, std::numeric_limits<double>::min());
  return bounded_check(
      "", std::abs(end - start - added + sunk) / scale,
      model.steps * water_roundings_per_step * 2.0 * unit_roundoff_of(run.backend), std::nullopt,
      fmt::format("|W_end − W_start − added + sunk| / (W_start + added): W {:.6g} → {:.6g} m³, {:.6g} m³ added (rain, "
                  "the river's rise), {:.6g} m³ sunk; bound S·{}·2u",
                  start, end, added, sunk, water_roundings_per_step));
}

bool negative_or_not_finite(double value) { return !std::isfinite(value) || value < 0.0; }

// Whether column c's water is broken: a negative or non-finite depth, flux, carried amount or wetness.
bool invalid_water(const LayeredWater<double>& water, std::size_t c) {
  bool broken = negative_or_not_finite(water.water[c]) || negative_or_not_finite(water.wetness[c]);
  for (int pipe = 0; pipe < water_pipe_count; ++pipe) broken = broken || negative_or_not_finite(water.flux_at(pipe, c));
  for (int kind = 0; kind < carried_kind_count; ++kind) broken = broken || negative_or_not_finite(water.carried_at(kind, c));
  return broken;
}

// Whether column c's ground is broken: a non-finite surface, a negative or non-finite thickness, a
// topsoil above `topsoil_limit`.
bool invalid_column(const LayeredGround<double>& ground, std::size_t c, double topsoil_limit) {
  bool broken = !std::isfinite(ground.surface[c]) || ground.soil_thickness(0, c) > topsoil_limit;
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    for (int component = 0; component < soil_component_count; ++component) {
      broken = broken || negative_or_not_finite(ground.soil_at(layer, component, c));
    }
  }
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
    broken = broken || negative_or_not_finite(ground.bedrock_at(layer, c));
  }
  return broken;
}

Check invalid_term(const LedgerRun& run, const LedgerModel& model) {
  const LayeredGround<double> ground = layered_ground_of(run.final, model.bedrock_layers);
  const auto water = layered_water_of(run.final);
  const double topsoil_limit = model.topsoil_max * (1.0 + 64.0 * unit_roundoff_of(run.backend));
  std::size_t invalid = 0;
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    invalid += invalid_column(ground, c, topsoil_limit) || (water && invalid_water(*water, c)) ? 1 : 0;
  }
  return bounded_check("", double(invalid), 0.0, std::nullopt,
                       "columns with a negative or non-finite thickness or surface, or a topsoil above "
                       "topsoil_max·(1 + 64u), or a negative or non-finite depth, flux, carried amount or wetness");
}

double column_thickness(const LayeredGround<double>& ground, std::size_t c) {
  double thickness = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) thickness += ground.bedrock_at(layer, c);
  return thickness;
}

Check surface_term(const LedgerRun& run, const LedgerModel& model) {
  const LayeredGround<double> start = layered_ground_of(run.initial, model.bedrock_layers);
  const LayeredGround<double> end = layered_ground_of(run.final, model.bedrock_layers);
  double worst = 0.0, scale = 0.0;
  for (std::size_t c = 0; c < start.cells(); ++c) {
    const double base_start = start.surface[c] - column_thickness(start, c);
    const double base_end = end.surface[c] - column_thickness(end, c);
    worst = std::max(worst, std::abs(base_end - base_start));
    scale = std::max(scale, std::abs(start.surface[c]) + column_thickness(start, c));
  }
  return bounded_check("", worst, model.bound(run.backend) * scale, std::nullopt,
                       "largest change of surface − Σ thicknesses over the columns, m (the surface moves with every "
                       "layer change)");
}

std::vector<LedgerTerm> layered_ledger_terms(const LedgerModel& model) {
  const auto term = [&](const std::string& check, Check (*evaluate)(const LedgerRun&, const LedgerModel&)) {
    return LedgerTerm{check, [model, evaluate](const LedgerRun& run) { return evaluate(run, model); }};
  };
  std::vector<LedgerTerm> terms = {term("ledger.materials", materials_term), term("ledger.total", total_term),
                                   term("ledger.conversions", conversions_term), term("layers.invalid", invalid_term),
                                   term("layers.surface", surface_term)};
  if (model.wet) terms.push_back(term("ledger.water", water_term));
  return terms;
}

// ---- ref<double>'s own checks and pictures ----------------------------------------------------

// The pipe model's wave Courant number at the deepest column: Δt·sqrt(g·w_max)/min(l_x, l_y). The
// flux update is explicit, so shallow-water waves (speed sqrt(g·w)) must cross less than a cell a
// step: in 2-D, C ≤ 1/√2; beyond it the water oscillates from column to column in a checkerboard.
void add_courant_check(const std::vector<LedgerRecord>& records, const LayeredParams& params, const StateGrid& grid,
                       CaseResult& result) {
  double deepest = 0.0;
  for (const LedgerRecord& record : records) deepest = std::max(deepest, record.totals.at("deepest_water"));
  const double courant = params.time_step * std::sqrt(params.gravity * deepest) / std::min(grid.cell_size_x, grid.cell_size_y);
  const double stable = 1.0 / std::sqrt(2.0);
  result.checks.push_back(informative_check(
      "spec.courant.cpu", courant,
      fmt::format("the pipe flow's wave Courant number Δt·sqrt(g·w_max)/min(l) at its largest over the steps; the "
                  "explicit flux update is stable for C ≤ 1/√2 = {:.3f}",
                  stable)));
  if (courant <= stable) return;
  result.notes.push_back(fmt::format(
      "warning: the Courant number reached {:.3g} > 1/√2: the water oscillates between columns (a checkerboard); a "
      "time_step below {:.3g} s keeps it stable at this depth",
      courant, params.time_step * stable / courant));
}

// Eq. 3.1 with the depth factor, written apart from the reference's soil_repose: the least repose
// slope over the column's non-empty soil layers; +∞ without soil.
double repose_slope(const LayeredGround<double>& ground, const LayeredParams& params, std::size_t c) {
  double least = std::numeric_limits<double>::infinity();
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const double thickness = ground.soil_thickness(layer, c);
    if (thickness <= 0.0) continue;
    double mixed = 0.0;
    for (int component = 0; component < soil_component_count; ++component) {
      mixed += params.repose_tan[std::size_t(component)] * ground.soil_at(layer, component, c) / thickness;
    }
    const double vegetation = 1.0 + params.vegetation_repose * ground.vegetation[c];
    least = std::min(least, std::pow(params.depth_factor, layer) * mixed * vegetation);
  }
  return least;
}

void add_repose_check(const LayeredGround<double>& ground, const LayeredParams& params, CaseResult& result) {
  double worst = 0.0;
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const double repose = repose_slope(ground, params, c);
      if (!std::isfinite(repose)) continue;
      for (int k = 0; k < layered_neighbour_count; ++k) {
        const auto n = layered_neighbour(ground, params.border, x, y, k);
        if (!n) continue;
        const double slope = (ground.surface[c] - ground.surface[*n]) /
                             layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k);
        worst = std::max(worst, slope / repose);
      }
    }
  }
  result.checks.push_back(bounded_check(
      "spec.repose.cpu", worst, 1.0, std::nullopt,
      "largest slope to a neighbour over the column's repose slope (eq. 3.1, written apart), columns with soil: "
      "below 1 at rest"));
}

// Each material's volume change and what the ledger cannot account for, over ref<double>'s steps.
void plot_ledger(const std::vector<LedgerRecord>& records, std::size_t materials, const RunOptions& options,
                 CaseResult& result) {
  const auto& first = records.front().totals;
  double total = 0.0;
  for (std::size_t m = 0; m < materials; ++m) total += first.at(layered_volume_key(m));
  SeriesPlot changes{"each material's volume", "step", "(V − V_start) / V_all", false, false, {}};
  SeriesPlot drift{"ledger drift", "step", "|V − V_start − converted| / V_all", false, false, {}};
  for (std::size_t m = 0; m < materials; ++m) {
    Series change{layered_material_name(m), {}, {}, false, {}}, unaccounted = change;
    for (const LedgerRecord& record : records) {
      const double moved = record.totals.at(layered_volume_key(m)) - first.at(layered_volume_key(m));
      change.x.push_back(record.step);
      change.y.push_back(moved / total);
      unaccounted.x.push_back(record.step);
      unaccounted.y.push_back(std::abs(moved - record.totals.at(layered_converted_key(m))) / total);
    }
    changes.series.push_back(std::move(change));
    drift.series.push_back(std::move(unaccounted));
  }
  attach_plot({changes, drift}, options, "ledger.png",
              "the ledger per material over the steps, ref<double>: each material's volume change (fragmentation turns "
              "bedrock into sand..boulders) and what the ledger cannot account for",
              result);
}

void finish_layered(const LayeredSetup& setup, const std::vector<BackendEnd>& ends, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result) {
  const BackendEnd& truth = ends.front();
  const int bedrock_layers = setup.bedrock_layers();
  const LayeredGround<double> ground = layered_ground_of(truth.final, bedrock_layers);
  if (has_water(setup.params)) add_courant_check(truth.records, setup.params, truth.final.grid, result);
  if (expect.is_object() && expect.value("at_rest", false)) add_repose_check(ground, setup.params, result);
  if (options.report_dir.empty()) return;
  write_layered_pictures(ground, setup.params, options, result);
  plot_ledger(truth.records, soil_component_count + setup.params.bedrock_types.size(), options, result);
}

// ---- the case -------------------------------------------------------------------------------

// A profile, top down: "1.25 m topsoil and 2.25 m subsoil of seed001_code, bedrock 3 m type 0, ...".
std::string profile_words(const LayeredProfile& profile, const std::string& soil) {
  std::vector<std::string> bedrock;
  for (const auto& layer : profile.bedrock) bedrock.push_back(fmt::format("{:.6g} m type {}", layer.thickness, layer.type));
  return fmt::format("{:.6g} m topsoil and {:.6g} m subsoil of {}, bedrock {}",
                     std::accumulate(profile.topsoil.begin(), profile.topsoil.end(), 0.0),
                     std::accumulate(profile.subsoil.begin(), profile.subsoil.end(), 0.0), soil,
                     fmt::join(bedrock, ", "));
}

// The initial columns as said to the user: each profile with the columns that take it, and the
// vegetation (one value, or the map's range).
std::vector<std::string> columns_notes(const LayeredSetup& setup) {
  const LayeredColumns& columns = setup.columns;
  std::vector<std::string> notes;
  if (columns.profile_of.empty()) {
    notes.push_back("initial profile in every column, top down: " + profile_words(columns.profiles[0], setup.soils[0]));
  } else {
    for (std::size_t p = 0; p < columns.profiles.size(); ++p) {
      const auto count = std::count(columns.profile_of.begin(), columns.profile_of.end(), std::int32_t(p));
      notes.push_back(fmt::format("profile {} (the profile field's value {}) in {} of {} columns, top down: {}", p, p,
                                  count, columns.profile_of.size(), profile_words(columns.profiles[p], setup.soils[p])));
    }
  }
  if (columns.vegetation.size() == 1) {
    notes.push_back(fmt::format("vegetation {:.6g} on every column", columns.vegetation[0]));
  } else {
    const auto [least, most] = std::minmax_element(columns.vegetation.begin(), columns.vegetation.end());
    notes.push_back(fmt::format("vegetation from the input field 'vegetation', {:.6g} .. {:.6g} (the vegetation "
                                "parameter is not read)",
                                *least, *most));
  }
  if (!setup.params.talus) notes.push_back("talus is switched off (talus=false)");
  return notes;
}

// Decisions taken for the user: the columns, and whether and how water runs.
std::vector<std::string> setup_notes(const LayeredSetup& setup) {
  const LayeredParams& params = setup.params;
  std::vector<std::string> notes = columns_notes(setup);
  if (!has_water(params)) {
    notes.push_back("no water given (initial_water, rain_rate and river all off): the water processes do not run");
    return notes;
  }
  const std::string river =
      params.river ? fmt::format(", the river: {} m held at column ({}, {}), rows y >= {} a sink", params.river_depth,
                                 setup.surface.width / 2, setup.surface.height / 16, (15 * setup.surface.height + 15) / 16)
                   : std::string();
  const std::string diffusion =
      params.sediment_diffusion > 0.0
          ? fmt::format("sediment diffusion with {} weights (σ = {}{})", diffusion_weighting_name(params.diffusion_weighting),
                        params.sediment_diffusion, params.regolith_diffusion ? ", the regolith too" : ", not the regolith")
          : std::string("no sediment diffusion");
  const std::string rain_steps =
      params.rain_steps > 0 && params.rain_rate > 0.0 ? fmt::format(" on the first {} steps", params.rain_steps) : "";
  const std::string drain =
      params.drain_step > 0
          ? fmt::format(", every column drained of its water and what it carries at the start of step {}", params.drain_step)
          : "";
  notes.push_back(fmt::format("water: {} m on every column at the start, rain {} m/s{}{}{}; the water processes run "
                              "each step (pipe flow, force erosion, dissolution with K_r = {} m, {}, wetness and the "
                              "flood death)",
                              params.initial_water, params.rain_rate, rain_steps, river, drain, params.regolith_depth,
                              diffusion));
  return notes;
}

const std::string bit_exact_model =
    "bit for bit: the GPU does ref<float>'s float operations in the same order, every division rounded to nearest by "
    "gt_div (gpu/erosion/layered/ground_buffers.hpp)";

SteppedTwin layered_twin(const LayeredSetup& given) {
  auto setup = std::make_shared<const LayeredSetup>(given);
  const int bedrock_layers = setup->bedrock_layers();
  const bool wet = has_water(setup->params);
  SteppedTwin twin{.algorithm = "erosion.layered",
                   .fields = layered_fields(bedrock_layers, wet),
                   .initial = layered_start_state(*setup),
                   .iterations = setup->steps,
                   .time_walks = true,
                   .gpu_bit_exact = true,
                   .gpu_not_described =
                       "the GPU is graded bit for bit against ref<float> (parity.*.gpu_vs_float); its distance "
                       "from ref<double> after a whole run is ref<float>'s, which no error model bounds"};
  twin.reference_double = [setup] { return layered_reference_stepper<double>(*setup); };
  twin.reference_float = [setup] { return layered_reference_stepper<float>(*setup); };
  twin.make_gpu = [setup] { return layered_gpu_stepper(*setup); };
  twin.shadow_bounds = [fields = twin.fields.size()](const State& from, int) {
    std::vector<ShadowBound> bounds;
    for (std::size_t f = 0; f < fields; ++f) {
      double scale = 0.0;
      for (const double value : from.fields[f]) scale = std::max(scale, std::abs(value));
      bounds.push_back({.strict = 0.0, .scale = scale, .model = bit_exact_model});
    }
    return bounds;
  };
  twin.ledger = layered_ledger_terms({.steps = setup->steps, .types = setup->params.bedrock_types.size(),
                                      .bedrock_layers = bedrock_layers, .wet = wet,
                                      .diffusing = wet && setup->params.sediment_diffusion > 0.0,
                                      .topsoil_max = setup->params.topsoil_max});
  twin.finish = [setup](const std::vector<BackendEnd>& ends, const nlohmann::json& expect, const RunOptions& options,
                        CaseResult& result) { finish_layered(*setup, ends, expect, options, result); };
  return twin;
}

PreparedTwin prepare_layered(const nlohmann::json& resolved, const LoadedInput& input) {
  const LayeredSetup setup = layered_setup(resolved, input.heights, input.fields);
  return {.kind = layered_twin(setup),
          .extra_checks = [notes = setup_notes(setup)](const nlohmann::json&, const RunOptions&, CaseResult& result) {
            result.notes.insert(result.notes.end(), notes.begin(), notes.end());
          }};
}

// ---- performance ----------------------------------------------------------------------------

// Šťava et al. 2008 (issue 14): at least 20 frames per second at 2048×1024 with 4 layers on the
// GPU of 2008, one erosion step a frame: at most 50 ms a step. Other work (their layers are
// (material, thickness) pairs under water erosion), named for scale in every table.
BenchmarkRow published_layered_row() {
  BenchmarkRow row = published_row("erosion.layered", "Šťava et al. 2008 (GPU of 2008)", 2048, 1, 50.0,
                                   "≥ 20 fps at 2048×1024 cells (not 2048²), 4 layers, water erosion: other work, as "
                                   "published");
  row.mcell_iterations_per_s = 2048.0 * 1024.0 / 0.05 / 1e6;  // the cells they had
  return row;
}

// Seed 001's own figure (its §1 and evaluation): one step on 128×128 in 0.03–0.045 s, every process
// on, single-threaded Cython in double, hardware not named; the midpoint shown beside our rows at
// 128 (`bench 'erosion.layered' --sizes 128`), whose "+water" rows run the same processes.
std::vector<BenchmarkRow> seed_layered_rows() {
  return {published_row("erosion.layered", "seed 001 (Cython, one thread, double; hardware not named)", 128, 1, 37.5,
                        "0.03–0.045 s a step on 128×128, every process on (compare the +water rows), as published; "
                        "midpoint shown")};
}

// A benchmark variant: the processes without water, then the whole model under rain (backends
// suffixed "+water").
struct BenchmarkVariant {
  std::string suffix;
  double rain_rate = 0.0;
  std::string cpu_detail, gpu_detail;
};

const std::vector<BenchmarkVariant> benchmark_variants = {
    {"", 0.0, "creep, talus, vegetation, weathering; ref<double>, one thread",
     "9 passes an iteration (creep and talus: snapshot copy, outflow, apply; vegetation 2; weathering 1) and the "
     "conversions read back after each process"},
    {"+water", 0.01,
     "the whole model under rain 0.01 m/s (sources, creep, talus, flow, force erosion, dissolution, sediment "
     "diffusion, wetness, vegetation, weathering); ref<double>, one thread",
     "19 passes an iteration (the 9 above; sources 1; flow: flux, snapshot copy, move; force erosion: surface copy "
     "and its pass; dissolution 1; diffusion: snapshot copy and its pass; wetness 1) and the conversions read back "
     "after each process"}};

// Up to 4 iterations on a noisy cone under the default loam profile, each variant, timed as the
// case's steppers run them (time_stepped_work).
std::vector<BenchmarkRow> benchmark_layered(const BenchmarkOptions& options, bool gpu_available,
                                            const Environment& environment) {
  std::vector<BenchmarkRow> rows{published_layered_row()};
  const int steps = std::max(1, std::min(options.iterations, 4));
  for (const int size : options.sizes) {
    const nlohmann::json cone = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                 {"peak", 0.2 * size}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap surface = load_input(cone, nullptr, {}).heights;
    for (const BenchmarkVariant& variant : benchmark_variants) {
      const nlohmann::json overrides = {{"steps", steps}, {"rain_rate", variant.rain_rate}};
      const SteppedTwin twin =
          layered_twin(layered_setup(resolve_params("erosion.layered", layered_case_param_specs(), overrides), surface));
      const auto row = [&](const std::string& backend, const std::vector<double>& times, const std::string& device,
                           const std::string& detail) {
        BenchmarkRow timed{.algorithm = "erosion.layered", .backend = backend + variant.suffix, .size = size,
                           .iterations = steps, .reps = options.reps, .median_ms = median(times), .device = device,
                           .dimensions = 2};
        timed.mcell_iterations_per_s = double(size) * size * steps / (timed.median_ms * 1e-3) / 1e6;
        timed.detail = fmt::format("{:.1f} ms a step; {}", timed.median_ms / steps, detail);
        return timed;
      };
      rows.push_back(row("cpu", time_stepped_cpu(twin, options.reps), environment.cpu, variant.cpu_detail));
      if (!gpu_available) continue;
      rows.push_back(row("gpu", time_stepped_gpu(twin, options.reps), environment.gl_renderer, variant.gpu_detail));
    }
  }
  return rows;
}

// "at_rest" (finish_layered's check that talus came to rest) and the descriptors' "fidelity".
nlohmann::json layered_expect_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape["at_rest"] = "boolean";
  return shape;
}

}  // namespace

Algorithm layered_algorithm() {
  return {.name = "erosion.layered",
          .summary = "seed 001's layered ground: soil–rock layers over bedrock, creep and per-material talus, "
                     "vegetation and weathering, and with water the pipe flow, force, impact and dissolution erosion and "
                     "sediment diffusion; a ledger per material",
          .source = "seed 001 §3.1, §3.3–3.5, §3.8, §3.10–3.17, §3.19, §4 (eq. 2.1–2.7, 3.1–3.12)",
          .params = &layered_case_param_specs(),
          .prepare = prepare_layered,
          .kind = CaseKind::stepped,
          .input_fields = layered_input_fields(),
          .benchmark = benchmark_layered,
          .published = seed_layered_rows(),
          .expect_shape = layered_expect_shape(),
          // The models: the double state (5·2 components, 2 bedrock layers, types, surface,
          // vegetation: ~112 B), its snapshot each step and its start copy, 8 outflows (64 B), the
          // float run's half of all that, the pictures' grids: under 700 B a cell; 1000 kept. With
          // water, the water's state (14 values: 112 B in double, 56 in float, on the GPU twice
          // over), the flow's copies of it and its fractions (~150 B), impact erosion's pipe loads
          // (20 values: 160 B), the material masks' grids (8 × 8 B), the diffusion's shares and copy
          // (4 + 7 values: 88 B): about 800 B more; 1900 kept.
          // The runner: ref<double>'s and ref<float>'s states at the 8 checkpoints and the end, 16
          // doubles a cell dry, 30 wet (layered_fields), 2·9·8 B each: 2304 B dry, 4320 B wet.
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const bool wet = resolved.value("initial_water", 0.0) > 0.0 || resolved.value("rain_rate", 0.0) > 0.0 ||
                             resolved.value("river", false);
            return memory_for(static_cast<double>(input.heights.size()), "cells", wet ? 1900 + 4320 : 1000 + 2304);
          }};
}

}  // namespace gt
