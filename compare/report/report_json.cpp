// report.json, schema 1 of DESIGN.md.
//
// Optional fields (threshold, loose_threshold, detail, cpu_ms, gpu_ms, expected_failure, error,
// earlier_attempts, known_flake, shard) are left out when absent or empty. compare/report/
// report_read.hpp reads the file back into a Report (workers, merge). Non-finite numbers become null so the file stays valid
// JSON; a check keeps its status, and its value's spelling ("nan", "inf", "-inf") is added as
// "value_text". Strings that are not valid UTF-8 are written with U+FFFD replacements.
#include <cmath>

#include "compare/mutation.hpp"
#include "compare/report/report_common.hpp"
#include "compare/report/writers.hpp"
#include "core/io/atomic_file.hpp"

namespace gt {

namespace {

using nlohmann::json;
using report_detail::all_outcomes;

json number_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json environment_to_json(const Environment& environment) {
  json out = {{"gl_renderer", environment.gl_renderer}, {"gl_version", environment.gl_version},
              {"gl_platform", environment.gl_platform}, {"cpu", environment.cpu},
              {"compiler", environment.compiler},       {"build_type", environment.build_type},
              {"git", environment.git},                 {"mutant", environment.mutant},
              {"graded", environment.graded}};
  if (environment.calibration_ms) out["calibration_ms"] = number_or_null(*environment.calibration_ms);
  out["run_started"] = environment.run_started;
  out["command_line"] = environment.command_line;
  out["git_revision"] = environment.git_revision;
  out["git_dirty"] = environment.git_dirty;
  out["git_at_configure"] = environment.git_at_configure;
  out["build_flags"] = environment.build_flags;
  out["shaders"] = environment.shaders;
  out["data"] = environment.data;
  return out;
}

json check_to_json(const Check& check) {
  json out = {{"name", check.name}, {"value", number_or_null(check.value)}};
  if (!std::isfinite(check.value)) out["value_text"] = report_detail::format_value(check.value);
  if (check.threshold) out["threshold"] = number_or_null(*check.threshold);
  if (check.loose_threshold) out["loose_threshold"] = number_or_null(*check.loose_threshold);
  out["status"] = outcome_name(check.status);
  if (!check.detail.empty()) out["detail"] = check.detail;
  if (check.expected) {
    out["expected"] = outcome_name(*check.expected);
    out["expectation"] = check.expectation;
  }
  return out;
}

json timings_to_json(const Timings& timings) {
  json out = json::object();
  if (timings.cpu_ms) out["cpu_ms"] = number_or_null(*timings.cpu_ms);
  if (timings.gpu_ms) out["gpu_ms"] = number_or_null(*timings.gpu_ms);
  out["cpu_reps"] = timings.cpu_reps;
  out["gpu_reps"] = timings.gpu_reps;
  return out;
}

json attempts_to_json(const std::vector<CaseResult::Attempt>& attempts) {
  json out = json::array();
  for (const auto& attempt : attempts) {
    out.push_back({{"status", outcome_name(attempt.status)}, {"error", attempt.error},
                   {"failing_checks", attempt.failing_checks}});
  }
  return out;
}

json case_to_json(const CaseResult& result) {
  json out = {{"name", result.name},     {"algorithm", result.algorithm}, {"input", result.input},
              {"width", result.width},   {"height", result.height},
              {"status", outcome_name(result.status)}};
  if (!result.expected_failure.empty()) out["expected_failure"] = result.expected_failure;
  if (!result.notes.empty()) out["notes"] = result.notes;
  out["params"] = result.params;
  out["checks"] = json::array();
  for (const Check& check : result.checks) out["checks"].push_back(check_to_json(check));
  out["timings"] = timings_to_json(result.timings);
  out["artifacts"] = json::array();
  out["artifact_details"] = json::array();
  for (const Artifact& artifact : result.artifacts) {
    out["artifacts"].push_back(artifact.path);
    json details = {{"kind", artifact.kind}, {"caption", artifact.caption}};
    if (artifact.scale) {
      details["scale"] = {{"palette", artifact.scale->palette}, {"low", artifact.scale->low},
                          {"high", artifact.scale->high}, {"unit", artifact.scale->unit},
                          {"colours", artifact.scale->colours}};
    }
    if (artifact.width_m) details["width_m"] = number_or_null(*artifact.width_m);
    out["artifact_details"].push_back(std::move(details));
  }
  if (!result.descriptors.is_null()) out["descriptors"] = result.descriptors;
  if (!result.error.empty()) out["error"] = result.error;
  out["seconds"] = number_or_null(result.seconds);
  if (result.expected_seconds) out["expected_seconds"] = number_or_null(*result.expected_seconds);
  if (!result.tier.empty()) out["tier"] = result.tier;
  if (!result.earlier_attempts.empty()) out["earlier_attempts"] = attempts_to_json(result.earlier_attempts);
  if (!result.known_flake.empty()) out["known_flake"] = result.known_flake;
  return out;
}

json optional_number(const std::optional<double>& value) { return value ? number_or_null(*value) : json(nullptr); }

json benchmark_to_json(const BenchmarkRow& row) {
  return {{"algorithm", row.algorithm},
          {"backend", row.backend},
          {"size", row.size},
          {"iterations", row.iterations},
          {"reps", row.reps},
          {"median_ms", number_or_null(row.median_ms)},
          {"mcell_iterations_per_s", number_or_null(row.mcell_iterations_per_s)},
          {"device", row.device},
          {"dimensions", row.dimensions},
          {"mtriangles_per_s", optional_number(row.mtriangles_per_s)},
          {"note", row.note},
          {"detail", row.detail},
          {"peer", row.peer},
          {"bytes_per_cell", optional_number(row.bytes_per_cell)},
          {"floor_ms", optional_number(row.floor_ms)},
          {"times_floor", row.floor_ms ? number_or_null(row.median_ms / *row.floor_ms) : json(nullptr)},
          {"times_peer", optional_number(row.times_peer)},
          {"fastest_peer", row.fastest_peer}};
}

json scaling_to_json(const std::vector<BenchmarkRow>& rows) {
  json out = json::array();
  for (const ScalingFit& fit : fit_scaling(rows)) {
    out.push_back({{"algorithm", fit.algorithm},
                   {"backend", fit.backend},
                   {"peer", fit.peer},
                   {"device", fit.device},
                   {"dimensions", fit.dimensions},
                   {"sizes", fit.sizes},
                   {"exponent", number_or_null(fit.exponent)},
                   {"linear", fit.linear()},
                   {"linear_exponent_limit", linear_exponent_limit}});
  }
  return out;
}

}  // namespace

json report_detail::benchmarks_to_json(const std::vector<BenchmarkRow>& rows) {
  json out = json::array();
  for (const BenchmarkRow& row : rows) out.push_back(benchmark_to_json(row));
  return out;
}

namespace {

json summary_to_json(const Report& report) {
  const auto counts = report_detail::count_case_outcomes(report);
  json out = json::object();
  for (Outcome outcome : all_outcomes) out[outcome_name(outcome)] = counts[outcome];
  out["failed"] = run_failed(report) || (report.mutation && !report.mutation->passed());
  return out;
}

}  // namespace

json report_to_json(const Report& report) {
  json out = {{"schema", 1}, {"environment", environment_to_json(report.environment)}};
  out["cases"] = json::array();
  for (const CaseResult& result : report.cases) out["cases"].push_back(case_to_json(result));
  out["benchmarks"] = report_detail::benchmarks_to_json(report.benchmarks);
  out["scaling"] = scaling_to_json(report.benchmarks);
  out["summary"] = summary_to_json(report);
  out["expectation_problems"] = report.expectation_problems;
  if (report.mutation) out["mutation"] = mutation_to_json(*report.mutation);
  if (!report.scope.empty()) out["scope"] = report.scope;
  if (report.baseline_diff) out["baseline"] = {{"file", report.baseline_file}, {"diff", to_json(*report.baseline_diff)}};
  if (report.shard) {
    out["shard"] = {{"index", report.shard->index}, {"count", report.shard->count},
                    {"selection", report.shard->selection}, {"balanced_by", report.shard->balanced_by}};
  }
  return out;
}

void write_report_json(const Report& report, const std::filesystem::path& file) {
  const std::string text = report_to_json(report).dump(2, ' ', false, json::error_handler_t::replace) + "\n";
  write_file_atomically(file, text);
}

}  // namespace gt
