// Runs a droplet eroder's twins on one case and checks them; see droplet_twin.hpp.
#include "compare/droplet_twin.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "compare/case_descriptors.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/params/thermal.hpp"
#include "core/sum.hpp"
#include "gpu/timing.hpp"

namespace gt {

using reference::DropletLedger;
using reference::DropletRun;

namespace {

// Shadow steps: up to 8 checkpoints spread over the run, one iteration from each.
constexpr int shadow_checkpoints = 8;
// Race mode: at least this many GPU runs against the one sequential truth (issue 12).
constexpr int race_runs = 5;
// Race mode: the spacings whose distance from the truth the case measures (one iteration each).
constexpr int race_spacings[] = {16, 8, 4, 2, 1};

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

// The droplet steps a run can take at most: every droplet it releases (spacing² passes of
// ceil(W/S)·ceil(H/S) droplets per iteration) living its whole lifetime.
double most_droplet_steps(const DropletTwin& twin) {
  const double spacing = twin.setup.spacing;
  const double droplets_per_pass =
      std::ceil(twin.input.width / spacing) * std::ceil(twin.input.height / spacing);
  return double(twin.iterations) * spacing * spacing * droplets_per_pass * double(twin.lifetime);
}

// The ledger's closure checks of one reference run.
template <class Real>
void add_ledger_checks(const DropletTwin& twin, const Grid<Real>& before, const DropletRun<Real>& run,
                       const std::string& backend, CaseResult& result) {
  const DropletLedger& l = run.ledger;
  const FieldTotals totals = field_totals(before);
  const double scale = std::max(totals.sum_abs, 1e-300);
  const double residual = std::abs(ledger_residual(before, run.heights, l)) / scale;
  const bool is_float = sizeof(Real) == sizeof(float);
  const bool batch = is_float && twin.setup.ordering == DropletOrdering::batch;
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
    // Float, sequential: every stored height rounds once (≤ u·M, M the largest |height| of the
    // input, which the eroders' bounds keep the heights within) and so does every update of the
    // carried sediment: at most twin.roundings_per_step of them per droplet step, and at most
    // lifetime steps for each droplet the run releases (known before it runs). Worst case all add
    // up (loose); strict: a random walk.
    const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high));
    const double roundings = twin.roundings_per_step * most_droplet_steps(twin);
    const double per_rounding = unit_roundoff_float * magnitude / scale;
    result.checks.push_back(bounded_check(
        "ledger.closure." + backend, residual, 6.0 / std::sqrt(3.0) * std::sqrt(roundings) * per_rounding,
        roundings * per_rounding,
        fmt::format("as ledger.closure.cpu, in float: {} roundings of at most u·{:.3g} ({} per droplet step), "
                    "random walk (strict) and worst case (loose)",
                    roundings, magnitude, twin.roundings_per_step)));
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
  DropletRun<float> run;
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

FloatRun run_float(const DropletTwin& twin) {
  FloatRun out;
  out.checkpoints = shadow_starts(twin.iterations);
  Grid<float> state = twin.input.cast<float>();
  out.run.heights = state;
  std::size_t next = 0;
  for (int iteration = 0; iteration < twin.iterations; ++iteration) {
    const bool checkpoint = next < out.checkpoints.size() && out.checkpoints[next] == iteration;
    if (checkpoint) out.states.push_back(state);
    auto step = twin.reference_float(state, 1, twin.setup);
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
// float operations (a cell is touched by one droplet per pass, at most writes_per_cell_per_step
// times a step, so at most lifetime·spacing² times an iteration).
void add_shadow_parity(const DropletTwin& twin, const FloatRun& float_run, GpuFieldRunner& gpu,
                       CaseResult& result) {
  double worst_abs = 0.0;
  std::size_t worst_cells = 0;
  for (std::size_t k = 0; k < float_run.states.size(); ++k) {
    gpu.load(float_run.states[k]);
    gpu.step(0, 1);
    const FieldDifference difference = field_difference(float_run.states_after[k], gpu.result());
    worst_abs = std::max(worst_abs, std::isnan(difference.max_abs) ? INFINITY : difference.max_abs);
    worst_cells = std::max(worst_cells, difference.differing_bits);
  }
  const FieldTotals totals = field_totals(twin.input);
  const double range = std::max(totals.high - totals.low, 1e-300);
  const std::string where = fmt::format("{} checkpoints, one iteration each", float_run.states.size());
  if (twin.setup.ordering == DropletOrdering::batch) {
    result.checks.push_back(bounded_check("parity.shadow.cells_differing.gpu_vs_float", double(worst_cells), 0.0,
                                          std::nullopt,
                                          "batch ordering is order-independent integer arithmetic on one frozen "
                                          "state: every bit equal; " + where));
    return;
  }
  const double additions = twin.writes_per_cell_per_step * twin.lifetime * twin.setup.spacing * twin.setup.spacing;
  const Bounds bounds = parity_bounds_same_arithmetic(additions, std::max(std::abs(totals.low), std::abs(totals.high)) / range);
  result.checks.push_back(bounded_check("parity.shadow.max_abs.gpu_vs_float", worst_abs / range, bounds.strict,
                                        bounds.loose,
                                        fmt::format("{}; {} additions per cell and iteration ({} per step of the one "
                                                    "droplet per pass that reaches it); {}",
                                                    where, additions, twin.writes_per_cell_per_step, bounds.model)));
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
void add_race_statistics(const DropletTwin& twin, const FloatRun& float_run, const RunOptions& options,
                         CaseResult& result) {
  const Grid<double> truth_change = height_change(twin.input, float_run.run.heights);
  const double truth_moved = absolute_total(truth_change);
  Spread correlation_spread, rms_spread, moved_spread;
  const int runs = std::max(race_runs, options.gpu_reps);
  GpuFieldRunner gpu = twin.make_gpu(twin.setup);
  for (int run = 0; run < runs; ++run) {
    gpu.load(twin.input.cast<float>());
    gpu.run();
    const Grid<double> change = height_change(twin.input, gpu.result());
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
    const DropletSetup at_spacing{spacing, DropletOrdering::race};
    const auto sequential = twin.reference_float(twin.input.cast<float>(), 1, at_spacing);
    GpuFieldRunner raced = twin.make_gpu(at_spacing);
    raced.load(twin.input.cast<float>());
    raced.step(0, 1);
    const double value = relative_rms(height_change(twin.input, sequential.heights),
                                      height_change(twin.input, raced.result()));
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
void add_batch_distance(const DropletTwin& twin, const Grid<double>& truth, const Grid<float>& batch,
                        CaseResult& result) {
  const Grid<double> truth_change = height_change(twin.input, truth);
  const Grid<double> batch_change = height_change(twin.input, batch);
  result.checks.push_back(informative_check(
      "batch.relative_rms_vs_sequential", relative_rms(truth_change, batch_change),
      "rms of (batch ref<float> change - sequential ref<double> change) over the sequential change's rms: what "
      "reading a frozen state costs against droplets that see their predecessors"));
  result.checks.push_back(informative_check("batch.erosion_correlation_vs_sequential",
                                            correlation(truth_change, batch_change),
                                            "correlation of the batch change with the sequential one"));
}

// The checks add_gpu_checks makes, by name: a CPU-only run has them as `skip`.
std::vector<std::string> gpu_check_names(const DropletTwin& twin) {
  if (twin.setup.ordering == DropletOrdering::race) {
    std::vector<std::string> names = {"race.erosion_correlation.gpu_vs_float", "race.relative_rms.gpu_vs_float",
                                      "race.material_moved_ratio.gpu_vs_float"};
    for (const int spacing : race_spacings) {
      names.push_back(fmt::format("race.relative_rms.spacing_{}.gpu_vs_float", spacing));
    }
    return names;
  }
  std::vector<std::string> names = {"determinism.gpu"};
  if (twin.setup.ordering == DropletOrdering::disjoint) names.emplace_back("parity.shadow.max_abs.gpu_vs_float");
  names.emplace_back("parity.shadow.cells_differing.gpu_vs_float");
  names.emplace_back("parity.cells_differing.gpu_vs_float");
  return names;
}

void add_gpu_checks(const DropletTwin& twin, const FloatRun& float_run, const RunOptions& options,
                    CaseResult& result, std::optional<Grid<float>>& gpu_heights) {
  GpuFieldRunner gpu = twin.make_gpu(twin.setup);
  const Grid<float> input = twin.input.cast<float>();
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
  if (twin.setup.ordering == DropletOrdering::race) {
    add_race_statistics(twin, float_run, options, result);
    return;
  }
  gpu.load(input);
  gpu.run();
  result.checks.push_back(bounded_check("determinism.gpu", double(field_difference(*gpu_heights, gpu.result()).differing_bits),
                                        0.0, std::nullopt,
                                        "cells differing in any bit between two GPU runs (no droplets share a "
                                        "texel, or their changes add as integers)"));
  add_shadow_parity(twin, float_run, gpu, result);
  const FieldDifference whole = field_difference(float_run.run.heights, *gpu_heights);
  if (twin.setup.ordering == DropletOrdering::batch) {
    result.checks.push_back(bounded_check("parity.cells_differing.gpu_vs_float", double(whole.differing_bits), 0.0,
                                          std::nullopt, "the whole run, GPU against ref<float> in batch ordering: "
                                                        "every bit equal"));
  } else {
    result.checks.push_back(informative_check("parity.cells_differing.gpu_vs_float", double(whole.differing_bits),
                                              "the whole run against the sequential ref<float>: droplets never meet, "
                                              "so only rounding can differ"));
  }
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

void write_pictures(const DropletTwin& twin, const DropletRun<double>& truth,
                    const std::optional<Grid<float>>& gpu_heights, const Grid<float>& float_heights,
                    const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  const auto add = [&](const std::string& file, const std::string& caption) {
    result.artifacts.push_back({result.name + "/" + file, "image", caption});
  };
  const auto& before = twin.input;
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
  // With a contrast c, full red at 1/c: the picture is Hydra's min(1, c·amount).
  const auto add_side_map = [&](const Grid<double>& map, double contrast, const std::string& file,
                                const std::string& what) {
    const double scale = contrast > 0.0 ? 1.0 / contrast : robust_scale(zero, map);
    write_difference_image(zero, map, folder / file, scale);
    add(file, contrast > 0.0 ? fmt::format("{} with its contrast {} (full red at {:.3g})", what, contrast, scale)
                             : fmt::format("{}, full red at {:.3g} (99th percentile)", what, scale));
  };
  add_side_map(truth.eroded_at_droplet, twin.erosion_contrast, "depth_cpu.png",
               "Hydra's depth map: erosion at the droplet's texel");
  add_side_map(truth.deposited_at_droplet, twin.deposition_contrast, "sediment_cpu.png",
               "Hydra's sediment map: deposition at the droplet's texel");
  if (twin.setup.ordering == DropletOrdering::batch) {
    const auto batch = write_difference_image(truth.heights, float_heights.cast<double>(), folder / "batch_vs_sequential.png");
    add("batch_vs_sequential.png", fmt::format("batch ref<float> - sequential ref<double>: max {:.3g}", batch.max_abs));
  }
  if (!gpu_heights) return;
  const auto gpu = write_difference_image(truth.heights, gpu_heights->cast<double>(), folder / "gpu_vs_cpu.png");
  add("gpu_vs_cpu.png", fmt::format("GPU - ref<double>: max {:.3g}", gpu.max_abs));
}

// The terrain before and after (ref<double>, ref<float>, GPU) and Hydra's depth and sediment maps
// of the truth, in the input's own units, as field files.
template <class OwnUnits>
void write_droplet_fields(const DropletTwin& twin, const Grid<double>& input, const DropletRun<double>& truth,
                          const Grid<double>& float_heights, const OwnUnits& own_units,
                          const std::optional<Grid<float>>& gpu_heights, const RunOptions& options,
                          CaseResult& result) {
  const std::string unit = input.vertical_unit;
  write_field_files(input, {"input", "terrain", "input", unit, "terrain before"}, options, result);
  write_field_files(own_units(truth.heights), {"cpu", "terrain", "cpu", unit, "terrain after, ref<double> (sequential "
                                                                                "droplets)"},
                    options, result);
  write_field_files(float_heights,
                    {"cpu_float", "terrain", "cpu_float", unit, "terrain after, ref<float> (the case's ordering)"},
                    options, result);
  const auto amounts = [&](Grid<double> map) {  // amounts scale as heights, without the offset
    for (double& amount : map.values) amount *= twin.height_scale;
    map.vertical_unit = unit;
    return map;
  };
  write_field_files(amounts(truth.eroded_at_droplet),
                    {"eroded_at_droplet_cpu", "eroded_at_droplet", "cpu", unit,
                     "what the droplets standing on each texel eroded over the run (Hydra's depth map before its "
                     "contrast), ref<double>"},
                    options, result);
  write_field_files(amounts(truth.deposited_at_droplet),
                    {"deposited_at_droplet_cpu", "deposited_at_droplet", "cpu", unit,
                     "what the droplets standing on each texel deposited over the run (Hydra's sediment map before "
                     "its contrast), ref<double>"},
                    options, result);
  if (!gpu_heights) return;
  write_field_files(own_units(gpu_heights->cast<double>()), {"gpu", "terrain", "gpu", unit, "terrain after, GPU"},
                    options, result);
}

BenchmarkRow iteration_row(const std::string& algorithm, const std::string& backend, int size, int reps,
                           double ms_per_iteration, double steps_per_iteration, const std::string& device,
                           const std::string& what) {
  BenchmarkRow row{.algorithm = algorithm, .backend = backend, .size = size, .iterations = 1, .reps = reps,
                   .median_ms = ms_per_iteration, .device = device};
  row.mcell_iterations_per_s = double(size) * size / (ms_per_iteration * 1e-3) / 1e6;
  row.detail = fmt::format("{}; {:.3g} droplet steps/s", what, steps_per_iteration / (ms_per_iteration * 1e-3));
  return row;
}

}  // namespace

Grid<float> run_droplet_case(const DropletTwin& twin, const nlohmann::json& expect, const RunOptions& options,
                             CaseResult& result) {
  result.width = twin.input.width;
  result.height = twin.input.height;
  for (const auto& note : twin.notes) result.notes.push_back(note);
  if (!options.report_dir.empty()) std::filesystem::create_directories(options.report_dir / result.name);

  if (options.progress) options.progress->stage("CPU reference (double, sequential)");
  DropletRun<double> truth;
  const DropletSetup sequential{twin.setup.spacing, DropletOrdering::race};
  time_cpu(std::max(1, options.cpu_reps), [&] { truth = twin.reference_double(twin.input, twin.iterations, sequential); },
           result.timings);
  add_ledger_checks(twin, twin.input, truth, "cpu", result);
  add_ledger_notes(truth.ledger, result);

  if (options.progress) options.progress->stage("CPU reference (float)");
  const FloatRun float_run = run_float(twin);
  add_ledger_checks(twin, twin.input.cast<float>(), float_run.run, "cpu_float", result);
  if (twin.setup.ordering == DropletOrdering::batch) add_batch_distance(twin, truth.heights, float_run.run.heights, result);

  std::optional<Grid<float>> gpu_heights;
  if (options.gpu_available) {
    if (options.progress) options.progress->stage("GPU");
    add_gpu_checks(twin, float_run, options, result, gpu_heights);
  } else {
    for (const auto& name : gpu_check_names(twin)) result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
  }
  write_pictures(twin, truth, gpu_heights, float_run.run.heights, options, result);
  if (options.progress) options.progress->stage("terrain descriptors");
  const auto own_units = [&](Grid<double> heights) {
    for (double& height : heights.values) height = height * twin.height_scale + twin.height_offset;
    if (!twin.height_unit.empty()) heights.vertical_unit = twin.height_unit;
    return heights;
  };
  const Grid<double> input = own_units(twin.input);
  const Grid<double> truth_heights = own_units(truth.heights);
  const Grid<double> float_as_double = own_units(float_run.run.heights.cast<double>());
  write_droplet_fields(twin, input, truth, float_as_double, own_units, gpu_heights, options, result);
  // The GPU's terrain is judged against ref<float> (bit for bit, or by the race figures); against
  // ref<double> a droplet's discrete path parts at the first rounding that moves its texel, so the
  // descriptors' GPU-to-double parity would grade that chaos: the descriptors show the references.
  add_case_descriptors({&input, &truth_heights, &float_as_double, nullptr},
                       expect, options, result);
  return float_run.run.heights;
}

void set_droplet_input(DropletTwin& twin, const Heightmap& given, bool normalise) {
  if (!normalise) {
    twin.input = given;
    return;
  }
  twin.input = normalise_heights(given);
  const auto [low, high] = valid_range(given);
  twin.height_scale = high > low ? high - low : 1.0;
  twin.height_offset = low > high ? 0.0 : low;
  twin.height_unit = given.vertical_unit;
  twin.notes.push_back(fmt::format(
      "heights normalised to [0, 1] as seed 000 does ((h - {:.6g})/{:.6g}); the kernel works in texels, so the cell "
      "size does not enter; the terrain descriptors are measured in the input's own heights",
      twin.height_offset, twin.height_scale));
}

std::vector<BenchmarkRow> droplet_benchmark_rows(const DropletTwin& twin, int reps, bool gpu_available,
                                                 const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  const int size = twin.input.width;
  long long steps = 0;
  std::vector<double> cpu_times;
  const DropletSetup sequential{twin.setup.spacing, DropletOrdering::race};
  for (int rep = 0; rep < reps; ++rep) {
    cpu_times.push_back(cpu_wall_ms([&] { steps = twin.reference_double(twin.input, 1, sequential).ledger.steps; }));
  }
  rows.push_back(iteration_row(twin.algorithm, "cpu", size, reps, median(cpu_times), double(steps), environment.cpu,
                               "ref<double>, sequential droplets"));
  if (!gpu_available) return rows;
  const Grid<float> input = twin.input.cast<float>();
  const int passes = twin.setup.spacing * twin.setup.spacing;
  for (const DropletOrdering ordering : {DropletOrdering::race, DropletOrdering::batch}) {
    const DropletSetup setup{twin.setup.spacing, ordering};
    const auto gpu_steps = twin.reference_float(input, 1, setup).ledger.steps;
    GpuFieldRunner gpu = twin.make_gpu(setup);
    std::vector<double> times;
    for (int rep = 0; rep < reps; ++rep) {
      gpu.load(input);  // the upload is not timed
      times.push_back(gpu_wall_ms([&] { gpu.step(0, 1); }));
    }
    rows.push_back(iteration_row(twin.algorithm, "gpu", size, reps, median(times), double(gpu_steps),
                                 environment.gl_renderer,
                                 ordering == DropletOrdering::batch
                                     ? fmt::format("batch droplets, {} passes + {} applies", passes, passes)
                                     : fmt::format("race droplets, {} passes", passes)));
  }
  return rows;
}

}  // namespace gt
