// What changed between two runs (issue 15): `groundtruth diff-reports BASE NEW`, check by check.
//
// Inputs: two report.json files (schema 1). Outputs, each a list of entries "case: check":
//   regressions       a check (or a case) that passed, warned or was inconclusive in BASE and fails
//                     or errors in NEW, unless NEW's expectation list names that outcome for it;
//   fixes             the reverse;
//   outcome_changes   any other change of a check's outcome (pass → warn, pass → skip, ...);
//   added, removed    checks and cases present in one report only;
//   moved             checks whose outcome is unchanged but whose value moved: checks of the CPU
//                     reference in double (names ending ".cpu") are deterministic and must be bit
//                     for bit the same, so any change is listed; others when the change exceeds 1 %
//                     of their strict bound (or, without one, 1e-6 of the larger magnitude): rounding
//                     differences of a GPU driver stay far below a bound, a changed algorithm not;
//   timings           a case's CPU or GPU median time divided by its run's calibration kernel
//                     (compare/calibration.hpp), NEW against BASE, listed when the ratio changed by
//                     more than a factor 1.25: medians of a few repetitions on a quiet machine
//                     scatter by about 10 %, twice that is noise; a real change of the code is more.
//                     Absent when either report has no calibration.
// Throws InputError when a file is unreadable, not a groundtruth report, of another schema, has
// malformed cases or checks (a name or status of the wrong type), or
// when the two share no case (a baseline from another algorithm set).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

struct Report;  // compare/result.hpp, which includes this header

struct ReportDiff {
  struct Change {
    std::string where;   // "case" or "case: check"
    std::string before;  // outcome, value or time in BASE ("" when absent)
    std::string after;   // the same in NEW
  };
  std::vector<Change> regressions;
  std::vector<Change> fixes;
  std::vector<Change> outcome_changes;
  std::vector<Change> added;
  std::vector<Change> removed;
  std::vector<Change> moved;
  std::vector<Change> timings;
  int common_cases = 0;
  double timing_noise_factor = 1.25;
};

// A report.json read under the size, memory and depth limits, checked as strictly as
// report_from_json checks it (an unknown outcome, a field of the wrong type, no cases: InputError
// naming the file): as its JSON document, or rebuilt as a Report (parsed once).
nlohmann::json read_report_json(const std::filesystem::path& file);
Report read_report(const std::filesystem::path& file);

ReportDiff diff_reports(const nlohmann::json& base, const nlohmann::json& next);

nlohmann::json to_json(const ReportDiff& diff);

// Human-readable summary: one section per non-empty list, "no changes" otherwise.
std::string describe(const ReportDiff& diff);

}  // namespace gt
