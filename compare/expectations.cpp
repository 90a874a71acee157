// Loading and applying datasets/expectations.txt; the rules are in compare/expectations.hpp.
#include "compare/expectations.hpp"

#include <algorithm>
#include <fnmatch.h>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/errors.hpp"
#include "core/io/text_file.hpp"

namespace gt {
namespace {

bool matches(const std::string& pattern, const std::string& text) {
  return fnmatch(pattern.c_str(), text.c_str(), 0) == 0;
}

Outcome parse_outcome(const std::string& word, const std::string& where) {
  const auto outcome = outcome_from_name(word);
  if (!outcome) {
    throw InputError(fmt::format("{}: '{}' is not an outcome (pass, warn, inconclusive, fail, skip, error, flaky)",
                                 where, word));
  }
  return *outcome;
}

Expectation parse_entry(const std::string& line, int number, const std::string& where) {
  std::istringstream words(line);
  Expectation entry;
  entry.file = where;
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

std::vector<Expectation> load_expectations(const std::filesystem::path& file, const std::vector<CaseSpec>& suite,
                                           ExpectationFile kind) {
  std::vector<Expectation> entries;
  std::error_code absent;
  if (kind == ExpectationFile::optional && !std::filesystem::exists(file, absent)) {
    return entries;  // no bundled file: nothing is expected to fail
  }
  std::istringstream stream(
      read_text_file(file, hand_written_limits, kind == ExpectationFile::flakes_only ? "--flakes" : "--expectations"));
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
    if (kind == ExpectationFile::flakes_only && entry.outcome != Outcome::flaky) {
      throw InputError(fmt::format("{}: a flake list holds only `flaky` entries (this one says {})", where,
                                   outcome_name(entry.outcome)));
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

std::string known_flake_reason(const std::vector<Expectation>& expectations, const CaseResult& result) {
  if (result.status != Outcome::flaky) return {};
  std::vector<std::string> reasons;
  const auto reason_for = [&](const std::string& check_name) -> const Expectation* {
    for (const Expectation& entry : expectations) {
      if (entry.outcome == Outcome::flaky && matches(entry.case_pattern, result.name) &&
          matches(entry.check_pattern, check_name)) {
        return &entry;
      }
    }
    return nullptr;
  };
  for (const auto& attempt : result.earlier_attempts) {
    std::vector<std::string> names;
    for (const auto& check : attempt.failing_checks) names.push_back(check.substr(0, check.find(' ')));
    if (!attempt.error.empty()) names.push_back("error");
    for (const auto& name : names) {
      const Expectation* entry = reason_for(name);
      if (entry == nullptr) return {};
      if (std::find(reasons.begin(), reasons.end(), entry->reason) == reasons.end()) reasons.push_back(entry->reason);
    }
  }
  return fmt::format("{}", fmt::join(reasons, "; "));
}

bool named_as_flaky(const std::vector<Expectation>& expectations, const std::string& case_name) {
  return std::any_of(expectations.begin(), expectations.end(), [&](const Expectation& entry) {
    return entry.outcome == Outcome::flaky && matches(entry.case_pattern, case_name);
  });
}

std::vector<std::string> apply_expectations(const std::vector<Expectation>& expectations, Report& report) {
  std::vector<std::string> problems;
  for (const Expectation& entry : expectations) {
    if (entry.outcome == Outcome::flaky) continue;  // the flake list: see known_flake_reason
    for (CaseResult& result : report.cases) {
      if (!applies_to(entry, result, report.environment)) continue;
      int matched = 0;
      for (Check& check : result.checks) {
        if (!matches(entry.check_pattern, check.name)) continue;
        ++matched;
        check.expected = entry.outcome;
        check.expectation = entry.reason;
        if (check.status != entry.outcome) {
          problems.push_back(fmt::format("{} {}: expected {} ({}), got {}", result.name, check.name,
                                         outcome_name(entry.outcome), entry.file, outcome_name(check.status)));
        }
      }
      if (matched == 0) {
        problems.push_back(fmt::format("{}: {} names check '{}', which this case {}", result.name, entry.file,
                                       entry.check_pattern,
                                       result.error.empty() ? "does not have" : "did not reach: " + result.error));
      }
    }
  }
  for (CaseResult& result : report.cases) {
    std::vector<std::string> reasons;
    bool unexpected = false;
    for (const Check& check : result.checks) {
      if (check.status != Outcome::fail && check.status != Outcome::error) continue;
      if (met_expectation(check)) {
        if (std::find(reasons.begin(), reasons.end(), check.expectation) == reasons.end()) {
          reasons.push_back(check.expectation);
        }
      } else {
        unexpected = true;
      }
    }
    result.expected_failure = unexpected ? "" : fmt::format("{}", fmt::join(reasons, "; "));
    result.known_flake = known_flake_reason(expectations, result);
  }
  return problems;
}

}  // namespace gt
