// groundtruth: the command line of DESIGN.md.
//   list [--json]                      algorithms (parameters, defaults, ranges, units) and cases
//   run PATTERN... | --algorithm A --input FILE [--set k=v]... [--backend] [--out] [--gl]
//       [--cases FILE_OR_FOLDER] [--mutant NAME] [--require-gpu] [--quiet]
//   report [--out] [--gl] [--no-benchmark] [--no-mutants] [--require-gpu]
//                                      the default suite, benchmarks and mutants into reports/latest
//   bench [PATTERN...] [--sizes] [--iterations]  only the performance table (with its peers and floor)
//   mutants [PATTERN...] [--list] [--json] [--out] [--specificity-sets N]
//                                      each registered mutant on its cases: which checks kill it
//   check-mesh FILE [--json]           the mesh checks on an OFF, OBJ, PLY or STL file
//   diff-image A B [--json] [--out diff.png] [--tolerance T]
//                                      image differences, a heat map and a verdict mask
//   diff-reports BASE NEW [--json]     what changed between two report.json files (exit 1: a regression)
//   merge SHARD_DIR... --out DIR       one report from the folders of a sharded run (--shard K/N)
//   history REPORT... --out DIR        checks and timings over a series of reports, as plots
// run/report/bench also take -j N, --case-timeout S, --retries N, --expectations FILE, --flakes FILE,
// --shard K/N|auto and --baseline FILE.
//   stats DEM [--json] [--out DIR] [--cell-size] [--stream-threshold]
//                                      terrain descriptors: hypsometry, slope, curvature, drainage, spectrum
//   render INPUT --out out.png [--backend cpu|gpu] [--width --height --azimuth --elevation --fov
//          --distance | --eye --target] [--look]   a mesh or a heightmap (as a terrain solid) to a PNG
// Every command takes --memory-limit MIB (core/memory.hpp).
// Exit status: 0 nothing unexpected failed, 1 something did (mutants: one survived), 2 bad usage or
// bad input (README's "Outcomes and exit status")
// (check-mesh: 0 watertight and consistently oriented, 1 not, 2 unreadable;
// diff-image: 0 no pixel fails the neighbourhood-tolerant comparison, 1 some do, 2 bad input;
// stats: 0 something measured, 2 unreadable or nothing measurable;
// render: 0 written, 2 bad input, a camera inside the mesh or seeing nothing, or no GL context for gpu).

#include <algorithm>
#include <cmath>
#include <cerrno>
#include <cstdio>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <system_error>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/ab.hpp"
#include "compare/algorithm.hpp"
#include "compare/case_seconds.hpp"
#include "compare/cases.hpp"
#include "core/memory.hpp"
#include "compare/cli/check_mesh.hpp"
#include "compare/cli/compare_mesh.hpp"
#include "compare/cli/diff_image.hpp"
#include "compare/cli/render.hpp"
#include "compare/cli/stats.hpp"
#include "compare/driver.hpp"
#include "compare/mutants/mutants.hpp"
#include "compare/output_folder.hpp"
#include "compare/progress.hpp"
#include "compare/provenance.hpp"
#include "compare/report_diff.hpp"
#include "compare/report_history.hpp"
#include "compare/shards.hpp"
#include "compare/specificity.hpp"
#include "compare/sweep.hpp"
#include "compare/worker.hpp"
#include "core/errors.hpp"

namespace {

using gt::Backends;

constexpr int exit_bad_input = 2;

// A number that is finite as well as in range: CLI11's range validators let "nan" through.
const CLI::Validator finite_number(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value)) return "'" + text + "' is not a finite number";
      return {};
    },
    "FINITE");

struct Shared {
  std::string gl = "egl";
  std::string backend = "both";
  std::string out;
  int cpu_reps = 3;
  int gpu_reps = 5;
  int checkpoints = 0;
  bool require_gpu = false;
  bool quiet = false;
  std::string baseline;
  int parallel = 1;
  double case_timeout = 0.0;
  int retries = 0;
  std::vector<std::string> expectations;
  std::vector<std::string> flakes;
  std::string shard;
  bool worker = false;
  double heartbeat = 30.0;
};

// What makes an ad-hoc case (run, sweep, ab) beside its algorithm: the input, the parameters held
// fixed, the red channel of a colour image, a generator's grid and cell size, and the backends.
void add_ad_hoc_options(CLI::App& command, gt::AdHocCase& ad_hoc, std::string& grid_size, Shared& shared) {
  command.add_option("--input", ad_hoc.input, "a heightmap file (PNG, TIFF/GeoTIFF, EXR, volcano JSON, npz, npy)");
  command.add_option("--set", ad_hoc.assignments, "a parameter, name=value (repeatable)");
  command.add_option("--field", ad_hoc.fields,
                     "an input field of the --input heightmap, name=file, of its size (repeatable; `groundtruth list "
                     "--json` names the fields each algorithm reads, e.g. erosion.layered's profile, vegetation and "
                     "obstacle, erosion.thermal_jako's hardness)");
  command.add_flag("--red-channel", ad_hoc.red_channel,
                   "take a colour image's red channel as height (seed 000 §4.2); without it a colour image is refused "
                   "as not a heightmap");
  command.add_option("--size", grid_size, "a generator (noise) without --input: the grid, WxH (256x256)");
  auto* cell_size = command.add_option("--cell-size", ad_hoc.cell_size,
                     "cell size in metres: a generator's grid (default 1), or in place of the --input file's own")
      ->check(finite_number & CLI::PositiveNumber);
  command.add_option("--cell-size-y", ad_hoc.cell_size_y,
                     "rectangular cells: the rows' spacing in metres, --cell-size then being the columns'")
      ->check(finite_number & CLI::PositiveNumber)
      ->needs(cell_size);
  command.add_option("--image-vertical-scale", ad_hoc.image_vertical_scale,
                     "metres per unit of an 8/16-bit image --input (default 1; a case file's \"vertical_scale\")")
      ->check(finite_number & CLI::Range(1e-9, 1e9));
  command.add_option("--backend", shared.backend, "cpu (references only), gpu, or both")
      ->check(CLI::IsMember({"cpu", "gpu", "both"}))
      ->capture_default_str();
}

void add_shared_options(CLI::App& command, Shared& shared, const std::string& default_out) {
  shared.out = default_out;
  command.add_option("--gl", shared.gl, "GL context: egl (hardware device, else surfaceless llvmpipe) or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}))
      ->capture_default_str();
  command.add_option("--out", shared.out, "report folder (written atomically; an existing report is replaced)")
      ->capture_default_str();
  command.add_flag("--quiet", shared.quiet, "no progress lines on stderr");
  command.add_option("--heartbeat", shared.heartbeat,
                     "seconds without a progress line after which a `still running` line names the running cases")
      ->check(finite_number & CLI::Range(0.05, 3600.0))
      ->capture_default_str();
  command.add_option("--baseline", shared.baseline,
                     "a previous report.json: what changed (diff-reports) is printed at the end and heads index.html");
  command.add_flag("--require-gpu", shared.require_gpu,
                   "a missing GL context or a skipped GPU half makes the case `error` (exit 1) instead of `skip`");
  command.add_option("-j,--jobs", shared.parallel,
                     "run the cases in this many worker processes at once (each its own GL context; a crash or hang "
                     "ends only its case)")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  command.add_option("--case-timeout", shared.case_timeout,
                     "seconds a case may take before its worker is killed and it ends as error (runs cases in workers; "
                     "with -j alone the limit is 3600)")
      ->check(finite_number & CLI::Range(1.0, 604800.0));
  command.add_option("--retries", shared.retries, "run a failing case again up to this often; one that then passes is flaky")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  command.add_option("--expectations", shared.expectations,
                     "known outcomes of your own cases (the format of datasets/expectations.txt; repeatable)");
  command.add_option("--flakes", shared.flakes, "a flake list: expectation lines whose outcome is `flaky` (repeatable)");
  command.add_option("--shard", shared.shard,
                     "run the K-th of N parts of the cases, K/N (1-based), or auto from SLURM_ARRAY_TASK_ID, "
                     "CI_NODE_INDEX or JOB_COMPLETION_INDEX; join the parts with `groundtruth merge`");
  command.add_flag("--worker", shared.worker, "(internal) a worker process of a parent run")->group("");
  command.add_option("--cpu-reps", shared.cpu_reps, "timed repetitions of the CPU reference")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  command.add_option("--gpu-reps", shared.gpu_reps, "timed repetitions of the GPU twin")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command.add_option("--checkpoints", shared.checkpoints,
                     "states along an iterative (stepped) case's run from which the GPU and ref<float> take their "
                     "shadow steps, and at which the run is compared with ref<double> (default: each algorithm's own, "
                     "8; erosion.pipe its parameter checkpoints)")
      ->check(CLI::Range(1, 1000));
}

gt::DriverOptions driver_options(const Shared& shared, const std::string& command_line, double memory_limit_mib) {
  gt::DriverOptions options;
  options.gl = gt::parse_gl_backend(shared.gl);
  options.backends = shared.backend == "cpu" ? Backends::cpu : shared.backend == "gpu" ? Backends::gpu : Backends::both;
  options.out = shared.out;
  options.baseline = shared.baseline;
  options.dataset_dir = GT_DATASET_DIR;
  options.cpu_reps = shared.cpu_reps;
  options.gpu_reps = shared.gpu_reps;
  options.checkpoints = shared.checkpoints;
  options.require_gpu = shared.require_gpu;
  options.quiet = shared.quiet;
  options.heartbeat_seconds = shared.heartbeat;
  options.parallel = shared.parallel;
  if (shared.case_timeout > 0.0) options.case_timeout = shared.case_timeout;
  options.retries = shared.retries;
  options.expectation_files.assign(shared.expectations.begin(), shared.expectations.end());
  options.flake_files.assign(shared.flakes.begin(), shared.flakes.end());
  options.shard = shared.shard;
  options.worker = shared.worker;
  options.command_line = command_line;
  options.memory_limit_mib = memory_limit_mib;
  if (options.require_gpu && options.backends == Backends::cpu) {
    throw gt::InputError("--require-gpu and --backend cpu contradict each other: choose one");
  }
  return options;
}

// One side of "WxH": digits only, at most 65536 (no sign, no overflow: 4294967297 is refused).
std::optional<int> grid_side(const std::string& digits) {
  if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return {};
  const int side = std::stoi(digits);
  if (side < 1 || side > 65536) return {};
  return side;
}

// "WxH" -> width and height, each in [1, 65536].
void parse_grid_size(const std::string& text, gt::AdHocCase& ad_hoc) {
  const auto separator = text.find('x');
  const auto width = separator == std::string::npos ? std::nullopt : grid_side(text.substr(0, separator));
  const auto height = separator == std::string::npos ? std::nullopt : grid_side(text.substr(separator + 1));
  if (!width || !height) {
    throw gt::InputError(fmt::format("--size '{}': expected WxH with sides in [1, 65536], e.g. 512x256", text));
  }
  ad_hoc.width = *width;
  ad_hoc.height = *height;
}


// What `list` shows: every algorithm and case, or those a pattern names (an algorithm by its name,
// a case by its own name or its algorithm's); cases left out with --algorithms.
struct ListRequest {
  std::vector<std::string> patterns;  // shell-style (fnmatch); empty: everything
  bool algorithms_only = false;
  bool as_json = false;
};

nlohmann::json list_json(const ListRequest& request) {
  nlohmann::json out = {{"algorithms", nlohmann::json::array()}, {"cases", nlohmann::json::array()}};
  for (const auto& algorithm : gt::algorithms()) {
    if (gt::named_by_any(request.patterns, algorithm.name)) out["algorithms"].push_back(gt::algorithm_json(algorithm));
  }
  if (request.algorithms_only) return out;
  const auto recorded = gt::bundled_case_seconds(GT_DATASET_DIR);
  for (const auto& spec : gt::load_cases(std::filesystem::path(GT_DATASET_DIR) / "cases")) {
    if (!gt::named_by_any(request.patterns, spec.name) && !gt::named_by_any(request.patterns, spec.algorithm)) continue;
    nlohmann::json entry = {{"name", spec.name},   {"algorithm", spec.algorithm},     {"params", spec.params},
                            {"input", spec.input}, {"file", spec.origin},             {"tier", gt::tier_name(spec.tier)}};
    if (const auto found = recorded.find(spec.name); found != recorded.end()) entry["expected_seconds"] = found->second;
    out["cases"].push_back(std::move(entry));
  }
  return out;
}

// The default report's performance table: the smallest size of the full table (`report --full`
// times every size of gt::BenchmarkOptions).
const std::vector<int> report_tier_benchmark_sizes = {256};
// The parameter sets per algorithm of `report --full`'s specificity: issue 38's figure (20 sets on
// each of two inputs, 240 runs; about 20 minutes on 2 cores).
constexpr int full_report_specificity_sets = 20;

// A parameter's range as a person reads it: [0, 100000] for a whole number, [0.0, 85.0] for a real.
std::string range_text(const nlohmann::json& param) {
  if (param.contains("choices")) return param["choices"].dump();
  if (!param.contains("min")) return "true|false";
  if (param["kind"] == "integer") {
    return fmt::format("[{}, {}]", param["min"].get<long long>(), param["max"].get<long long>());
  }
  return fmt::format("[{}, {}]", param["min"].dump(), param["max"].dump());
}

void print_list(const ListRequest& request) {
  const auto listing = list_json(request);
  if (listing["algorithms"].empty() && listing["cases"].empty()) {
    throw gt::InputError(fmt::format("list: no algorithm or case matches {}; `groundtruth list` shows them all",
                                     fmt::join(request.patterns, " ")));
  }
  if (request.as_json) {
    fmt::print("{}\n", listing.dump(2));
    return;
  }
  fmt::print("Algorithms\n");
  for (const auto& algorithm : listing["algorithms"]) {
    fmt::print("  {}  {}\n    source: {}\n", algorithm["name"].get<std::string>(),
               algorithm["summary"].get<std::string>(), algorithm["source"].get<std::string>());
    // Columns as wide as the algorithm's widest entry (at least the usual widths), so that a long
    // name or range does not push the rest of its row out of line.
    std::size_t name_width = 16, default_width = 12, range_width = 22, unit_width = 8;
    for (const auto& param : algorithm["params"]) {
      name_width = std::max(name_width, param["name"].get<std::string>().size());
      default_width = std::max(default_width, param["default"].dump().size());
      range_width = std::max(range_width, range_text(param).size());
      unit_width = std::max(unit_width, param["unit"].get<std::string>().size());
    }
    for (const auto& param : algorithm["params"]) {
      fmt::print("    {:{}} default {:{}} {:{}} {:{}} {}\n", param["name"].get<std::string>(), name_width,
                 param["default"].dump(), default_width, range_text(param), range_width,
                 param["unit"].get<std::string>(), unit_width, param["description"].get<std::string>());
    }
  }
  if (request.algorithms_only) return;
  fmt::print("Cases (tier, and the seconds each took on the 2-core reference machine: datasets/case-seconds.json)\n");
  for (const auto& spec : listing["cases"]) {
    fmt::print("  {:64} {:6} {}\n", spec["name"].get<std::string>(), spec["tier"].get<std::string>(),
               spec.contains("expected_seconds") ? gt::human_duration(spec["expected_seconds"].get<double>()) : "");
  }
}

void print_mutant_list(const std::vector<gt::Mutant>& selected, bool as_json) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& mutant : selected) {
    out.push_back({{"name", mutant.name}, {"family", gt::mutant_family(mutant)}, {"kind", gt::mutant_kind_name(mutant.kind)},
                   {"description", mutant.description}, {"cases", mutant.cases}});
  }
  if (as_json) {
    fmt::print("{}\n", out.dump(2));
    return;
  }
  for (const auto& mutant : selected) {
    fmt::print("{:44} {:10} {}\n{:44} cases: {}\n", mutant.name, gt::mutant_kind_name(mutant.kind), mutant.description,
               "", fmt::format("{}", fmt::join(mutant.cases, " ")));
  }
}

}  // namespace

namespace {

// One option naming a parameter twice (--set a=1 --set a=2) is refused: which value was meant?
void refuse_repeated(const std::vector<std::string>& assignments, const char* option) {
  std::map<std::string, std::string> given;
  for (const std::string& assignment : assignments) {
    const std::string name = assignment.substr(0, assignment.find('='));
    const auto [earlier, first] = given.emplace(name, assignment);
    if (!first) {
      throw gt::InputError(fmt::format("{} names {} twice ({} and {}): give it once", option, name, earlier->second,
                                       assignment));
    }
  }
}

bool output_failure(const std::error_code& code) {
  return code == std::errc::broken_pipe || code == std::errc::no_space_on_device || code == std::errc::file_too_large ||
         code == std::errc::io_error;
}

int run_command_line(int argc, char** argv) {
  CLI::App app{"groundtruth: CPU references and GPU twins of terrain and cave algorithms, compared"};
  app.require_subcommand(1);
  // Before or after the subcommand (fallthrough): a cap below what the machine and ulimit -v allow.
  double memory_limit_mib = 0.0;
  app.add_option("--memory-limit", memory_limit_mib,
                 "refuse any input or case whose memory estimate exceeds this many MiB (the machine's available "
                 "memory and ulimit -v are always respected)")
      ->check(finite_number & CLI::Range(1.0, 1e9));
  app.fallthrough();

  app.set_version_flag("--version", [] { return gt::version_line(); }, "the version: the source tree's git revision and the build");
  ListRequest list_request;
  auto* list = app.add_subcommand("list", "algorithms with their parameters, and the cases");
  list->add_option("patterns", list_request.patterns,
                   "only the algorithms and cases these shell-style patterns name (a case also by its algorithm), "
                   "e.g. 'erosion.pipe*'");
  list->add_flag("--algorithms", list_request.algorithms_only, "the algorithms alone, without the cases");
  list->add_flag("--json", list_request.as_json, "machine-readable");

  Shared run_shared;
  std::vector<std::string> patterns;
  gt::AdHocCase ad_hoc;
  auto* run = app.add_subcommand("run", "run cases (globs over case names) or one ad-hoc case");
  run->add_option("patterns", patterns, "case-name patterns, e.g. 'erosion.thermal.*'");
  run->add_option("--algorithm", ad_hoc.algorithm, "ad-hoc case: the algorithm");
  std::string grid_size;
  add_ad_hoc_options(*run, ad_hoc, grid_size, run_shared);
  add_shared_options(*run, run_shared, "groundtruth-report");
  std::vector<std::string> extra_cases;
  run->add_option("--cases", extra_cases, "more case files (JSON arrays of cases) or folders of them, beside the bundled ones");
  run->add_option("--case-name", ad_hoc.name, "ad-hoc case: its name (a sweep's worker)")->group("");
  std::string implementation;
  std::string gpu_shaders;
  std::string candidate;
  run->add_option("--candidate", candidate,
                  "grade your own output where the GPU twin's stands: a noise field (.npy float32/float64 or EXR) "
                  "on the case's grid, a cave block's mesh (.ply/.obj/.off, lattice units) or a rendered image "
                  "(render.phong, render.terrain: PNG/EXR/..., the case's size); docs/external-implementations.md");
  run->add_option("--gpu-shaders", gpu_shaders,
                  "grade your own GLSL: a folder of shader files laid over the built-in ones by their path "
                  "(erosion/thermal_transfer.comp, ...; docs/gpu-shader-drop-ins.md)");
  run->add_option("--implementation", implementation,
                  "grade your own implementation where the GPU twin stands: a shared library with the C Basic Model "
                  "Interface (include/groundtruth/bmi.h), LIBRARY[:REGISTER_FUNCTION] (default register_bmi)");
  bool quick = false;
  run->add_flag("--quick", quick,
                "the quick tier: a pre-commit answer on every algorithm family in about two minutes (with "
                "patterns: their cases of the tier)");
  std::string mutant;
  run->add_option("--mutant", mutant,
                  "run with a registered deliberate bug switched on (see `groundtruth mutants --list`)");

  Shared sweep_shared;
  gt::AdHocCase sweep_base;
  std::vector<std::string> vary;
  std::string sweep_grid_size;
  bool force_sweep = false;
  auto* sweep = app.add_subcommand("sweep", "one algorithm on one input over a grid of parameter values: a table, "
                                            "plots against the varied parameter and a thumbnail of each run");
  sweep->add_option("--algorithm", sweep_base.algorithm, "the algorithm")->required();
  std::string sweep_sets;
  auto* vary_option =
      sweep->add_option("--vary", vary, "a parameter and its values, name=v1,v2,... (repeatable: every combination runs)");
  sweep->add_option("--sets", sweep_sets,
                    "a JSON file of named parameter sets, {\"name\": {\"parameter\": value, ...}, ...}: one run each, "
                    "instead of --vary")
      ->excludes(vary_option);
  add_ad_hoc_options(*sweep, sweep_base, sweep_grid_size, sweep_shared);
  sweep->add_flag("--force", force_sweep, fmt::format("run more than {} combinations", gt::sweep_run_cap));
  add_shared_options(*sweep, sweep_shared, "groundtruth-sweep");

  Shared ab_shared;
  gt::AdHocCase ab_base;
  std::vector<std::string> a_assignments, b_assignments;
  std::string ab_grid_size;
  auto* ab = app.add_subcommand("ab", "two variants of one algorithm on one input side by side: both results, their "
                                      "difference map and the change of every metric");
  ab->add_option("--algorithm", ab_base.algorithm, "the algorithm")->required();
  ab->add_option("--a", a_assignments, "variant A's parameter, name=value (repeatable)");
  ab->add_option("--b", b_assignments, "variant B's parameter, name=value (repeatable)");
  add_ad_hoc_options(*ab, ab_base, ab_grid_size, ab_shared);
  add_shared_options(*ab, ab_shared, "groundtruth-ab");

  Shared specificity_shared;
  std::vector<std::string> specificity_patterns;
  int specificity_sets = 20;
  std::uint32_t specificity_seed = 1;
  auto* specificity = app.add_subcommand(
      "specificity", "the harness's false-alarm rate: each stepping algorithm with parameter sets drawn from plausible "
                     "ranges, on two real inputs; every fail or error is counted and shown");
  specificity->add_option("patterns", specificity_patterns,
                          fmt::format("algorithm-name patterns (all of {} when none)", fmt::join(gt::specificity_algorithms(), ", ")));
  specificity->add_option("--sets", specificity_sets, "parameter sets per algorithm (each runs on both inputs)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  specificity->add_option("--seed", specificity_seed, "seed of the draws (the same sets on every machine)")->capture_default_str();
  add_shared_options(*specificity, specificity_shared, "groundtruth-specificity");

  Shared report_shared;
  bool skip_benchmark = false;
  auto* report = app.add_subcommand("report", "the main job: every algorithm family's cases and the benchmarks "
                                              "(--full: the long cases, every benchmark size and the mutants too)");
  add_shared_options(*report, report_shared, std::string(GT_SOURCE_DIR) + "/reports/latest");
  report->add_flag("--no-benchmark", skip_benchmark, "leave out the performance table");
  bool skip_mutants = false;
  report->add_flag("--no-mutants", skip_mutants,
                   "leave out the mutation score (every registered mutant run) and the specificity beside it");
  bool full_report = false;
  report->add_flag("--full", full_report,
                   "every case (the full tier's long runs too), the benchmark at every size, the mutants and the "
                   "specificity (`groundtruth specificity --sets 20`)");

  Shared bench_shared;
  gt::BenchmarkOptions bench_options;
  auto* bench = app.add_subcommand("bench", "only the performance table");
  add_shared_options(*bench, bench_shared, "groundtruth-bench");
  bench->add_option("patterns", bench_options.patterns, "algorithm-name patterns, e.g. 'noise.*' (all when none)");
  bench->add_option("--sizes", bench_options.sizes, "grid sides, comma-separated")
      ->delimiter(',')
      ->check(CLI::Range(8, 8192))
      ->capture_default_str();
  bench->add_option("--iterations", bench_options.iterations, "iterations per run")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  bench->add_option("--reps", bench_options.reps, "timed runs per size")->check(CLI::Range(1, 100))->capture_default_str();

  gt::MutationOptions mutation_options;
  std::string mutants_out = "groundtruth-mutants";
  bool mutants_as_json = false, list_mutants = false;
  double mutant_timeout = 600.0;
  auto* mutants = app.add_subcommand("mutants", "run each registered mutant (a deliberate bug) and show which checks kill it");
  mutants->add_option("patterns", mutation_options.patterns, "mutant-name patterns, e.g. 'erosion.*' (all when none)");
  mutants->add_flag("--list", list_mutants, "list the registered mutants and exit");
  mutants->add_flag("--json", mutants_as_json, "machine-readable");
  mutants->add_option("--out", mutants_out, "folder for the runs' reports and mutants.json")->capture_default_str();
  mutants->add_option("--gl", mutation_options.gl, "GL context: egl or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}))
      ->capture_default_str();
  mutants->add_flag("--require-gpu", mutation_options.require_gpu, "a run without a GL context is an error");
  mutants->add_option("-j,--jobs", mutation_options.parallel, "worker runs at once")
      ->check(CLI::Range(1, 256))
      ->capture_default_str();
  mutants->add_option("--specificity-sets", mutation_options.specificity_sets,
                      "also measure the specificity with this many parameter sets per algorithm (as `groundtruth "
                      "specificity --sets N`) and show it beside the mutation score; 0: not")
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  mutants->add_option("--timeout", mutant_timeout, "seconds a mutant's run may take")
      ->check(finite_number & CLI::Range(1.0, 86400.0))
      ->capture_default_str();

  std::string mesh_file;
  bool mesh_as_json = false;
  auto* check_mesh = app.add_subcommand("check-mesh", "is a mesh file watertight and consistently oriented? (CGAL and OpenMesh)");
  check_mesh->add_option("file", mesh_file, "OFF, OBJ, PLY or STL")->required();
  check_mesh->add_flag("--json", mesh_as_json, "machine-readable");
  std::string mesh_annotation;
  check_mesh->add_option("--annotate", mesh_annotation,
                         "write the mesh here (.ply) with each vertex's count of problems as a property and a colour");

  gt::CompareMeshOptions compare_mesh_options;
  auto* compare_mesh = app.add_subcommand("compare-mesh", "how and where do two meshes differ? (topology, Hausdorff "
                                                          "distance, the farthest vertices; CGAL)");
  compare_mesh->add_option("a", compare_mesh_options.a, "first mesh: OFF, OBJ, PLY or STL")->required();
  compare_mesh->add_option("b", compare_mesh_options.b, "second mesh")->required();
  compare_mesh->add_flag("--json", compare_mesh_options.as_json, "machine-readable");
  compare_mesh->add_option("--out", compare_mesh_options.out,
                           "write a_to_b.ply and b_to_a.ply here: each mesh coloured by its distance to the other");
  compare_mesh->add_option("--tolerance", compare_mesh_options.tolerance,
                           "largest symmetric Hausdorff distance that counts as the same (the meshes' unit)")
      ->check(finite_number & CLI::NonNegativeNumber);
  compare_mesh->add_option("--spacing", compare_mesh_options.spacing,
                           "CGAL's sampling grid (the meshes' unit; 1/200 of the larger bounding-box diagonal)")
      ->check(finite_number & CLI::PositiveNumber);

  gt::DiffImageOptions diff_options;
  auto* diff_image = app.add_subcommand("diff-image", "how and where do two images differ? (OpenImageIO)");
  diff_image->add_option("a", diff_options.a, "first image (any format OpenImageIO reads)")->required();
  diff_image->add_option("b", diff_options.b, "second image, same size and channels")->required();
  diff_image->add_flag("--json", diff_options.as_json, "machine-readable");
  diff_image->add_option("--out", diff_options.out,
                         "write the difference heat map here, and <stem>.mask.png beside it");
  diff_image->add_option("--tolerance", diff_options.tolerance, "per-channel tolerance in normalised values (4/255)")
      ->check(finite_number & CLI::NonNegativeNumber);

  gt::RenderOptions render_options;
  auto* render = app.add_subcommand("render", "draw a mesh, or a heightmap as a terrain solid, to a PNG (Phong twins)");
  render->add_option("input", render_options.input, "mesh (OFF, OBJ, PLY, STL) or heightmap (PNG, TIFF, EXR, volcano JSON, npz)")
      ->required();
  render->add_option("--out", render_options.out, "the PNG to write (never the input)")->required();
  render->add_option("--backend", render_options.backend, "cpu (reference rasterizer, exact) or gpu (GL pipeline)")
      ->check(CLI::IsMember({"cpu", "gpu"}))
      ->capture_default_str();
  render->add_option("--gl", render_options.gl, "GL context for gpu: egl or osmesa")
      ->check(CLI::IsMember({"egl", "osmesa"}))
      ->capture_default_str();
  render->add_option("--width", render_options.width, "pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  render->add_option("--height", render_options.height, "pixels")->check(CLI::Range(1, 16384))->capture_default_str();
  render->add_option("--azimuth", render_options.azimuth_deg, "orbit camera: degrees around +y, from +z towards +x")
      ->check(finite_number & CLI::Range(-360.0, 360.0))
      ->capture_default_str();
  render->add_option("--elevation", render_options.elevation_deg, "orbit camera: degrees above the xz plane")
      ->check(finite_number & CLI::Range(-89.0, 89.0))
      ->capture_default_str();
  render->add_option("--distance", render_options.distance,
                     "orbit camera: distance in bounding-box half diagonals (0: the box's sphere fits the view)")
      ->check(finite_number & CLI::NonNegativeNumber)
      ->capture_default_str();
  render->add_option("--fov", render_options.fov_deg, "vertical field of view, degrees")
      ->check(finite_number & CLI::Range(1.0, 179.0))
      ->capture_default_str();
  render->add_option("--eye", render_options.eye, "free camera: eye X,Y,Z (with --target)")->delimiter(',')->expected(3);
  render->add_option("--target", render_options.target, "free camera: point looked at X,Y,Z")->delimiter(',')->expected(3);
  render->add_option("--look", render_options.look, "auto (terrain for heightmaps), plain, terrain or cave")
      ->check(CLI::IsMember({"auto", "plain", "terrain", "cave"}))
      ->capture_default_str();
  render->add_option("--vertical-scale", render_options.vertical_scale, "heightmaps: vertical exaggeration")
      ->check(finite_number & CLI::Range(0.01, 100.0))
      ->capture_default_str();
  render->add_option("--cell-size", render_options.cell_size, "heightmaps: cell size in metres (0: the file's)")
      ->check(finite_number & CLI::NonNegativeNumber);
  render->add_option("--image-vertical-scale", render_options.image_vertical_scale,
                     "heightmaps: metres per unit of 8/16-bit images")
      ->check(finite_number & CLI::PositiveNumber)
      ->capture_default_str();

  std::filesystem::path base_report, next_report;
  bool diff_as_json = false;
  auto* diff_reports = app.add_subcommand("diff-reports", "what changed between two runs? check by check, timings "
                                                          "as ratios to each run's calibration kernel");
  diff_reports->add_option("base", base_report, "the baseline's report.json")->required();
  diff_reports->add_option("new", next_report, "the new run's report.json")->required();
  diff_reports->add_flag("--json", diff_as_json, "machine-readable");

  gt::MergeOptions merge_options;
  auto* merge = app.add_subcommand("merge", "join the report folders of a sharded run (--shard K/N) into one report");
  merge->add_option("shards", merge_options.shards, "the shards' report folders, every one of them")->required();
  merge->add_option("--out", merge_options.out, "the merged report folder")->required();
  merge->add_flag("--quiet", merge_options.quiet, "no summary line");

  gt::HistoryOptions history_options;
  auto* history = app.add_subcommand("history", "each case's checks and timings over a series of reports, as an HTML "
                                                "page: where did a drift start?");
  history->add_option("reports", history_options.inputs, "report.json files, report folders, or a folder of them")
      ->required();
  history->add_option("--out", history_options.out, "the history page's folder")->required();

  std::filesystem::path stats_file;
  gt::StatsOptions stats_options;
  auto* stats = app.add_subcommand("stats", "does it look like Earth? terrain descriptors of a DEM (hypsometry, "
                                            "slope, curvature, drainage, power spectrum)");
  stats->add_option("dem", stats_file, "heightmap (PNG, TIFF, GeoTIFF, EXR, volcano JSON, npz)")->required();
  stats->add_flag("--json", stats_options.as_json, "machine-readable");
  stats->add_option("--out", stats_options.out, "also write stats.json and descriptors.png into this folder");
  stats->add_option("--cell-size", stats_options.cell_size, "cell size in metres (0: the file's)")
      ->check(finite_number & CLI::NonNegativeNumber);
  stats->add_option("--image-vertical-scale", stats_options.image_vertical_scale,
                    "metres per unit of 8/16-bit images")
      ->check(finite_number & CLI::PositiveNumber)
      ->capture_default_str();
  stats->add_option("--stream-threshold", stats_options.stream_threshold_cells,
                    "contributing area, in cells, where a stream starts")
      ->check(finite_number & CLI::Range(2.0, 1e9))
      ->capture_default_str();

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : exit_bad_input;
  }
  gt::set_memory_limit(memory_limit_mib * 1024.0 * 1024.0);
  const std::string command_line = gt::command_line_of(argc, argv);

  try {
    if (check_mesh->parsed()) return gt::check_mesh_command(mesh_file, mesh_as_json, mesh_annotation);
    if (compare_mesh->parsed()) return gt::compare_mesh_command(compare_mesh_options);
    if (diff_image->parsed()) return gt::diff_image_command(diff_options);
    if (render->parsed()) return gt::render_command(render_options);
    if (stats->parsed()) return gt::stats_command(stats_file, stats_options);
    if (merge->parsed()) return gt::merge_shards(merge_options, command_line);
    if (history->parsed()) return gt::history_command(history_options);
    if (diff_reports->parsed()) {
      const auto diff = gt::diff_reports(gt::read_report_json(base_report), gt::read_report_json(next_report));
      fmt::print("{}", diff_as_json ? gt::to_json(diff).dump(2) + "\n" : gt::describe(diff));
      return diff.regressions.empty() ? 0 : 1;
    }
    if (mutants->parsed()) {
      if (list_mutants) {
        print_mutant_list(gt::select_mutants(mutation_options.patterns), mutants_as_json);
        return 0;
      }
      mutation_options.timeout_seconds = mutant_timeout;
      return gt::run_mutants_command(mutation_options, mutants_out, mutants_as_json, command_line);
    }
    if (list->parsed()) {
      print_list(list_request);
      return 0;
    }
    if (run->parsed()) {
      auto options = driver_options(run_shared, command_line, memory_limit_mib);
      options.patterns = patterns;
      if (quick) {
        if (!ad_hoc.algorithm.empty()) throw gt::InputError("--quick selects bundled cases: leave out --algorithm");
        options.tier = gt::Tier::quick;
        if (options.patterns.empty()) options.patterns = {"*"};
      }
      options.mutant = mutant;
      options.extra_cases.assign(extra_cases.begin(), extra_cases.end());
      if (ad_hoc.algorithm.empty() && !ad_hoc.input.empty()) {
        throw gt::InputError("--input belongs to an ad-hoc run: name its --algorithm too");
      }
      if (!grid_size.empty()) parse_grid_size(grid_size, ad_hoc);
      refuse_repeated(ad_hoc.assignments, "--set");
      if (!ad_hoc.assignments.empty() && ad_hoc.algorithm.empty()) {
        throw gt::InputError("--set applies to an ad-hoc run: give --algorithm too");
      }
      if (!ad_hoc.algorithm.empty()) options.ad_hoc = ad_hoc;
      if (!implementation.empty()) options.implementation = gt::parse_implementation(implementation);
      options.gpu_shaders = gpu_shaders;
      options.candidate = candidate;
      if (options.patterns.empty() && !options.ad_hoc) {
        throw gt::InputError("nothing to run: name case patterns (see `groundtruth list`) or --algorithm with --input");
      }
      return gt::run_driver(options);
    }
    if (sweep->parsed()) {
      auto options = driver_options(sweep_shared, command_line, memory_limit_mib);
      if (!sweep_grid_size.empty()) parse_grid_size(sweep_grid_size, sweep_base);
      refuse_repeated(sweep_base.assignments, "--set");
      options.sweep = sweep_sets.empty() ? gt::make_sweep(sweep_base, vary, force_sweep)
                                         : gt::make_sweep_of_sets(sweep_base, sweep_sets, force_sweep);
      return gt::run_driver(options);
    }
    if (specificity->parsed()) {
      auto options = driver_options(specificity_shared, command_line, memory_limit_mib);
      options.sweep = gt::make_specificity(specificity_patterns, specificity_sets, specificity_seed);
      return gt::run_driver(options);
    }
    if (ab->parsed()) {
      auto options = driver_options(ab_shared, command_line, memory_limit_mib);
      if (!ab_grid_size.empty()) parse_grid_size(ab_grid_size, ab_base);
      refuse_repeated(ab_base.assignments, "--set");
      refuse_repeated(a_assignments, "--a");
      refuse_repeated(b_assignments, "--b");
      options.sweep = gt::make_ab(ab_base, a_assignments, b_assignments);
      return gt::run_driver(options);
    }
    if (report->parsed()) {
      auto options = driver_options(report_shared, command_line, memory_limit_mib);
      options.patterns = {"*"};
      options.tier = full_report ? gt::Tier::full : gt::Tier::report;
      if (!full_report) skip_mutants = true;
      if (!options.shard.empty() && !(skip_benchmark && skip_mutants)) {
        fmt::print(stderr, "groundtruth: a shard holds cases only; run the benchmarks (`groundtruth bench`) and the "
                           "mutants (`groundtruth mutants`) once, unsharded\n");
        skip_benchmark = skip_mutants = true;
      }
      if (!skip_benchmark) {
        options.benchmark = gt::BenchmarkOptions{.quiet = report_shared.quiet};
        if (!full_report) {
          options.benchmark->sizes = report_tier_benchmark_sizes;
          options.benchmark->studies = false;
        }
      }
      if (!full_report) {
        options.left_out = fmt::format("the benchmark {}, the mutants not run (`groundtruth report --full` runs "
                                       "everything, `groundtruth mutants` the mutants alone)",
                                       skip_benchmark ? "not run"
                                                      : fmt::format("at {} cells a side only, without the parameter "
                                                                    "studies",
                                                                    fmt::join(report_tier_benchmark_sizes, ", ")));
      }
      if (!skip_mutants) {
        options.mutation = gt::MutationOptions{.gl = report_shared.gl,
                                               .require_gpu = report_shared.require_gpu,
                                               .parallel = report_shared.parallel,
                                               .specificity_sets = full_report_specificity_sets};
      }
      return gt::run_driver(options);
    }
    auto options = driver_options(bench_shared, command_line, memory_limit_mib);
    bench_options.quiet = bench_shared.quiet;
    options.benchmark = bench_options;
    return gt::run_driver(options);
  } catch (const gt::InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_bad_input;
  } catch (const std::filesystem::filesystem_error& error) {
    // A path the user gave that the system refuses (too long, a loop of links, a full disk, no
    // permission): the path and the system's reason, as bad input.
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_bad_input;
  } catch (const std::system_error& error) {
    // fmt::print (which writes only to stdout and stderr) to a closed pipe or a full disk: the
    // output could not be written, not a bug.
    if (!output_failure(error.code())) {
      fmt::print(stderr, "groundtruth: internal error: {}\n", error.what());
      return 1;
    }
    std::fprintf(stderr, "groundtruth: cannot write to standard output: %s\n", error.code().message().c_str());
    return exit_bad_input;
  } catch (const std::exception& error) {
    fmt::print(stderr, "groundtruth: internal error: {}\n", error.what());
    return 1;
  }
}

}  // namespace

// A command's output that could not be written (stdout on a full disk, a closed pipe) is not a
// success: its status becomes 2 with the reason on stderr. SIGPIPE and SIGXFSZ are ignored so that
// a closed pipe or a file-size limit reaches the code as a failed write (EPIPE, EFBIG), which is
// reported and cleaned up like a full disk, instead of killing the process with its staging
// folder and temporary files left behind.
int main(int argc, char** argv) {
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  gt::end_with_parent();
  gt::install_interrupt_cleanup();
  const int status = run_command_line(argc, argv);
  const bool written = std::fflush(stdout) == 0 && !std::ferror(stdout);
  if (!written && (status == 0 || status == 1)) {
    fmt::print(stderr, "groundtruth: cannot write to standard output: {}\n", std::strerror(errno));
    return exit_bad_input;
  }
  return status;
}
