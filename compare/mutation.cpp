// The mutation runner; see compare/mutation.hpp.
#include "compare/mutation.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <fstream>
#include <map>
#include <set>

#include <fmt/format.h>

#include "compare/cases.hpp"
#include "compare/worker.hpp"
#include "core/errors.hpp"
#include "core/json_keys.hpp"
#include "core/wording.hpp"

namespace gt {
namespace {

// A run's checks that failed, keyed "case: check".
using Failures = std::map<std::string, nlohmann::json>;

struct WorkerReport {
  bool readable = false;
  Failures failures;
  std::set<std::string> graded_checks;   // names of the checks with a bound
  std::vector<std::string> case_errors;  // "case: error"
};

WorkerReport read_worker_report(const std::filesystem::path& folder) {
  WorkerReport report;
  std::ifstream stream(folder / "report.json");
  if (!stream) return report;
  nlohmann::json document;
  try {
    document = parse_json_bounded(stream, (folder / "report.json").string());
  } catch (const nlohmann::json::exception&) {
    return report;
  }
  report.readable = true;
  for (const auto& result : document.value("cases", nlohmann::json::array())) {
    const std::string name = result.value("name", "");
    if (result.value("status", "") == "error") {
      report.case_errors.push_back(fmt::format("{}: {}", name, result.value("error", std::string("error"))));
    }
    for (const auto& check : result.value("checks", nlohmann::json::array())) {
      const std::string status = check.value("status", "");
      if (status == "fail" || status == "error") report.failures[name + ": " + check.value("name", "")] = check;
      if (check.contains("threshold") && status != "skip") report.graded_checks.insert(check.value("name", ""));
    }
  }
  return report;
}

std::string describe_check(const std::string& key, const nlohmann::json& check) {
  std::string text = key;
  if (check.contains("value") && check["value"].is_number()) text += fmt::format(" = {:.3g}", check["value"].get<double>());
  if (check.contains("threshold") && check["threshold"].is_number()) {
    text += fmt::format(" (bound {:.3g})", check["threshold"].get<double>());
  }
  return text;
}

std::vector<std::string> case_names(const Mutant& mutant, const std::vector<CaseSpec>& suite) {
  std::vector<std::string> names;
  try {
    for (const auto& spec : select_cases(suite, mutant.cases)) names.push_back(spec.name);
  } catch (const InputError& error) {
    throw InputError(fmt::format("mutant {}: {}", mutant.name, error.what()));
  }
  if (names.empty()) throw InputError(fmt::format("mutant {} names no case", mutant.name));
  return names;
}

std::vector<std::string> worker_args(const std::vector<std::string>& cases, const std::filesystem::path& out,
                                     const MutationOptions& options, const std::string& mutant) {
  std::vector<std::string> args = {"run"};
  args.insert(args.end(), cases.begin(), cases.end());
  args.insert(args.end(), {"--out", out.string(), "--gl", options.gl, "--cpu-reps", "1", "--gpu-reps", "1"});
  if (options.require_gpu) args.push_back("--require-gpu");
  if (!mutant.empty()) args.insert(args.end(), {"--mutant", mutant});
  return args;
}

void print_line(const std::string& line) { fmt::print(stderr, "groundtruth mutants: {}\n", line); }

WorkerTask baseline_task(const std::string& family, const std::vector<std::string>& cases,
                         const MutationOptions& options, const std::filesystem::path& folder) {
  return {worker_args(cases, folder / "baseline" / family, options, ""), folder / "baseline" / (family + ".log"),
          llvmpipe_share(options.parallel)};
}

MutationBaseline baseline_outcome(const std::string& family, const std::vector<std::string>& cases,
                                  const MutationOptions& options, const std::filesystem::path& folder,
                                  const WorkerResult& worker, Failures& failures) {
  MutationBaseline baseline;
  baseline.family = family;
  baseline.cases = cases;
  baseline.run_folder = "baseline/" + family;
  baseline.seconds = worker.seconds;
  const WorkerReport report = read_worker_report(folder / baseline.run_folder);
  failures = report.failures;
  baseline.graded_checks.assign(report.graded_checks.begin(), report.graded_checks.end());
  if (worker.timed_out) baseline.problems.push_back(fmt::format("timed out after {:.0f} s", options.timeout_seconds));
  if (!report.readable) baseline.problems.push_back(fmt::format("no readable report (exit status {})", worker.status));
  for (const auto& error : report.case_errors) baseline.problems.push_back(error);
  for (const auto& [key, check] : report.failures) baseline.problems.push_back(describe_check(key, check));
  if (worker.status != 0 && baseline.problems.empty()) {
    baseline.problems.push_back(fmt::format("exit status {} (see baseline/{}.log)", worker.status, family));
  }
  baseline.clean = baseline.problems.empty();
  return baseline;
}

WorkerTask mutant_task(const Mutant& mutant, const std::vector<std::string>& cases, const MutationOptions& options,
                       const std::filesystem::path& folder) {
  return {worker_args(cases, folder / "runs" / mutant.name, options, mutant.name), folder / "runs" / (mutant.name + ".log"),
          llvmpipe_share(options.parallel)};
}

MutantOutcome mutant_outcome(const Mutant& mutant, const std::vector<std::string>& cases, const Failures& baseline,
                             const MutationOptions& options, const std::filesystem::path& folder,
                             const WorkerResult& worker) {
  MutantOutcome outcome{.name = mutant.name, .family = mutant_family(mutant), .kind = mutant_kind_name(mutant.kind),
                        .description = mutant.description, .must_survive = mutant.must_survive, .cases = cases};
  outcome.run_folder = "runs/" + mutant.name;
  outcome.seconds = worker.seconds;
  const WorkerReport report = read_worker_report(folder / outcome.run_folder);
  for (const auto& [key, check] : report.failures) {
    if (baseline.contains(key)) continue;
    const auto check_name = key.substr(key.find(": ") + 2);
    const bool kills = check_kind_kills(mutant.kind, check_name);
    (kills ? outcome.killed_by : outcome.other_failures).push_back(describe_check(key, check));
    const auto& named = outcome.killing_checks;
    if (kills && !mutant.must_survive && std::find(named.begin(), named.end(), check_name) == named.end()) {
      outcome.killing_checks.push_back(check_name);
    }
  }
  // A must-survive mutant is killed by any new failure: an honest deviation failed is a false alarm.
  if (outcome.must_survive) {
    outcome.killed_by.insert(outcome.killed_by.end(), outcome.other_failures.begin(), outcome.other_failures.end());
    outcome.other_failures.clear();
  }
  if (!outcome.killed_by.empty()) {
    outcome.status = "killed";
  } else if (worker.timed_out) {
    outcome.status = "timeout";
    outcome.error = fmt::format("timed out after {:.0f} s", options.timeout_seconds);
  } else if (!report.readable || !report.case_errors.empty() || worker.status > 1) {
    outcome.status = "error";
    outcome.error = !report.case_errors.empty() ? report.case_errors.front()
                                                : fmt::format("exit status {} (see runs/{}.log)", worker.status, mutant.name);
  } else {
    outcome.status = "survived";
  }
  return outcome;
}

// `groundtruth specificity --sets N` in a worker into `folder`/specificity (its own report there),
// its figures read back from specificity.json; a run that did not finish gives a summary naming why.
SpecificitySummary run_specificity_worker(const MutationOptions& options, const std::filesystem::path& folder) {
  // A whole specificity run (20 sets: about 20 minutes on 2 cores) may take hours on a slow machine;
  // its own cases have their limits.
  constexpr double timeout_seconds = 6.0 * 3600.0;
  const auto out = folder / "specificity";
  print_line(fmt::format("specificity: {} per algorithm", counted(static_cast<std::size_t>(options.specificity_sets), "parameter set")));
  std::vector<std::string> args = {"specificity", "--sets", std::to_string(options.specificity_sets), "--out",
                                   out.string(), "--gl", options.gl, "-j", std::to_string(options.parallel), "--quiet"};
  const WorkerResult worker = run_worker(args, folder / "specificity.log", timeout_seconds);
  SpecificitySummary summary;
  summary.page = "specificity/specificity.html";
  std::ifstream stream(out / "specificity.json");
  try {
    if (!stream) throw std::runtime_error("no specificity.json");
    const auto document = parse_json_bounded(stream, (out / "specificity.json").string());
    summary.runs = document.at("runs").get<int>();
    summary.false_alarms = document.at("false_alarms").get<int>();
  } catch (const std::exception& error) {
    summary.problem = worker.timed_out ? fmt::format("timed out after {:.0f} s", timeout_seconds)
                                       : fmt::format("{} (exit status {}; see specificity.log)", error.what(), worker.status);
  }
  return summary;
}

}  // namespace

std::vector<Mutant> select_mutants(const std::vector<std::string>& patterns) {
  if (patterns.empty()) return mutants();
  std::vector<Mutant> selected;
  for (const auto& pattern : patterns) {
    bool any = false;
    for (const auto& mutant : mutants()) {
      if (fnmatch(pattern.c_str(), mutant.name.c_str(), 0) != 0) continue;
      any = true;
      const bool already = std::any_of(selected.begin(), selected.end(),
                                       [&](const Mutant& chosen) { return chosen.name == mutant.name; });
      if (!already) selected.push_back(mutant);
    }
    if (!any) {
      if (pattern.find_first_of("*?[") == std::string::npos) find_mutant(pattern);  // throws, naming the closest
      throw InputError(fmt::format("no mutant matches '{}'; `groundtruth mutants --list` shows them", pattern));
    }
  }
  return selected;
}

MutationReport run_mutation(const MutationOptions& options, const std::filesystem::path& folder,
                            const std::filesystem::path& dataset_dir) {
  const auto selected = select_mutants(options.patterns);
  const auto suite = load_cases(dataset_dir / "cases");
  std::vector<std::vector<std::string>> cases_of;
  std::map<std::string, std::vector<std::string>> family_cases;
  for (const auto& mutant : selected) {
    cases_of.push_back(case_names(mutant, suite));
    auto& cases = family_cases[mutant_family(mutant)];
    for (const auto& name : cases_of.back()) {
      if (std::find(cases.begin(), cases.end(), name) == cases.end()) cases.push_back(name);
    }
  }
  std::filesystem::create_directories(folder / "runs");
  std::filesystem::create_directories(folder / "baseline");
  MutationReport report;
  std::map<std::string, Failures> baseline_failures;
  std::vector<std::string> families;
  std::vector<WorkerTask> tasks;
  for (const auto& [family, cases] : family_cases) {
    families.push_back(family);
    tasks.push_back(baseline_task(family, cases, options, folder));
  }
  report.baselines.resize(families.size());
  run_workers(
      tasks, options.parallel, options.timeout_seconds,
      [&](std::size_t index) {
        print_line(fmt::format("baseline of {} ({})", families[index], counted(family_cases[families[index]].size(), "case")));
      },
      [&](std::size_t index, const WorkerResult& worker) {
        const auto& family = families[index];
        report.baselines[index] =
            baseline_outcome(family, family_cases[family], options, folder, worker, baseline_failures[family]);
      });
  tasks.clear();
  for (std::size_t index = 0; index < selected.size(); ++index) {
    tasks.push_back(mutant_task(selected[index], cases_of[index], options, folder));
  }
  report.mutants.resize(selected.size());
  int finished = 0;
  run_workers(
      tasks, options.parallel, options.timeout_seconds, [](std::size_t) {},
      [&](std::size_t index, const WorkerResult& worker) {
        const Mutant& mutant = selected[index];
        report.mutants[index] =
            mutant_outcome(mutant, cases_of[index], baseline_failures[mutant_family(mutant)], options, folder, worker);
        print_line(fmt::format("[{}/{}] {:9} {} ({:.1f} s)", ++finished, selected.size(), report.mutants[index].status,
                               mutant.name, worker.seconds));
      });
  if (options.specificity_sets > 0) report.specificity = run_specificity_worker(options, folder);
  return report;
}


nlohmann::json mutation_to_json(const MutationReport& report) {
  nlohmann::json out = {{"folder", report.folder},
                        {"killed", report.killed()},
                        {"bugs", report.bugs()},
                        {"registered", report.mutants.size()},
                        {"score", report.score()},
                        {"passed", report.passed()},
                        {"baselines", nlohmann::json::array()},
                        {"mutants", nlohmann::json::array()}};
  for (const auto& baseline : report.baselines) {
    out["baselines"].push_back({{"family", baseline.family}, {"cases", baseline.cases}, {"clean", baseline.clean},
                                {"problems", baseline.problems}, {"graded_checks", baseline.graded_checks},
                                {"seconds", baseline.seconds},
                                {"run_folder", baseline.run_folder}});
  }
  for (const auto& mutant : report.mutants) {
    out["mutants"].push_back({{"name", mutant.name}, {"family", mutant.family}, {"kind", mutant.kind},
                              {"description", mutant.description}, {"must_survive", mutant.must_survive},
                              {"cases", mutant.cases},
                              {"status", mutant.status}, {"killed_by", mutant.killed_by},
                              {"killing_checks", mutant.killing_checks},
                              {"other_failures", mutant.other_failures}, {"error", mutant.error},
                              {"seconds", mutant.seconds}, {"run_folder", mutant.run_folder}});
  }
  out["kill_matrix"] = nlohmann::json::object();
  for (const auto& row : report.kill_matrix()) out["kill_matrix"][row.check] = row.mutants;
  if (report.specificity) {
    const auto& specificity = *report.specificity;
    out["specificity"] = {{"runs", specificity.runs}, {"false_alarms", specificity.false_alarms},
                          {"page", specificity.page}, {"problem", specificity.problem}};
  }
  return out;
}

}  // namespace gt
