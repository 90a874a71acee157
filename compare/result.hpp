// What a run produces: checks grouped into case results, the environment and benchmark rows.
// The report writers (compare/report/) turn a Report into report.json (schema 1 of DESIGN.md),
// report.md, junit.xml and index.html.
#pragma once

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
//   error         could not run (an exception, a GL error, --require-gpu without a context).
enum class Outcome { pass, fail, warn, inconclusive, skip, error };

const char* outcome_name(Outcome outcome);

// The worse of two outcomes: error > fail > skip > inconclusive > warn > pass. A case with any
// skipped check is at best skip (its GPU half did not run: not a pass); any failure makes it fail.
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

struct Artifact {
  std::string path;     // relative to the report folder
  std::string kind;     // "image" (PNG to show), "field" (EXR data), "plot"
  std::string caption;
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
};

struct Environment {
  std::string gl_renderer;    // GL_RENDERER, or "none: <reason>"
  std::string gl_version;
  std::string gl_platform;    // "egl-device", "egl-surfaceless", "osmesa", or "none"
  std::string cpu;
  std::string compiler;
  std::string build_type;
  std::string git;
  std::string mutant;         // the deliberate bug this run was made with (compare/mutants/), or empty
  std::optional<double> calibration_ms;  // compare/calibration.hpp: timings are compared as ratios to it
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
};

// `groundtruth mutants` (compare/mutation.hpp): each registered mutant run on its cases in a worker.
struct MutantOutcome {
  std::string name;         // e.g. erosion.pipe.half_rain
  std::string family;       // erosion, noise, cave, render
  std::string kind;         // "one-twin" or "both-twins"
  std::string description;
  std::vector<std::string> cases;     // the case names it ran
  std::string status;                 // killed, survived, error (the run could not tell), timeout
  std::vector<std::string> killed_by; // "case: check = value (bound)", checks of the kind meant for it
  std::vector<std::string> other_failures;  // failing checks of the other kind: they do not count
  std::string error;                  // why the run could not tell
  double seconds = 0.0;
  std::string run_folder;             // its report, relative to the mutation report's folder
};

struct MutationBaseline {
  std::string family;
  std::vector<std::string> cases;
  bool clean = false;                 // every case ran and nothing failed unmutated
  std::vector<std::string> problems;  // what failed unmutated
  double seconds = 0.0;
  std::string run_folder;
};

struct MutationReport {
  std::string folder;                 // where the runs are, relative to the report's root ("" or "mutants/")
  std::vector<MutationBaseline> baselines;
  std::vector<MutantOutcome> mutants;
  int killed() const;
  double score() const;               // killed / registered, 0..1 (1 when none ran)
  bool passed() const;                // every mutant killed and every baseline clean
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
};

// Outcome of a whole case from its checks (and the expectation list).
Outcome case_outcome(const CaseResult& result);

// Whether the run as a whole failed: a case errored, a check failed that the expectation list
// does not name with that outcome, or a rule of the expectation list was broken.
bool run_failed(const Report& report);

}  // namespace gt
