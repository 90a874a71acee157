// report.md: a Markdown summary for reading in a terminal or a code-hosting web view.
//
// Sections: environment, summary line, case table, one section per case that has something
// other than passing checks (error, expectation, warn/fail/skip checks), benchmark table, plots.
// Table cells escape '|' and a '<' that could open an HTML tag (before a letter, '/', '!' or '?') with
// a backslash, CommonMark's escape, which reads as itself in a terminal (no HTML entities), and fold
// line breaks into spaces.
#include <cctype>

#include <fmt/format.h>

#include "compare/report/report_common.hpp"
#include "compare/report/writers.hpp"
#include "core/io/atomic_file.hpp"
#include "core/wording.hpp"

namespace gt {

namespace {

using namespace report_detail;

bool opens_a_tag(std::string_view text, std::size_t at) {
  if (at + 1 >= text.size()) return false;
  const char next = text[at + 1];
  return std::isalpha(static_cast<unsigned char>(next)) || next == '/' || next == '!' || next == '?';
}

std::string cell(std::string_view text) {
  std::string escaped;
  for (std::size_t at = 0; at < text.size(); ++at) {
    const char c = text[at];
    switch (c) {
      case '|': escaped += "\\|"; break;
      case '<': escaped += opens_a_tag(text, at) ? "\\<" : "<"; break;
      case '\n':
      case '\r': escaped += ' '; break;
      default: escaped += c;
    }
  }
  return escaped;
}

void append_environment(std::string& out, const Environment& environment) {
  out += "| environment | |\n|---|---|\n";
  for (const auto& [label, value] : environment_fields(environment)) {
    if (value->empty()) continue;  // no mutant, nothing graded but our own twins
    out += fmt::format("| {} | {} |\n", label, cell(*value));
  }
  out += '\n';
}

void append_summary(std::string& out, const Report& report) {
  const OutcomeCounts counts = count_case_outcomes(report);
  out += fmt::format("**{}** — {}: {}; expected failures: {}\n\n",
                     run_failed(report) ? "RUN FAILED" : "run ok", counted(counts.total(), "case"), format_counts(counts, ", "),
                     counts.expected_failures);
  if (!report.scope.empty()) out += fmt::format("{}\n\n", cell(report.scope));
}


void append_case_table(std::string& out, const Report& report) {
  out += "## Cases\n\n| case | status | algorithm | input | size | cpu ms (reps) | gpu ms (reps) | checks |\n"
         "|---|---|---|---|---|---:|---:|---|\n";
  for (const CaseResult& result : report.cases) {
    const std::string expected = result.expected_failure.empty() ? "" : " (expected)";
    out += fmt::format("| {} | **{}**{} | {} | {} | {} | {} ({}) | {} ({}) | {} |\n", cell(result.name),
                       outcome_name(result.status), expected, cell(result.algorithm), cell(result.input),
                       case_size_text(result), format_ms(result.timings.cpu_ms), result.timings.cpu_reps,
                       format_ms(result.timings.gpu_ms), result.timings.gpu_reps,
                       format_counts(count_check_outcomes(result), ", "));
  }
  out += '\n';
}

bool has_details(const CaseResult& result) {
  if (!result.error.empty() || !result.expected_failure.empty() || !result.notes.empty()) return true;
  if (!result.earlier_attempts.empty()) return true;
  for (const Check& check : result.checks) {
    if (check.status != Outcome::pass) return true;
  }
  return false;
}

void append_case_details(std::string& out, const CaseResult& result) {
  out += fmt::format("### {} — {}\n\n", result.name, outcome_name(result.status));
  if (!result.expected_failure.empty()) out += fmt::format("Expected failure: {}\n\n", cell(result.expected_failure));
  if (!result.error.empty()) out += fmt::format("Error: {}\n\n", cell(result.error));
  for (const auto& line : attempt_lines(result)) out += fmt::format("- {}\n", cell(line));
  if (!result.earlier_attempts.empty()) out += '\n';
  for (const auto& note : result.notes) out += fmt::format("- input: {}\n", cell(note));
  if (!result.notes.empty()) out += '\n';
  bool header_written = false;
  for (const Check& check : result.checks) {
    if (check.status == Outcome::pass) continue;
    if (!header_written) {
      out += "| check | value | bound | status | detail |\n|---|---:|---|---|---|\n";
      header_written = true;
    }
    out += fmt::format("| {} | {} | {} | **{}** | {} |\n", cell(check.name), format_value(check.value),
                       format_bounds(check), outcome_name(check.status), cell(check.detail));
  }
  if (header_written) out += '\n';
}

void append_scaling(std::string& out, const Report& report) {
  const auto fits = fit_scaling(report.benchmarks);
  out += fmt::format("### Scaling\n\n{}\n\n", scaling_explanation());
  if (fits.empty()) {
    out += scaling_missing_text() + "\n\n";
    return;
  }
  out += "| algorithm | backend | device | sizes | exponent |\n|---|---|---|---|---:|\n";
  for (const ScalingFit& fit : fits) {
    out += fmt::format("| {} | {} | {} | {} | {} |\n", cell(fit.algorithm),
                       cell(scaling_line_text(fit)), cell(fit.device),
                       scaling_sizes_text(fit), scaling_exponent_text(fit));
  }
  out += '\n';
}

void append_benchmarks(std::string& out, const Report& report) {
  out += "## Benchmarks\n\n";
  if (report.benchmarks.empty()) {
    out += "No benchmarks in this run.\n\n";
  } else {
    const std::string devices = benchmark_devices_once(report.benchmarks);
    if (!devices.empty()) out += fmt::format("Devices: {}\n\n", cell(devices));
    out += fmt::format("| algorithm | backend | {}size | iterations | reps | median ms | GPU speed-up | Mcell-it/s (noise: "
                       "M samples/s; cave: M voxels/s) | M triangles/s | B/cell | × floor | × peer | note |\n"
                       "|---|---|{}---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n",
                       devices.empty() ? "device | " : "", devices.empty() ? "---|" : "");
    for (const BenchmarkRow& row : report.benchmarks) {
      out += fmt::format("| {} | {} | {}{} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", cell(row.algorithm),
                         cell(benchmark_backend_text(row)), devices.empty() ? cell(row.device) + " | " : "",
                         benchmark_size_text(row), row.iterations, row.reps, benchmark_time_text(row),
                         benchmark_speedup_text(report.benchmarks, row), benchmark_rate_text(row),
                         benchmark_triangle_rate_text(row), benchmark_bytes_text(row), benchmark_floor_text(row),
                         cell(benchmark_peer_text(row)), cell(benchmark_note_text(row)));
    }
    out += '\n';
    append_scaling(out, report);
  }
  for (const Artifact& plot : report.plots) {
    out += plot.path.empty() ? fmt::format("{}\n\n", cell(plot.caption))
                             : fmt::format("![{}]({})\n\n", cell(plot.caption), plot.path);
  }
}

void append_mutation(std::string& out, const Report& report) {
  for (const auto& problem : report.expectation_problems) out += fmt::format("Expectation not met: {}\n\n", cell(problem));
  if (!report.mutation) return;
  const MutationReport& mutation = *report.mutation;
  out += fmt::format("## Mutants\n\nMutation score: {} of {} killed ({:.0f} %).\n\n", mutation.killed(), mutation.bugs(),
                     100.0 * mutation.score());
  if (const auto& specificity = mutation.specificity) {
    out += specificity->problem.empty()
               ? fmt::format("Specificity: {} of {} honest runs without a false alarm ({}{}).\n\n",
                             specificity->runs - specificity->false_alarms, specificity->runs, mutation.folder,
                             specificity->page)
               : fmt::format("Specificity not measured: {}.\n\n", cell(specificity->problem));
  }
  for (const auto& baseline : mutation.baselines) {
    if (!baseline.clean) out += fmt::format("Baseline of {} not clean: {}\n\n", baseline.family, cell(baseline.problems.front()));
  }
  out += "| status | mutant | kind | killed by |\n|---|---|---|---|\n";
  for (const auto& mutant : mutation.mutants) {
    out += fmt::format("| {} | {} | {}{} | {} |\n", mutant.status, mutant.name, mutant.kind,
                       mutant.must_survive ? " (must survive)" : "",
                       cell(mutant.killed_by.empty() ? mutant.error : mutant.killed_by.front()));
  }
  out += "\n";
  std::vector<std::string> unproved;
  for (const auto& row : mutation.kill_matrix()) {
    if (row.mutants.empty()) unproved.push_back(row.check);
  }
  if (!unproved.empty()) {
    out += fmt::format("Graded checks that killed no mutant: {}.\n\n", cell(fmt::format("{}", fmt::join(unproved, ", "))));
  }
}

}  // namespace

void write_report_markdown(const Report& report, const std::filesystem::path& file) {
  std::string out = "# groundtruth report\n\n";
  append_environment(out, report.environment);
  // `groundtruth mutants` or `bench` alone: the mutation score or the performance table, without
  // the scaffolding of a case run.
  if (report.cases.empty()) {
    if (!report.benchmarks.empty()) append_benchmarks(out, report);
    append_mutation(out, report);
    write_file_atomically(file, out);
    return;
  }
  append_summary(out, report);
  append_case_table(out, report);
  out += "## Details\n\n";
  bool any_details = false;
  for (const CaseResult& result : report.cases) {
    if (!has_details(result)) continue;
    append_case_details(out, result);
    any_details = true;
  }
  if (!any_details) out += "Every check of every case passed.\n\n";
  append_benchmarks(out, report);
  append_mutation(out, report);
  write_file_atomically(file, out);
}

}  // namespace gt
