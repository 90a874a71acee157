// Runs the three versions of a field algorithm and measures how they agree; see field_twin.hpp.
#include "compare/field_twin.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/case_descriptors.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "core/errors.hpp"
#include "core/io/heightmap_io.hpp"
#include "compare/timing.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

// Shadow steps: 8 checkpoints spread evenly over the run (every iteration of a shorter run), and
// from each one iteration and then up to 4.
constexpr int shadow_checkpoints = 8;
constexpr int shadow_iterations = 4;

void report_stage(const RunOptions& options, const std::string& what) {
  if (options.progress != nullptr) options.progress->stage(what);
}

// The iterations the shadow steps start from: k·N/8 for k = 0..7, 0..N-1 when N < 8, and 0 alone
// for a run of no iterations (whose shadow step is then the GPU's load and download).
std::vector<int> shadow_starts(int iterations) {
  std::vector<int> starts;
  const int count = std::clamp(iterations, 1, shadow_checkpoints);
  for (int k = 0; k < count; ++k) {
    starts.push_back(static_cast<int>(static_cast<long long>(k) * iterations / count));
  }
  return starts;
}

// The shadow step's first part (one iteration, none when the run has none) and its whole length.
int shadow_first(int iterations, int start) { return std::min(1, iterations - start); }
int shadow_length(int iterations, int start) { return std::min(shadow_iterations, iterations - start); }

// The iterations after which a run's state is kept: the shadow starts, then the end of the run.
std::vector<int> path_marks(int iterations) {
  std::vector<int> marks = shadow_starts(iterations);
  if (marks.back() != iterations) marks.push_back(iterations);
  return marks;
}

template <class Real>
using Stepper = std::function<Grid<Real>(const Grid<Real>&, int, int)>;

// The states after marks[i] iterations of one run from `input`.
template <class Real>
std::vector<Grid<Real>> step_through(const Stepper<Real>& step, const Grid<Real>& input, const std::vector<int>& marks) {
  std::vector<Grid<Real>> states;
  Grid<Real> state = input;
  int done = 0;
  for (const int mark : marks) {
    state = step(state, done, mark - done);
    done = mark;
    states.push_back(state);
  }
  return states;
}

// From one checkpoint's state: after shadow_first (one) and after shadow_length iterations.
struct ShadowStep {
  Grid<float> one;
  Grid<float> multi;
};

// One twin's shadow step from one checkpoint: `advance(from, count)` steps the state the twin was
// given by `count` iterations numbered from `from` and returns it.
ShadowStep shadow_step(int iterations, int start, const std::function<Grid<float>(int, int)>& advance) {
  const int first = shadow_first(iterations, start);
  ShadowStep step;
  step.one = advance(start, first);
  step.multi = advance(start + first, shadow_length(iterations, start) - first);
  return step;
}

struct ReferenceRuns {
  Grid<double> cpu;                        // ref<double>, whole run
  Grid<float> cpu_float;                   // ref<float>, whole run
  std::vector<Grid<double>> double_path;   // at path_marks (stepping twins)
  std::vector<Grid<float>> float_path;
  std::vector<ShadowStep> shadow;          // ref<float> from its own states at the shadow starts
};

struct GpuOutputs {
  Grid<float> first;                    // whole run; stepped through the path marks when the twin steps
  Grid<float> second;                   // whole run in one go, for determinism
  std::vector<Grid<float>> path;        // at path_marks (stepping twins)
  std::vector<ShadowStep> shadow;       // from ref<float>'s states at the shadow starts
};

std::vector<ShadowStep> reference_shadow(const FieldTwin::Stepping& stepping, const std::vector<Grid<float>>& path) {
  std::vector<ShadowStep> steps;
  const auto starts = shadow_starts(stepping.iterations);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    Grid<float> state = path[k];
    steps.push_back(shadow_step(stepping.iterations, starts[k], [&](int from, int count) {
      state = stepping.reference_float(state, from, count);
      return state;
    }));
  }
  return steps;
}

// The GPU through the run's checkpoints, then from each of ref<float>'s checkpoint states.
void step_gpu(const FieldTwin::Stepping& stepping, GpuFieldRunner& runner, const Grid<float>& input,
              const std::vector<Grid<float>>& float_path, GpuOutputs& outputs) {
  if (!runner.step) throw std::logic_error("the GPU runner of an iterative field twin must offer step()");
  runner.load(input);
  int done = 0;
  for (const int mark : path_marks(stepping.iterations)) {
    runner.step(done, mark - done);
    done = mark;
    outputs.path.push_back(runner.result());
  }
  outputs.first = outputs.path.back();
  const auto starts = shadow_starts(stepping.iterations);
  for (std::size_t k = 0; k < starts.size(); ++k) {
    runner.load(float_path[k]);
    outputs.shadow.push_back(shadow_step(stepping.iterations, starts[k], [&](int from, int count) {
      runner.step(from, count);
      return runner.result();
    }));
  }
}

// First run gives the result (stepped through the checkpoints, with the shadow steps, when the twin
// steps), a second run from the same input in one go checks determinism, then `gpu_reps` timed runs
// of the iterations alone (upload and download excluded).
GpuOutputs run_gpu(const FieldTwin& twin, const Grid<float>& input, const ReferenceRuns& reference,
                   const RunOptions& options, CaseResult& result) {
  report_stage(options, "gpu");
  GpuFieldRunner runner = twin.make_gpu();
  GpuOutputs outputs;
  if (twin.stepping) {
    step_gpu(*twin.stepping, runner, input, reference.float_path, outputs);
  } else {
    runner.load(input);
    runner.run();
    outputs.first = runner.result();
  }
  runner.load(input);
  runner.run();
  outputs.second = runner.result();
  if (options.gpu_reps == 0) return outputs;
  std::vector<double> times;
  for (int rep = 0; rep < options.gpu_reps; ++rep) {
    runner.load(input);
    times.push_back(gpu_wall_ms(runner.run));
  }
  result.timings.gpu_ms = median(times);
  result.timings.gpu_reps = options.gpu_reps;
  return outputs;
}

// ref<double> timed (its first run is the warm-up), ref<float>; a stepping twin's references also
// run once through the checkpoints, and ref<float> takes the shadow steps from its states.
ReferenceRuns run_references(const FieldTwin& twin, const Heightmap& input, const RunOptions& options,
                             CaseResult& result) {
  ReferenceRuns runs;
  report_stage(options, "cpu reference (double)");
  runs.cpu = twin.reference_double(input);  // also the warm-up run
  time_cpu(options.cpu_reps, [&] { runs.cpu = twin.reference_double(input); }, result.timings);
  report_stage(options, "cpu reference (float)");
  const Grid<float> input_float = input.cast<float>();
  if (!twin.stepping) {
    runs.cpu_float = twin.reference_float(input_float);
    return runs;
  }
  const auto& stepping = *twin.stepping;
  const auto marks = path_marks(stepping.iterations);
  runs.float_path = step_through<float>(stepping.reference_float, input_float, marks);
  runs.cpu_float = runs.float_path.back();
  runs.shadow = reference_shadow(stepping, runs.float_path);
  report_stage(options, "cpu reference (double) through the checkpoints");
  runs.double_path = step_through<double>(stepping.reference_double, input, marks);
  return runs;
}

// Roundings of one float height over a run: the input's conversion to float, then every addition.
double float_roundings(const FieldTwin& twin) { return twin.additions_per_cell + 1.0; }

void add_mass_checks(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu, const Grid<float>& cpu_float,
                     const std::optional<Grid<float>>& gpu, const RunOptions& options, CaseResult& result) {
  if (!twin.conserves_mass) return;
  const auto totals = field_totals(input);
  const auto double_bounds = mass_drift_bounds(unit_roundoff_double, twin.additions_per_cell, totals);
  const auto float_bounds = mass_drift_bounds(unit_roundoff_float, float_roundings(twin), totals);
  result.checks.push_back(bounded_check("mass.relative_drift.cpu", relative_mass_drift(input, cpu),
                                        double_bounds.strict, double_bounds.loose, double_bounds.model));
  result.checks.push_back(bounded_check("mass.relative_drift.cpu_float", relative_mass_drift(input, cpu_float),
                                        float_bounds.strict, float_bounds.loose, float_bounds.model));
  if (gpu) {
    result.checks.push_back(bounded_check("mass.relative_drift.gpu", relative_mass_drift(input, *gpu),
                                          float_bounds.strict, float_bounds.loose, float_bounds.model));
  } else {
    result.checks.push_back(skipped_check("mass.relative_drift.gpu", options.gpu_unavailable_reason));
  }
}

// The material the double reference moves in its first iteration from the input, against the
// twin's spec of that iteration (both ½Σ|h1 - h0|). Catches a transfer misapplied in both twins
// (talus, rate, a side of the exchange), which the twins' agreement cannot.
void add_moved_ledger(const FieldTwin::Stepping& stepping, const Heightmap& input, CaseResult& result) {
  if (!stepping.first_iteration_spec || stepping.iterations < 1) return;
  const double moved_spec = moved_material(input, stepping.first_iteration_spec(input));
  const double moved_twin = moved_material(input, stepping.reference_double(input, 0, 1));
  const std::string measured = fmt::format("moved {:.9g} where the spec (host, double) moves {:.9g}", moved_twin, moved_spec);
  if (moved_spec == 0.0) {
    result.checks.push_back(bounded_check("mass.moved_first_iteration.cpu", moved_twin, 0.0, std::nullopt,
                                          measured + "; the spec moves nothing, so the twin must not"));
    return;
  }
  const auto bounds = moved_ledger_bounds(stepping.additions_per_iteration, field_totals(input), moved_spec);
  result.checks.push_back(bounded_check("mass.moved_first_iteration.cpu", std::abs(moved_twin - moved_spec) / moved_spec,
                                        bounds.strict, std::nullopt,
                                        fmt::format("relative to the spec's: {}; {}", measured, bounds.model)));
}

void add_parity_pair(const std::string& what, const FieldDifference& difference, double range, const Bounds& bounds,
                     CaseResult& result) {
  result.checks.push_back(bounded_check("parity.max_abs." + what, difference.max_abs / range, bounds.strict,
                                        bounds.loose, bounds.model));
  result.checks.push_back(
      bounded_check("parity.rms." + what, difference.rms / range, bounds.strict, bounds.loose, bounds.model));
}

std::string exactness(const FieldDifference& difference) {
  return difference.differing_bits == 0 ? "bit-exact; " : fmt::format("{} cells differ; ", difference.differing_bits);
}

// A whole run's distance, reported without a verdict (see field_twin.hpp).
void add_informative_pair(const std::string& what, const FieldDifference& difference, double range, int iterations,
                          CaseResult& result) {
  const std::string detail = fmt::format(
      "{}at the end of the run ({} iterations), relative to the input's height range; informative: over a run "
      "the method amplifies rounding differences by an amount not known before it (verdicts: parity.shadow.*)",
      exactness(difference), iterations);
  result.checks.push_back(informative_check("parity.max_abs." + what, difference.max_abs / range, detail));
  result.checks.push_back(informative_check("parity.rms." + what, difference.rms / range, detail));
}

// NaN (a non-finite cell) wins, so that the check fails.
double worse(double a, double b) { return std::isnan(a) || std::isnan(b) ? std::nan("") : std::max(a, b); }

// GPU vs ref<float>, each stepped from ref<float>'s state at the checkpoints.
void add_shadow_checks(const FieldTwin::Stepping& stepping, const std::vector<ShadowStep>& expected,
                       const std::vector<ShadowStep>& measured, double range, double magnitude, CaseResult& result) {
  const auto starts = shadow_starts(stepping.iterations);
  double worst_one = 0.0, worst_multi = 0.0;
  std::size_t differing_one = 0, differing_multi = 0;
  int first = 0, longest = 0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const auto one = field_difference(expected[k].one, measured[k].one);
    const auto multi = field_difference(expected[k].multi, measured[k].multi);
    worst_one = worse(worst_one, one.max_abs / range);
    worst_multi = worse(worst_multi, multi.max_abs / range);
    differing_one += one.differing_bits;
    differing_multi += multi.differing_bits;
    first = std::max(first, shadow_first(stepping.iterations, starts[k]));
    longest = std::max(longest, shadow_length(stepping.iterations, starts[k]));
  }
  const std::string from = fmt::format("from ref<float>'s state at {} checkpoints (after iterations {})", starts.size(),
                                       fmt::join(starts, ", "));
  const auto bit_exact = [](std::size_t differing) {
    return differing == 0 ? std::string("bit-exact; ") : fmt::format("{} cell-steps differ; ", differing);
  };
  // Values are relative to the height range: a bug that moves under 1 % of it in one iteration must
  // still show, so a bound wider than that cannot tell (inconclusive).
  constexpr double tellable_share_of_range = 0.01;
  const auto one_bounds = parity_bounds_same_arithmetic(stepping.additions_per_iteration * first, magnitude);
  result.checks.push_back(decisive_check(
      "parity.shadow.max_abs.gpu_vs_float", worst_one, one_bounds.strict, one_bounds.loose, 1.0,
      tellable_share_of_range,
      fmt::format("{}max over checkpoints of |gpu - ref<float>| after {} iteration {}; {} ({} additions per cell)",
                  bit_exact(differing_one), first, from, one_bounds.model, stepping.additions_per_iteration * first)));
  const auto multi_bounds = parity_bounds_same_arithmetic(stepping.additions_per_iteration * longest, magnitude);
  result.checks.push_back(decisive_check(
      "parity.shadow.max_abs_multi.gpu_vs_float", worst_multi, multi_bounds.strict, multi_bounds.loose, 1.0,
      tellable_share_of_range,
      fmt::format("{}the same after up to {} iterations; {} ({} additions per cell)", bit_exact(differing_multi),
                  longest, multi_bounds.model, stepping.additions_per_iteration * longest)));
  result.checks.push_back(informative_check(
      "parity.shadow.cells_differing.gpu_vs_float", static_cast<double>(differing_one),
      fmt::format("cells whose bits differ after {} iteration, summed over the checkpoints (0 where division rounds "
                  "correctly)",
                  first)));
}

// exp of the least-squares slope of ln y over x, over the points with y > 0: the factor by which y
// grows per unit of x. Empty with fewer than two such points at different x.
std::optional<double> fitted_growth(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<std::pair<double, double>> points;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (y[i] > 0.0 && std::isfinite(y[i])) points.emplace_back(x[i], std::log(y[i]));
  }
  if (points.size() < 2) return std::nullopt;
  double mean_x = 0.0, mean_y = 0.0;
  for (const auto& [px, py] : points) mean_x += px, mean_y += py;
  mean_x /= static_cast<double>(points.size());
  mean_y /= static_cast<double>(points.size());
  double sxy = 0.0, sxx = 0.0;
  for (const auto& [px, py] : points) sxy += (px - mean_x) * (py - mean_y), sxx += (px - mean_x) * (px - mean_x);
  if (sxx == 0.0) return std::nullopt;
  return std::exp(sxy / sxx);
}

// How fast each float run leaves ref<double>: distances at the checkpoints, a fitted growth per
// iteration (informative) and a plot.
void add_divergence(const FieldTwin::Stepping& stepping, const ReferenceRuns& runs, const std::optional<GpuOutputs>& gpu,
                    double range, const RunOptions& options, CaseResult& result) {
  constexpr double plotted_zero = 1e-18;
  const auto marks = path_marks(stepping.iterations);
  SeriesPlot plot{.title = "Distance from ref<double> along the run",
                  .x_label = "iteration",
                  .y_label = "max |· - ref<double>| / height range (exact zeros at 1e-18)",
                  .log_y = true};
  const auto add_series = [&](const std::string& label, const std::string& backend, const auto& path, bool dashed) {
    Series series{.label = label, .dashed = dashed};
    std::vector<double> distances;
    for (std::size_t i = 0; i < marks.size(); ++i) {
      const double distance = field_difference(runs.double_path[i], path[i]).max_abs / range;
      series.x.push_back(marks[i]);
      series.y.push_back(std::max(distance, plotted_zero));
      distances.push_back(distance);
    }
    if (const auto growth = fitted_growth(series.x, distances)) {
      result.checks.push_back(informative_check(
          "parity.growth_per_iteration." + backend + "_vs_double", *growth,
          fmt::format("factor per iteration of max |{} - ref<double>|, least squares of its log over {} checkpoints "
                      "(iterations {}); informative",
                      label, marks.size(), fmt::join(marks, ", "))));
    }
    plot.series.push_back(std::move(series));
  };
  add_series("ref<float>", "float", runs.float_path, true);
  if (gpu) add_series("GPU", "gpu", gpu->path, false);
  attach_plot({plot}, options.report_dir, "parity.png",
              "distance from ref<double> at the checkpoints: GPU (solid), ref<float> (dashed)", result);
}

void add_determinism_check(const GpuOutputs& gpu, CaseResult& result) {
  const auto repeat = field_difference(gpu.first, gpu.second);
  result.checks.push_back(bounded_check("determinism.gpu", static_cast<double>(repeat.differing_bits), 0.0,
                                        std::nullopt,
                                        "cells whose bits differ between two GPU runs of the same input (the first "
                                        "stepped through the checkpoints when the twin steps, the second in one go)"));
}

void skip_checks(std::initializer_list<const char*> names, const std::string& reason, CaseResult& result) {
  for (const char* name : names) result.checks.push_back(skipped_check(name, reason));
}

// A generator's whole output against the bounds it declares.
void add_generated_parity(const FieldTwin& twin, const ReferenceRuns& runs, const std::optional<GpuOutputs>& gpu,
                          const RunOptions& options, CaseResult& result) {
  add_parity_pair("float_vs_double", field_difference(runs.cpu, runs.cpu_float), 1.0, twin.generated->precision, result);
  if (!gpu) {
    skip_checks({"parity.max_abs.gpu_vs_float", "parity.rms.gpu_vs_float", "parity.max_abs.gpu_vs_double",
                 "parity.rms.gpu_vs_double", "determinism.gpu"},
                options.gpu_unavailable_reason, result);
    return;
  }
  add_parity_pair("gpu_vs_float", field_difference(runs.cpu_float, gpu->first), 1.0, twin.generated->logic, result);
  add_parity_pair("gpu_vs_double", field_difference(runs.cpu, gpu->first), 1.0, twin.generated->precision, result);
  add_determinism_check(*gpu, result);
}

// An iterative twin: shadow steps give the verdicts, the whole run's distances are informative.
void add_stepping_parity(const FieldTwin::Stepping& stepping, const Heightmap& input, const ReferenceRuns& runs,
                         const std::optional<GpuOutputs>& gpu, const RunOptions& options, CaseResult& result) {
  const auto totals = field_totals(input);
  const double range = totals.high > totals.low ? totals.high - totals.low : 1.0;
  const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high)) / range;
  add_informative_pair("float_vs_double", field_difference(runs.cpu, runs.cpu_float), range, stepping.iterations,
                       result);
  if (gpu) {
    add_informative_pair("gpu_vs_float", field_difference(runs.cpu_float, gpu->first), range, stepping.iterations,
                         result);
    add_informative_pair("gpu_vs_double", field_difference(runs.cpu, gpu->first), range, stepping.iterations, result);
    add_determinism_check(*gpu, result);
    add_shadow_checks(stepping, runs.shadow, gpu->shadow, range, magnitude, result);
  } else {
    skip_checks({"parity.max_abs.gpu_vs_float", "parity.rms.gpu_vs_float", "parity.max_abs.gpu_vs_double",
                 "parity.rms.gpu_vs_double", "determinism.gpu", "parity.shadow.max_abs.gpu_vs_float",
                 "parity.shadow.max_abs_multi.gpu_vs_float"},
                options.gpu_unavailable_reason, result);
  }
  add_divergence(stepping, runs, gpu, range, options, result);
}

template <class Real>
void add_spec_checks(const nlohmann::json& expect, const Grid<Real>& output, const std::string& backend,
                     CaseResult& result) {
  const double tolerance = expect.value("tolerance", 0.0);
  const std::string model = fmt::format("expected values from the seed's worked example; tolerance {}", tolerance);
  if (expect.contains("cells")) {
    double worst = 0.0;
    for (const auto& cell : expect["cells"]) {
      const int x = cell.at(0), y = cell.at(1);
      const double expected = cell.at(2);
      if (!output.inside(x, y)) throw InputError(fmt::format("expected cell ({}, {}) is outside the grid", x, y));
      worst = std::max(worst, std::abs(static_cast<double>(output.at(x, y)) - expected));
    }
    result.checks.push_back(bounded_check("spec.cells." + backend, worst, tolerance, std::nullopt, model));
  }
  if (expect.contains("total")) {
    const double deviation = std::abs(field_totals(output).sum - expect["total"].template get<double>());
    result.checks.push_back(bounded_check("spec.total." + backend, deviation, tolerance, std::nullopt, model));
  }
}

void add_artifact(CaseResult& result, const std::string& file, const std::string& kind, const std::string& caption) {
  result.artifacts.push_back({result.name + "/" + file, kind, caption});
}

// Input, results and the change they made, on the input's colour scale.
void write_change_pictures(const Heightmap& input, const Grid<double>& cpu, const Grid<float>& cpu_float,
                           const std::optional<GpuOutputs>& gpu, const std::filesystem::path& folder,
                           CaseResult& result) {
  const auto totals = field_totals(input);
  const double exaggeration = write_height_image(input, totals.low, totals.high, folder / "before.png");
  add_artifact(result, "before.png", "image", "input");
  write_height_image(cpu, totals.low, totals.high, folder / "after_cpu.png", exaggeration);
  add_artifact(result, "after_cpu.png", "image", "after, CPU reference (double)");
  if (gpu) {
    write_height_image(gpu->first.cast<double>(), totals.low, totals.high, folder / "after_gpu.png", exaggeration);
    add_artifact(result, "after_gpu.png", "image", "after, GPU");
  }
  const auto change = write_difference_image(input, cpu, folder / "change_cpu.png");
  add_artifact(result, "change_cpu.png", "image",
               fmt::format("after - before, CPU (red gain, blue loss; ±{:.3g} {})", change.scale_used, input.vertical_unit));
  if (gpu) {
    const auto disagreement =
        write_difference_image(cpu_float.cast<double>(), gpu->first.cast<double>(), folder / "gpu_vs_float.png");
    add_artifact(result, "gpu_vs_float.png", "image",
                 fmt::format("GPU - reference (float) (±{:.3g} {})", disagreement.scale_used, input.vertical_unit));
  }
}

// A generated field from both sides on its own colour scale, and where the GPU departs from the truth.
void write_generated_pictures(const Grid<double>& cpu, const std::optional<GpuOutputs>& gpu,
                              const std::filesystem::path& folder, CaseResult& result) {
  const auto totals = field_totals(cpu);
  const double exaggeration = write_height_image(cpu, totals.low, totals.high, folder / "cpu.png");
  add_artifact(result, "cpu.png", "image", "CPU reference (double)");
  if (!gpu) return;
  const auto gpu_values = gpu->first.cast<double>();
  write_height_image(gpu_values, totals.low, totals.high, folder / "gpu.png", exaggeration);
  add_artifact(result, "gpu.png", "image", "GPU");
  const auto disagreement = write_difference_image(cpu, gpu_values, folder / "gpu_vs_double.png");
  add_artifact(result, "gpu_vs_double.png", "image",
               fmt::format("GPU - reference (double) (±{:.3g})", disagreement.scale_used));
}

void write_artifacts(const FieldTwin& twin, const Heightmap& input, const Grid<double>& cpu,
                     const Grid<float>& cpu_float, const std::optional<GpuOutputs>& gpu, const RunOptions& options,
                     CaseResult& result) {
  report_stage(options, "pictures");
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  if (twin.generated) {
    write_generated_pictures(cpu, gpu, folder, result);
  } else {
    write_change_pictures(input, cpu, cpu_float, gpu, folder, result);
  }
  // A generator's output is a dimensionless value; an eroder's, the terrain in the input's units.
  const std::string field = twin.generated ? "value" : "terrain";
  const std::string unit = twin.generated ? "1" : cpu.vertical_unit;
  if (!twin.generated) write_field_files(input, {"input", field, "input", unit, "the input"}, options, result);
  write_field_files(cpu, {"cpu", field, "cpu", unit, "CPU reference (double)"}, options, result);
  write_field_files(cpu_float.cast<double>(), {"cpu_float", field, "cpu_float", unit, "CPU reference (float)"}, options,
                    result);
  if (!gpu) return;
  write_field_files(gpu->first.cast<double>(), {"gpu", field, "gpu", unit, "GPU"}, options, result);
}

}  // namespace

nlohmann::json field_spec_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape.update({{"cells", nullptr}, {"total", nullptr}, {"tolerance", nullptr}});
  return shape;
}

void run_field_twin(const FieldTwin& twin, const Heightmap& input, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result) {
  if (!twin.generated && !twin.stepping) {
    throw std::logic_error("a field twin is either generated or iterative (stepping)");
  }
  const ReferenceRuns runs = run_references(twin, input, options, result);
  std::optional<GpuOutputs> gpu;
  if (options.gpu_available) {
    try {
      gpu = run_gpu(twin, input.cast<float>(), runs, options, result);
    } catch (const std::exception& error) {
      result.error = fmt::format("GPU twin failed: {}", error.what());
    }
  }
  const std::string unavailable = gpu ? "" : (result.error.empty() ? options.gpu_unavailable_reason : result.error);
  RunOptions checked_options = options;
  checked_options.gpu_unavailable_reason = unavailable;
  add_mass_checks(twin, input, runs.cpu, runs.cpu_float, gpu ? std::optional<Grid<float>>(gpu->first) : std::nullopt,
                  checked_options, result);
  if (twin.stepping) {
    add_moved_ledger(*twin.stepping, input, result);
    add_stepping_parity(*twin.stepping, input, runs, gpu, checked_options, result);
  } else {
    add_generated_parity(twin, runs, gpu, checked_options, result);
  }
  if (expect.is_object()) {
    add_spec_checks(expect, runs.cpu, "cpu", result);
    if (gpu) add_spec_checks(expect, gpu->first, "gpu", result);
  }
  write_artifacts(twin, input, runs.cpu, runs.cpu_float, gpu, options, result);
  if (case_describes_terrain(result)) {
    report_stage(options, "terrain descriptors");
    const Grid<double> cpu_float = runs.cpu_float.cast<double>();
    const std::optional<Grid<double>> gpu_heights =
        gpu ? std::optional<Grid<double>>(gpu->first.cast<double>()) : std::nullopt;
    add_case_descriptors({twin.generated ? nullptr : &input, &runs.cpu, &cpu_float, gpu_heights ? &*gpu_heights : nullptr},
                         expect, options, result);
  }
}

}  // namespace gt
