// The comparison driver behind `groundtruth run`, `report` and `bench`: selects cases, loads and
// checks every input before anything runs (bad input -> InputError, exit 2, nothing written),
// makes the GL context, runs the cases, and writes the report folder atomically.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/benchmark.hpp"
#include "compare/cases.hpp"
#include "compare/external/bmi_model.hpp"
#include "compare/external/implementation.hpp"
#include "compare/mutation.hpp"
#include "compare/output_folder.hpp"
#include "compare/result.hpp"
#include "gpu/context/context.hpp"

namespace gt {

enum class Backends { cpu, gpu, both };

struct AdHocCase {
  std::string algorithm;
  std::string input;                     // a heightmap file; empty for a generator (noise) on a
  int width = 256;                       //   width x height grid of cell_size
  int height = 256;
  double cell_size = 0.0;                // metres; 0: the file's own, or 1 m for a generator
  double cell_size_y = 0.0;              // the rows' spacing when it differs from cell_size (0: cell_size)
  std::vector<std::string> assignments;  // "name=value"
  bool red_channel = false;              // a colour image's red channel as height (else it is refused)
  double image_vertical_scale = 0.0;     // metres per unit of an 8/16-bit image (0: the reader's 1)
  std::vector<std::string> fields;       // input fields of the heightmap, "name=file" (--field)
  std::string name;                      // the case's name; empty: adhoc.<algorithm>.<input>
};

// The input's part of an ad-hoc case's name: the input file's stem, a generator's WxH grid, or
// "params" for an algorithm that takes no heightmap; as a case name part (compare/cases.hpp).
std::string ad_hoc_input_name(const AdHocCase& ad_hoc);

// `groundtruth sweep` (compare/sweep.hpp): one ad-hoc case per combination of the varied values;
// `groundtruth ab` (compare/ab.hpp): two variants, A and B, side by side; `groundtruth
// specificity` (compare/specificity.hpp): drawn parameter sets of several algorithms, tallied.
enum class SweepKind { grid, ab, specificity };

struct Sweep {
  std::vector<std::string> varied;   // the varied parameters, in the order given (named sets: "set"; ab: none)
  std::vector<AdHocCase> variants;   // each with its assignments and name (ab: A, then B)
  std::vector<std::vector<std::string>> varied_values;  // per variant, its value of each varied one
  SweepKind kind = SweepKind::grid;  // how the runs are summarised
  std::string ab_stem = "ab";        // its files: <stem>.html, <stem>.json, <stem>_difference.png
};

struct DriverOptions {
  std::vector<std::string> patterns;     // case-name globs
  std::optional<Tier> tier;              // only the cases of this tier and those it holds (run --quick, report)
  std::string left_out;                  // what else the tier leaves out (report: benchmark sizes, mutants)
  std::optional<AdHocCase> ad_hoc;
  std::optional<Sweep> sweep;            // a sweep's variants, run as ad-hoc cases and tabled
  Backends backends = Backends::both;
  GlBackend gl = GlBackend::egl;
  std::filesystem::path out;
  std::filesystem::path dataset_dir;
  std::vector<std::filesystem::path> extra_cases;  // --cases: more case files or folders
  int cpu_reps = 3;                      // timed repetitions; 0: the twins run untimed (and no calibration)
  int gpu_reps = 5;
  bool pictures = true;                  // RunOptions::pictures and ::descriptors (the Python module's knobs)
  bool descriptors = true;
  int checkpoints = 0;  // a stepped case's shadow-step starts (--checkpoints); 0: the algorithm's own
  std::optional<BenchmarkOptions> benchmark;
  std::string mutant;                    // a registered mutant to activate (compare/mutants/), or empty
  bool require_gpu = false;              // a missing GL context makes every GPU-using case `error`
  bool quiet = false;                    // no progress lines on stderr
  double heartbeat_seconds = 30.0;       // a "still running" line after this long without one
  bool summary = true;                   // each case's outcome and the totals on stdout (the Python module asks none)
  std::filesystem::path baseline;        // a previous report.json to diff against (compare/report_diff.hpp)
  std::optional<MutationOptions> mutation;  // also run the mutants (report: into OUT/mutants/)
  std::vector<std::filesystem::path> expectation_files;  // --expectations: the user's known outcomes
  std::vector<std::filesystem::path> flake_files;        // --flakes: flake lists (entries `flaky`)
  int parallel = 1;                      // -j: cases in this many worker processes at once
  std::optional<double> case_timeout;    // --case-timeout seconds (runs the cases in workers)
  int retries = 0;                       // --retries: a failing case is run again up to this often
  std::string shard;                     // --shard K/N or auto (compare/shards.hpp), or empty
  std::string command_line;              // for the report's provenance
  double memory_limit_mib = 0.0;         // --memory-limit, passed on to workers (0: none)
  bool worker = false;                   // a worker process of a parent run (compare/isolated_cases.hpp)
  // --implementation: an outside model graded where the GPU twin stands (compare/external/); its
  // cases run in workers.
  std::optional<ExternalImplementation> implementation;
  // An outside model made in this process (the Python module's groundtruth.check): run in-process,
  // never in workers (it lives in the caller's interpreter).
  std::optional<ExternalModel> external_model;
  // --gpu-shaders: a folder of the user's shader files laid over the built-in ones
  // (compare/external/gpu_shader_drop_ins.hpp); empty: none.
  std::filesystem::path gpu_shaders;
  // --candidate: a user's output file graded where the GPU twin's stands (one generated case).
  std::filesystem::path candidate;
};

// `groundtruth mutants`: runs the mutation into `out` (atomically, like a report), writes
// mutants.json there and prints the table (or the JSON); returns 0 when every mutant was killed
// and every baseline was clean, else 1.
int run_mutants_command(const MutationOptions& options, const std::filesystem::path& out, bool as_json,
                        const std::string& command_line);

// Runs everything and writes the report; returns the process exit status (0 nothing unexpected
// failed, 1 something did). Throws InputError for bad usage or input before writing anything.
int run_driver(const DriverOptions& options);

}  // namespace gt
