// How long each case is expected to take: the progress lines' ETA, `groundtruth list` and each
// case's expected_seconds in report.json (issue 35).
//
// Sources, a later one overriding an earlier one case by case:
//   datasets/case-seconds.json   recorded on the 2-core reference machine without a GPU
//                                (scripts/record-case-seconds.sh writes it from a report.json):
//                                {"recorded_on": "...", "seconds": {"case.name": 12.3, ...}}
//   the report a run replaces    --out's report.json from the run before, when it reads
//   the baseline                 --baseline's report.json
// A case none of them names has no expectation (the ETA counts it at the mean of those known).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gt {

using CaseSeconds = std::map<std::string, double>;

// Each case's wall seconds in a report.json document (its cases' "seconds"); cases without a
// positive finite time are left out.
CaseSeconds case_seconds_of_report(const nlohmann::json& report);

// The recorded times of datasets/case-seconds.json; empty when the file is missing. Throws
// InputError when it is there but malformed (it is part of the checkout).
CaseSeconds bundled_case_seconds(const std::filesystem::path& dataset_dir);

// The mean of the recorded seconds of those `names` that have one; std::nullopt when none has. A
// case without a record counts as this mean (the ETA, the workers' longest-first order).
std::optional<double> mean_expected_seconds(const std::vector<std::string>& names, const CaseSeconds& expected);

// The sources above merged; `previous_report` is the out folder's report.json, read when it can be
// (a report that does not parse gives no times: it is only an estimate's source).
CaseSeconds expected_case_seconds(const std::filesystem::path& dataset_dir, const std::filesystem::path& previous_report,
                                  const std::optional<nlohmann::json>& baseline);

}  // namespace gt
