// The one runner of iterative twins; see stepped_case.hpp.
#include "compare/stepped_case.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/case_descriptors.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/external/bmi_config.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/steppers/bmi.hpp"
#include "compare/subprocess.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/memory.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

void report_stage(const RunOptions& options, const std::string& what) {
  if (options.progress != nullptr) options.progress->stage(what);
}

// The iterations after which a run's state is kept: the shadow starts, then the end of the run.
std::vector<int> path_marks(const SteppedTwin& twin) {
  std::vector<int> marks = shadow_starts(twin.iterations, twin.checkpoints);
  if (marks.back() != twin.iterations) marks.push_back(twin.iterations);
  return marks;
}

// The shadow step's first part (one iteration, none when the run has none) and its whole length.
int shadow_first(const SteppedTwin& twin, int start) { return std::min(1, twin.iterations - start); }
int shadow_length(const SteppedTwin& twin, int start) { return std::min(twin.shadow_length, twin.iterations - start); }

// Distances of one field over its components and valid cells: the worst |a − b| (NaN or infinite
// counts as infinite), the RMS and the values differing in any bit.
struct Distance {
  double max_abs = 0.0;
  double rms = 0.0;
  std::size_t differing = 0;
};

Distance distance(const SteppedTwin& twin, std::size_t field, const State& a, const State& b) {
  Distance d;
  double squares = 0.0;
  std::size_t counted = 0;
  for (int k = 0; k < twin.fields[field].components; ++k) {
    const auto difference =
        field_difference(component_grid(twin.fields, a, field, k), component_grid(twin.fields, b, field, k));
    const double worst = std::isnan(difference.max_abs) ? std::numeric_limits<double>::infinity() : difference.max_abs;
    d.max_abs = std::max(d.max_abs, worst);
    const std::size_t cells = std::max<std::size_t>(1, a.grid.cells());
    squares += difference.rms * difference.rms * static_cast<double>(cells);
    counted += cells;
    d.differing += difference.differing_bits;
  }
  d.rms = std::sqrt(squares / static_cast<double>(std::max<std::size_t>(1, counted)));
  return d;
}

// The backend graded against the references: groundtruth's GPU twin, or an outside implementation
// (--implementation) standing where the GPU stands, with its checks named by its own backend.
struct Candidate {
  std::string backend = "gpu";  // check and file name part
  std::string label = "GPU";    // in details and captions
  std::function<std::unique_ptr<Stepper>()> make;
  std::function<std::unique_ptr<Stepper>()> make_timed;  // unset: make
  // Graded against ref<double> from ref<double>'s states, with the error model scaled to double's
  // unit roundoff, instead of against ref<float> (an outside model that declares float64 fields).
  bool double_precision = false;
  double (*clock)(const std::function<void()>&) = gpu_wall_ms;
  std::string nondeterminism;  // SteppedTwin::gpu_nondeterminism for the GPU, else empty
  bool bit_exact = false;      // SteppedTwin::gpu_bit_exact for the GPU
  std::string not_described;   // SteppedTwin::gpu_not_described, or why an outside end is not described
  bool external = false;       // no algorithm checks of its end (SteppedTwin::finish), no ledger records

  std::string versus() const { return double_precision ? "vs_double" : "vs_float"; }
  std::string reference_label() const { return double_precision ? "ref<double>" : "ref<float>"; }
};

// Where an outside model's config goes: beside the case's pictures, or a temporary file for a run
// without a report folder (the Python module).
std::filesystem::path external_config_path(const RunOptions& options, const CaseResult& result) {
  if (!options.report_dir.empty()) return options.report_dir / result.name / "bmi_config.txt";
  return temporary_path("groundtruth-bmi-config", ".txt");
}

// The run's outside model, with the case's config written for it. Its precision is read off a first
// instance, which the walk then uses.
Candidate external_candidate(const SteppedTwin& twin, const RunOptions& options, CaseResult& result) {
  const ExternalModel external = *options.external;
  const std::filesystem::path config = external_config_path(options, result);
  // A temporary config lives as long as the steppers may be made, and is removed with the last.
  const auto temporary = options.report_dir.empty() ? std::make_shared<TemporaryFiles>(std::vector{config}) : nullptr;
  write_bmi_config(config, twin.algorithm, result.name, twin.initial.grid, result.params);
  if (!options.report_dir.empty()) {
    result.artifacts.push_back({result.name + "/" + config.filename().string(), "text",
                                "the config file the outside model was initialised with"});
  }
  const auto make = [=, keep_config = temporary, fields = twin.fields, grid = twin.initial.grid,
                     algorithm = twin.algorithm] {
    return std::make_unique<BmiStepper>(external.make(config), fields, grid, algorithm);
  };
  auto first = std::make_shared<std::unique_ptr<BmiStepper>>(make());
  const bool double_precision = (*first)->double_precision();
  result.notes.push_back(fmt::format("graded: {} ({}), standing where the GPU twin stands; its fields are {}",
                                     external.label, external.origin, double_precision ? "double" : "float"));
  return {.backend = "external",
          .label = "external " + external.label,
          .make = [first, make]() -> std::unique_ptr<Stepper> {
            if (*first) return std::move(*first);
            return make();
          },
          .double_precision = double_precision,
          .clock = cpu_wall_ms,
          .not_described = "an outside implementation's end is in its field files and pictures",
          .external = true};
}

Candidate gpu_candidate(const SteppedTwin& twin) {
  return {.make = twin.make_gpu,
          .make_timed = twin.make_timed_gpu,
          .nondeterminism = twin.gpu_nondeterminism,
          .bit_exact = twin.gpu_bit_exact,
          .not_described = twin.gpu_not_described};
}

// A run from the start state through the marks: the states there (or only the last), its ledger.
struct BackendRun {
  std::vector<State> path;
  std::vector<LedgerRecord> ledger;
  const State& final() const { return path.back(); }
};

// Walks `stepper` from the start state through the marks; `at_mark(i, state)` sees each state, and
// the path keeps them all or, with keep_path = false, the last alone.
BackendRun walk(Stepper& stepper, const SteppedTwin& twin, bool keep_path,
                const std::function<void(std::size_t, const State&)>& at_mark = {}) {
  BackendRun run;
  stepper.set_state(twin.initial, 0);
  int done = 0;
  const auto marks = path_marks(twin);
  for (std::size_t i = 0; i < marks.size(); ++i) {
    stepper.update(marks[i] - done);
    done = marks[i];
    State state = stepper.get_state();
    if (at_mark) at_mark(i, state);
    if (keep_path || i + 1 == marks.size()) run.path.push_back(std::move(state));
  }
  run.ledger = stepper.ledger();
  return run;
}

// Median time of `reps` whole runs from the start state (the stepper already warm).
double timed_runs(Stepper& stepper, const SteppedTwin& twin, int reps, double (*clock)(const std::function<void()>&)) {
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) {
    stepper.set_state(twin.initial, 0);
    times.push_back(clock([&] { stepper.update(twin.iterations); }));
  }
  return median(times);
}

// ref<double> through the marks, timed (its walk is the warm-up, or with time_walks the one run).
BackendRun run_double(const SteppedTwin& twin, const RunOptions& options, CaseResult& result) {
  report_stage(options, "cpu reference (double)");
  auto stepper = twin.reference_double();
  if (twin.time_walks) {
    BackendRun run;
    result.timings.cpu_ms = cpu_wall_ms([&] { run = walk(*stepper, twin, true); });
    result.timings.cpu_reps = 1;
    return run;
  }
  BackendRun run = walk(*stepper, twin, true);
  if (options.cpu_reps > 0) {
    result.timings.cpu_ms = timed_runs(*stepper, twin, options.cpu_reps, cpu_wall_ms);
    result.timings.cpu_reps = options.cpu_reps;
  }
  return run;
}

// Every value of every field, compared bit for bit.
std::size_t differing_values(const State& a, const State& b) {
  std::size_t differing = 0;
  for (std::size_t f = 0; f < a.fields.size(); ++f) {
    for (std::size_t i = 0; i < a.fields[f].size(); ++i) {
      const double x = a.fields[f][i], y = b.fields[f][i];
      if (std::memcmp(&x, &y, sizeof x) != 0) ++differing;
    }
  }
  return differing;
}

// The worst shadow distance of one field over the checkpoints, against its bound there.
struct ShadowWorst {
  double distance = 0.0;
  ShadowBound bound;  // per_value dropped: `strict` holds the bound at `where`
  std::optional<double> tellable_bound;  // per-value bounds: their 90th percentile there
  std::string where;                     // per-value bounds: the value where the ratio peaked
  double ratio = -1.0;
  int checkpoint = 0;
  std::size_t differing = 0;
  int count = 0;      // iterations of the longest such shadow step
  double scale = 0.0;  // the field's largest own size over the checkpoints
};

double distance_over_bound(double distance, double bound) {
  if (!std::isfinite(distance) || (bound <= 0.0 && distance > 0.0)) return std::numeric_limits<double>::infinity();
  return bound > 0.0 ? distance / bound : 0.0;
}

// A field's distance against one bound per value: the value with the largest ratio (the largest
// distance among ties), the bound there and the 90th percentile of the bounds over valid cells.
struct PerValueWorst {
  double ratio = -1.0;
  double distance = 0.0;
  double bound = 0.0;
  double tellable_bound = 0.0;
  std::string where;
};

PerValueWorst per_value_worst(const SteppedTwin& twin, std::size_t f, const State& a, const State& b,
                              const std::vector<double>& bounds) {
  const FieldDecl& field = twin.fields[f];
  const auto components = static_cast<std::size_t>(field.components);
  const auto& expected = a.fields[f];
  const auto& got = b.fields[f];
  if (bounds.size() != expected.size()) {
    throw std::logic_error(fmt::format("{}: {} per-value bounds for the {} values of {}", twin.algorithm, bounds.size(),
                                       expected.size(), field.name));
  }
  PerValueWorst worst;
  std::size_t worst_index = 0;
  std::vector<double> valid_bounds;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const std::size_t cell = i / components;
    if (!a.grid.is_valid(cell)) continue;
    valid_bounds.push_back(bounds[i]);
    const double difference = std::isnan(got[i] - expected[i]) ? std::numeric_limits<double>::infinity()
                                                                 : std::abs(got[i] - expected[i]);
    const double ratio = distance_over_bound(difference, bounds[i]);
    if (ratio > worst.ratio || (ratio == worst.ratio && difference > worst.distance)) {
      worst = {ratio, difference, bounds[i]};
      worst_index = i;
    }
  }
  const std::size_t cell = worst_index / components;
  const auto width = static_cast<std::size_t>(std::max(1, a.grid.width));
  worst.where = components == 1 ? fmt::format("cell (x={}, y={})", cell % width, cell / width)
                                : fmt::format("cell (x={}, y={}), component {}", cell % width, cell / width,
                                              worst_index % components);
  if (!valid_bounds.empty()) {
    const auto rank = valid_bounds.begin() + static_cast<std::ptrdiff_t>(valid_bounds.size() * 9 / 10);
    std::nth_element(valid_bounds.begin(), rank, valid_bounds.end());
    worst.tellable_bound = *rank;
  }
  return worst;
}

void keep_worst(ShadowWorst& worst, const SteppedTwin& twin, std::size_t f, const State& expected, const State& got,
                ShadowBound bound, int checkpoint, int count) {
  const Distance d = distance(twin, f, expected, got);
  worst.differing += d.differing;
  worst.count = std::max(worst.count, count);
  worst.scale = std::max(worst.scale, bound.scale);
  std::optional<PerValueWorst> at;
  if (!bound.per_value.empty()) {
    at = per_value_worst(twin, f, expected, got, bound.per_value);
    bound.per_value = {};  // kept no further: the worst keeps the bound at one value
  }
  ShadowWorst here{.distance = d.max_abs, .bound = std::move(bound), .checkpoint = checkpoint};
  if (!at) {
    here.ratio = distance_over_bound(d.max_abs, here.bound.loose.value_or(here.bound.strict));
  } else {
    here.bound.strict = at->bound;
    here.distance = at->distance;
    here.ratio = at->ratio;
    here.tellable_bound = at->tellable_bound;
    here.where = at->where;
  }
  // Ties (no bound: every ratio 0 or infinite) keep the largest distance.
  if (here.ratio > worst.ratio || (here.ratio == worst.ratio && here.distance > worst.distance)) {
    worst.distance = here.distance;
    worst.bound = std::move(here.bound);
    worst.tellable_bound = here.tellable_bound;
    worst.where = std::move(here.where);
    worst.ratio = here.ratio;
    worst.checkpoint = checkpoint;
  }
}

// What the candidate's half measures: its run, its distance from ref<double> at each mark (per
// field), the worst shadow steps per field (one iteration and shadow_length).
struct GpuRun {
  BackendRun run;
  std::vector<std::vector<double>> from_double;  // [mark][field]
  std::vector<ShadowWorst> one, multi;
};

// The bounds of a shadow step for the candidate's precision: the models are linear in the unit
// roundoff, so a double candidate's are the float model's scaled by u_double/u_float.
// A read-only field is bounded at 0 here: a model hands it back as loaded.
std::vector<ShadowBound> candidate_bounds(const SteppedTwin& twin, const Candidate& candidate, const State& from, int count) {
  std::vector<ShadowBound> modelled = twin.shadow_bounds(from, count);
  const auto changing = std::count_if(twin.fields.begin(), twin.fields.end(), [](const FieldDecl& field) {
    return !field.read_only;
  });
  if (modelled.size() != std::size_t(changing)) {
    throw std::logic_error(fmt::format("{}: {} shadow bounds for {} declared fields that are not read-only",
                                       twin.algorithm, modelled.size(), changing));
  }
  std::vector<ShadowBound> bounds;
  auto next = modelled.begin();
  for (const FieldDecl& field : twin.fields) {
    bounds.push_back(field.read_only ? ShadowBound{.model = "an input the model reads and hands back as loaded"}
                                     : std::move(*next++));
  }
  if (!candidate.double_precision) return bounds;
  constexpr double double_over_float = 0x1p-53 / 0x1p-24;
  for (ShadowBound& bound : bounds) {
    bound.strict *= double_over_float;
    if (bound.loose) *bound.loose *= double_over_float;
    for (double& value_bound : bound.per_value) value_bound *= double_over_float;
    bound.model += "; scaled to double's unit roundoff (2^-53 for 2^-24)";
  }
  return bounds;
}

// From the reference's state at each checkpoint (ref<float>'s, or ref<double>'s for a double
// candidate) the candidate and a fresh copy of that reference step side by side; the distances are
// kept, the states dropped.
void shadow_steps(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& reference_run, Stepper& gpu,
                  GpuRun& measured) {
  const auto starts = shadow_starts(twin.iterations, twin.checkpoints);
  auto reference = candidate.double_precision ? twin.reference_double() : twin.reference_float();
  measured.one.assign(twin.fields.size(), {});
  measured.multi.assign(twin.fields.size(), {});
  const auto compare = [&](std::vector<ShadowWorst>& worst, const State& from, int start, int count) {
    const State expected = reference->get_state();
    const State got = gpu.get_state();
    std::vector<ShadowBound> bounds = candidate_bounds(twin, candidate, from, count);
    for (std::size_t f = 0; f < twin.fields.size(); ++f) {
      keep_worst(worst[f], twin, f, expected, got, std::move(bounds[f]), start, count);
    }
  };
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const State& from = reference_run.path[k];
    const int first = shadow_first(twin, starts[k]);
    const int length = shadow_length(twin, starts[k]);
    for (Stepper* stepper : {reference.get(), &gpu}) {
      stepper->set_state(from, starts[k]);
      stepper->update(first);
    }
    compare(measured.one, from, starts[k], first);
    for (Stepper* stepper : {reference.get(), &gpu}) stepper->update(length - first);
    compare(measured.multi, from, starts[k], length);
  }
}

// The candidate through the marks (measured against ref<double> there), a second run in one go
// (determinism), the shadow steps, then the timed runs.
GpuRun run_candidate(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& truth,
                     const BackendRun& float_run, const RunOptions& options, CaseResult& result) {
  report_stage(options, candidate.backend);
  auto stepper = candidate.make();
  GpuRun measured;
  measured.run = walk(*stepper, twin, false, [&](std::size_t i, const State& state) {
    std::vector<double> distances;
    for (std::size_t f = 0; f < twin.fields.size(); ++f) distances.push_back(distance(twin, f, truth.path[i], state).max_abs);
    measured.from_double.push_back(std::move(distances));
  });
  stepper->set_state(twin.initial, 0);
  const double one_go_ms = candidate.clock([&] { stepper->update(twin.iterations); });
  const auto differing = static_cast<double>(differing_values(measured.run.final(), stepper->get_state()));
  const std::string determinism = "determinism." + candidate.backend;
  if (!candidate.nondeterminism.empty()) {
    result.checks.push_back(not_applicable_check(
        determinism, fmt::format("{} ({} values differ between two runs)", candidate.nondeterminism, differing)));
  } else {
    result.checks.push_back(bounded_check(
        determinism, differing, 0.0, std::nullopt,
        fmt::format("values of any field whose bits differ between two {} runs of the same start state (the first "
                    "stepped through the checkpoints, the second in one go)",
                    candidate.label)));
  }
  report_stage(options, candidate.backend + " shadow steps");
  shadow_steps(twin, candidate, candidate.double_precision ? truth : float_run, *stepper, measured);
  if (twin.time_walks && !candidate.make_timed) {
    result.timings.gpu_ms = one_go_ms;
    result.timings.gpu_reps = 1;
    return measured;
  }
  const int reps = twin.time_walks ? 1 : options.gpu_reps;
  if (reps == 0) return measured;
  auto timed = candidate.make_timed ? candidate.make_timed() : std::move(stepper);
  timed->set_state(twin.initial, 0);
  if (!twin.time_walks) timed->update(twin.iterations);  // warm-up
  result.timings.gpu_ms = timed_runs(*timed, twin, reps, candidate.clock);
  result.timings.gpu_reps = reps;
  return measured;
}

Check shadow_check(const std::string& name, const ShadowWorst& worst, const std::string& unit, const std::string& from,
                   const Candidate& candidate) {
  const std::string exact = worst.differing == 0 ? "bit for bit at every checkpoint; "
                                                 : fmt::format("{} values differ in some bit; ", worst.differing);
  const std::string measured =
      worst.where.empty()
          ? fmt::format("max |{} - {}| in {}, {} at the checkpoint after iteration {}", candidate.backend,
                        candidate.reference_label(), unit,
                        worst.bound.model.empty() ? "the largest" : "worst against its bound", worst.checkpoint)
          : fmt::format("|{} - {}| in {} where it came closest to its own bound (one per value): at the checkpoint "
                        "after iteration {}, {}",
                        candidate.backend, candidate.reference_label(), unit, worst.checkpoint, worst.where);
  const std::string detail = fmt::format("{}{}, {} iteration(s) beside it: {}{}", exact, from, worst.count, measured,
                                         worst.bound.model.empty() ? "" : "; " + worst.bound.model);
  if (!worst.bound.graded) {
    // A model that gave no bound (none named) is not quoted.
    const std::string bound_there =
        worst.bound.model.empty() ? "" : fmt::format("; the model's bound there, {:.3g}", worst.bound.strict);
    return informative_check(name, worst.distance, detail + bound_there + "; not graded: " + worst.bound.why_not_graded);
  }
  // Whether the bound can tell is judged against the field's largest size over the run's
  // checkpoints (a dry start has no water to measure a share of).
  return decisive_check(name, worst.distance, worst.bound.strict, worst.bound.loose, worst.scale,
                        worst.bound.tellable_share, detail, worst.tellable_bound);
}

void add_shadow_checks(const SteppedTwin& twin, const Candidate& candidate, const GpuRun& gpu, CaseResult& result) {
  const auto starts = shadow_starts(twin.iterations, twin.checkpoints);
  const std::string from = fmt::format("{} loaded with {}'s state at {} checkpoints (after iterations {})",
                                       candidate.label, candidate.reference_label(), starts.size(), fmt::join(starts, ", "));
  for (std::size_t f = 0; f < twin.fields.size(); ++f) {
    const FieldDecl& field = twin.fields[f];
    const std::string pair = candidate.backend + "_" + candidate.versus();
    result.checks.push_back(
        shadow_check(fmt::format("parity.shadow.{}.{}", field.name, pair), gpu.one[f], field.unit, from, candidate));
    result.checks.push_back(
        shadow_check(fmt::format("parity.shadow.{}.multi.{}", field.name, pair), gpu.multi[f], field.unit, from, candidate));
  }
}

// exp of the least-squares slope of ln y over x, over the points with 0 < y < inf: the factor by
// which y grows per unit of x. Empty with fewer than two such points at different x.
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

const std::string end_of_run_detail =
    "at the end of the run; informative: over a run the method amplifies rounding differences by an amount not known "
    "before it (verdicts: parity.shadow.*)";

void add_end_pair(const SteppedTwin& twin, std::size_t f, const std::string& pair, bool bit_exact, const State& a,
                  const State& b, CaseResult& result) {
  const FieldDecl& field = twin.fields[f];
  const Distance d = distance(twin, f, a, b);
  const std::string exact = d.differing == 0 ? "bit-exact; " : fmt::format("{} values differ; ", d.differing);
  const std::string name = fmt::format("parity.{}.max_abs.{}", field.name, pair);
  if (bit_exact) {
    result.checks.push_back(bounded_check(
        name, d.max_abs, 0.0, std::nullopt,
        fmt::format("{}max |difference| in {} at the end of the run; a bit-exact twin: bound 0", exact, field.unit)));
  } else {
    result.checks.push_back(informative_check(
        name, d.max_abs, fmt::format("{}max |difference| in {} {}", exact, field.unit, end_of_run_detail)));
  }
  result.checks.push_back(informative_check(fmt::format("parity.{}.rms.{}", field.name, pair), d.rms,
                                            fmt::format("RMS of the difference in {} {}", field.unit, end_of_run_detail)));
}

// Whole-run distances and how fast the float runs leave ref<double>, field by field, with a plot.
void add_divergence(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& truth,
                    const BackendRun& float_run, const GpuRun* gpu, const RunOptions& options, CaseResult& result) {
  constexpr double plotted_zero = 1e-18;
  const auto marks = path_marks(twin);
  SeriesPlot plot{.title = "Distance from ref<double> along the run",
                  .x_label = "iteration",
                  .y_label = "max |· - ref<double>| in the field's unit (exact zeros at 1e-18)",
                  .log_y = true};
  for (std::size_t f = 0; f < twin.fields.size(); ++f) {
    const std::string& name = twin.fields[f].name;
    add_end_pair(twin, f, "float_vs_double", false, truth.final(), float_run.final(), result);
    if (gpu) {
      add_end_pair(twin, f, candidate.backend + "_vs_float", candidate.bit_exact, float_run.final(), gpu->run.final(), result);
      add_end_pair(twin, f, candidate.backend + "_vs_double", false, truth.final(), gpu->run.final(), result);
    }
    // The distance at mark i of a backend, from ref<double>.
    const auto add_series = [&](const std::string& label, const std::string& backend,
                                const std::function<double(std::size_t)>& at, bool dashed) {
      Series series{.label = name + " " + label, .dashed = dashed, .group = name};
      std::vector<double> distances;
      for (std::size_t i = 0; i < marks.size(); ++i) {
        const double d = at(i);
        series.x.push_back(marks[i]);
        series.y.push_back(std::max(d, plotted_zero));
        distances.push_back(d);
      }
      const std::string check = fmt::format("parity.{}.growth_per_iteration.{}_vs_double", name, backend);
      if (const auto growth = fitted_growth(series.x, distances)) {
        result.checks.push_back(informative_check(
            check, *growth,
            fmt::format("factor per iteration of max |{} - ref<double>|, least squares of its log over {} checkpoints "
                        "(iterations {}); informative",
                        label, marks.size(), fmt::join(marks, ", "))));
      } else {
        result.checks.push_back(not_applicable_check(
            check, "fewer than two checkpoints at which the distance is finite and above 0: no growth to fit"));
      }
      plot.series.push_back(std::move(series));
    };
    if (gpu) add_series(candidate.label, candidate.backend, [&](std::size_t i) { return gpu->from_double[i][f]; }, false);
    add_series("ref<float>", "float",
               [&](std::size_t i) { return distance(twin, f, truth.path[i], float_run.path[i]).max_abs; }, true);
  }
  attach_plot({plot}, options, "parity.png",
              fmt::format("distance from ref<double> at the checkpoints, each field: {} (solid), ref<float> (dashed)",
                          candidate.label),
              result);
}

// A read-only field handed back as loaded: the largest change of a valid value (a NaN where the
// loaded value was a number counts as infinite), bound 0; the detail counts the values changed.
Check read_only_unchanged(const FieldDecl& field, std::size_t index, const LedgerRun& run) {
  const std::vector<double>& loaded = run.initial.fields.at(index);
  const std::vector<double>& handed_back = run.final.fields.at(index);
  double largest = 0.0;
  std::size_t changed = 0;
  for (std::size_t value = 0; value < loaded.size(); ++value) {
    if (!run.initial.grid.is_valid(value / std::size_t(field.components))) continue;
    const bool same = loaded[value] == handed_back[value] || (std::isnan(loaded[value]) && std::isnan(handed_back[value]));
    if (same) continue;
    ++changed;
    const double change = std::abs(handed_back[value] - loaded[value]);
    largest = std::max(largest, std::isnan(change) ? std::numeric_limits<double>::infinity() : change);
  }
  return bounded_check("", largest, 0.0, std::nullopt,
                       fmt::format("largest change of the read-only input {} ({}), {} of {} values changed: a model "
                                   "reads it and hands it back as loaded",
                                   field.name, field.unit, changed, loaded.size()));
}

// The twin's ledger terms and, for each read-only field, state.<field>.unchanged.
std::vector<LedgerTerm> ledger_terms(const SteppedTwin& twin) {
  std::vector<LedgerTerm> terms = twin.ledger;
  for (std::size_t f = 0; f < twin.fields.size(); ++f) {
    if (!twin.fields[f].read_only) continue;
    terms.push_back({fmt::format("state.{}.unchanged", twin.fields[f].name),
                     [field = twin.fields[f], f](const LedgerRun& run) { return read_only_unchanged(field, f, run); },
                     /*reads_records=*/false});
  }
  return terms;
}

// `booked`: the references' records, where the algorithm books some beside its state; a run
// without records of its own (an outside model hands over its state alone) cannot be read by terms
// that need them, and they are not applicable there.
void add_ledger_checks(const SteppedTwin& twin, const BackendRun& run, const std::string& backend, CaseResult& result,
                       const std::vector<LedgerRecord>& booked = {}) {
  for (const LedgerTerm& term : ledger_terms(twin)) {
    if (run.ledger.empty() && !booked.empty() && term.reads_records) {
      result.checks.push_back(not_applicable_check(
          term.check + "." + backend,
          fmt::format("{} reads the records the model books beside its state, which {} does not give", term.check,
                      backend)));
      continue;
    }
    Check check = term.evaluate({twin.initial, run.final(), run.ledger, backend});
    check.name = term.check + "." + backend;
    result.checks.push_back(std::move(check));
  }
}

// The shown field before and after, the change and the GPU's difference from ref<float>, on the
// input's colour scale; every other field at the end of ref<double>'s run.
void write_pictures(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& truth,
                    const BackendRun& float_run, const BackendRun* gpu, const std::filesystem::path& folder,
                    CaseResult& result) {
  const std::size_t shown = twin.shown_field;
  const std::string& unit = twin.fields[shown].unit;
  const Grid<double> before = component_grid(twin.fields, twin.initial, shown, 0);
  const Grid<double> after = component_grid(twin.fields, truth.final(), shown, 0);
  const auto totals = field_totals(before);
  const double exaggeration = write_height_image(before, totals.low, totals.high, folder / "before.png");
  const ColourScale heights = height_scale(totals.low, totals.high, unit);
  const auto width_m = map_width_m(before.width, before.cell_size_x);
  add_picture(result, "before.png", "input", heights, width_m);
  write_height_image(after, totals.low, totals.high, folder / "after_cpu.png", exaggeration);
  add_picture(result, "after_cpu.png", "after, CPU reference (double)", heights, width_m);
  const auto change = write_difference_image(before, after, folder / "change_cpu.png");
  add_picture(result, "change_cpu.png", "after - before, CPU: red gain, blue loss", difference_scale(change, unit),
              width_m);
  if (gpu) {
    const Grid<double> gpu_after = component_grid(twin.fields, gpu->final(), shown, 0);
    const std::string after_file = fmt::format("after_{}.png", candidate.backend);
    write_height_image(gpu_after, totals.low, totals.high, folder / after_file, exaggeration);
    add_picture(result, after_file, "after, " + candidate.label, heights, width_m);
    const std::string difference_file = fmt::format("{}_vs_float.png", candidate.backend);
    const auto disagreement = write_difference_image(component_grid(twin.fields, float_run.final(), shown, 0), gpu_after,
                                                     folder / difference_file);
    add_picture(result, difference_file, candidate.label + " - reference (float)", difference_scale(disagreement, unit),
                width_m);
  }
  for (std::size_t f = 0; f < twin.fields.size(); ++f) {
    if (f == shown) continue;
    const FieldDecl& field = twin.fields[f];
    for (int k = 0; k < field.components; ++k) {
      const Grid<double> values = component_grid(twin.fields, truth.final(), f, k);
      const std::string label = component_label(field, k);
      const auto drawn = write_difference_image(twin.initial.grid.blank(0.0, field.unit), values, folder / (label + "_cpu.png"));
      add_picture(result, label + "_cpu.png", fmt::format("{}: {}, end of ref<double>'s run", label, field.meaning),
                  difference_scale(drawn, field.unit), width_m);
    }
  }
}

// Every component of every field, for the input and each backend's end state.
void write_fields(const SteppedTwin& twin, const State& state, const std::string& backend, const std::string& when,
                  const RunOptions& options, CaseResult& result) {
  for (std::size_t f = 0; f < twin.fields.size(); ++f) {
    const FieldDecl& field = twin.fields[f];
    for (int k = 0; k < field.components; ++k) {
      const std::string label = component_label(field, k);
      write_field_files(component_grid(twin.fields, state, f, k),
                        {fmt::format("{}_{}", label, backend), label, backend, field.unit,
                         fmt::format("{}, {}", field.meaning, when)},
                        options, result);
    }
  }
}

void write_artifacts(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& truth,
                     const BackendRun& float_run, const BackendRun* gpu, const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  report_stage(options, "pictures");
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  if (options.pictures) write_pictures(twin, candidate, truth, float_run, gpu, folder, result);
  write_fields(twin, twin.initial, "input", "the start state", options, result);
  write_fields(twin, truth.final(), "cpu", "after the run, ref<double>", options, result);
  write_fields(twin, float_run.final(), "cpu_float", "after the run, ref<float>", options, result);
  if (gpu) write_fields(twin, gpu->final(), candidate.backend, "after the run, " + candidate.label, options, result);
}

void add_descriptors(const SteppedTwin& twin, const Candidate& candidate, const BackendRun& truth,
                     const BackendRun& float_run, const BackendRun* gpu, const nlohmann::json& expect,
                     const RunOptions& options, CaseResult& result) {
  if (!case_describes_terrain(result) || !options.descriptors) return;
  report_stage(options, "terrain descriptors");
  const std::size_t shown = twin.shown_field;
  const Grid<double> input = component_grid(twin.fields, twin.initial, shown, 0);
  const Grid<double> cpu = component_grid(twin.fields, truth.final(), shown, 0);
  const Grid<double> cpu_float = component_grid(twin.fields, float_run.final(), shown, 0);
  const bool described = candidate.not_described.empty();
  if (!described) result.notes.push_back("terrain descriptors of the references alone: " + candidate.not_described);
  const std::optional<Grid<double>> gpu_terrain =
      gpu && described ? std::optional<Grid<double>>(component_grid(twin.fields, gpu->final(), shown, 0)) : std::nullopt;
  add_case_descriptors({.input = &input,
                        .cpu = &cpu,
                        .cpu_float = &cpu_float,
                        .gpu = gpu_terrain ? &*gpu_terrain : nullptr,
                        .ends_of_a_run = true},
                       expect, options, result);
  if (gpu || !described) return;
  for (const auto& name : descriptor_gpu_check_names(expect)) {
    result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
  }
}

// ref<double>'s and ref<float>'s states at every mark, kept for the divergence and the shadow starts.
MemoryEstimate kept_states_memory(const SteppedTwin& twin) {
  double values = 0.0;
  for (const FieldDecl& field : twin.fields) values += field.components;
  const double states = 2.0 * static_cast<double>(path_marks(twin).size());
  return memory_for(static_cast<double>(twin.initial.grid.cells()) * states, "states' cells",
                    values * sizeof(double));
}

}  // namespace

std::size_t expected_field(const SteppedTwin& twin, const nlohmann::json& expect) {
  if (!expect.is_object() || !expect.contains("field")) return twin.shown_field;
  const std::string name = expect["field"].get<std::string>();
  std::vector<std::string> names;
  for (std::size_t field = 0; field < twin.fields.size(); ++field) {
    if (twin.fields[field].name == name) return field;
    names.push_back(twin.fields[field].name);
  }
  throw InputError(fmt::format("expect.field '{}' is not a field of {}; its fields: {}", name, twin.algorithm,
                               fmt::join(names, ", ")));
}

nlohmann::json stepped_spec_shape() {
  nlohmann::json shape = field_spec_shape();
  shape["field"] = "string";
  return shape;
}

std::vector<int> shadow_starts(int iterations, int checkpoints) {
  std::vector<int> starts;
  const int count = std::clamp(iterations, 1, std::max(1, checkpoints));
  for (int k = 0; k < count; ++k) {
    starts.push_back(static_cast<int>(static_cast<long long>(k) * iterations / count));
  }
  return starts;
}

std::vector<std::string> gpu_check_names(const SteppedTwin& twin, const nlohmann::json& expect) {
  std::vector<std::string> names = {"determinism.gpu"};
  for (const LedgerTerm& term : ledger_terms(twin)) names.push_back(term.check + ".gpu");
  for (const FieldDecl& field : twin.fields) {
    names.push_back(fmt::format("parity.shadow.{}.gpu_vs_float", field.name));
    names.push_back(fmt::format("parity.shadow.{}.multi.gpu_vs_float", field.name));
  }
  for (const auto& name : field_spec_names(expect, "gpu")) names.push_back(name);
  if (twin.finish_gpu_checks) {
    for (const auto& name : twin.finish_gpu_checks(expect)) names.push_back(name);
  }
  for (const FieldDecl& field : twin.fields) {
    for (const char* pair : {"gpu_vs_float", "gpu_vs_double"}) {
      names.push_back(fmt::format("parity.{}.max_abs.{}", field.name, pair));
      names.push_back(fmt::format("parity.{}.rms.{}", field.name, pair));
    }
    names.push_back(fmt::format("parity.{}.growth_per_iteration.gpu_vs_double", field.name));
  }
  return names;
}

void run_stepped_case(const SteppedTwin& given, const nlohmann::json& expect, const RunOptions& options,
                      CaseResult& result) {
  check_state_decl(given.fields, given.algorithm);
  check_state_shape(given.fields, given.initial, given.algorithm + " start state");
  SteppedTwin twin = given;
  if (options.checkpoints > 0) twin.checkpoints = options.checkpoints;
  require_memory(kept_states_memory(twin), result.name);
  result.width = twin.initial.grid.width;
  result.height = twin.initial.grid.height;
  const BackendRun truth = run_double(twin, options, result);
  report_stage(options, "cpu reference (float)");
  const BackendRun float_run = walk(*twin.reference_float(), twin, true);
  const Candidate candidate = options.external ? external_candidate(twin, options, result) : gpu_candidate(twin);
  std::optional<GpuRun> gpu;
  std::string unavailable = options.gpu_unavailable_reason;
  if (options.gpu_available || candidate.external) {
    try {
      gpu = run_candidate(twin, candidate, truth, float_run, options, result);
    } catch (const RunawayRun&) {
      throw;  // a reference's shadow step left the range: the driver makes the case inconclusive
    } catch (const std::exception& error) {
      result.error = fmt::format("{} failed: {}", candidate.external ? candidate.label : "GPU twin", error.what());
      unavailable = result.error;
      std::erase_if(result.checks, [&](const Check& check) { return check.name == "determinism." + candidate.backend; });
    }
  }
  const BackendRun* gpu_run = gpu ? &gpu->run : nullptr;
  add_ledger_checks(twin, truth, "cpu", result);
  add_ledger_checks(twin, float_run, "cpu_float", result);
  const std::size_t spec_field = expected_field(twin, expect);
  add_field_spec_checks(expect, component_grid(twin.fields, truth.final(), spec_field, 0), "cpu", result);
  if (gpu) {
    add_ledger_checks(twin, gpu->run, candidate.backend, result, truth.ledger);
    add_shadow_checks(twin, candidate, *gpu, result);
    add_field_spec_checks(expect, component_grid(twin.fields, gpu->run.final(), spec_field, 0), candidate.backend, result);
  } else if (!candidate.external) {
    for (const auto& name : gpu_check_names(twin, expect)) result.checks.push_back(skipped_check(name, unavailable));
  }
  add_divergence(twin, candidate, truth, float_run, gpu ? &*gpu : nullptr, options, result);
  if (twin.finish) {
    std::vector<BackendEnd> ends = {{"cpu", truth.final(), truth.ledger}, {"cpu_float", float_run.final(), float_run.ledger}};
    if (gpu && !candidate.external) ends.push_back({"gpu", gpu->run.final(), gpu->run.ledger});
    twin.finish(ends, expect, options, result);
  }
  write_artifacts(twin, candidate, truth, float_run, gpu_run, options, result);
  RunOptions described = options;
  described.gpu_unavailable_reason = unavailable;
  add_descriptors(twin, candidate, truth, float_run, gpu_run, expect, described, result);
}

}  // namespace gt
