// Outcome arithmetic of compare/result.hpp: names, the order of outcomes, a case's outcome from its
// checks, and whether a run failed once the expectation list is taken into account.
#include "compare/result.hpp"

#include <cmath>

#include <algorithm>
#include <map>

#include <fmt/format.h>

namespace gt {

namespace {

// Higher is worse: pass < warn < inconclusive < skip < flaky < fail < error. A skipped check
// outranks the passes and warnings around it, so a case whose GPU half did not run is never `pass`.
int severity(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass: return 0;
    case Outcome::warn: return 1;
    case Outcome::inconclusive: return 2;
    case Outcome::skip: return 3;
    case Outcome::flaky: return 4;
    case Outcome::fail: return 5;
    case Outcome::error: return 6;
  }
  return 6;
}

bool is_failure(Outcome outcome) { return outcome == Outcome::fail || outcome == Outcome::error; }

}  // namespace

const char* outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass: return "pass";
    case Outcome::fail: return "fail";
    case Outcome::warn: return "warn";
    case Outcome::inconclusive: return "inconclusive";
    case Outcome::skip: return "skip";
    case Outcome::error: return "error";
    case Outcome::flaky: return "flaky";
  }
  return "error";
}

std::optional<Outcome> outcome_from_name(const std::string& name) {
  for (Outcome outcome : {Outcome::pass, Outcome::warn, Outcome::inconclusive, Outcome::skip, Outcome::flaky,
                          Outcome::fail, Outcome::error}) {
    if (name == outcome_name(outcome)) return outcome;
  }
  return std::nullopt;
}

Outcome worse(Outcome a, Outcome b) { return severity(a) >= severity(b) ? a : b; }

bool left_out_by_request(const Check& check) {
  return check.status == Outcome::skip && check.detail == gpu_not_requested;
}

Outcome case_outcome(const CaseResult& result) {
  if (!result.error.empty()) return Outcome::error;
  const bool any_ran = std::any_of(result.checks.begin(), result.checks.end(),
                                   [](const Check& check) { return !left_out_by_request(check); });
  Outcome outcome = any_ran ? Outcome::pass : Outcome::skip;
  for (const Check& check : result.checks) {
    if (!left_out_by_request(check)) outcome = worse(outcome, check.status);
  }
  return !result.earlier_attempts.empty() && !is_failure(outcome) ? worse(outcome, Outcome::flaky) : outcome;
}

bool met_expectation(const Check& check) { return check.expected == check.status; }

bool failed_unexpectedly(const CaseResult& result) {
  if (!result.error.empty()) return true;
  if (result.status == Outcome::flaky && result.known_flake.empty()) return true;
  return std::any_of(result.checks.begin(), result.checks.end(),
                     [](const Check& check) { return is_failure(check.status) && !met_expectation(check); });
}

bool run_failed(const Report& report) {
  return !report.expectation_problems.empty() ||
         std::any_of(report.cases.begin(), report.cases.end(), failed_unexpectedly);
}

double specificity_share(int false_alarms, int runs) {
  return 1.0 - static_cast<double>(false_alarms) / std::max(1, runs);
}

int MutationReport::bugs() const {
  return static_cast<int>(std::count_if(mutants.begin(), mutants.end(), [](const auto& m) { return !m.must_survive; }));
}

int MutationReport::killed() const {
  return static_cast<int>(
      std::count_if(mutants.begin(), mutants.end(), [](const auto& m) { return !m.must_survive && m.status == "killed"; }));
}

std::vector<KillRow> MutationReport::kill_matrix() const {
  std::map<std::string, std::vector<std::string>> killers;
  for (const auto& baseline : baselines) {
    for (const auto& check : baseline.graded_checks) killers[check];
  }
  for (const auto& mutant : mutants) {
    for (const auto& check : mutant.killing_checks) killers[check].push_back(mutant.name);
  }
  std::vector<KillRow> rows;
  for (auto& [check, names] : killers) rows.push_back({check, std::move(names)});
  return rows;
}

double MutationReport::score() const { return bugs() == 0 ? 1.0 : double(killed()) / double(bugs()); }

bool MutationReport::passed() const {
  for (const auto& baseline : baselines) {
    if (!baseline.clean) return false;
  }
  return std::all_of(mutants.begin(), mutants.end(), [](const auto& mutant) { return mutant.as_expected(); });
}

std::vector<std::string> failing_checks(const CaseResult& result) {
  std::vector<std::string> failing;
  for (const Check& check : result.checks) {
    if (!is_failure(check.status)) continue;
    failing.push_back(fmt::format("{} = {:.6g}{}", check.name, check.value,
                                  check.threshold ? fmt::format(" (bound {:.6g})", *check.threshold) : ""));
  }
  return failing;
}

void add_picture(CaseResult& result, const std::string& file, std::string caption, std::optional<ColourScale> scale,
                 std::optional<double> width_m) {
  result.artifacts.push_back({result.name + "/" + file, "image", std::move(caption), std::move(scale), width_m});
}

std::optional<double> map_width_m(int width, double cell_size_x) {
  const double metres = width * cell_size_x;
  if (!std::isfinite(metres) || metres <= 0.0) return std::nullopt;
  return metres;
}

}  // namespace gt
