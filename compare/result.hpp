// What a run produces: checks grouped into case results, the environment and benchmark rows.
// The report writers (compare/report/) turn a Report into report.json (schema 1 of DESIGN.md),
// report.md, junit.xml and index.html.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

// dEQP-style outcome vocabulary of DESIGN.md.
enum class Outcome { pass, fail, warn, skip, error };

const char* outcome_name(Outcome outcome);

// The worse of two outcomes: error > fail > warn > pass > skip (a case whose checks all skipped
// is skip; any failure makes it fail).
Outcome worse(Outcome a, Outcome b);

struct Check {
  std::string name;                  // <kind>.<what>[.<backend>], e.g. mass.relative_drift.gpu
  double value = 0.0;
  std::optional<double> threshold;   // strict bound: value <= threshold passes
  std::optional<double> loose_threshold;  // value <= loose_threshold is `warn` rather than `fail`
  Outcome status = Outcome::pass;
  std::string detail;                // error model or reason (why a skip, what failed)
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
  std::string expected_failure;  // reason from datasets/expectations.txt, empty when not expected
  nlohmann::json params = nlohmann::json::object();
  std::vector<Check> checks;
  Timings timings;
  std::vector<Artifact> artifacts;
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

struct Report {
  Environment environment;
  std::vector<CaseResult> cases;
  std::vector<BenchmarkRow> benchmarks;
  std::vector<Artifact> plots;  // report-level plots (timings over sizes)
};

// Outcome of a whole case from its checks (and the expectation list).
Outcome case_outcome(const CaseResult& result);

// Whether the run as a whole failed: some case failed or errored and was not expected to, or an
// expected failure passed (the expectation list is stale).
bool run_failed(const Report& report);

}  // namespace gt
