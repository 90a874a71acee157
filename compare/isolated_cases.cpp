// Cases in worker processes; see compare/isolated_cases.hpp.
#include "compare/isolated_cases.hpp"

#include <fstream>

#include <fmt/format.h>

#include "compare/provenance.hpp"
#include "compare/report/report_read.hpp"
#include "compare/report_diff.hpp"
#include "compare/worker.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

std::string last_line_of(const std::filesystem::path& log) {
  std::ifstream stream(log);
  std::string line, last;
  while (std::getline(stream, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

// Why a worker gave no result: its signal, the timeout, or its exit status and last words.
std::string worker_failure(const WorkerResult& worker, double timeout_seconds, const std::filesystem::path& log) {
  if (worker.status < 0) return "the worker process could not be started";
  if (worker.timed_out) return fmt::format("ran past --case-timeout {:g} s: the worker was killed", timeout_seconds);
  if (worker.signal != 0) return fmt::format("the worker process was killed by {}", signal_description(worker.signal));
  const std::string last = last_line_of(log);
  return fmt::format("the worker process exited with status {} without a report{}", worker.status,
                     last.empty() ? "" : ": " + last);
}

// The case's result from its worker's report folder, or std::nullopt when there is none.
std::optional<CaseResult> worker_case(const std::filesystem::path& worker_folder, const std::string& name,
                                      Environment& environment) {
  if (!std::filesystem::exists(worker_folder / "report.json")) return std::nullopt;
  Report report;
  try {
    report = read_report(worker_folder / "report.json");
  } catch (const InputError&) {
    return std::nullopt;
  }
  for (auto& result : report.cases) {
    if (result.name != name) continue;
    if (environment.gl_platform.empty() || environment.gl_platform == "none") {
      environment.gl_renderer = report.environment.gl_renderer;
      environment.gl_version = report.environment.gl_version;
      environment.gl_platform = report.environment.gl_platform;
    }
    merge_digests(environment, report.environment);
    return std::move(result);
  }
  return std::nullopt;
}

// The worker's case folder (its pictures and fields) moved into the report folder.
void adopt_case_folder(const std::filesystem::path& worker_folder, const std::filesystem::path& folder,
                       const std::string& name) {
  const auto source = worker_folder / name;
  if (std::filesystem::is_directory(source)) std::filesystem::rename(source, folder / name);
}

CaseResult failed_case(const IsolatedCase& isolated, const std::string& why, const std::filesystem::path& log,
                       const std::filesystem::path& folder) {
  CaseResult result = isolated.known;
  result.error = why;
  const auto kept = folder / result.name / "worker.log";
  std::filesystem::create_directories(kept.parent_path());
  std::filesystem::copy_file(log, kept, std::filesystem::copy_options::overwrite_existing);
  result.artifacts.push_back({result.name + "/worker.log", "log", "what the worker process printed"});
  result.status = case_outcome(result);
  return result;
}

}  // namespace

std::string exact_pattern(const std::string& case_name) {
  std::string pattern;
  for (char c : case_name) {
    if (c == '*' || c == '?' || c == '[' || c == ']' || c == '\\') pattern += '\\';
    pattern += c;
  }
  return pattern;
}

std::vector<CaseResult> run_isolated(const std::vector<IsolatedCase>& cases, const IsolationOptions& options,
                                     const std::filesystem::path& folder, Environment& environment,
                                     Progress& progress) {
  const auto workers = folder / ".workers";
  std::filesystem::create_directories(workers);
  std::vector<WorkerTask> tasks;
  for (std::size_t index = 0; index < cases.size(); ++index) {
    std::vector<std::string> args = {"run"};
    args.insert(args.end(), cases[index].selection.begin(), cases[index].selection.end());
    args.insert(args.end(), options.common_args.begin(), options.common_args.end());
    args.insert(args.end(), {"--worker", "--quiet", "--out", (workers / std::to_string(index)).string()});
    tasks.push_back({args, workers / fmt::format("{}.log", index), llvmpipe_share(options.parallel)});
  }
  std::vector<CaseResult> results(cases.size());
  run_workers(
      tasks, options.parallel, options.timeout_seconds,
      [&](std::size_t index) { progress.start_case(cases[index].known.name); },
      [&](std::size_t index, const WorkerResult& worker) {
        const auto worker_folder = workers / std::to_string(index);
        const std::string& name = cases[index].known.name;
        if (auto result = worker_case(worker_folder, name, environment)) {
          adopt_case_folder(worker_folder, folder, name);
          results[index] = std::move(*result);
        } else {
          results[index] = failed_case(cases[index], worker_failure(worker, options.timeout_seconds, tasks[index].log),
                                       tasks[index].log, folder);
        }
        results[index].seconds = worker.seconds;
        progress.end_case(results[index]);
      });
  std::filesystem::remove_all(workers);
  return results;
}

}  // namespace gt
