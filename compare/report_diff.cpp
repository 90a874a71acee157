// Check-by-check comparison of two report.json files: see report_diff.hpp.
#include "compare/report_diff.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "compare/report/report_read.hpp"
#include "core/errors.hpp"
#include "core/io/text_file.hpp"
#include "core/json_keys.hpp"
#include "core/wording.hpp"

namespace gt {

namespace {

using json = nlohmann::json;

constexpr int supported_schema = 1;
constexpr double moved_share_of_bound = 0.01;
constexpr double moved_share_of_magnitude = 1e-6;

bool good(const std::string& outcome) { return outcome == "pass" || outcome == "warn" || outcome == "inconclusive"; }
bool bad(const std::string& outcome) { return outcome == "fail" || outcome == "error"; }

std::map<std::string, const json*> by_name(const json& list) {
  std::map<std::string, const json*> out;
  for (const auto& entry : list) out[entry.at("name").get<std::string>()] = &entry;
  return out;
}

std::string value_text(const json& check) {
  if (check.contains("value_text")) return check["value_text"].get<std::string>();
  if (!check.contains("value") || !check["value"].is_number()) return "";
  return fmt::format("{:.17g}", check["value"].get<double>());
}

std::optional<double> number(const json& object, const char* key) {
  if (!object.contains(key) || !object[key].is_number()) return std::nullopt;
  return object[key].get<double>();
}

bool value_moved(const std::string& name, const json& before, const json& after) {
  const auto a = number(before, "value"), b = number(after, "value");
  if (!a || !b) return value_text(before) != value_text(after);
  if (name.ends_with(".cpu")) return *a != *b;  // the double reference is deterministic
  const double difference = std::abs(*a - *b);
  if (const auto bound = number(after, "threshold"); bound && *bound > 0.0) {
    return difference > moved_share_of_bound * *bound;
  }
  return difference > moved_share_of_magnitude * std::max(std::abs(*a), std::abs(*b));
}

void compare_check(const std::string& where, const json& before, const json& after, ReportDiff& diff) {
  const std::string was = before.at("status"), is = after.at("status");
  const bool expected_now = after.contains("expected") && after["expected"] == is;
  if (was != is) {
    ReportDiff::Change change{where, was, is};
    if (good(was) && bad(is) && !expected_now) {
      diff.regressions.push_back(change);
    } else if (bad(was) && good(is)) {
      diff.fixes.push_back(change);
    } else {
      diff.outcome_changes.push_back(change);
    }
  } else if (value_moved(after.at("name"), before, after)) {
    diff.moved.push_back({where, value_text(before), value_text(after)});
  }
}

// A case's time on one backend as a multiple of its run's calibration kernel.
std::optional<double> relative_time(const json& report_case, const char* key, std::optional<double> calibration) {
  if (!calibration || *calibration <= 0.0 || !report_case.contains("timings")) return std::nullopt;
  const auto ms = number(report_case["timings"], key);
  if (!ms || *ms <= 0.0) return std::nullopt;
  return *ms / *calibration;
}

void compare_timings(const std::string& name, const json& before, const json& after, std::optional<double> base_unit,
                     std::optional<double> next_unit, ReportDiff& diff) {
  for (const char* key : {"cpu_ms", "gpu_ms"}) {
    const auto was = relative_time(before, key, base_unit), is = relative_time(after, key, next_unit);
    if (!was || !is) continue;
    const double ratio = *is / *was;
    if (ratio > diff.timing_noise_factor || ratio < 1.0 / diff.timing_noise_factor) {
      diff.timings.push_back({fmt::format("{}: {}", name, key), fmt::format("{:.3g} × calibration", *was),
                              fmt::format("{:.3g} × calibration ({:.2f}× {})", *is, ratio,
                                          ratio > 1.0 ? "slower" : "faster")});
    }
  }
}

void compare_case(const std::string& name, const json& before, const json& after, std::optional<double> base_unit,
                  std::optional<double> next_unit, ReportDiff& diff) {
  const auto before_checks = by_name(before.at("checks")), after_checks = by_name(after.at("checks"));
  for (const auto& [check, entry] : after_checks) {
    const std::string where = fmt::format("{}: {}", name, check);
    const auto found = before_checks.find(check);
    if (found == before_checks.end()) {
      diff.added.push_back({where, "", entry->at("status")});
    } else {
      compare_check(where, *found->second, *entry, diff);
    }
  }
  for (const auto& [check, entry] : before_checks) {
    if (!after_checks.contains(check)) diff.removed.push_back({fmt::format("{}: {}", name, check), entry->at("status"), ""});
  }
  const std::string was = before.at("status"), is = after.at("status");
  if (good(was) && bad(is) && !after.contains("expected_failure")) diff.regressions.push_back({name, was, is});
  compare_timings(name, before, after, base_unit, next_unit, diff);
}

void check_report(const json& report, const std::string& which) {
  if (!report.is_object() || !report.contains("schema") || !report.contains("cases") || !report["cases"].is_array()) {
    throw InputError(fmt::format("{} is not a groundtruth report.json (no schema or cases)", which));
  }
  if (report["schema"] != supported_schema) {
    throw InputError(fmt::format("{} has report schema {}; this groundtruth reads schema {}", which,
                                 report["schema"].dump(), supported_schema));
  }
}

void append_section(std::string& out, const char* title, const std::vector<ReportDiff::Change>& changes) {
  if (changes.empty()) return;
  out += fmt::format("{} ({}):\n", title, changes.size());
  for (const auto& change : changes) {
    out += fmt::format("  {}  {} → {}\n", change.where, change.before.empty() ? "—" : change.before,
                       change.after.empty() ? "—" : change.after);
  }
}

json changes_json(const std::vector<ReportDiff::Change>& changes) {
  json out = json::array();
  for (const auto& change : changes) out.push_back({{"where", change.where}, {"before", change.before}, {"after", change.after}});
  return out;
}


// diff_reports once both files are known to be reports; json::exception where an entry is malformed.
ReportDiff diff_checked_reports(const json& base, const json& next) {
  ReportDiff diff;
  const auto base_cases = by_name(base["cases"]), next_cases = by_name(next["cases"]);
  const auto base_unit = base.contains("environment") ? number(base["environment"], "calibration_ms") : std::nullopt;
  const auto next_unit = next.contains("environment") ? number(next["environment"], "calibration_ms") : std::nullopt;
  for (const auto& [name, entry] : next_cases) {
    const auto found = base_cases.find(name);
    if (found == base_cases.end()) {
      diff.added.push_back({name, "", entry->at("status")});
      continue;
    }
    ++diff.common_cases;
    compare_case(name, *found->second, *entry, base_unit, next_unit, diff);
  }
  for (const auto& [name, entry] : base_cases) {
    if (!next_cases.contains(name)) diff.removed.push_back({name, entry->at("status"), ""});
  }
  if (diff.common_cases == 0 && !base_cases.empty() && !next_cases.empty()) {
    throw InputError("the two reports share no case: a baseline from another suite or algorithm set");
  }
  return diff;
}

}  // namespace

namespace {

json parse_report_document(const std::filesystem::path& file) {
  std::istringstream stream(read_text_file(file, json_document_limits, "report"));
  json report;
  try {
    report = parse_json_bounded(stream, file.string());
  } catch (const json::exception& error) {
    throw InputError(fmt::format("{} is not valid JSON: {}", file.string(), error.what()));
  }
  check_report(report, file.string());
  return report;
}

Report rebuilt_report(const json& document, const std::filesystem::path& file) {
  try {
    return report_from_json(document);
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", file.string(), error.what()));
  }
}

}  // namespace

json read_report_json(const std::filesystem::path& file) {
  json document = parse_report_document(file);
  // As strict as the readers that rebuild the report (history, merge, a run's workers): an unknown
  // outcome ("FAIL", "eror") or a field of the wrong type is refused, never read as no change.
  (void)rebuilt_report(document, file);
  return document;
}

Report read_report(const std::filesystem::path& file) { return rebuilt_report(parse_report_document(file), file); }

ReportDiff diff_reports(const json& base, const json& next) {
  check_report(base, "BASE");
  check_report(next, "NEW");
  for (const auto& [report, which] : {std::pair{&base, "BASE"}, std::pair{&next, "NEW"}}) {
    if ((*report)["cases"].empty()) throw InputError(fmt::format("{} holds no case: there is nothing to compare", which));
  }
  try {
    return diff_checked_reports(base, next);
  } catch (const json::exception& error) {
    throw InputError(fmt::format("a report's cases are malformed (a name, status or check of the wrong type or "
                                 "missing): {}", error.what()));
  }
}

json to_json(const ReportDiff& diff) {
  return {{"common_cases", diff.common_cases},
          {"regressions", changes_json(diff.regressions)},
          {"fixes", changes_json(diff.fixes)},
          {"outcome_changes", changes_json(diff.outcome_changes)},
          {"added", changes_json(diff.added)},
          {"removed", changes_json(diff.removed)},
          {"moved", changes_json(diff.moved)},
          {"timings", changes_json(diff.timings)},
          {"timing_noise_factor", diff.timing_noise_factor}};
}

std::string describe(const ReportDiff& diff) {
  std::string out = fmt::format("{} in both reports\n", counted(diff.common_cases, "case"));
  append_section(out, "REGRESSIONS", diff.regressions);
  append_section(out, "fixes", diff.fixes);
  append_section(out, "other outcome changes", diff.outcome_changes);
  append_section(out, "added", diff.added);
  append_section(out, "removed", diff.removed);
  append_section(out, "values moved (CPU double: any bit; others: beyond 1 % of the bound)", diff.moved);
  append_section(out, "timings beyond noise (ratio to each run's calibration kernel, factor 1.25)", diff.timings);
  if (diff.regressions.empty() && diff.fixes.empty() && diff.outcome_changes.empty() && diff.added.empty() &&
      diff.removed.empty() && diff.moved.empty() && diff.timings.empty()) {
    out += "no changes\n";
  }
  return out;
}

}  // namespace gt
