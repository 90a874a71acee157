// The comparison driver; see driver.hpp.
#include "compare/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <type_traits>
#include <variant>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/ab.hpp"
#include "compare/algorithm.hpp"
#include "compare/benchmark.hpp"
#include "compare/calibration.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/cases.hpp"
#include "compare/expectations.hpp"
#include "compare/inputs.hpp"
#include "compare/external/bmi_preflight.hpp"
#include "compare/external/c_bmi_model.hpp"
#include "compare/external/candidate.hpp"
#include "compare/external/gpu_shader_drop_ins.hpp"
#include "core/io/atomic_file.hpp"
#include "core/wording.hpp"
#include "gpu/shader_program.hpp"
#include "compare/isolated_cases.hpp"
#include "compare/case_seconds.hpp"
#include "compare/progress.hpp"
#include "compare/provenance.hpp"
#include "compare/report/report_common.hpp"
#include "compare/shards.hpp"
#include "compare/specificity.hpp"
#include "compare/sweep.hpp"
#include "compare/mutants/mutants.hpp"
#include "compare/output_folder.hpp"
#include "compare/report/plots.hpp"
#include "compare/report_diff.hpp"
#include "compare/report/writers.hpp"
#include "core/errors.hpp"
#include "core/json_keys.hpp"
#include "core/mutant.hpp"

namespace gt {
namespace {

// A case ready to run: its algorithm found, parameters resolved, input loaded and checked, and
// the twins set up (which is where parameters that only make sense together are refused).
struct Job {
  CaseSpec spec;
  nlohmann::json resolved;
  LoadedInput input;
  PreparedTwin prepared;
};

const std::string ad_hoc_origin = "command line";

// --field name=file: the heightmap input's "fields" as a case file gives them (compare/inputs.hpp
// checks each when it loads: its size, its values, the names the algorithm reads).
void add_ad_hoc_fields(const AdHocCase& ad_hoc, nlohmann::json& input) {
  for (const auto& field : ad_hoc.fields) {
    const auto equals = field.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == field.size()) {
      throw InputError(fmt::format("--field '{}': expected name=file (an input field of the heightmap, as a case file's "
                                   "\"fields\")",
                                   field));
    }
    const auto name = field.substr(0, equals);
    if (input.contains("fields") && input["fields"].contains(name)) {
      throw InputError(fmt::format("--field names '{}' twice", name));
    }
    input["fields"][name] = {{"file", std::filesystem::absolute(field.substr(equals + 1)).string()}};
  }
}

// Refuses --field where the case has no heightmap file to carry it.
void require_no_fields(const AdHocCase& ad_hoc) {
  if (ad_hoc.fields.empty()) return;
  throw InputError(fmt::format("--field '{}': input fields ride on a heightmap file; {} takes none here (give --input a "
                               "heightmap, or drop --field)",
                               ad_hoc.fields.front(), ad_hoc.algorithm));
}

CaseSpec ad_hoc_spec(const AdHocCase& ad_hoc) {
  const auto& algorithm = find_algorithm(ad_hoc.algorithm);
  if (ad_hoc.cell_size_y > 0.0 && !(ad_hoc.cell_size > 0.0)) {
    throw InputError("cell_size_y (the rows' spacing) needs cell_size (the columns') too");
  }
  CaseSpec spec;
  spec.algorithm = ad_hoc.algorithm;
  spec.origin = ad_hoc_origin;
  const bool heightmap_file = algorithm.ad_hoc_input == AdHocInput::heightmap && !ad_hoc.input.empty();
  if (!heightmap_file) require_no_fields(ad_hoc);
  if (algorithm.ad_hoc_input == AdHocInput::none) {
    if (!ad_hoc.input.empty()) {
      throw InputError(fmt::format("{} makes its own field from its parameters: drop --input, use --set", ad_hoc.algorithm));
    }
    spec.input = nlohmann::json::object();
  } else if (algorithm.ad_hoc_input == AdHocInput::optional_global_grid) {
    spec.input = ad_hoc.input.empty() ? nlohmann::json::object()
                                      : nlohmann::json{{"global_grid", std::filesystem::absolute(ad_hoc.input).string()}};
  } else if (algorithm.ad_hoc_input == AdHocInput::optional_volume) {
    spec.input = ad_hoc.input.empty() ? nlohmann::json::object()
                                      : nlohmann::json{{"volume", std::filesystem::absolute(ad_hoc.input).string()}};
  } else if (algorithm.ad_hoc_input == AdHocInput::mesh) {
    if (ad_hoc.input.empty()) throw InputError(fmt::format("{} checks a mesh: give it one with --input", ad_hoc.algorithm));
    spec.input = {{"mesh", std::filesystem::absolute(ad_hoc.input).string()}};
  } else if (!ad_hoc.input.empty()) {
    spec.input = {{"file", std::filesystem::absolute(ad_hoc.input).string()}};
    if (ad_hoc.red_channel) spec.input["red_channel"] = true;
    if (ad_hoc.image_vertical_scale > 0.0) spec.input["vertical_scale"] = ad_hoc.image_vertical_scale;
    if (ad_hoc.cell_size > 0.0) spec.input["cell_size"] = ad_hoc.cell_size;
    if (ad_hoc.cell_size_y > 0.0) spec.input["cell_size_y"] = ad_hoc.cell_size_y;
    add_ad_hoc_fields(ad_hoc, spec.input);
  } else if (algorithm.kind == CaseKind::generated) {
    spec.input = {{"generator", "flat"}, {"width", ad_hoc.width}, {"height", ad_hoc.height}, {"cell_size", ad_hoc.cell_size > 0.0 ? ad_hoc.cell_size : 1.0}};
    if (ad_hoc.cell_size_y > 0.0) spec.input["cell_size_y"] = ad_hoc.cell_size_y;
  } else {
    // Only a generated field samples a grid of --width x --height without an input; anything else
    // on a flat grid made up for it would run silently on nothing.
    throw InputError(fmt::format("{} works on a heightmap: give it one with --input (only noise algorithms sample a "
                                 "grid of their own)",
                                 ad_hoc.algorithm));
  }
  for (const auto& assignment : ad_hoc.assignments) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos || equals == 0) {
      throw InputError(fmt::format("--set '{}': expected name=value", assignment));
    }
    const auto name = assignment.substr(0, equals);
    spec.params[name] = parse_param_text(spec.algorithm, *algorithm.params, name, assignment.substr(equals + 1));
  }
  spec.name = ad_hoc.name.empty() ? fmt::format("adhoc.{}.{}", ad_hoc.algorithm, ad_hoc_input_name(ad_hoc))
                                  : ad_hoc.name;
  return spec;
}

// The ad-hoc case (the run's own, or a sweep's variant) a spec of ad-hoc origin was made from.
const AdHocCase& ad_hoc_of(const CaseSpec& spec, const DriverOptions& options) {
  if (options.sweep) {
    for (const AdHocCase& variant : options.sweep->variants) {
      if (variant.name == spec.name) return variant;
    }
  }
  return *options.ad_hoc;
}

// The cases the patterns select that the tier keeps; none kept is refused.
std::vector<CaseSpec> tiered_cases(const DriverOptions& options, const std::vector<CaseSpec>& suite) {
  const auto matched = select_cases(suite, options.patterns);
  if (!options.tier) return matched;
  auto kept = cases_in_tier(matched, *options.tier);
  if (kept.empty()) {
    throw InputError(fmt::format("none of the {} cases selected is in the {} tier (each case file entry's \"tier\"); "
                                 "name them without the tier's flag to run them",
                                 matched.size(), tier_name(*options.tier)));
  }
  return kept;
}

// What the tier left out of the selection, for the report's scope line; empty when nothing was.
std::string tier_scope(const DriverOptions& options, const std::vector<CaseSpec>& suite, std::size_t kept) {
  if (!options.tier || options.patterns.empty()) return "";
  const auto matched = select_cases(suite, options.patterns);
  std::vector<std::string> left;
  for (const auto& spec : matched) {
    if (spec.tier > *options.tier) left.push_back(spec.name);
  }
  if (left.empty() && options.left_out.empty()) return "";
  std::string scope = fmt::format("tier {}: {} of {} cases ran", tier_name(*options.tier), kept, matched.size());
  if (!left.empty()) scope += fmt::format("; left out: {}", fmt::join(left, ", "));
  if (!options.left_out.empty()) scope += "; " + options.left_out;
  return scope + ".";
}

std::vector<CaseSpec> selected_specs(const DriverOptions& options, const std::vector<CaseSpec>& suite) {
  std::vector<CaseSpec> specs;
  if (!options.patterns.empty()) specs = tiered_cases(options, suite);
  if (options.ad_hoc) specs.push_back(ad_hoc_spec(*options.ad_hoc));
  if (options.sweep) {
    for (const AdHocCase& variant : options.sweep->variants) specs.push_back(ad_hoc_spec(variant));
  }
  if (specs.empty()) throw InputError("nothing to run: name case patterns or an --algorithm with an --input");
  return specs;
}

std::vector<Job> prepare_jobs(const std::vector<CaseSpec>& specs, const std::filesystem::path& dataset_dir) {
  std::vector<Job> jobs;
  for (const auto& spec : specs) {
    Job job;
    job.spec = spec;
    const Algorithm& algorithm = find_algorithm(spec.algorithm);
    job.resolved = resolve_params(spec.name, *algorithm.params, spec.params);
    if (!spec.expect.is_null()) {
      require_shape(spec.expect, algorithm.expect_shape, fmt::format("case {}: expect", spec.name));
    }
    try {
      job.input = load_input(spec.input, spec.crop, dataset_dir);
      require_known_fields(algorithm, job.input);
      require_memory(algorithm.memory(job.resolved, job.input), spec.algorithm);
      job.prepared = algorithm.prepare(job.resolved, job.input);
      if (job.prepared.kind.index() != static_cast<std::size_t>(algorithm.kind)) {
        throw std::logic_error(fmt::format("{}: prepare() gave another kind of case than Algorithm::kind declares",
                                           spec.algorithm));
      }
    } catch (const InputError& error) {
      throw InputError(fmt::format("case {}: {}", spec.name, error.what()));
    } catch (const nlohmann::json::exception& error) {
      // A value of the wrong type in the case ("width": "big"): the reader asked for another kind.
      throw InputError(fmt::format("case {}: a value has the wrong type: {}", spec.name, error.what()));
    }
    if (spec.origin == ad_hoc_origin) {
      for (const auto& note : job.input.notes) fmt::print(stderr, "groundtruth: {}: {}\n", spec.name, note);
    }
    jobs.push_back(std::move(job));
  }
  return jobs;
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  }
  return "unknown CPU";
}

// The machine, the build and the run's provenance (compare/provenance.hpp).
Environment base_environment(const std::string& command_line) {
  Environment environment;
  environment.cpu = fmt::format("{} ({} logical cores)", cpu_model(), sysconf(_SC_NPROCESSORS_ONLN));
  environment.compiler = fmt::format("GCC {}", __VERSION__);
  environment.mutant = active_mutant();
  add_run_provenance(environment, command_line);
  return environment;
}

// What the run grades where the GPU twin stands (Environment::graded), empty for our own twins.
std::string graded_in_the_gpu_twins_place(const DriverOptions& options) {
  if (!options.candidate.empty()) return fmt::format("the candidate file {}", options.candidate.string());
  if (options.implementation) return fmt::format("the implementation {}", options.implementation->text());
  if (options.external_model) return "a Python model (groundtruth.check)";
  if (!options.gpu_shaders.empty()) return fmt::format("the GPU shaders in {} over groundtruth's", options.gpu_shaders.string());
  return "";
}

// A case that skipped a check because the GPU was unavailable, when the user required the GPU.
bool skipped_for_want_of_gpu(const CaseResult& result, const RunOptions& options) {
  return std::any_of(result.checks.begin(), result.checks.end(), [&](const Check& check) {
    return check.status == Outcome::skip && check.detail == options.gpu_unavailable_reason;
  });
}

// What a case's result says before it runs: its name, algorithm, input and parameters.
CaseResult case_header(const Job& job) {
  CaseResult result;
  result.name = job.spec.name;
  result.algorithm = job.spec.algorithm;
  result.input = job.input.description;
  result.notes = job.input.notes;
  result.width = job.input.heights.width;
  result.height = job.input.heights.height;
  result.params = job.resolved;
  return result;
}

// A run the reference found to leave the twins' common range: the case cannot be decided, and no
// twin is to blame (the checks it had made before are kept).
Check runaway_check(const RunawayRun& error) {
  return {.name = "stability.runaway.cpu",
          .value = error.change,
          .threshold = error.limit,
          .status = Outcome::inconclusive,
          .detail = error.what()};
}

CaseResult run_job(const Job& job, const RunOptions& options, GlContext* context, bool require_gpu) {
  const auto started = std::chrono::steady_clock::now();
  CaseResult result = case_header(job);
  try {
    const PreparedTwin& prepared = job.prepared;
    const nlohmann::json& expect = job.spec.expect;
    std::visit(
        [&](const auto& kind) {
          using Kind = std::decay_t<decltype(kind)>;
          if constexpr (std::is_same_v<Kind, GeneratedCase>) run_field_twin(kind.twin, kind.grid, expect, options, result);
          if constexpr (std::is_same_v<Kind, SteppedTwin>) run_stepped_case(kind, expect, options, result);
          if constexpr (std::is_same_v<Kind, CaseRun>) kind(expect, options, result);
        },
        prepared.kind);
    if (prepared.extra_checks) prepared.extra_checks(job.spec.expect, options, result);
  } catch (const RunawayRun& error) {
    result.checks.push_back(runaway_check(error));
  } catch (const std::exception& error) {
    result.error = error.what();
  }
  if (context != nullptr) {
    const auto errors = context->take_errors();
    if (!errors.empty() && result.error.empty()) {
      result.error = fmt::format("GL error during the case: {}{}", errors.front(),
                                 errors.size() > 1 ? fmt::format(" (and {} more)", errors.size() - 1) : "");
    }
  }
  if (require_gpu && result.error.empty() && skipped_for_want_of_gpu(result, options)) {
    result.error = fmt::format("--require-gpu: the GPU half did not run ({})", options.gpu_unavailable_reason);
  }
  result.status = case_outcome(result);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return result;
}

void print_summary(const Report& report, const std::filesystem::path& out) {
  std::map<Outcome, int> counts;
  for (const auto& result : report.cases) {
    ++counts[result.status];
    const std::string remark = !result.expected_failure.empty() ? " (expected failure)"
                               : result.status != Outcome::flaky ? ""
                               : result.known_flake.empty()      ? " (a new flake: fix it or add it to a flake list)"
                                                                 : " (known flake: " + result.known_flake + ")";
    fmt::print("{:12} {}{}\n", outcome_name(result.status), result.name, remark);
    if (!result.error.empty()) fmt::print("             {}\n", result.error);
  }
  for (const auto& problem : report.expectation_problems) fmt::print("expectation  {}\n", problem);
  if (report.cases.empty()) {  // `groundtruth bench`: the rows, not "0 cases: 0 pass, ..."
    fmt::print("groundtruth: {}; report in {}\n", counted(report.benchmarks.size(), "benchmark row"),
               (out / "index.html").string());
    return;
  }
  fmt::print("groundtruth: {}: {} pass, {} warn, {} inconclusive, {} skip, {} flaky, {} fail, {} error; report in {}\n",
             counted(report.cases.size(), "case"), counts[Outcome::pass], counts[Outcome::warn], counts[Outcome::inconclusive],
             counts[Outcome::skip], counts[Outcome::flaky], counts[Outcome::fail], counts[Outcome::error],
             (out / "index.html").string());
}

void print_mutation(const MutationReport& mutation) {
  for (const auto& baseline : mutation.baselines) {
    fmt::print("baseline     {} ({}): {}\n", baseline.family, counted(baseline.cases.size(), "case"),
               baseline.clean ? "clean" : "NOT CLEAN: " + baseline.problems.front());
  }
  for (const auto& mutant : mutation.mutants) {
    fmt::print("{:12} {} [{}{}]{}\n", mutant.status, mutant.name, mutant.kind, mutant.must_survive ? ", must survive" : "",
               mutant.killed_by.empty() ? (mutant.error.empty() ? "" : ": " + mutant.error) : ": " + mutant.killed_by.front());
  }
  fmt::print("groundtruth: mutation score {}/{} ({:.0f} %){}\n", mutation.killed(), mutation.bugs(),
             100.0 * mutation.score(),
             mutation.passed() ? "" : "; not every bug was killed by its kind of check, a must-survive mutant was killed, or a baseline failed");
  if (const auto& specificity = mutation.specificity) {
    if (specificity->problem.empty()) {
      fmt::print("groundtruth: specificity {} in {}\n", counted(static_cast<std::size_t>(specificity->false_alarms), "false alarm"),
                 counted(static_cast<std::size_t>(specificity->runs), "honest run"));
    } else {
      fmt::print("groundtruth: specificity not measured: {}\n", specificity->problem);
    }
  }
}

// The baseline's report.json, read and checked before anything runs: bad input exits 2 at once.
std::optional<nlohmann::json> read_baseline(const std::filesystem::path& file, const std::vector<CaseSpec>& specs) {
  if (file.empty()) return std::nullopt;
  nlohmann::json baseline = read_report_json(file);
  const bool shares_a_case = std::any_of(specs.begin(), specs.end(), [&](const CaseSpec& spec) {
    return std::any_of(baseline["cases"].begin(), baseline["cases"].end(),
                       [&](const nlohmann::json& entry) { return entry.value("name", "") == spec.name; });
  });
  if (!shares_a_case) {
    throw InputError(fmt::format("--baseline {}: none of its cases is among those selected (a baseline from another "
                                 "suite or algorithm set)", file.string()));
  }
  return baseline;
}

// --shard: keeps this shard's part of the selection and records the whole selection.
std::vector<CaseSpec> shard_specs(const std::vector<CaseSpec>& specs, const DriverOptions& options,
                                  const std::optional<nlohmann::json>& baseline, Report& report) {
  if (options.shard.empty()) return specs;
  const ShardSpec shard = parse_shard(options.shard);
  ShardInfo info{shard.index, shard.count, {}, baseline ? options.baseline.string() : ""};
  for (const auto& spec : specs) info.selection.push_back(spec.name);
  const auto assigned = assign_shards(info.selection, shard.count, baseline.value_or(nlohmann::json()));
  std::vector<CaseSpec> mine;
  for (std::size_t index = 0; index < specs.size(); ++index) {
    if (assigned[index] == shard.index) mine.push_back(specs[index]);
  }
  if (!options.quiet) {
    fmt::print(stderr, "groundtruth: shard {}/{}: {} of the {} selected cases{}\n", shard.index, shard.count,
               mine.size(), specs.size(), baseline ? ", balanced by the baseline's case times" : "");
  }
  report.shard = std::move(info);
  return mine;
}

std::vector<Expectation> all_expectations(const DriverOptions& options, const std::vector<CaseSpec>& suite) {
  auto expectations = load_expectations(options.dataset_dir / "expectations.txt", suite);
  for (const auto& file : options.expectation_files) {
    auto more = load_expectations(file, suite, ExpectationFile::required);
    expectations.insert(expectations.end(), more.begin(), more.end());
  }
  for (const auto& file : options.flake_files) {
    auto more = load_expectations(file, suite, ExpectationFile::flakes_only);
    expectations.insert(expectations.end(), more.begin(), more.end());
  }
  return expectations;
}

const char* backends_name(Backends backends) {
  return backends == Backends::cpu ? "cpu" : backends == Backends::gpu ? "gpu" : "both";
}

// What every worker of this run is told: the same backends, context, repetitions, cases and mutant.
std::vector<std::string> worker_common_args(const DriverOptions& options) {
  std::vector<std::string> args = {"--gl",       options.gl == GlBackend::osmesa ? "osmesa" : "egl",
                                   "--backend",  backends_name(options.backends),
                                   "--cpu-reps", std::to_string(options.cpu_reps),
                                   "--gpu-reps", std::to_string(options.gpu_reps)};
  if (options.checkpoints > 0) args.insert(args.end(), {"--checkpoints", std::to_string(options.checkpoints)});
  for (const auto& file : options.extra_cases) args.insert(args.end(), {"--cases", std::filesystem::absolute(file).string()});
  if (!options.mutant.empty()) args.insert(args.end(), {"--mutant", options.mutant});
  if (options.require_gpu) args.push_back("--require-gpu");
  if (options.memory_limit_mib > 0.0) args.insert(args.end(), {"--memory-limit", fmt::format("{}", options.memory_limit_mib)});
  if (options.implementation) args.insert(args.end(), {"--implementation", options.implementation->text()});
  if (!options.gpu_shaders.empty()) {
    args.insert(args.end(), {"--gpu-shaders", std::filesystem::absolute(options.gpu_shaders).string()});
  }
  if (!options.candidate.empty()) args.insert(args.end(), {"--candidate", std::filesystem::absolute(options.candidate).string()});
  return args;
}

// The worker arguments that select this job alone: its exact name, or the ad-hoc case's options.
std::vector<std::string> job_selection(const Job& job, const DriverOptions& options) {
  if (job.spec.origin != ad_hoc_origin) return {exact_pattern(job.spec.name)};
  const AdHocCase& ad_hoc = ad_hoc_of(job.spec, options);
  std::vector<std::string> args = {"--algorithm", ad_hoc.algorithm, "--size",
                                   fmt::format("{}x{}", ad_hoc.width, ad_hoc.height)};
  if (ad_hoc.cell_size > 0.0) args.insert(args.end(), {"--cell-size", fmt::format("{}", ad_hoc.cell_size)});
  if (ad_hoc.cell_size_y > 0.0) args.insert(args.end(), {"--cell-size-y", fmt::format("{}", ad_hoc.cell_size_y)});
  if (ad_hoc.image_vertical_scale > 0.0) {
    args.insert(args.end(), {"--image-vertical-scale", fmt::format("{}", ad_hoc.image_vertical_scale)});
  }
  if (!ad_hoc.input.empty()) args.insert(args.end(), {"--input", std::filesystem::absolute(ad_hoc.input).string()});
  for (const auto& assignment : ad_hoc.assignments) args.insert(args.end(), {"--set", assignment});
  for (const auto& field : ad_hoc.fields) args.insert(args.end(), {"--field", field});
  if (ad_hoc.red_channel) args.push_back("--red-channel");
  if (!ad_hoc.name.empty()) args.insert(args.end(), {"--case-name", ad_hoc.name});
  return args;
}

CaseResult::Attempt attempt_of(const CaseResult& result) {
  return {result.status, result.error, failing_checks(result)};
}

// An outside model (--implementation, or the Python module's): every selected case is a stepped
// one, and (for a library, in the parent) the model conforms to each case's declared state, checked
// in a child process before anything runs. A Python model is checked when its case makes it.
void check_implementation(const std::vector<Job>& jobs, const DriverOptions& options) {
  for (const Job& job : jobs) {
    const auto* twin = std::get_if<SteppedTwin>(&job.prepared.kind);
    if (twin == nullptr) {
      throw InputError(fmt::format("case {}: --implementation grades an iterative algorithm through its state fields "
                                   "(`groundtruth list --json`: algorithms with a \"state\"); {} is not one",
                                   job.spec.name, job.spec.algorithm));
    }
    if (options.worker) continue;
    constexpr double preflight_seconds = 60.0;
    const bool library = options.implementation.has_value();
    preflight_implementation(library ? c_bmi_external_model(*options.implementation) : *options.external_model,
                             twin->algorithm, twin->fields, twin->initial.grid, job.resolved, job.spec.name,
                             std::min(preflight_seconds, options.case_timeout.value_or(preflight_seconds)), library);
  }
}

// --gpu-shaders: the drop-ins laid over the built-in shaders for the rest of the process, and the
// note every case carries (said on stderr too, once, by the parent); empty without drop-ins.
std::string lay_drop_ins(const DriverOptions& options) {
  if (options.gpu_shaders.empty()) return "";
  const auto folder = std::filesystem::absolute(options.gpu_shaders);
  const auto drop_ins = gpu_shader_drop_ins(folder, shader_root());
  set_shader_overlay(folder);
  const std::string note = fmt::format("GPU shaders: {} drop-in file(s) from {} over the built-in ones: {}",
                                       drop_ins.size(), folder.string(), fmt::join(drop_ins, ", "));
  if (!options.worker && !options.quiet) fmt::print(stderr, "groundtruth: {}\n", note);
  return note;
}

// The algorithms that take a --candidate file, with what they take, for the refusal.
std::string candidate_algorithms() {
  std::vector<std::string> names;
  for (const Algorithm& algorithm : algorithms()) {
    if (algorithm.candidate == CandidateOutput::none) continue;
    const char* kind = algorithm.candidate == CandidateOutput::field ? "field"
                       : algorithm.candidate == CandidateOutput::mesh ? "mesh"
                                                                       : "image";
    names.push_back(fmt::format("{} ({})", algorithm.name, kind));
  }
  return fmt::format("{}", fmt::join(names, ", "));
}

// --candidate: the one selected case takes a user's output, and the file holds one of its kind
// and size; read once, before the run, so that bad input exits 2.
CandidateOutputs load_candidate(const std::vector<Job>& jobs, const DriverOptions& options) {
  CandidateOutputs candidate;
  if (options.candidate.empty()) return candidate;
  if (jobs.size() != 1) {
    throw InputError(fmt::format("--candidate {}: one file grades one case, and {} are selected", options.candidate.string(),
                                 jobs.size()));
  }
  const Job& job = jobs.front();
  switch (find_algorithm(job.spec.algorithm).candidate) {
    case CandidateOutput::none:
      throw InputError(fmt::format("--candidate grades a generated field, a mesh or a rendered image; {} takes none "
                                   "(a stepping algorithm takes an outside model: --implementation). Those that do: {}",
                                   job.spec.algorithm, candidate_algorithms()));
    case CandidateOutput::field:
      candidate.field = load_candidate_field(options.candidate, std::get<GeneratedCase>(job.prepared.kind).grid);
      break;
    case CandidateOutput::mesh: candidate.mesh = load_candidate_mesh(options.candidate); break;
    case CandidateOutput::image:
      candidate.image =
          load_candidate_image(options.candidate, job.resolved.at("width").get<int>(), job.resolved.at("height").get<int>());
      break;
  }
  return candidate;
}

// Runs a list of jobs in this process or in workers, and returns their results in order.
class CaseRunner {
 public:
  CaseRunner(const DriverOptions& options, const std::filesystem::path& folder, Report& report, CaseSeconds expected,
             const std::vector<Expectation>& expectations)
      : options_(options), folder_(folder), report_(report), expected_(std::move(expected)), expectations_(expectations) {
    run_options_.dataset_dir = options.dataset_dir;
    run_options_.cpu_reps = options.backends == Backends::gpu ? 0 : options.cpu_reps;
    run_options_.gpu_reps = options.gpu_reps;
    run_options_.checkpoints = options.checkpoints;
    run_options_.pictures = options.pictures;
    run_options_.descriptors = options.descriptors;
    run_options_.report_dir = folder;
    run_options_.external =
        options.implementation ? std::optional(c_bmi_external_model(*options.implementation)) : options.external_model;
    if (isolated()) {
      isolation_.parallel = options.parallel;
      isolation_.timeout_seconds = options.case_timeout.value_or(default_case_timeout_seconds);
      isolation_.common_args = worker_common_args(options);
    } else {
      open_context();
    }
  }

  // An outside implementation always runs in workers: its crash or hang ends its case alone.
  bool isolated() const {
    return !options_.worker && (options_.parallel > 1 || options_.case_timeout || options_.implementation);
  }

  std::vector<CaseResult> run(const std::vector<const Job*>& jobs) {
    ProgressOptions shown{.quiet = options_.quiet,
                          .workers = isolated() ? options_.parallel : 1,
                          .expected = expected_,
                          .heartbeat = std::chrono::milliseconds(std::lround(options_.heartbeat_seconds * 1000.0)),
                          .remark = [this](const CaseResult& result) { return expectation_remark(result); }};
    for (const Job* job : jobs) shown.planned.push_back(job->spec.name);
    Progress progress(static_cast<int>(jobs.size()), std::move(shown));
    std::vector<CaseResult> results;
    if (isolated()) {
      // Longest first, so that no long case starts last while the other workers idle.
      const auto order = longest_first(jobs);
      std::vector<IsolatedCase> cases;
      for (const std::size_t index : order) cases.push_back({job_selection(*jobs[index], options_), case_header(*jobs[index])});
      auto ordered = run_isolated(cases, isolation_, folder_, report_.environment, progress);
      results.resize(jobs.size());
      for (std::size_t k = 0; k < order.size(); ++k) results[order[k]] = std::move(ordered[k]);
    } else {
      run_options_.progress = &progress;
      for (const Job* job : jobs) {
        progress.start_case(job->spec.name);
        results.push_back(run_job(*job, run_options_, context_.get(), options_.require_gpu));
        progress.end_case(results.back());
      }
      run_options_.progress = nullptr;
    }
    progress.finish();
    for (std::size_t index = 0; index < jobs.size(); ++index) {
      results[index].tier = tier_name(jobs[index]->spec.tier);
      if (const auto found = expected_.find(jobs[index]->spec.name); found != expected_.end()) {
        results[index].expected_seconds = found->second;
      }
    }
    return results;
  }

  // "(expected failure: <reasons>)" when the expectation list names every failing check of a
  // failed case; the run's verdict comes later, from the same list (apply_expectations).
  std::string expectation_remark(const CaseResult& result) const {
    if (result.status != Outcome::fail || expectations_.empty()) return "";
    Report one;
    one.environment = report_.environment;
    one.cases = {result};
    apply_expectations(expectations_, one);
    return one.cases.front().expected_failure.empty() ? "" : "(expected failure: " + one.cases.front().expected_failure + ")";
  }

  // The jobs' indices by expected seconds, longest first (a job without a record counts as the mean
  // of those with one); ties keep the load order.
  std::vector<std::size_t> longest_first(const std::vector<const Job*>& jobs) const {
    std::vector<std::string> names;
    for (const Job* job : jobs) names.push_back(job->spec.name);
    const double unknown = mean_expected_seconds(names, expected_).value_or(0.0);
    std::vector<double> seconds;
    for (const Job* job : jobs) {
      const auto found = expected_.find(job->spec.name);
      seconds.push_back(found != expected_.end() ? found->second : unknown);
    }
    std::vector<std::size_t> order(jobs.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return seconds[a] > seconds[b]; });
    return order;
  }

  // A user's output file in the GPU twin's place (--candidate).
  void grade_candidate(const CandidateOutputs& candidate) { run_options_.candidate = candidate; }

  // The context benchmarks need (opened now in a run whose cases ran in workers).
  bool gpu_available() {
    if (!context_opened_) open_context();
    return run_options_.gpu_available;
  }

 private:
  // A run without --case-timeout that runs its cases in workers still ends one that hangs.
  static constexpr double default_case_timeout_seconds = 3600.0;

  void open_context() {
    context_opened_ = true;
    Environment& environment = report_.environment;
    if (options_.backends == Backends::cpu) {
      run_options_.gpu_unavailable_reason = gpu_not_requested;
    } else {
      try {
        context_ = GlContext::create(options_.gl);
        run_options_.gpu_available = true;
        // A fallback taken for the user (e.g. a GPU's EGL device gave no context): said, with why.
        if (!options_.quiet && !context_->info().passed_over.empty()) {
          fmt::print(stderr, "groundtruth: GL through {} ({}), after: {}\n", context_->info().platform,
                     context_->info().renderer, fmt::join(context_->info().passed_over, "; "));
        }
      } catch (const GpuUnavailable& error) {
        run_options_.gpu_unavailable_reason = fmt::format("no GL context: {}", error.what());
        fmt::print(stderr, "groundtruth: {}; {}\n", error.what(),
                   options_.require_gpu ? "--require-gpu: every case with a GPU half ends as error"
                                        : "GPU checks are skipped (never counted as passed), the CPU side still runs");
      }
    }
    if (!environment.gl_platform.empty()) return;  // the workers' context describes the cases
    environment.gl_renderer = context_ ? context_->info().renderer : "none: " + run_options_.gpu_unavailable_reason;
    environment.gl_version = context_ ? context_->info().version : "";
    environment.gl_platform = context_ ? context_->info().platform : "none";
  }

  const DriverOptions& options_;
  std::filesystem::path folder_;
  Report& report_;
  RunOptions run_options_;
  IsolationOptions isolation_;
  std::unique_ptr<GlContext> context_;
  bool context_opened_ = false;
  CaseSeconds expected_;
  const std::vector<Expectation>& expectations_;
};

// --retries (and the flake list): a case that failed unexpectedly is run again; one that then
// passes becomes `flaky` with its failed attempts listed, one that never does stays failed.
void retry_failures(const std::vector<Job>& jobs, const DriverOptions& options,
                    const std::vector<Expectation>& expectations, CaseRunner& runner, Report& report) {
  const auto budget = [&](std::size_t index) {
    return std::max(options.retries, named_as_flaky(expectations, jobs[index].spec.name) ? 1 : 0);
  };
  for (int attempt = 1;; ++attempt) {
    std::vector<std::size_t> again;
    std::vector<const Job*> rerun;
    for (std::size_t index = 0; index < jobs.size(); ++index) {
      const CaseResult& result = report.cases[index];
      if (attempt > budget(index) || (result.status != Outcome::fail && result.status != Outcome::error) ||
          !failed_unexpectedly(result)) {
        continue;
      }
      if (!options.quiet) {
        fmt::print(stderr, "groundtruth: {} is {}; running it again (attempt {})\n", result.name,
                   outcome_name(result.status), attempt + 1);
      }
      again.push_back(index);
      rerun.push_back(&jobs[index]);
    }
    if (again.empty()) return;
    auto results = runner.run(rerun);
    for (std::size_t k = 0; k < again.size(); ++k) {
      CaseResult& previous = report.cases[again[k]];
      results[k].earlier_attempts = previous.earlier_attempts;
      results[k].earlier_attempts.push_back(attempt_of(previous));
      results[k].status = case_outcome(results[k]);
      previous = std::move(results[k]);
    }
    report.expectation_problems = apply_expectations(expectations, report);
  }
}

std::vector<std::filesystem::path> data_files(const std::vector<Job>& jobs) {
  std::set<std::filesystem::path> files;
  for (const auto& job : jobs) {
    if (!job.input.source.empty()) files.insert(job.input.source);
  }
  return {files.begin(), files.end()};
}

}  // namespace

std::string ad_hoc_input_name(const AdHocCase& ad_hoc) {
  const Algorithm& algorithm = find_algorithm(ad_hoc.algorithm);
  const std::string input_name =
      !ad_hoc.input.empty()                      ? std::filesystem::path(ad_hoc.input).stem().string()
      : algorithm.ad_hoc_input != AdHocInput::heightmap ? "params"
                                                        : fmt::format("{}x{}", ad_hoc.width, ad_hoc.height);
  return case_name_part(input_name);
}

int run_driver(const DriverOptions& options) {
  if (!options.mutant.empty()) set_active_mutant(find_mutant(options.mutant).name);
  const auto suite = load_suite(options.dataset_dir / "cases", options.extra_cases);
  const auto selection = options.patterns.empty() && !options.ad_hoc && !options.sweep
                             ? std::vector<CaseSpec>{}
                             : selected_specs(options, suite);
  const auto baseline = read_baseline(options.baseline, selection);
  Report report;
  report.scope = tier_scope(options, suite, selection.size());
  const auto specs = shard_specs(selection, options, baseline, report);
  const auto jobs = prepare_jobs(specs, options.dataset_dir);
  if (options.implementation || options.external_model) check_implementation(jobs, options);
  const std::string drop_in_note = lay_drop_ins(options);
  const CandidateOutputs candidate = load_candidate(jobs, options);
  // A worker's parent applies the expectations and makes the retries.
  const auto expectations = options.worker ? std::vector<Expectation>{} : all_expectations(options, suite);
  check_output_folder(options.out);

  report.environment = base_environment(options.command_line);
  report.environment.graded = graded_in_the_gpu_twins_place(options);
  // Only runs that time their cases need it: workers report to a parent, and untimed runs time nothing.
  if (!options.worker && (options.cpu_reps > 0 || options.gpu_reps > 0)) report.environment.calibration_ms = calibration_ms();

  write_folder_atomically(options.out, [&](const std::filesystem::path& folder) {
    CaseRunner runner(options, folder, report,
                      expected_case_seconds(options.dataset_dir, options.out / "report.json", baseline), expectations);
    runner.grade_candidate(candidate);
    std::vector<const Job*> all;
    for (const auto& job : jobs) all.push_back(&job);
    report.cases = runner.run(all);
    if (!drop_in_note.empty()) {
      for (CaseResult& result : report.cases) result.notes.push_back(drop_in_note);
    }
    report.expectation_problems = apply_expectations(expectations, report);
    retry_failures(jobs, options, expectations, runner, report);
    if (options.benchmark) {
      report.benchmarks = run_benchmarks(*options.benchmark, runner.gpu_available(), report.environment);
      std::string reason;
      if (auto plot = plot_benchmarks(report.benchmarks, folder, reason)) {
        report.plots.push_back(*plot);
      } else {
        report.plots.push_back({"", "plot", "plot unavailable: " + reason});
        fmt::print(stderr, "groundtruth: plot unavailable: {}\n", reason);
      }
    }
    if (!options.worker) write_case_ab_summaries(specs, report, folder);
    if (options.sweep && !options.worker) {
      switch (options.sweep->kind) {
        case SweepKind::ab: write_ab_summary(*options.sweep, report, folder); break;
        case SweepKind::specificity: write_specificity_summary(*options.sweep, report, folder); break;
        case SweepKind::grid: write_sweep_summary(*options.sweep, report, folder); break;
      }
    }
    if (report.environment.gl_platform.empty()) runner.gpu_available();  // every worker failed: describe ours
    add_digests(report.environment, data_files(jobs));
    if (options.mutation) {
      report.mutation = run_mutation(*options.mutation, folder / "mutants", options.dataset_dir);
      report.mutation->folder = "mutants/";
      write_file_atomically(folder / "mutants" / "mutants.json",
                                          mutation_to_json(*report.mutation).dump(2) + '\n');
    }
    if (baseline) {
      report.baseline_file = options.baseline.string();
      report.baseline_diff = diff_reports(*baseline, report_to_json(report));
    }
    write_report_files(report, folder);
  });
  if (options.worker) return run_failed(report) ? 1 : 0;
  if (options.summary) print_summary(report, options.out);
  if (report.baseline_diff) fmt::print("against {}: {}", report.baseline_file, describe(*report.baseline_diff));
  if (report.mutation) print_mutation(*report.mutation);
  return run_failed(report) || (report.mutation && !report.mutation->passed()) ? 1 : 0;
}

int run_mutants_command(const MutationOptions& options, const std::filesystem::path& out, bool as_json,
                        const std::string& command_line) {
  select_mutants(options.patterns);  // bad patterns are refused before anything is written
  check_output_folder(out);
  Report report;  // no cases: the environment and the mutation, in the usual four files
  report.environment = base_environment(command_line);
  report.environment.gl_renderer = "each run's own (its report.json under runs/ or baseline/)";
  report.environment.gl_platform = "worker processes";
  write_folder_atomically(out, [&](const std::filesystem::path& folder) {
    report.mutation = run_mutation(options, folder, GT_DATASET_DIR);
    write_file_atomically(folder / "mutants.json", mutation_to_json(*report.mutation).dump(2) + '\n');
    write_report_files(report, folder);
  });
  if (as_json) {
    fmt::print("{}\n", mutation_to_json(*report.mutation).dump(2));
  } else {
    print_mutation(*report.mutation);
  }
  return report.mutation->passed() ? 0 : 1;
}

}  // namespace gt
