// Loading and applying datasets/expectations.txt; the rules are in compare/expectations.hpp.
#include "compare/expectations.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt {
namespace {

bool matches(const std::string& pattern, const std::string& text) {
  return fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

Outcome parse_outcome(const std::string& word, const std::string& where) {
  for (Outcome outcome : {Outcome::pass, Outcome::warn, Outcome::inconclusive, Outcome::fail, Outcome::skip,
                          Outcome::error}) {
    if (word == outcome_name(outcome)) return outcome;
  }
  throw InputError(fmt::format("{}: '{}' is not an outcome (pass, warn, inconclusive, fail, skip, error)", where, word));
}

Expectation parse_entry(const std::string& line, int number, const std::string& where) {
  std::istringstream words(line);
  Expectation entry;
  entry.line = number;
  std::string outcome;
  if (!(words >> entry.case_pattern >> entry.check_pattern >> outcome)) {
    throw InputError(fmt::format("{}: expected 'CASE CHECK OUTCOME [device=GLOB] REASON'", where));
  }
  entry.outcome = parse_outcome(outcome, where);
  std::string word;
  if (words >> word && word.rfind("device=", 0) == 0) {
    entry.device_pattern = word.substr(7);
    if (entry.device_pattern.empty()) throw InputError(fmt::format("{}: device= needs a pattern", where));
    word.clear();
  }
  std::string rest;
  std::getline(words >> std::ws, rest);
  entry.reason = word.empty() || rest.empty() ? word + rest : word + " " + rest;
  if (entry.reason.find_first_not_of(" \t") == std::string::npos) {
    throw InputError(fmt::format("{}: say why this outcome is expected (a reason after the outcome)", where));
  }
  return entry;
}

bool names_a_case(const Expectation& entry, const std::vector<CaseSpec>& suite) {
  return std::any_of(suite.begin(), suite.end(), [&](const CaseSpec& spec) { return matches(entry.case_pattern, spec.name); });
}

bool applies_to(const Expectation& entry, const CaseResult& result, const Environment& environment) {
  return matches(entry.case_pattern, result.name) &&
         (entry.device_pattern.empty() || matches(entry.device_pattern, environment.gl_renderer));
}

}  // namespace

std::vector<Expectation> load_expectations(const std::filesystem::path& file, const std::vector<CaseSpec>& suite) {
  std::vector<Expectation> entries;
  std::ifstream stream(file);
  if (!stream) return entries;  // no file: nothing is expected to fail
  std::string line;
  for (int number = 1; std::getline(stream, line); ++number) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::string where = fmt::format("{}:{}", file.string(), number);
    Expectation entry = parse_entry(line.substr(first), number, where);
    if (!names_a_case(entry, suite)) {
      throw InputError(fmt::format("{}: '{}' matches no case of the suite; remove or correct the entry", where,
                                   entry.case_pattern));
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::vector<std::string> apply_expectations(const std::vector<Expectation>& expectations, Report& report) {
  std::vector<std::string> problems;
  for (const Expectation& entry : expectations) {
    for (CaseResult& result : report.cases) {
      if (!applies_to(entry, result, report.environment)) continue;
      int matched = 0;
      for (Check& check : result.checks) {
        if (!matches(entry.check_pattern, check.name)) continue;
        ++matched;
        check.expected = entry.outcome;
        check.expectation = entry.reason;
        if (check.status != entry.outcome) {
          problems.push_back(fmt::format("{} {}: expected {} (expectations.txt line {}), got {}", result.name,
                                         check.name, outcome_name(entry.outcome), entry.line,
                                         outcome_name(check.status)));
        }
      }
      if (matched == 0) {
        problems.push_back(fmt::format("{}: expectations.txt line {} names check '{}', which this case {}", result.name,
                                       entry.line, entry.check_pattern,
                                       result.error.empty() ? "does not have" : "did not reach: " + result.error));
      }
    }
  }
  for (CaseResult& result : report.cases) {
    std::vector<std::string> reasons;
    bool unexpected = false;
    for (const Check& check : result.checks) {
      if (check.status != Outcome::fail && check.status != Outcome::error) continue;
      if (check.expected == check.status) {
        if (std::find(reasons.begin(), reasons.end(), check.expectation) == reasons.end()) {
          reasons.push_back(check.expectation);
        }
      } else {
        unexpected = true;
      }
    }
    result.expected_failure.clear();
    if (!unexpected && !reasons.empty()) {
      for (const auto& reason : reasons) result.expected_failure += (result.expected_failure.empty() ? "" : "; ") + reason;
    }
  }
  return problems;
}

}  // namespace gt
