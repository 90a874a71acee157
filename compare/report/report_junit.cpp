// junit.xml: the cases as JUnit test cases for CI test views.
//
// One <testsuite> per algorithm (in order of first appearance), one <testcase> per case with
// name = case name and classname = algorithm. The verdict follows run_failed():
//   fail / error, not expected           -> <failure> / <error>, failing checks in the message
//   expected failure that failed/errored -> passes, <system-out> names the expectation
//   expected failure that passed/warned  -> <failure>: the expectation list is stale
//   skip                                 -> <skipped message="...">
//   warn                                 -> passes, the warnings listed in <system-out>
// No time attributes: a case's wall time is not measured as one number.
#include <map>
#include <vector>

#include <fmt/format.h>

#include "compare/report/report_common.hpp"
#include "compare/report/writers.hpp"
#include "core/io/atomic_file.hpp"

namespace gt {

namespace {

using namespace report_detail;

enum class Verdict { pass, failure, error, skipped };

// A case whose failing checks datasets/expectations.txt all names passes as a known failure, and
// so does a flaky case on the flake list (a new flake is a failure); a case that could not run is
// an error; one that skipped a check or could not tell is skipped.
Verdict verdict(const CaseResult& result) {
  switch (result.status) {
    case Outcome::pass:
    case Outcome::warn: return Verdict::pass;
    case Outcome::fail: return result.expected_failure.empty() ? Verdict::failure : Verdict::pass;
    case Outcome::flaky: return result.known_flake.empty() ? Verdict::failure : Verdict::pass;
    case Outcome::error: return Verdict::error;
    case Outcome::inconclusive:
    case Outcome::skip: return Verdict::skipped;
  }
  return Verdict::error;
}

std::string check_line(const Check& check) {
  std::string line = fmt::format("{} {} = {}", outcome_name(check.status), check.name, format_value(check.value));
  if (const std::string bounds = format_bounds(check); !bounds.empty()) line += fmt::format(" (bound {})", bounds);
  if (!check.detail.empty()) line += fmt::format(": {}", check.detail);
  return line;
}

bool is_problem(Outcome status) { return status == Outcome::fail || status == Outcome::error; }

std::string check_lines(const CaseResult& result, bool (*wanted)(Outcome)) {
  std::string lines;
  for (const Check& check : result.checks) {
    if (wanted(check.status)) lines += check_line(check) + "\n";
  }
  return lines;
}

std::string skip_reason(const CaseResult& result) {
  for (const Check& check : result.checks) {
    if (check.status == result.status && !check.detail.empty()) {
      return fmt::format("{} {}: {}", outcome_name(check.status), check.name, check.detail);
    }
  }
  return result.checks.empty() ? "no checks ran" : fmt::format("a check is {}", outcome_name(result.status));
}

std::string failure_message(const CaseResult& result) {
  if (result.status == Outcome::flaky) {
    return fmt::format("flaky: failed, then passed on attempt {} (not on the flake list)", result.earlier_attempts.size() + 1);
  }
  const int failed = count_check_outcomes(result)[Outcome::fail];
  return fmt::format("{} of {} checks failed", failed, result.checks.size());
}

std::string error_message(const CaseResult& result) {
  if (!result.error.empty()) return result.error;
  const int errored = count_check_outcomes(result)[Outcome::error];
  return fmt::format("{} of {} checks could not run", errored, result.checks.size());
}

// What goes to <system-out>: expectation notes and warnings.
std::string system_out(const CaseResult& result) {
  std::string text;
  if (!result.expected_failure.empty()) {
    text += fmt::format("expected failure ({}): {}\n", outcome_name(result.status), result.expected_failure);
  }
  for (const auto& line : attempt_lines(result)) text += line + "\n";
  text += check_lines(result, [](Outcome status) { return status == Outcome::warn; });
  return text;
}

void append_testcase(std::string& out, const CaseResult& result) {
  out += fmt::format("    <testcase name=\"{}\" classname=\"{}\">\n", escape_markup(result.name),
                     escape_markup(result.algorithm));
  switch (verdict(result)) {
    case Verdict::pass: break;
    case Verdict::failure:
      out += fmt::format("      <failure message=\"{}\">{}</failure>\n", escape_markup(failure_message(result)),
                         escape_markup(check_lines(result, is_problem)));
      break;
    case Verdict::error:
      out += fmt::format("      <error message=\"{}\">{}</error>\n", escape_markup(error_message(result)),
                         escape_markup(check_lines(result, is_problem)));
      break;
    case Verdict::skipped:
      out += fmt::format("      <skipped message=\"{}\"/>\n", escape_markup(skip_reason(result)));
      break;
  }
  if (const std::string text = system_out(result); !text.empty()) {
    out += fmt::format("      <system-out>{}</system-out>\n", escape_markup(text));
  }
  out += "    </testcase>\n";
}

struct SuiteCounts {
  int tests = 0, failures = 0, errors = 0, skipped = 0;

  void add(Verdict v) {
    ++tests;
    failures += v == Verdict::failure;
    errors += v == Verdict::error;
    skipped += v == Verdict::skipped;
  }
};

std::string counts_attributes(const SuiteCounts& counts) {
  return fmt::format("tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\"", counts.tests, counts.failures,
                     counts.errors, counts.skipped);
}

// Cases grouped by algorithm, algorithms in order of first appearance.
std::vector<std::vector<const CaseResult*>> group_by_algorithm(const Report& report) {
  std::vector<std::vector<const CaseResult*>> groups;
  std::map<std::string, std::size_t> group_of_algorithm;
  for (const CaseResult& result : report.cases) {
    const auto [it, inserted] = group_of_algorithm.try_emplace(result.algorithm, groups.size());
    if (inserted) groups.emplace_back();
    groups[it->second].push_back(&result);
  }
  return groups;
}

}  // namespace

void write_report_junit(const Report& report, const std::filesystem::path& file) {
  std::string suites;
  SuiteCounts all;
  for (const auto& group : group_by_algorithm(report)) {
    SuiteCounts counts;
    std::string testcases;
    for (const CaseResult* result : group) {
      counts.add(verdict(*result));
      all.add(verdict(*result));
      append_testcase(testcases, *result);
    }
    suites += fmt::format("  <testsuite name=\"{}\" {}>\n{}  </testsuite>\n", escape_markup(group.front()->algorithm),
                          counts_attributes(counts), testcases);
  }
  const std::string out = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"groundtruth\" {}>\n{}</testsuites>\n",
      counts_attributes(all), suites);
  write_file_atomically(file, out);
}

}  // namespace gt
