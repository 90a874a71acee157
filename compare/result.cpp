// Outcome arithmetic of compare/result.hpp: names, the order of outcomes, a case's outcome from its
// checks, and whether a run failed once the expectation list is taken into account.
#include "compare/result.hpp"

namespace gt {

namespace {

// Higher is worse: skip < pass < warn < fail < error.
int severity(Outcome outcome) {
  switch (outcome) {
    case Outcome::skip: return 0;
    case Outcome::pass: return 1;
    case Outcome::warn: return 2;
    case Outcome::fail: return 3;
    case Outcome::error: return 4;
  }
  return 4;
}

bool is_failure(Outcome outcome) { return outcome == Outcome::fail || outcome == Outcome::error; }

bool is_success(Outcome outcome) { return outcome == Outcome::pass || outcome == Outcome::warn; }

}  // namespace

const char* outcome_name(Outcome outcome) {
  switch (outcome) {
    case Outcome::pass: return "pass";
    case Outcome::fail: return "fail";
    case Outcome::warn: return "warn";
    case Outcome::skip: return "skip";
    case Outcome::error: return "error";
  }
  return "error";
}

Outcome worse(Outcome a, Outcome b) { return severity(a) >= severity(b) ? a : b; }

Outcome case_outcome(const CaseResult& result) {
  if (!result.error.empty()) return Outcome::error;
  Outcome outcome = Outcome::skip;
  for (const Check& check : result.checks) outcome = worse(outcome, check.status);
  return outcome;
}

bool run_failed(const Report& report) {
  for (const CaseResult& result : report.cases) {
    const bool expected = !result.expected_failure.empty();
    if (!expected && is_failure(result.status)) return true;
    if (expected && is_success(result.status)) return true;  // stale expectation
  }
  return false;
}

}  // namespace gt
