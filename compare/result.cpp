// Outcome arithmetic of compare/result.hpp: names, the order of outcomes, a case's outcome from its
// checks, and whether a run failed once the expectation list is taken into account.
#include "compare/result.hpp"

namespace gt {

namespace {

// Higher is worse: pass < warn < inconclusive < skip < fail < error. A skipped check outranks
// the passes and warnings around it, so a case whose GPU half did not run is never `pass`.
int severity(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass: return 0;
    case Outcome::warn: return 1;
    case Outcome::inconclusive: return 2;
    case Outcome::skip: return 3;
    case Outcome::fail: return 4;
    case Outcome::error: return 5;
  }
  return 5;
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
  }
  return "error";
}

Outcome worse(Outcome a, Outcome b) { return severity(a) >= severity(b) ? a : b; }

Outcome case_outcome(const CaseResult& result) {
  if (!result.error.empty()) return Outcome::error;
  if (result.checks.empty()) return Outcome::skip;
  Outcome outcome = Outcome::pass;
  for (const Check& check : result.checks) outcome = worse(outcome, check.status);
  return outcome;
}

bool run_failed(const Report& report) {
  if (!report.expectation_problems.empty()) return true;
  for (const CaseResult& result : report.cases) {
    if (!result.error.empty()) return true;
    for (const Check& check : result.checks) {
      if (is_failure(check.status) && check.expected != check.status) return true;
    }
  }
  return false;
}

int MutationReport::killed() const {
  int count = 0;
  for (const auto& mutant : mutants) count += mutant.status == "killed" ? 1 : 0;
  return count;
}

double MutationReport::score() const { return mutants.empty() ? 1.0 : double(killed()) / double(mutants.size()); }

bool MutationReport::passed() const {
  for (const auto& baseline : baselines) {
    if (!baseline.clean) return false;
  }
  return killed() == static_cast<int>(mutants.size());
}

}  // namespace gt
