// What a run produces: checks grouped into case results, the environment and benchmark rows.
// The report writers (compare/report/) turn a Report into report.json (schema 1 of DESIGN.md),
// report.md, junit.xml and index.html.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/report_diff.hpp"

namespace gt {

// dEQP-style outcome vocabulary of DESIGN.md:
//   pass          the value is within the strict bound (or the check is informative);
//   warn          beyond the strict bound, within a finite loose one justified beside the check;
//   inconclusive  the error model's bound exceeds the share of the field's scale at which the
//                 comparison could still tell a bug from rounding: nothing is known either way;
//   fail          beyond every bound;
//   skip          not run here, with the reason (a GPU half without a GL context): never a pass;
//   error         could not run (an exception, a GL error, --require-gpu without a context, a
//                 worker process that crashed or ran past --case-timeout);
//   flaky         (cases only) failed, then passed when run again (--retries): never a pass.
enum class Outcome { pass, fail, warn, inconclusive, skip, error, flaky };

const char* outcome_name(Outcome outcome);

// The outcome named `name` ("pass", ..., "flaky"), or std::nullopt.
std::optional<Outcome> outcome_from_name(const std::string& name);

// The worse of two outcomes: error > fail > flaky > skip > inconclusive > warn > pass. A case with
// any skipped check is at best skip (its GPU half did not run: not a pass); any failure makes it fail.
Outcome worse(Outcome a, Outcome b);

struct Check {
  std::string name;                  // <kind>.<what>[.<backend>], e.g. mass.relative_drift.gpu
  double value = 0.0;
  std::optional<double> threshold;   // strict bound: value <= threshold passes
  std::optional<double> loose_threshold;  // value <= loose_threshold is `warn` rather than `fail`
  Outcome status = Outcome::pass;
  std::string detail;                // error model or reason (why a skip, what failed)
  std::optional<Outcome> expected;   // the outcome datasets/expectations.txt names for this check
  std::string expectation;           // that entry's reason
};

struct Timings {
  std::optional<double> cpu_ms;      // median wall time of one run of the reference (double)
  std::optional<double> gpu_ms;      // median wall time of one GPU run, bracketed by glFinish
  int cpu_reps = 0;
  int gpu_reps = 0;
};

// How a map's colours read as values: what its colour bar shows. Rendered views and colour
// photographs carry none.
struct ColourScale {
  std::string palette;  // its name: "terrain" (hillshaded heights), "diverging" (blue −, white 0, red +), ...
  double low = 0.0;     // the value at the palette's left end
  double high = 0.0;    // the value at its right end
  std::string unit;     // "m", "levels", ...; "1" for a dimensionless value
  std::vector<std::array<float, 3>> colours;  // the palette sampled evenly from low to high, RGB in [0, 1]
};

struct Artifact {
  std::string path;     // relative to the report folder
  std::string kind;     // "image" (PNG to show), "field" (EXR data), "plot"
  std::string caption;
  std::optional<ColourScale> scale;  // maps: their colour bar
  // Maps of a grid: the picture's width in metres (the grid's width times its cell size), for its
  // scale bar; unset for rendered views, photographs and plots.
  std::optional<double> width_m;
};


struct CaseResult {
  std::string name;           // stable dotted name, e.g. erosion.thermal.cardinal.volcano
  std::string algorithm;      // e.g. erosion.thermal
  std::string input;          // what the input was, e.g. "volcano.json (87x61, 10 m)"
  std::vector<std::string> notes;  // what the input reader decided (channel used, units, no-data)
  int width = 0;
  int height = 0;
  Outcome status = Outcome::pass;
  std::string expected_failure;  // when every failing check is listed in datasets/expectations.txt: their reasons
  nlohmann::json params = nlohmann::json::object();
  std::vector<Check> checks;
  Timings timings;
  std::vector<Artifact> artifacts;
  // Terrain descriptors of the input, each twin's result and a real DEM (compare/case_descriptors.hpp),
  // null for cases that are not terrains.
  nlohmann::json descriptors;
  std::string error;          // set when status == error
  double seconds = 0.0;       // wall time of the whole case (twins, checks, pictures); balances shards
  std::string tier;           // the suite tier its case file declares (compare/cases.hpp); empty: ad hoc
  std::optional<double> expected_seconds;  // what it was expected to take (compare/case_seconds.hpp)
  // When the case was run again (--retries): the attempts before the last, whose results these are.
  struct Attempt {
    Outcome status = Outcome::fail;
    std::string error;
    std::vector<std::string> failing_checks;  // "check = value (bound)"
  };
  std::vector<Attempt> earlier_attempts;
  std::string known_flake;    // a flaky case's reason from the flake list (an expectation `flaky`)
};

// Adds the picture `file` of the case's folder (result.name/file) with its caption and, for a map,
// its colour scale and its width in metres (map_width_m of the grid it shows).
void add_picture(CaseResult& result, const std::string& file, std::string caption,
                 std::optional<ColourScale> scale = std::nullopt, std::optional<double> width_m = std::nullopt);

// The width in metres of a map of a grid `width` cells across of `cell_size_x` metres; unset when
// that is not a positive finite length.
std::optional<double> map_width_m(int width, double cell_size_x);

struct Environment {
  std::string gl_renderer;    // GL_RENDERER, or "none: <reason>"
  std::string gl_version;
  std::string gl_platform;    // "egl-device", "egl-surfaceless", "osmesa", or "none"
  std::string cpu;
  std::string compiler;
  std::string build_type;
  std::string git;            // `git describe --always --dirty` of the source tree at run time
  std::string mutant;         // the deliberate bug this run was made with (compare/mutants/), or empty
  // What stood where the GPU twin stands, when it was not groundtruth's own shaders: "the candidate
  // file F", "the implementation LIB:SYMBOL", "a Python model (groundtruth.check)", "the GPU shaders
  // in DIR over groundtruth's"; empty for groundtruth's GPU twins. The report's headline names it.
  std::string graded;
  std::optional<double> calibration_ms;  // compare/calibration.hpp: timings are compared as ratios to it
  // Provenance (compare/provenance.hpp): what exactly ran, so that two reports can be told apart.
  std::string run_started;       // UTC, ISO 8601, e.g. "2026-12-02T04:13:46Z"
  std::string command_line;      // the words of the command, shell-quoted where needed
  std::string git_revision;      // the source tree's commit at run time (shaders are read from it), or why unknown
  bool git_dirty = false;        // the source tree had uncommitted changes to tracked files
  std::string git_at_configure;  // `git describe` when the build was configured: what the binary was built from
  std::string build_flags;       // the C++ compiler flags of this build type
  std::map<std::string, std::string> shaders;  // shader stage compiled (path, defines) -> SHA-256 of its expanded source
  std::map<std::string, std::string> data;     // data file read -> SHA-256
};

struct BenchmarkRow {
  std::string algorithm;
  std::string backend;        // "cpu" (reference, double) or "gpu"
  int size = 0;               // grid side: size x size cells
  int iterations = 0;
  int reps = 0;
  double median_ms = 0.0;     // one run of `iterations` iterations
  double mcell_iterations_per_s = 0.0;
  std::string device;         // CPU model or GL_RENDERER
  int dimensions = 2;         // size^dimensions cells (3: voxels of a cave block)
  std::optional<double> mtriangles_per_s;  // meshers: output triangles per second, millions
  std::string note;           // why a row has no time (the size did not fit the device)
  std::string detail;         // what a timed row measured beyond its numbers (GPU passes per step, a published source)
  // A peer's row: the library and function timed on the same input (e.g. "VTK 9.1 vtkFlyingEdges3D");
  // empty for groundtruth's own twins and for the bandwidth probe.
  std::string peer;
  // Memory traffic counted from the kernel's passes: bytes read plus written per cell (voxel,
  // sample) and iteration, as stated beside each kernel. Unset where it was not counted.
  std::optional<double> bytes_per_cell;
  // The memory-bound floor: bytes_per_cell · cells · iterations over the copy bandwidth measured on
  // the same device in the same run (compare/benchmark_table.hpp), and median_ms / floor_ms.
  std::optional<double> floor_ms;
  // median_ms over the fastest peer's on the same algorithm and size (our rows only), and its name.
  std::optional<double> times_peer;
  std::string fastest_peer;
};

// `groundtruth mutants` (compare/mutation.hpp): each registered mutant run on its cases in a worker.
struct MutantOutcome {
  std::string name;         // e.g. erosion.pipe.half_rain
  std::string family;       // erosion, noise, cave, render
  std::string kind;         // "one-twin" or "both-twins"
  std::string description;
  bool must_survive = false;          // a calibration mutant below its error model's bound
  std::vector<std::string> cases;     // the case names it ran
  std::string status;                 // killed, survived, error (the run could not tell), timeout
  std::vector<std::string> killed_by; // "case: check = value (bound)", checks of the kind meant for it
  std::vector<std::string> killing_checks;  // the names of those checks, each once (the kill matrix)
  std::vector<std::string> other_failures;  // failing checks of the other kind: they do not count
  std::string error;                  // why the run could not tell
  double seconds = 0.0;
  std::string run_folder;             // its report, relative to the mutation report's folder
  // Killed for a bug, survived for a must-survive mutant.
  bool as_expected() const { return status == (must_survive ? "survived" : "killed"); }
};

struct MutationBaseline {
  std::string family;
  std::vector<std::string> cases;
  bool clean = false;                 // every case ran and nothing failed unmutated
  std::vector<std::string> problems;  // what failed unmutated
  std::vector<std::string> graded_checks;  // the names of its checks that carry a bound, each once
  double seconds = 0.0;
  std::string run_folder;
};

// The harness's false-alarm rate beside the mutation score (`groundtruth specificity`, run by
// `report --full`): honest runs with drawn parameters, and those that failed or erred.
// 1 − false_alarms / runs (1 when nothing ran): the share of honest runs not failed.
double specificity_share(int false_alarms, int runs);

struct SpecificitySummary {
  int runs = 0;
  int false_alarms = 0;
  std::string page;                   // its specificity.html, relative to the report's root
  std::string problem;                // why there is no figure (the run did not finish), else empty
};

// One row of the kill matrix: a graded check and the mutants of its kind it killed.
struct KillRow {
  std::string check;
  std::vector<std::string> mutants;
};

struct MutationReport {
  std::string folder;                 // where the runs are, relative to the report's root ("" or "mutants/")
  std::vector<MutationBaseline> baselines;
  std::vector<MutantOutcome> mutants;
  std::optional<SpecificitySummary> specificity;
  int bugs() const;                   // the mutants meant to be killed (all but the must-survive ones)
  int killed() const;                 // of those, killed
  double score() const;               // killed / bugs, 0..1 (1 when none ran)
  // Every bug killed, every must-survive mutant survived, and every baseline clean.
  bool passed() const;
  // Every check graded in a baseline or killing a mutant, by name, with the mutants it killed;
  // sorted by name.
  std::vector<KillRow> kill_matrix() const;
};

// A shard of a run (--shard K/N, compare/shards.hpp): every shard records the whole selection, so
// that `groundtruth merge` can tell a missing or overlapping shard from a complete set.
struct ShardInfo {
  int index = 1;                       // K, 1-based
  int count = 1;                       // N
  std::vector<std::string> selection;  // every case name selected before sharding, in run order
  std::string balanced_by;             // the baseline whose case times balanced the shards, or empty
};

struct Report {
  Environment environment;
  std::vector<CaseResult> cases;
  std::vector<BenchmarkRow> benchmarks;
  std::vector<Artifact> plots;  // report-level plots (timings over sizes)
  // Broken rules of datasets/expectations.txt (compare/expectations.hpp): each fails the run.
  std::vector<std::string> expectation_problems;
  std::optional<MutationReport> mutation;  // when the run included the mutants (groundtruth report)
  std::string baseline_file;               // --baseline, and what changed against it
  std::optional<ReportDiff> baseline_diff;
  std::optional<ShardInfo> shard;          // --shard K/N: which part of the selection this report holds
  // What a tiered run left out and how to run it (compare/cases.hpp Tier), e.g. "tier report: ...";
  // empty when nothing was left out by a tier.
  std::string scope;
};

// Why a GPU check is skipped when the user asked for the references alone (--backend cpu).
inline constexpr const char* gpu_not_requested = "GPU backend not requested (--backend cpu)";

// Whether the user left this check out (a skip for gpu_not_requested): shown with why, but not
// part of the case's outcome, which the checks that ran decide.
bool left_out_by_request(const Check& check);

// Outcome of a whole case from its checks (and the expectation list): the worst of the checks not
// left out by request (skip when there are none).
Outcome case_outcome(const CaseResult& result);

// Whether the expectation list names the outcome this check had.
bool met_expectation(const Check& check);

// The case's failed and errored checks as "name = value (bound b)", in check order.
std::vector<std::string> failing_checks(const CaseResult& result);

// Whether a case failed in a way nobody expected: it errored, a check failed that the expectation
// list does not name with that outcome, or it was flaky and is not on the flake list.
bool failed_unexpectedly(const CaseResult& result);

// Whether the run as a whole failed: a case failed unexpectedly, or a rule of the expectation
// list was broken.
bool run_failed(const Report& report);

}  // namespace gt
