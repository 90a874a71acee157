// A droplet eroder as a stepped twin; see droplet_twin.hpp.
#include "compare/droplet_twin.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_twin.hpp"
#include "compare/field_files.hpp"
#include "compare/steppers/height.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/thermal.hpp"
#include "core/sum.hpp"
#include "gpu/timing.hpp"

namespace gt {

using reference::DropletLedger;
using reference::DropletRun;

namespace {

// Race mode: at least this many GPU runs against the one sequential truth (issue 12).
constexpr int race_runs = 5;
// Race mode: the spacings whose distance from the truth the case measures (one iteration each).
constexpr int race_spacings[] = {16, 8, 4, 2, 1};

const char* const gpu_books_no_ledger =
    "the GPU twin books no droplet ledger (what the droplets carry away stays on the device); its terrain is held to "
    "ref<float>'s by parity.shadow.terrain.gpu_vs_float";

// The ledger's members by name, as a stepper's records carry them (the counts as doubles: exact
// below 2^53), summed over a run's parts; largest_cell_delta_quanta is their maximum instead.
constexpr std::pair<const char*, double DropletLedger::*> ledger_amounts[] = {
    {"eroded", &DropletLedger::eroded},
    {"deposited", &DropletLedger::deposited},
    {"eroded_outside", &DropletLedger::eroded_outside},
    {"deposited_outside", &DropletLedger::deposited_outside},
    {"clamp_created", &DropletLedger::clamp_created},
    {"sediment_at_end", &DropletLedger::sediment_at_end},
    {"sediment_left", &DropletLedger::sediment_left},
    {"apply_rounding", &DropletLedger::apply_rounding},
    {"apply_rounding_bound", &DropletLedger::apply_rounding_bound}};
constexpr std::pair<const char*, long long DropletLedger::*> ledger_counts[] = {
    {"droplets", &DropletLedger::droplets},
    {"droplets_left", &DropletLedger::droplets_left},
    {"steps", &DropletLedger::steps},
    {"eroded_quanta", &DropletLedger::eroded_quanta},
    {"deposited_quanta", &DropletLedger::deposited_quanta},
    {"eroded_outside_quanta", &DropletLedger::eroded_outside_quanta},
    {"deposited_outside_quanta", &DropletLedger::deposited_outside_quanta},
    {"clamp_created_quanta", &DropletLedger::clamp_created_quanta},
    {"sediment_end_quanta", &DropletLedger::sediment_end_quanta},
    {"applied_quanta", &DropletLedger::applied_quanta}};

void add_ledgers(DropletLedger& total, const DropletLedger& part) {
  for (const auto& [name, member] : ledger_amounts) total.*member += part.*member;
  for (const auto& [name, member] : ledger_counts) total.*member += part.*member;
  total.largest_cell_delta_quanta = std::max(total.largest_cell_delta_quanta, part.largest_cell_delta_quanta);
}

// A record of the ledger so far and the terrain's total (in the twin's heights) after `step`.
LedgerRecord record_of(int step, const DropletLedger& ledger, double terrain) {
  LedgerRecord record{.step = step, .totals = {{"terrain", terrain}}};
  for (const auto& [name, member] : ledger_amounts) record.totals[name] = ledger.*member;
  for (const auto& [name, member] : ledger_counts) record.totals[name] = static_cast<double>(ledger.*member);
  record.totals["largest_cell_delta_quanta"] = static_cast<double>(ledger.largest_cell_delta_quanta);
  return record;
}

DropletLedger ledger_of(const LedgerRecord& record) {
  DropletLedger ledger;
  for (const auto& [name, member] : ledger_amounts) ledger.*member = record.totals.at(name);
  for (const auto& [name, member] : ledger_counts) ledger.*member = static_cast<long long>(record.totals.at(name));
  ledger.largest_cell_delta_quanta = static_cast<long long>(record.totals.at("largest_cell_delta_quanta"));
  return ledger;
}

template <class Real>
double terrain_sum(const Grid<Real>& heights) {
  CompensatedSum sum;
  for (std::size_t i = 0; i < heights.size(); ++i) {
    if (heights.is_valid(i)) sum.add(static_cast<double>(heights.values[i]));
  }
  return sum.value();
}

// A reference as a stepper: loading a state starts a new ledger, and each update adds a record of
// the ledger so far and the terrain's total.
template <class Real>
class ReferenceStepper : public Stepper {
 public:
  using Run = std::function<DropletRun<Real>(const Grid<Real>& heights, int first, int count)>;
  ReferenceStepper(Run run, HeightScale own) : run_(std::move(run)), own_(own) {}
  void set_state(const State& state, int done) override {
    heights_ = own_.twin_heights<Real>(state);
    done_ = done;
    ledger_ = {};
    records_ = {record_of(0, ledger_, terrain_sum(heights_))};
  }
  void update(int count) override {
    DropletRun<Real> run = run_(heights_, done_, count);
    heights_ = std::move(run.heights);
    add_ledgers(ledger_, run.ledger);
    done_ += count;
    records_.push_back(record_of(records_.back().step + count, ledger_, terrain_sum(heights_)));
  }
  State get_state() override { return own_.state_of(heights_); }
  std::vector<LedgerRecord> ledger() override { return records_; }

 private:
  Run run_;
  HeightScale own_;
  Grid<Real> heights_;
  int done_ = 0;
  DropletLedger ledger_;
  std::vector<LedgerRecord> records_;
};

class GpuStepper : public Stepper {
 public:
  GpuStepper(DropletGpu gpu, HeightScale own) : gpu_(std::move(gpu)), own_(own) {}
  void set_state(const State& state, int done) override { gpu_.load(own_.twin_heights<float>(state), done); }
  void update(int count) override { gpu_.step(count); }
  State get_state() override { return own_.state_of(gpu_.result()); }

 private:
  DropletGpu gpu_;
  HeightScale own_;
};

// The setup of the truth: the case's spacing, the droplets one after the other.
DropletSetup sequential(const DropletTwin& twin) { return {twin.setup.spacing, DropletOrdering::race}; }

// A height range as the twins see it (1 for a flat input).
double twin_range(const FieldTotals& totals) { return totals.high > totals.low ? totals.high - totals.low : 1.0; }

// The input's height range in the state's unit.
double own_range(const DropletTwin& twin) { return twin_range(field_totals(twin.input)) * twin.own.scale; }

ShadowBound disjoint_bound(const DropletTwin& twin, int count) {
  const FieldTotals totals = field_totals(twin.input);
  const double range = twin_range(totals);
  const double additions = twin.writes_per_cell_per_step * twin.lifetime * twin.setup.spacing * twin.setup.spacing +
                           twin.cell_roundings_per_iteration;
  const Bounds bounds =
      parity_bounds_same_arithmetic(additions * count, std::max(std::abs(totals.low), std::abs(totals.high)) / range);
  const double own = range * twin.own.scale;
  return {.strict = bounds.strict * own,
          .loose = bounds.loose * own,
          .scale = own,
          .model = fmt::format("disjoint droplets: {} additions per cell and iteration ({} per step of the one droplet "
                               "per pass that reaches it, {} of the blur blend); {}",
                               additions, twin.writes_per_cell_per_step, twin.cell_roundings_per_iteration,
                               bounds.model)};
}

// The terrain's bound after `count` iterations, by ordering (see droplet_twin.hpp).
ShadowBound shadow_bound(const DropletTwin& twin, int count) {
  switch (twin.setup.ordering) {
    case DropletOrdering::batch:
      return {.scale = own_range(twin),
              .model = "batch droplets: order-independent integer arithmetic on the state frozen at each pass's "
                       "start, every bit equal"};
    case DropletOrdering::disjoint:
      return disjoint_bound(twin, count);
    case DropletOrdering::race:
      break;
  }
  return {.strict = std::numeric_limits<double>::infinity(),
          .scale = own_range(twin),
          .graded = false,
          .model = "race droplets: the GPU's droplets of a pass race for cells where ref<float> runs them one after "
                   "the other; no model bounds the distance (race.* report it)"};
}

// The droplet steps a run can take at most: every droplet it releases (spacing² passes of
// ceil(W/S)·ceil(H/S) droplets per iteration) living its whole lifetime.
double most_droplet_steps(const DropletTwin& twin) {
  const double spacing = twin.setup.spacing;
  const double droplets_per_pass = std::ceil(twin.input.width / spacing) * std::ceil(twin.input.height / spacing);
  return double(twin.iterations) * spacing * spacing * droplets_per_pass * double(twin.lifetime);
}

// The ledger's residual: what is left of Σ after + taken away - created - Σ before.
double ledger_residual(double before, double after, const DropletLedger& l) {
  CompensatedSum sum;
  for (const double term : {after, l.sediment_at_end, l.sediment_left, l.deposited_outside, -before,
                            -l.eroded_outside, -l.clamp_created, -l.apply_rounding}) {
    sum.add(term);
  }
  return sum.value();
}

// ledger.closure of one reference's run, relative to Σ|before| of the heights it started from.
Check ledger_closure(const DropletTwin& twin, const LedgerRun& run) {
  if (run.records.empty()) return not_applicable_check("", gpu_books_no_ledger);
  const bool in_float = run.backend != "cpu";
  const FieldTotals totals = in_float ? field_totals(twin.input.cast<float>()) : field_totals(twin.input);
  const double scale = std::max(totals.sum_abs, 1e-300);
  const double residual = std::abs(ledger_residual(run.records.front().totals.at("terrain"),
                                                   run.records.back().totals.at("terrain"),
                                                   ledger_of(run.records.back()))) /
                          scale;
  if (!in_float || twin.setup.ordering == DropletOrdering::batch) {
    // Double: each event rounds once in double (≤ u of its amount, amounts ≤ the height range) and the
    // ledger's sums are compensated; 1e-12 of Σ|before| leaves room for 10⁴ events per cell at u (a
    // blur blend adds 18 per cell and iteration: far inside it at the few iterations cases run).
    // Batch float: the terrain changes by integer quanta, exactly counted, and the rounding of
    // heights + delta is measured per cell in double: only the double sums remain.
    return bounded_check("", residual, 1e-12, std::nullopt,
                         "|Σ after + sediment taken away + deposited outside - eroded outside - clamp - apply rounding "
                         "- Σ before| / Σ|before|; double roundings only");
  }
  // Float, sequential: every stored height rounds once (≤ u·M, M the largest |height| of the input,
  // which the eroders' bounds keep the heights within) and so does every update of the carried
  // sediment: at most roundings_per_step of them per droplet step, and at most lifetime steps for
  // each droplet the run releases (known before it runs). A blur blend adds
  // cell_roundings_per_iteration at each cell and iteration: sums of exchanges, each |w·(h_b - h_a)|
  // ≤ 2M/9, so every partial sum stays below 2M, and the blended height (a convex mix, ≤ M): counted
  // as two roundings of u·M each. Worst case all add up (loose); strict: a random walk.
  const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high));
  const double blend_roundings = 2.0 * twin.cell_roundings_per_iteration * double(twin.input.size()) * twin.iterations;
  const double roundings = twin.roundings_per_step * most_droplet_steps(twin) + blend_roundings;
  const double per_rounding = unit_roundoff_float * magnitude / scale;
  return bounded_check("", residual, 6.0 / std::sqrt(3.0) * std::sqrt(roundings) * per_rounding,
                       roundings * per_rounding,
                       fmt::format("as ledger.closure.cpu, in float: {} roundings of at most u·{:.3g} ({} per droplet "
                                   "step, {} of the blur blend), random walk (strict) and worst case (loose)",
                                   roundings, magnitude, twin.roundings_per_step, blend_roundings));
}

Check ledger_quanta(const LedgerRun& run) {
  if (run.backend == "cpu") {
    return not_applicable_check("", "ref<double> runs the droplets one after the other (the truth): it counts no quanta");
  }
  if (run.records.empty()) return not_applicable_check("", gpu_books_no_ledger);
  const DropletLedger l = ledger_of(run.records.back());
  const long long quanta = l.applied_quanta + l.sediment_end_quanta + l.deposited_outside_quanta -
                           l.eroded_outside_quanta - l.clamp_created_quanta;
  return bounded_check("", static_cast<double>(std::llabs(quanta)), 0.0, std::nullopt,
                       "batch ordering in integer quanta: terrain change + sediment taken away + deposited outside - "
                       "eroded outside - clamp = 0 exactly");
}

// The batch ledger's rounding of the applications, which ledger.closure takes as measured, held to
// what one rounding of Real(delta) and one of the sum may add: a change applied at the wrong size in
// both twins would otherwise pass as rounding.
Check ledger_apply_rounding(const LedgerRun& run) {
  if (run.backend == "cpu") {
    return not_applicable_check("", "ref<double> runs the droplets one after the other (the truth): it applies no deltas");
  }
  if (run.records.empty()) return not_applicable_check("", gpu_books_no_ledger);
  const DropletLedger l = ledger_of(run.records.back());
  return bounded_check("", std::abs(l.apply_rounding), l.apply_rounding_bound, std::nullopt,
                       "|what applying the deltas added beyond Σ delta·quantum|, against Σ u·(|delta·quantum| + "
                       "|height after|): one rounding of Real(delta) and one of the sum per applied cell");
}

std::vector<LedgerTerm> ledger_terms(const std::shared_ptr<const DropletTwin>& twin) {
  std::vector<LedgerTerm> terms = {{"ledger.closure", [twin](const LedgerRun& run) { return ledger_closure(*twin, run); }}};
  if (twin->setup.ordering == DropletOrdering::batch) {
    terms.push_back({"ledger.quanta", ledger_quanta});
    terms.push_back({"ledger.apply_rounding", ledger_apply_rounding});
  }
  return terms;
}

void add_ledger_note(const DropletLedger& l, CaseResult& result) {
  result.notes.push_back(fmt::format(
      "droplet ledger (ref<double>): {} droplets, {} steps, {} left across x or y <= 0; eroded {:.6g} (what the stores "
      "removed: negative where the clamp raised a texel), deposited "
      "{:.6g}; taken away {:.6g} at the end of lives and {:.6g} by droplets leaving; created {:.6g} by erosion "
      "outside and {:.6g} by the clamp at 0; lost {:.6g} in deposits outside",
      l.droplets, l.steps, l.droplets_left, l.eroded, l.deposited, l.sediment_at_end, l.sediment_left,
      l.eroded_outside, l.clamp_created, l.deposited_outside));
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

// A whole GPU run of `setup` from the input.
Grid<float> gpu_run(const DropletTwin& twin, DropletSetup setup, int iterations) {
  DropletGpu gpu = twin.make_gpu(setup);
  gpu.load(twin.input.cast<float>(), 0);
  gpu.step(iterations);
  return gpu.result();
}

// The distance of one racing iteration from the sequential truth at each spacing, plotted.
void add_race_by_spacing(const DropletTwin& twin, const RunOptions& options, CaseResult& result) {
  Series distance{"GPU race vs sequential ref<float>", {}, {}, false, ""};
  for (const int spacing : race_spacings) {
    const DropletSetup at_spacing{spacing, DropletOrdering::race};
    const auto truth = twin.reference_float(twin.input.cast<float>(), 0, 1, at_spacing);
    const double value = relative_rms(height_change(twin.input, truth.heights),
                                      height_change(twin.input, gpu_run(twin, at_spacing, 1)));
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
              options, "race_by_spacing.png",
              "how far racing droplets land from the sequential truth as spacing shrinks", result);
}

// Race ordering: GPU runs against the sequential ref<float>'s end `truth`, reported over the runs.
void add_race_statistics(const DropletTwin& twin, const Grid<float>& truth, const RunOptions& options,
                         CaseResult& result) {
  const Grid<double> truth_change = height_change(twin.input, truth);
  const double truth_moved = absolute_total(truth_change);
  Spread correlation_spread, rms_spread, moved_spread;
  const int runs = std::max(race_runs, options.gpu_reps);
  for (int run = 0; run < runs; ++run) {
    const Grid<double> change = height_change(twin.input, gpu_run(twin, twin.setup, twin.iterations));
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
  add_race_by_spacing(twin, options, result);
}

// Race ordering: what of the case is order-independent, graded. The race's result depends on which
// droplet writes last; each droplet's kernel at the case's parameters does not. Batch ordering runs
// that kernel with every droplet of a pass reading the pass's start heights and adding integer quanta
// (core/params/droplets.hpp), so one iteration of the case's droplets from its input in batch is
// defined to the bit: the GPU against ref<float>, bound 0. Where the case's spacing lets a pass's
// droplets, blind to each other, pile more into one cell than the GPU's counters hold, the iteration
// runs at apart_spacing, where no two droplets of a pass meet. The race's own in-place arithmetic is
// the disjoint cases' to grade (the same shader code with the races ruled out by spacing).
Check race_kernel_in_batch(const DropletTwin& twin) {
  const std::string name = "parity.batch_kernel.gpu_vs_float";
  std::vector<int> spacings = {twin.setup.spacing};
  if (twin.apart_spacing > twin.setup.spacing) spacings.push_back(twin.apart_spacing);
  std::string refused;
  for (const int spacing : spacings) {
    const DropletSetup batch{spacing, DropletOrdering::batch};
    Grid<float> expected;
    try {
      expected = twin.reference_float(twin.input.cast<float>(), 0, 1, batch).heights;
    } catch (const RunawayRun& runaway) {
      refused += fmt::format("{}at spacing {}: {}", refused.empty() ? "" : "; ", spacing, runaway.what());
      continue;
    }
    const FieldDifference difference = field_difference(expected, gpu_run(twin, batch, 1));
    return bounded_check(
        name, double(difference.differing_bits), 0.0, std::nullopt,
        fmt::format("texels differing in any bit after one iteration of this case's droplets (its input and "
                    "parameters, spacing {}{}) in batch ordering, the order-independent form of the kernel the race "
                    "runs: GPU against ref<float>, every bit equal (max |difference| {:.3g} in the twins' heights)",
                    spacing, refused.empty() ? "" : "; batch refused the case's spacing: " + refused,
                    difference.max_abs));
  }
  return not_applicable_check(name, "batch ordering cannot count this case's changes " + refused);
}

// Batch ordering: how far its result lands from the sequential truth (ref<double>), and ref<float>'s
// largest change of a cell in a pass.
void add_batch_checks(const DropletTwin& twin, const std::vector<BackendEnd>& ends, CaseResult& result) {
  const Grid<double> truth_change = height_change(twin.input, twin.own.twin_heights<double>(ends[0].final));
  const Grid<double> batch_change = height_change(twin.input, twin.own.twin_heights<float>(ends[1].final));
  result.checks.push_back(informative_check(
      "batch.relative_rms_vs_sequential", relative_rms(truth_change, batch_change),
      "rms of (batch ref<float> change - sequential ref<double> change) over the sequential change's rms: what "
      "reading a frozen state costs against droplets that see their predecessors"));
  result.checks.push_back(informative_check("batch.erosion_correlation_vs_sequential",
                                            correlation(truth_change, batch_change),
                                            "correlation of the batch change with the sequential one"));
  result.checks.push_back(informative_check(
      "batch.largest_cell_delta_quanta", static_cast<double>(ledger_of(ends[1].records.back()).largest_cell_delta_quanta),
      "the largest change of one cell in one pass, in quanta; the GPU's counters hold 2^31 - 1"));
}

// Batch: the whole run, GPU against ref<float>, every bit equal.
void add_whole_run_parity(const BackendEnd& float_end, const BackendEnd& gpu_end, CaseResult& result) {
  const FieldDifference whole = field_difference(heights_of<double>(float_end.final), heights_of<double>(gpu_end.final));
  result.checks.push_back(bounded_check("parity.cells_differing.gpu_vs_float", double(whole.differing_bits), 0.0,
                                        std::nullopt,
                                        "the whole run, GPU against ref<float> in batch ordering: every bit equal"));
}

// The 99th percentile of |b| over valid cells: the colour scale of a side map, so that a few cells
// of extreme change (a crater's rim) do not wash out the rest.
double robust_scale(const Grid<double>& map) {
  std::vector<double> magnitudes;
  for (std::size_t i = 0; i < map.size(); ++i) {
    if (map.is_valid(i) && map.values[i] != 0.0) magnitudes.push_back(std::abs(map.values[i]));
  }
  if (magnitudes.empty()) return 0.0;
  const auto at = magnitudes.begin() + static_cast<std::ptrdiff_t>(0.99 * static_cast<double>(magnitudes.size() - 1));
  std::nth_element(magnitudes.begin(), at, magnitudes.end());
  return *at;
}

// One of Hydra's side maps of the truth: with a contrast c, full red at 1/c (Hydra's
// min(1, c·amount)); and its field file in the state's unit (amounts scale as heights, without the
// offset).
void write_side_map(const DropletTwin& twin, Grid<double> map, double contrast, const std::string& picture,
                    const std::string& field, const std::string& what, const RunOptions& options, CaseResult& result) {
  const std::filesystem::path folder = options.report_dir / result.name;
  Grid<double> zero = map;
  std::fill(zero.values.begin(), zero.values.end(), 0.0);
  const double scale = contrast > 0.0 ? 1.0 / contrast : robust_scale(map);
  const auto drawn = write_difference_image(zero, map, folder / picture, scale);
  add_picture(result, picture,
              contrast > 0.0 ? fmt::format("{} with its contrast {} (full red at 1/contrast), in normalised heights",
                                           what, contrast)
                             : fmt::format("{}, full red at its 99th percentile, in normalised heights", what),
              difference_scale(drawn, "1"), map_width_m(map.width, map.cell_size_x));
  for (double& amount : map.values) amount *= twin.own.scale;
  map.vertical_unit = twin.unit;
  write_field_files(map, {field + "_cpu", field, "cpu", twin.unit, what + " over the run, ref<double>"}, options, result);
}

// Hydra's depth and sediment maps of ref<double>'s run (one more run: they are not state) and, in
// batch ordering, the batch result against the truth.
void write_pictures(const DropletTwin& twin, const std::vector<BackendEnd>& ends, const RunOptions& options,
                    CaseResult& result) {
  if (options.report_dir.empty()) return;
  const DropletRun<double> truth = twin.reference_double(twin.input, 0, twin.iterations, sequential(twin));
  write_side_map(twin, truth.eroded_at_droplet, twin.erosion_contrast, "depth_cpu.png", "eroded_at_droplet",
                 "Hydra's depth map: what the droplets standing on each texel eroded", options, result);
  write_side_map(twin, truth.deposited_at_droplet, twin.deposition_contrast, "sediment_cpu.png",
                 "deposited_at_droplet", "Hydra's sediment map: what the droplets standing on each texel deposited",
                 options, result);
  if (twin.setup.ordering != DropletOrdering::batch) return;
  const auto batch = write_difference_image(heights_of<double>(ends[0].final), heights_of<double>(ends[1].final),
                                            options.report_dir / result.name / "batch_vs_sequential.png");
  add_picture(result, "batch_vs_sequential.png",
              fmt::format("batch ref<float> - sequential ref<double>: max {:.3g} {}", batch.max_abs, twin.unit),
              difference_scale(batch, twin.unit));
}

void finish(const DropletTwin& twin, const std::vector<BackendEnd>& ends, const RunOptions& options,
            CaseResult& result) {
  result.notes.insert(result.notes.end(), twin.notes.begin(), twin.notes.end());
  add_ledger_note(ledger_of(ends[0].records.back()), result);
  if (twin.setup.ordering == DropletOrdering::batch) add_batch_checks(twin, ends, result);
  write_pictures(twin, ends, options, result);
  if (ends.size() < 3) return;
  if (twin.setup.ordering == DropletOrdering::batch) add_whole_run_parity(ends[1], ends[2], result);
  if (twin.setup.ordering == DropletOrdering::race) {
    result.checks.push_back(race_kernel_in_batch(twin));
    add_race_statistics(twin, twin.own.twin_heights<float>(ends[1].final), options, result);
  }
}

// The checks finish adds with a GPU alone, by name.
std::vector<std::string> finish_gpu_checks(const DropletTwin& twin) {
  if (twin.setup.ordering == DropletOrdering::batch) return {"parity.cells_differing.gpu_vs_float"};
  if (twin.setup.ordering == DropletOrdering::disjoint) return {};
  std::vector<std::string> names = {"parity.batch_kernel.gpu_vs_float", "race.erosion_correlation.gpu_vs_float",
                                    "race.relative_rms.gpu_vs_float", "race.material_moved_ratio.gpu_vs_float"};
  for (const int spacing : race_spacings) names.push_back(fmt::format("race.relative_rms.spacing_{}.gpu_vs_float", spacing));
  return names;
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

void set_droplet_input(DropletTwin& twin, const Heightmap& given, bool normalise) {
  twin.initial = height_state(given);
  twin.unit = given.vertical_unit.empty() ? "m" : given.vertical_unit;
  if (!normalise) {
    twin.input = given;
    return;
  }
  twin.input = normalise_heights(given);
  const auto [low, high] = valid_range(given);
  twin.own = {.scale = high > low ? high - low : 1.0, .offset = low > high ? 0.0 : low};
  twin.notes.push_back(fmt::format(
      "heights normalised to [0, 1] as seed 000 does ((h - {:.6g})/{:.6g}); the kernel works in texels, so the cell "
      "size does not enter; the state, its files, pictures and terrain descriptors are in the input's own heights",
      twin.own.offset, twin.own.scale));
}

nlohmann::json droplet_spec_shape() {
  return {{"start", nlohmann::json::array({"integer", "integer"})},
          {"positions", nlohmann::json::array({nlohmann::json::array({"number", "number"})})},
          {"sediment", "number"},
          {"cells", cell_values_shape()},
          {"tolerance", "number"}};
}

void add_droplet_spec_checks(const nlohmann::json& spec, const DropletTrace& trace, CaseResult& result) {
  const double tolerance = spec.at("tolerance");
  const auto& positions = spec.at("positions");
  double position_error = positions.size() == trace.positions.size() ? 0.0 : INFINITY;
  for (std::size_t k = 0; k < std::min(positions.size(), trace.positions.size()); ++k) {
    position_error = std::max({position_error, std::abs(trace.positions[k].first - positions[k][0].get<double>()),
                               std::abs(trace.positions[k].second - positions[k][1].get<double>())});
  }
  double cell_error = 0.0;
  for (const auto& cell : spec.at("cells")) {
    cell_error = std::max(cell_error, std::abs(trace.heights_after.at(cell[0], cell[1]) - cell[2].get<double>()));
  }
  const std::string why = fmt::format("tolerance {:g}: the hand derivation's decimals against double roundings", tolerance);
  result.checks.push_back(bounded_check("spec.droplet.positions.cpu", position_error, tolerance, std::nullopt,
                                        "largest coordinate error over the droplet's positions (count must match); " + why));
  result.checks.push_back(bounded_check("spec.droplet.sediment.cpu",
                                        std::abs(trace.sediment - spec.at("sediment").get<double>()), tolerance,
                                        std::nullopt, "sediment carried at the end of its life; " + why));
  result.checks.push_back(bounded_check("spec.droplet.cells.cpu", cell_error, tolerance, std::nullopt,
                                        "heights after its life at the listed texels; " + why));
}

SteppedTwin droplet_stepped_twin(std::shared_ptr<const DropletTwin> twin) {
  SteppedTwin stepped{.algorithm = twin->algorithm,
                      .fields = {terrain_field(twin->unit)},
                      .initial = twin->initial,
                      .iterations = twin->iterations};
  stepped.reference_double = [twin]() -> std::unique_ptr<Stepper> {
    return std::make_unique<ReferenceStepper<double>>(
        [twin](const Grid<double>& heights, int first, int count) {
          return twin->reference_double(heights, first, count, sequential(*twin));
        },
        twin->own);
  };
  stepped.reference_float = [twin]() -> std::unique_ptr<Stepper> {
    return std::make_unique<ReferenceStepper<float>>(
        [twin](const Grid<float>& heights, int first, int count) {
          return twin->reference_float(heights, first, count, twin->setup);
        },
        twin->own);
  };
  stepped.make_gpu = [twin]() -> std::unique_ptr<Stepper> {
    return std::make_unique<GpuStepper>(twin->make_gpu(twin->setup), twin->own);
  };
  if (twin->setup.ordering == DropletOrdering::race) stepped.gpu_nondeterminism = "the GPU's droplets of a pass race for cells";
  stepped.gpu_not_described =
      "the GPU is held to ref<float> (bit for bit, within rounding, or racing by its droplets in batch); against "
      "ref<double> a droplet's discrete path parts from the truth's at the first rounding that moves its texel (and "
      "batch and race order the droplets otherwise), so the descriptors' GPU-to-double parity would grade that";
  stepped.shadow_bounds = [twin](const State&, int count) { return std::vector<ShadowBound>{shadow_bound(*twin, count)}; };
  stepped.ledger = ledger_terms(twin);
  stepped.finish = [twin](const std::vector<BackendEnd>& ends, const nlohmann::json&, const RunOptions& options,
                          CaseResult& result) { finish(*twin, ends, options, result); };
  stepped.finish_gpu_checks = [twin](const nlohmann::json&) { return finish_gpu_checks(*twin); };
  return stepped;
}

MemoryEstimate droplet_checkpoint_memory(double cells, int iterations) {
  const auto marks = static_cast<double>(shadow_starts(iterations, SteppedTwin{}.checkpoints).size() + 1);
  return memory_for(cells * marks, "cell-checkpoints", 2.0 * sizeof(double));
}

BenchmarkRow droplet_gpu_row(const DropletTwin& twin, DropletOrdering ordering, int reps, const Environment& environment,
                             const std::string& backend) {
  const Grid<float> input = twin.input.cast<float>();
  const int passes = twin.setup.spacing * twin.setup.spacing;
  const DropletSetup setup{twin.setup.spacing, ordering};
  const auto gpu_steps = twin.reference_float(input, 0, 1, setup).ledger.steps;
  DropletGpu gpu = twin.make_gpu(setup);
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) {
    gpu.load(input, 0);  // the upload is not timed
    times.push_back(gpu_wall_ms([&] { gpu.step(1); }));
  }
  return iteration_row(twin.algorithm, backend, twin.input.width, reps, median(times), double(gpu_steps),
                       environment.gl_renderer,
                       ordering == DropletOrdering::batch
                           ? fmt::format("batch droplets, {} passes + {} applies", passes, passes)
                           : fmt::format("race droplets, {} passes", passes));
}

std::vector<BenchmarkRow> droplet_benchmark_rows(const DropletTwin& twin, int reps, bool gpu_available,
                                                 const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  const int size = twin.input.width;
  long long steps = 0;
  std::vector<double> cpu_times;
  for (int rep = 0; rep < reps; ++rep) {
    cpu_times.push_back(
        cpu_wall_ms([&] { steps = twin.reference_double(twin.input, 0, 1, sequential(twin)).ledger.steps; }));
  }
  rows.push_back(iteration_row(twin.algorithm, "cpu", size, reps, median(cpu_times), double(steps), environment.cpu,
                               "ref<double>, sequential droplets"));
  if (!gpu_available) return rows;
  for (const DropletOrdering ordering : {DropletOrdering::race, DropletOrdering::batch}) {
    rows.push_back(droplet_gpu_row(twin, ordering, reps, environment, "gpu"));
  }
  return rows;
}

}  // namespace gt
