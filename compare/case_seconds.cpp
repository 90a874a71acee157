#include "compare/case_seconds.hpp"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "compare/report_diff.hpp"
#include "core/errors.hpp"
#include "core/json_keys.hpp"

namespace gt {

CaseSeconds case_seconds_of_report(const nlohmann::json& report) {
  CaseSeconds seconds;
  if (!report.is_object() || !report.contains("cases") || !report["cases"].is_array()) return seconds;
  for (const auto& entry : report["cases"]) {
    if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string()) continue;
    if (!entry.contains("seconds") || !entry["seconds"].is_number()) continue;
    const double value = entry["seconds"].get<double>();
    if (std::isfinite(value) && value > 0.0) seconds[entry["name"].get<std::string>()] = value;
  }
  return seconds;
}

CaseSeconds bundled_case_seconds(const std::filesystem::path& dataset_dir) {
  const auto file = dataset_dir / "case-seconds.json";
  if (!std::filesystem::exists(file)) return {};
  nlohmann::json document;
  try {
    std::ifstream in(file);
    document = parse_json_bounded(in, file.string());
  } catch (const nlohmann::json::exception& error) {
    throw InputError(fmt::format("{}: not valid JSON: {}", file.string(), error.what()));
  }
  if (!document.is_object() || !document.contains("seconds") || !document["seconds"].is_object()) {
    throw InputError(fmt::format("{}: expected {{\"recorded_on\": ..., \"seconds\": {{case: seconds}}}}", file.string()));
  }
  CaseSeconds seconds;
  for (const auto& [name, value] : document["seconds"].items()) {
    if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() < 0.0) {
      throw InputError(fmt::format("{}: {} must be a number of seconds, not {}", file.string(), name, value.dump()));
    }
    seconds[name] = value.get<double>();
  }
  return seconds;
}

std::optional<double> mean_expected_seconds(const std::vector<std::string>& names, const CaseSeconds& expected) {
  double sum = 0.0;
  int known = 0;
  for (const auto& name : names) {
    if (const auto found = expected.find(name); found != expected.end()) {
      sum += found->second;
      ++known;
    }
  }
  if (known == 0) return std::nullopt;
  return sum / known;
}

CaseSeconds expected_case_seconds(const std::filesystem::path& dataset_dir, const std::filesystem::path& previous_report,
                                  const std::optional<nlohmann::json>& baseline) {
  CaseSeconds seconds = bundled_case_seconds(dataset_dir);
  const auto overlay = [&](const CaseSeconds& later) {
    for (const auto& [name, value] : later) seconds[name] = value;
  };
  if (!previous_report.empty() && std::filesystem::is_regular_file(previous_report)) {
    try {
      overlay(case_seconds_of_report(read_report_json(previous_report)));
    } catch (const std::exception&) {
      // Not a report this build reads: the estimate keeps the other sources.
    }
  }
  if (baseline) overlay(case_seconds_of_report(*baseline));
  return seconds;
}

}  // namespace gt
