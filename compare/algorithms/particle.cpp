// The driver's view of seed 000's particle (droplet) erosion: parameters to constants, the three
// versions (ref<double> in sequential ordering, the truth; ref<float> and the GPU in the case's
// ordering), the droplet ledger, the parity each ordering can promise, and the pictures.
//
// What each ordering is checked by (core/params/particle.hpp explains the orderings):
//   ledger.closure.{cpu,cpu_float}     the droplet ledger of reference/erosion/particle.hpp: terrain
//                                      after + sediment the droplets took away + deposits lost outside
//                                      - erosion credited outside - clamp - apply rounding = terrain
//                                      before, relative to Σ|before|
//   ledger.quanta.cpu_float            batch: the same identity in integer quanta, exactly 0
//   parity.shadow.*.gpu_vs_float       disjoint, batch: the GPU loaded with ref<float>'s state at up
//                                      to 8 checkpoints, stepped one iteration beside it
//   parity.cells_differing.gpu_vs_float  batch: the whole run, bit for bit
//   determinism.gpu                    disjoint, batch: two GPU runs, bit for bit
//   race.*                             race: the GPU against the sequential ref<float> over repeated
//                                      runs, reported, not bounded (no error model gives a race's
//                                      distance before the run), and by spacing
//   batch.*_vs_sequential              batch: how far the batch result lands from the sequential truth
//   spec.droplet.*                     a case's hand-derived trajectory of one droplet
#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/json_keys.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "core/sum.hpp"
#include "gpu/erosion/particle.hpp"
#include "gpu/timing.hpp"
#include "reference/erosion/particle.hpp"

namespace gt {
namespace {

using reference::DropletLedger;
using reference::ParticleRun;

// Shadow steps: up to 8 checkpoints spread over the run, one iteration from each.
constexpr int shadow_checkpoints = 8;
// Race mode: at least this many GPU runs against the one sequential truth (issue 12).
constexpr int race_runs = 5;
// Race mode: the spacings whose distance from the truth the case measures (one iteration each).
constexpr int race_spacings[] = {16, 8, 4, 2, 1};

struct ParticleScenario {
  Heightmap input;  // as the twins see it (normalised unless the case says otherwise)
  ParticleConstants constants;
  std::vector<std::string> notes;
};

ParticleScenario make_scenario(const nlohmann::json& resolved, const Heightmap& given) {
  if (given.size() == 0) throw InputError("erosion.particle erodes a heightmap: the case needs an input");
  check_finite(given, "erosion.particle input");
  check_fits_float(given, "erosion.particle input");
  ParticleScenario scenario;
  const bool normalised = resolved.at("normalised").get<bool>();
  scenario.input = normalised ? normalise_heights(given) : given;
  scenario.constants = particle_constants(resolved, scenario.input);
  const auto& c = scenario.constants;
  if (normalised) {
    const auto [low, high] = valid_range(given);
    scenario.notes.push_back(fmt::format(
        "heights normalised to [0, 1] as seed 000 does ((h - {:.6g})/{:.6g}); the kernel works in texels, so the "
        "cell size does not enter",
        low, high - low));
  }
  if (given.has_mask()) {
    scenario.notes.push_back("no-data cells behave as outside the grid: they read 0 and writes to them are lost "
                             "(Hydra's empty regions); the ledger counts what crosses them");
  }
  scenario.notes.push_back(fmt::format(
      "ordering {}: {} droplets per pass, {} passes per iteration, lifetime {}; batch quantum {:.6g}",
      droplet_ordering_name(c.ordering),
      static_cast<long long>((given.width + c.spacing - 1) / c.spacing) * ((given.height + c.spacing - 1) / c.spacing),
      c.spacing * c.spacing, c.lifetime, c.quantum));
  for (auto& warning : particle_warnings(c)) scenario.notes.push_back(std::move(warning));
  return scenario;
}

// The ordering the references use for the case: the sequential truth unless batch.
DropletOrdering reference_ordering(const ParticleConstants& c) {
  return c.ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race;
}

void add_ledgers(DropletLedger& total, const DropletLedger& part) {
  total.eroded += part.eroded;
  total.deposited += part.deposited;
  total.eroded_outside += part.eroded_outside;
  total.deposited_outside += part.deposited_outside;
  total.clamp_created += part.clamp_created;
  total.sediment_at_end += part.sediment_at_end;
  total.sediment_left += part.sediment_left;
  total.apply_rounding += part.apply_rounding;
  total.droplets += part.droplets;
  total.droplets_left += part.droplets_left;
  total.steps += part.steps;
  total.eroded_quanta += part.eroded_quanta;
  total.deposited_quanta += part.deposited_quanta;
  total.eroded_outside_quanta += part.eroded_outside_quanta;
  total.deposited_outside_quanta += part.deposited_outside_quanta;
  total.clamp_created_quanta += part.clamp_created_quanta;
  total.sediment_end_quanta += part.sediment_end_quanta;
  total.applied_quanta += part.applied_quanta;
  total.largest_cell_delta_quanta = std::max(total.largest_cell_delta_quanta, part.largest_cell_delta_quanta);
}

template <class Real>
double terrain_sum(const Grid<Real>& heights) {
  CompensatedSum sum;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (heights.is_valid(i)) sum.add(static_cast<double>(heights.values[i]));
  }
  return sum.value();
}

// The ledger's residual: what is left of Σ after + taken away - created - Σ before.
template <class Real>
double ledger_residual(const Grid<Real>& before, const Grid<Real>& after, const DropletLedger& l) {
  CompensatedSum sum;
  for (const double term : {terrain_sum(after), l.sediment_at_end, l.sediment_left, l.deposited_outside,
                            -terrain_sum(before), -l.eroded_outside, -l.clamp_created, -l.apply_rounding}) {
    sum.add(term);
  }
  return sum.value();
}

// The ledger's closure checks of one reference run.
template <class Real>
void add_ledger_checks(const ParticleScenario& scenario, const Grid<Real>& before, const ParticleRun<Real>& run,
                       const std::string& backend, CaseResult& result) {
  const DropletLedger& l = run.ledger;
  const FieldTotals totals = field_totals(before);
  const double scale = std::max(totals.sum_abs, 1e-300);
  const double residual = std::abs(ledger_residual(before, run.heights, l)) / scale;
  const bool is_float = sizeof(Real) == sizeof(float);
  const bool batch = is_float && scenario.constants.ordering == DropletOrdering::batch;
  if (!is_float || batch) {
    // Double: each event rounds once in double (≤ u of its amount, amounts ≤ the height range) and the
    // ledger's sums are compensated; 1e-12 of Σ|before| leaves room for 10⁴ events per cell at u.
    // Batch float: the terrain changes by integer quanta, exactly counted, and the rounding of
    // heights + delta is measured per cell in double: only the double sums remain.
    result.checks.push_back(bounded_check(
        "ledger.closure." + backend, residual, 1e-12, std::nullopt,
        "|Σ after + sediment taken away + deposited outside - eroded outside - clamp - apply rounding - Σ before| "
        "/ Σ|before|; double roundings only"));
  } else {
    // Float, sequential: every stored height rounds once (≤ u·M, M the largest |height|, which
    // erosion bounded by the lowest neighbour, deposition by the highest and the clamp at 0 never
    // exceed) and so does every update of the carried sediment: at most 4 corner stores + 1 deposit
    // + 2 sediment updates per droplet step. Worst case all add up; strict: a random walk.
    const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high));
    const double roundings = 7.0 * static_cast<double>(l.steps);
    const double per_rounding = unit_roundoff_float * magnitude / scale;
    result.checks.push_back(bounded_check(
        "ledger.closure." + backend, residual, 6.0 / std::sqrt(3.0) * std::sqrt(roundings) * per_rounding,
        roundings * per_rounding,
        fmt::format("as ledger.closure.cpu, in float: {} roundings of at most u·{:.3g} (7 per droplet step), "
                    "random walk (strict) and worst case (loose)",
                    roundings, magnitude)));
  }
  if (batch) {
    const long long quanta = l.applied_quanta + l.sediment_end_quanta + l.deposited_outside_quanta -
                             l.eroded_outside_quanta - l.clamp_created_quanta;
    result.checks.push_back(bounded_check(
        "ledger.quanta." + backend, static_cast<double>(std::llabs(quanta)), 0.0, std::nullopt,
        "batch ordering in integer quanta: terrain change + sediment taken away + deposited outside - eroded "
        "outside - clamp = 0 exactly"));
    result.checks.push_back(informative_check(
        "batch.largest_cell_delta_quanta", static_cast<double>(l.largest_cell_delta_quanta),
        "the largest change of one cell in one pass, in quanta; the GPU's counters hold 2^31 - 1"));
  }
}

void add_ledger_notes(const DropletLedger& l, CaseResult& result) {
  result.notes.push_back(fmt::format(
      "droplet ledger (ref<double>): {} droplets, {} steps, {} left across x or y <= 0; eroded {:.6g} (what the stores "
      "removed: negative where the clamp raised a texel), deposited "
      "{:.6g}; taken away {:.6g} at the end of lives and {:.6g} by droplets leaving; created {:.6g} by erosion "
      "outside and {:.6g} by the clamp at 0; lost {:.6g} in deposits outside",
      l.droplets, l.steps, l.droplets_left, l.eroded, l.deposited, l.sediment_at_end, l.sediment_left,
      l.eroded_outside, l.clamp_created, l.deposited_outside));
}

// ref<float> one iteration at a time, keeping the states the shadow steps start from.
struct FloatRun {
  ParticleRun<float> run;
  std::vector<int> checkpoints;            // iterations after which a shadow step starts
  std::vector<Grid<float>> states;         // the state at each checkpoint
  std::vector<Grid<float>> states_after;   // and one iteration later
};

std::vector<int> shadow_starts(int iterations) {
  std::vector<int> starts;
  const int count = std::min(iterations, shadow_checkpoints);
  for (int k = 0; k < count; ++k) starts.push_back(static_cast<int>(static_cast<long long>(k) * iterations / count));
  return starts;
}

FloatRun run_float(const ParticleScenario& scenario) {
  const auto& c = scenario.constants;
  FloatRun out;
  out.checkpoints = shadow_starts(c.iterations);
  Grid<float> state = scenario.input.cast<float>();
  out.run.heights = state;
  std::size_t next = 0;
  for (int iteration = 0; iteration < c.iterations; ++iteration) {
    const bool checkpoint = next < out.checkpoints.size() && out.checkpoints[next] == iteration;
    if (checkpoint) out.states.push_back(state);
    auto step = reference::particle_erosion(state, c, 1, reference_ordering(c));
    add_ledgers(out.run.ledger, step.ledger);
    state = std::move(step.heights);
    if (checkpoint) {
      out.states_after.push_back(state);
      ++next;
    }
  }
  out.run.heights = std::move(state);
  return out;
}

// GPU vs ref<float> from shared states: batch bit for bit; disjoint within the model of the same
// float operations (a cell is touched by one droplet per pass, at most 5 times a step).
void add_shadow_parity(const ParticleScenario& scenario, const FloatRun& float_run, gpu::ParticleErosion& gpu,
                       CaseResult& result) {
  const auto& c = scenario.constants;
  double worst_abs = 0.0;
  std::size_t worst_cells = 0;
  for (std::size_t k = 0; k < float_run.states.size(); ++k) {
    gpu.load(float_run.states[k]);
    gpu.step(1);
    const FieldDifference difference = field_difference(float_run.states_after[k], gpu.result());
    worst_abs = std::max(worst_abs, std::isnan(difference.max_abs) ? INFINITY : difference.max_abs);
    worst_cells = std::max(worst_cells, difference.differing_bits);
  }
  const FieldTotals totals = field_totals(scenario.input);
  const double range = std::max(totals.high - totals.low, 1e-300);
  const std::string where = fmt::format("{} checkpoints, one iteration each", float_run.states.size());
  if (c.ordering == DropletOrdering::batch) {
    result.checks.push_back(bounded_check("parity.shadow.cells_differing.gpu_vs_float", double(worst_cells), 0.0,
                                          std::nullopt,
                                          "batch ordering is order-independent integer arithmetic on one frozen "
                                          "state: every bit equal; " + where));
    return;
  }
  const double additions = 5.0 * c.lifetime * c.spacing * c.spacing;
  const Bounds bounds = parity_bounds_same_arithmetic(additions, std::max(std::abs(totals.low), std::abs(totals.high)) / range);
  result.checks.push_back(bounded_check("parity.shadow.max_abs.gpu_vs_float", worst_abs / range, bounds.strict,
                                        bounds.loose,
                                        fmt::format("{}; {} additions per cell and iteration (5 per step of the one "
                                                    "droplet per pass that reaches it); {}",
                                                    where, additions, bounds.model)));
  result.checks.push_back(informative_check("parity.shadow.cells_differing.gpu_vs_float", double(worst_cells),
                                            "cells differing in any bit (0 where division and sqrt round correctly)"));
}

// Erosion and deposition of a run: after - before, in double.
template <class Real>
Grid<double> height_change(const Heightmap& before, const Grid<Real>& after) {
  Grid<double> change = before;
  for (std::size_t i = 0; i < change.size(); ++i) change.values[i] = static_cast<double>(after.values[i]) - before.values[i];
  return change;
}

double correlation(const Grid<double>& a, const Grid<double>& b) {
  double mean_a = 0, mean_b = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a.is_valid(i)) continue;
    mean_a += a.values[i];
    mean_b += b.values[i];
    ++n;
  }
  if (n == 0) return std::nan("");
  mean_a /= double(n);
  mean_b /= double(n);
  double ab = 0, aa = 0, bb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a.is_valid(i)) continue;
    ab += (a.values[i] - mean_a) * (b.values[i] - mean_b);
    aa += (a.values[i] - mean_a) * (a.values[i] - mean_a);
    bb += (b.values[i] - mean_b) * (b.values[i] - mean_b);
  }
  return aa > 0 && bb > 0 ? ab / std::sqrt(aa * bb) : std::nan("");
}

double absolute_total(const Grid<double>& field) {
  CompensatedSum sum;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field.is_valid(i)) sum.add(std::abs(field.values[i]));
  }
  return sum.value();
}

// How far a result's erosion lands from the truth's: rms of the difference of the two change maps
// over the rms of the truth's change.
double relative_rms(const Grid<double>& truth_change, const Grid<double>& change) {
  const FieldDifference difference = field_difference(truth_change, change);
  const FieldTotals totals = field_totals(truth_change);
  const double truth_rms = totals.cells > 0 ? std::sqrt(totals.sum_squares / double(totals.cells)) : 0.0;
  return truth_rms > 0 ? difference.rms / truth_rms : std::nan("");
}

struct Spread {
  double low = INFINITY, high = -INFINITY, mean = 0.0;
  void add(double value, int count) {
    low = std::min(low, value);
    high = std::max(high, value);
    mean += value / count;
  }
};

// Race ordering: GPU runs against the sequential ref<float>, reported over the runs; the distance
// of one iteration from the truth at each spacing, plotted.
void add_race_statistics(const ParticleScenario& scenario, const FloatRun& float_run, const RunOptions& options,
                         CaseResult& result) {
  const auto& c = scenario.constants;
  const Grid<double> truth_change = height_change(scenario.input, float_run.run.heights);
  const double truth_moved = absolute_total(truth_change);
  Spread correlation_spread, rms_spread, moved_spread;
  const int runs = std::max(race_runs, options.gpu_reps);
  gpu::ParticleErosion gpu(scenario.input.width, scenario.input.height, c);
  for (int run = 0; run < runs; ++run) {
    gpu.load(scenario.input.cast<float>());
    gpu.run();
    const Grid<double> change = height_change(scenario.input, gpu.result());
    correlation_spread.add(correlation(truth_change, change), runs);
    rms_spread.add(relative_rms(truth_change, change), runs);
    moved_spread.add(truth_moved > 0 ? absolute_total(change) / truth_moved : std::nan(""), runs);
  }
  const auto spread_text = [&](const Spread& s) {
    return fmt::format("over {} GPU runs: mean {:.4g}, from {:.4g} to {:.4g}", runs, s.mean, s.low, s.high);
  };
  result.checks.push_back(informative_check(
      "race.erosion_correlation.gpu_vs_float", correlation_spread.low,
      "lowest correlation of the GPU's height change with the sequential ref<float>'s (racing droplets overwrite "
      "each other's changes), " + spread_text(correlation_spread)));
  result.checks.push_back(informative_check(
      "race.relative_rms.gpu_vs_float", rms_spread.high,
      "largest rms of (GPU change - sequential change) over the rms of the sequential change, " +
          spread_text(rms_spread)));
  result.checks.push_back(informative_check(
      "race.material_moved_ratio.gpu_vs_float", moved_spread.mean,
      "Σ|change| of the GPU over that of the sequential ref<float>, " + spread_text(moved_spread)));

  Series distance{"GPU race vs sequential ref<float>", {}, {}, false, ""};
  for (const int spacing : race_spacings) {
    ParticleConstants at_spacing = c;
    at_spacing.spacing = spacing;
    const auto sequential = reference::particle_erosion(scenario.input.cast<float>(), at_spacing, 1,
                                                        DropletOrdering::race);
    gpu::ParticleErosion raced(scenario.input.width, scenario.input.height, at_spacing);
    raced.load(scenario.input.cast<float>());
    raced.step(1);
    const double value = relative_rms(height_change(scenario.input, sequential.heights),
                                      height_change(scenario.input, raced.result()));
    result.checks.push_back(informative_check(
        fmt::format("race.relative_rms.spacing_{}.gpu_vs_float", spacing), value,
        fmt::format("one iteration at spacing {}: rms distance of the race from the sequential truth over the "
                    "truth's rms change",
                    spacing)));
    distance.x.push_back(spacing);
    distance.y.push_back(value);
  }
  attach_plot({SeriesPlot{"race distance by spacing, one iteration", "spacing (texels)",
                          "rms(GPU - sequential) / rms(sequential change)", true, false, {distance}, {}}},
              options.report_dir, "race_by_spacing.png",
              "how far racing droplets land from the sequential truth as spacing shrinks", result);
}

// Batch ordering: how far its result lands from the sequential truth (ref<double>).
void add_batch_distance(const ParticleScenario& scenario, const Grid<double>& truth, const Grid<float>& batch,
                        CaseResult& result) {
  const Grid<double> truth_change = height_change(scenario.input, truth);
  const Grid<double> batch_change = height_change(scenario.input, batch);
  result.checks.push_back(informative_check(
      "batch.relative_rms_vs_sequential", relative_rms(truth_change, batch_change),
      "rms of (batch ref<float> change - sequential ref<double> change) over the sequential change's rms: what "
      "reading a frozen state costs against droplets that see their predecessors"));
  result.checks.push_back(informative_check("batch.erosion_correlation_vs_sequential",
                                            correlation(truth_change, batch_change),
                                            "correlation of the batch change with the sequential one"));
}

void add_gpu_checks(const ParticleScenario& scenario, const FloatRun& float_run, const RunOptions& options,
                    CaseResult& result, std::optional<Grid<float>>& gpu_heights) {
  const auto& c = scenario.constants;
  gpu::ParticleErosion gpu(scenario.input.width, scenario.input.height, c);
  const Grid<float> input = scenario.input.cast<float>();
  std::vector<double> times;
  for (int rep = 0; rep < std::max(1, options.gpu_reps); ++rep) {
    gpu.load(input);  // the upload is not timed
    times.push_back(gpu_wall_ms([&] { gpu.run(); }));
  }
  result.timings.gpu_ms = median(times);
  result.timings.gpu_reps = static_cast<int>(times.size());
  gpu.load(input);
  gpu.run();
  gpu_heights = gpu.result();
  if (c.ordering == DropletOrdering::race) {
    add_race_statistics(scenario, float_run, options, result);
    return;
  }
  gpu.load(input);
  gpu.run();
  result.checks.push_back(bounded_check("determinism.gpu", double(field_difference(*gpu_heights, gpu.result()).differing_bits),
                                        0.0, std::nullopt,
                                        "cells differing in any bit between two GPU runs (no droplets share a "
                                        "texel, or their changes add as integers)"));
  add_shadow_parity(scenario, float_run, gpu, result);
  const FieldDifference whole = field_difference(float_run.run.heights, *gpu_heights);
  if (c.ordering == DropletOrdering::batch) {
    result.checks.push_back(bounded_check("parity.cells_differing.gpu_vs_float", double(whole.differing_bits), 0.0,
                                          std::nullopt, "the whole run, GPU against ref<float> in batch ordering: "
                                                        "every bit equal"));
  } else {
    result.checks.push_back(informative_check("parity.cells_differing.gpu_vs_float", double(whole.differing_bits),
                                              "the whole run against the sequential ref<float>: droplets never meet, "
                                              "so only rounding can differ"));
  }
}

// A hand-derived trajectory in the case: {"droplet": {"start": [x, y], "positions": [[x, y], ...],
// "sediment": s, "cells": [[x, y, h], ...], "tolerance": t}} on the case's input, ref<double>.
void add_droplet_spec(const ParticleScenario& scenario, const nlohmann::json& expect, CaseResult& result) {
  if (!expect.is_object() || !expect.contains("droplet")) return;
  const auto& spec = expect["droplet"];
  Heightmap heights = scenario.input;
  const auto path = reference::run_one_droplet(heights, scenario.constants, spec.at("start")[0].get<int>(),
                                               spec.at("start")[1].get<int>());
  const double tolerance = spec.at("tolerance");
  const auto& positions = spec.at("positions");
  double position_error = positions.size() == path.positions.size() ? 0.0 : INFINITY;
  for (std::size_t k = 0; k < std::min(positions.size(), path.positions.size()); ++k) {
    position_error = std::max({position_error, std::abs(path.positions[k].first - positions[k][0].get<double>()),
                               std::abs(path.positions[k].second - positions[k][1].get<double>())});
  }
  double cell_error = 0.0;
  for (const auto& cell : spec.at("cells")) {
    cell_error = std::max(cell_error, std::abs(heights.at(cell[0], cell[1]) - cell[2].get<double>()));
  }
  const std::string why = fmt::format("tolerance {:g}: the hand derivation's decimals against double roundings", tolerance);
  result.checks.push_back(bounded_check("spec.droplet.positions.cpu", position_error, tolerance, std::nullopt,
                                        "largest coordinate error over the droplet's positions (count must match); " + why));
  result.checks.push_back(bounded_check("spec.droplet.sediment.cpu",
                                        std::abs(path.sediment - spec.at("sediment").get<double>()), tolerance,
                                        std::nullopt, "sediment carried at the end of its life; " + why));
  result.checks.push_back(bounded_check("spec.droplet.cells.cpu", cell_error, tolerance, std::nullopt,
                                        "heights after its life at the listed texels; " + why));
}

// The 99th percentile of |b - a| over cells valid in both: the colour scale of a change picture,
// so that a few cells of extreme change (a crater's rim) do not wash out the rest.
double robust_scale(const Grid<double>& a, const Grid<double>& b) {
  std::vector<double> magnitudes;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a.is_valid(i) && b.is_valid(i) && b.values[i] != a.values[i]) magnitudes.push_back(std::abs(b.values[i] - a.values[i]));
  }
  if (magnitudes.empty()) return 0.0;
  const auto at = magnitudes.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(magnitudes.size() - 1));
  std::nth_element(magnitudes.begin(), at, magnitudes.end());
  return *at;
}

void write_pictures(const ParticleScenario& scenario, const ParticleRun<double>& truth,
                    const std::optional<Grid<float>>& gpu_heights, const Grid<float>& float_heights,
                    const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  const auto add = [&](const std::string& file, const std::string& caption) {
    result.artifacts.push_back({result.name + "/" + file, "image", caption});
  };
  const auto& before = scenario.input;
  const FieldTotals totals = field_totals(before);
  const double exaggeration = write_height_image(before, totals.low, totals.high, folder / "before.png");
  add("before.png", "terrain before");
  write_height_image(truth.heights, totals.low, totals.high, folder / "after_cpu.png", exaggeration);
  add("after_cpu.png", "terrain after, ref<double> (sequential droplets)");
  const auto change = write_difference_image(before, truth.heights, folder / "erosion_cpu.png",
                                             robust_scale(before, truth.heights));
  add("erosion_cpu.png", fmt::format("after - before, ref<double>: blue eroded, red deposited, full colour at {:.3g} "
                                     "(99th percentile of |change|; max {:.3g})",
                                     change.scale_used, change.max_abs));
  Grid<double> zero = before;
  std::fill(zero.values.begin(), zero.values.end(), 0.0);
  const auto depth = write_difference_image(zero, truth.eroded_at_droplet, folder / "depth_cpu.png",
                                            robust_scale(zero, truth.eroded_at_droplet));
  add("depth_cpu.png", fmt::format("Hydra's depth map before its contrast: erosion at the droplet's texel, full red "
                                   "at {:.3g} (99th percentile)", depth.scale_used));
  const auto sediment = write_difference_image(zero, truth.deposited_at_droplet, folder / "sediment_cpu.png",
                                               robust_scale(zero, truth.deposited_at_droplet));
  add("sediment_cpu.png", fmt::format("Hydra's sediment map before its contrast: deposition, full red at {:.3g} "
                                      "(99th percentile)", sediment.scale_used));
  if (scenario.constants.ordering == DropletOrdering::batch) {
    const auto batch = write_difference_image(truth.heights, float_heights.cast<double>(), folder / "batch_vs_sequential.png");
    add("batch_vs_sequential.png", fmt::format("batch ref<float> - sequential ref<double>: max {:.3g}", batch.max_abs));
  }
  if (!gpu_heights) return;
  const auto gpu = write_difference_image(truth.heights, gpu_heights->cast<double>(), folder / "gpu_vs_cpu.png");
  add("gpu_vs_cpu.png", fmt::format("GPU - ref<double>: max {:.3g}", gpu.max_abs));
}

void run_particle_case(const ParticleScenario& scenario, const nlohmann::json& expect, const RunOptions& options,
                       CaseResult& result) {
  const auto& c = scenario.constants;
  result.width = scenario.input.width;
  result.height = scenario.input.height;
  for (const auto& note : scenario.notes) result.notes.push_back(note);
  if (!options.report_dir.empty()) std::filesystem::create_directories(options.report_dir / result.name);

  if (options.progress) options.progress->stage("CPU reference (double, sequential)");
  ParticleRun<double> truth;
  time_cpu(std::max(1, options.cpu_reps), [&] {
    truth = reference::particle_erosion(scenario.input, c, c.iterations, DropletOrdering::race);
  }, result.timings);
  add_ledger_checks(scenario, scenario.input, truth, "cpu", result);
  add_ledger_notes(truth.ledger, result);
  add_droplet_spec(scenario, expect, result);

  if (options.progress) options.progress->stage("CPU reference (float)");
  const FloatRun float_run = run_float(scenario);
  add_ledger_checks(scenario, scenario.input.cast<float>(), float_run.run, "cpu_float", result);
  if (c.ordering == DropletOrdering::batch) add_batch_distance(scenario, truth.heights, float_run.run.heights, result);

  std::optional<Grid<float>> gpu_heights;
  if (options.gpu_available) {
    if (options.progress) options.progress->stage("GPU");
    add_gpu_checks(scenario, float_run, options, result, gpu_heights);
  } else {
    for (const char* name : {"parity.gpu", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
  }
  write_pictures(scenario, truth, gpu_heights, float_run.run.heights, options, result);
  if (options.progress) options.progress->stage("terrain descriptors");
  const Grid<double> float_as_double = float_run.run.heights.cast<double>();
  // Racing droplets are another algorithm than the sequential truth, judged by the race.* figures:
  // their terrain is not held to the twins' descriptor parity.
  const bool gpu_is_twin = gpu_heights && c.ordering != DropletOrdering::race;
  const std::optional<Grid<double>> gpu_as_double =
      gpu_is_twin ? std::optional<Grid<double>>(gpu_heights->cast<double>()) : std::nullopt;
  add_case_descriptors({&scenario.input, &truth.heights, &float_as_double, gpu_as_double ? &*gpu_as_double : nullptr},
                       expect, options, result);
}

PreparedTwin prepare_particle(const nlohmann::json& resolved, const LoadedInput& input) {
  PreparedTwin prepared;
  prepared.run = [scenario = make_scenario(resolved, input.heights)](const nlohmann::json& expect,
                                                                     const RunOptions& options, CaseResult& result) {
    run_particle_case(scenario, expect, options, result);
  };
  return prepared;
}

// Hydra's Table 5.1 (digest 000 §6.2): total time of 50 iterations at spacing 4, lifetime 50.
struct PublishedTiming {
  const char* device;
  int size;
  double ms_for_50_iterations;
};
constexpr PublishedTiming hydra_table_5_1[] = {
    {"NVIDIA RTX 3080 12GB", 128, 3},     {"NVIDIA RTX 3080 12GB", 256, 9},   {"NVIDIA RTX 3080 12GB", 512, 20},
    {"NVIDIA RTX 3080 12GB", 1024, 72},   {"NVIDIA GTX 745 4GB", 128, 38},    {"NVIDIA GTX 745 4GB", 256, 172},
    {"NVIDIA GTX 745 4GB", 512, 804},     {"NVIDIA GTX 745 4GB", 1024, 3575}};
// The thesis measured up to 1024²; the sequential reference takes seconds an iteration there.
constexpr int largest_benchmark_side = 1024;

BenchmarkRow iteration_row(const std::string& backend, int size, int reps, double ms_per_iteration,
                           double steps_per_iteration, const std::string& device, const std::string& what) {
  BenchmarkRow row{.algorithm = "erosion.particle", .backend = backend, .size = size, .iterations = 1, .reps = reps,
                   .median_ms = ms_per_iteration, .device = device};
  row.mcell_iterations_per_s = double(size) * size / (ms_per_iteration * 1e-3) / 1e6;
  row.detail = fmt::format("{}; {:.3g} droplet steps/s", what, steps_per_iteration / (ms_per_iteration * 1e-3));
  return row;
}

// A noisy cone normalised to [0, 1] with Hydra's defaults at spacing 4: one iteration (one droplet
// per texel, 16 passes) per timed run, the median of `reps`; droplet steps from the references'
// ledgers (droplets that leave across x or y <= 0 stop early).
std::vector<BenchmarkRow> benchmark_particle(const BenchmarkOptions& options, bool gpu_available,
                                             const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  for (const int size : options.sizes) {
    if (size > largest_benchmark_side) continue;
    const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                  {"peak", 30.0}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap field = normalise_heights(load_input(input, nullptr, {}).heights);
    const auto resolved = resolve_params("erosion.particle", particle_param_specs(), {{"iterations", 1}});
    const ParticleConstants constants = particle_constants(resolved, field);
    long long steps = 0;
    std::vector<double> cpu_times;
    for (int rep = 0; rep < options.reps; ++rep) {
      cpu_times.push_back(cpu_wall_ms(
          [&] { steps = reference::particle_erosion(field, constants, 1, DropletOrdering::race).ledger.steps; }));
    }
    rows.push_back(iteration_row("cpu", size, options.reps, median(cpu_times), double(steps), environment.cpu,
                                 "ref<double>, sequential droplets"));
    if (!gpu_available) continue;
    const Grid<float> field_float = field.cast<float>();
    for (const DropletOrdering ordering : {DropletOrdering::race, DropletOrdering::batch}) {
      ParticleConstants timed = constants;
      timed.ordering = ordering;
      const auto gpu_steps = reference::particle_erosion(field_float, timed, 1, reference_ordering(timed)).ledger.steps;
      gpu::ParticleErosion gpu(size, size, timed);
      std::vector<double> times;
      for (int rep = 0; rep < options.reps; ++rep) {
        gpu.load(field_float);
        times.push_back(gpu_wall_ms([&] { gpu.run(); }));
      }
      rows.push_back(iteration_row("gpu", size, options.reps, median(times), double(gpu_steps), environment.gl_renderer,
                                   fmt::format("{} droplets, 16 passes{}", droplet_ordering_name(ordering),
                                               ordering == DropletOrdering::batch ? " + 16 applies" : "")));
    }
  }
  for (const auto& published : hydra_table_5_1) {
    if (std::find(options.sizes.begin(), options.sizes.end(), published.size) == options.sizes.end()) continue;
    const double steps = double(published.size) * published.size * 50;  // every droplet its whole life, as quoted
    rows.push_back(iteration_row("published", published.size, 0, published.ms_for_50_iterations / 50.0, steps,
                                 fmt::format("{} (Hydra, thesis Table 5.1)", published.device),
                                 "race droplets (Hydra's fragment shader), total of 50 iterations / 50"));
  }
  return rows;
}

nlohmann::json particle_expect_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape["droplet"] = {{"start", nullptr}, {"positions", nullptr}, {"sediment", nullptr}, {"cells", nullptr},
                      {"tolerance", nullptr}};
  return shape;
}

}  // namespace

Algorithm particle_algorithm() {
  return {.name = "erosion.particle",
          .summary = "droplet water erosion (Hydra's kernel), sequential, racing, disjoint or batch droplets",
          .source = "seed 000 §4.4.1, Algorithms 4-7, eqs. 4.5-4.6, Appendix A (digest 000 §4.4)",
          .params = &particle_param_specs(),
          .prepare = prepare_particle,
          .iterates = false,
          .has_field_twin = false,
          .benchmark = benchmark_particle,
          .expect_shape = particle_expect_shape(),
          // Estimated, not yet measured: the input and ref<double> with its two side maps (5 doubles),
          // ref<float> with up to 16 checkpoint states and the GPU's copies (about 30 floats), the
          // difference and change maps of the checks (6 doubles), the descriptors.
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 300 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
