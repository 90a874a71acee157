// Helpers shared by the report writers, and write_report_files (all four formats at once).
#include "compare/report/report_common.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include <fmt/format.h>

#include "compare/report/writers.hpp"

namespace gt::report_detail {

namespace {

std::size_t outcome_index(Outcome outcome) {
  return static_cast<std::size_t>(std::find(all_outcomes.begin(), all_outcomes.end(), outcome) -
                                  all_outcomes.begin());
}

// Control characters other than tab, line feed and carriage return are not allowed in XML 1.0.
bool forbidden_in_xml(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 && c != '\t' && c != '\n' && c != '\r';
}

}  // namespace

int& OutcomeCounts::operator[](Outcome outcome) { return by_outcome[outcome_index(outcome)]; }
int OutcomeCounts::operator[](Outcome outcome) const { return by_outcome[outcome_index(outcome)]; }

int OutcomeCounts::total() const {
  int sum = 0;
  for (int count : by_outcome) sum += count;
  return sum;
}

std::array<LabelledField, 7> environment_fields(const Environment& environment) {
  return {{{"GL renderer", &environment.gl_renderer},
           {"GL version", &environment.gl_version},
           {"GL platform", &environment.gl_platform},
           {"CPU", &environment.cpu},
           {"compiler", &environment.compiler},
           {"build type", &environment.build_type},
           {"git", &environment.git}}};
}

OutcomeCounts count_case_outcomes(const Report& report) {
  OutcomeCounts counts;
  for (const CaseResult& result : report.cases) {
    ++counts[result.status];
    if (!result.expected_failure.empty()) ++counts.expected_failures;
  }
  return counts;
}

OutcomeCounts count_check_outcomes(const CaseResult& result) {
  OutcomeCounts counts;
  for (const Check& check : result.checks) ++counts[check.status];
  return counts;
}

std::string format_counts(const OutcomeCounts& counts, std::string_view separator) {
  std::string text;
  for (Outcome outcome : all_outcomes) {
    if (counts[outcome] == 0) continue;
    if (!text.empty()) text += separator;
    text += fmt::format("{} {}", outcome_name(outcome), counts[outcome]);
  }
  return text.empty() ? "none" : text;
}

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  return fmt::format("{:.3g}", value);
}

std::string format_ms(std::optional<double> ms) {
  if (!ms) return "–";
  if (std::isfinite(*ms) && std::abs(*ms) >= 1000.0) return fmt::format("{:.0f}", *ms);
  return format_value(*ms);
}

std::string format_bounds(const Check& check) {
  std::string text;
  if (check.threshold) text = fmt::format("≤ {}", format_value(*check.threshold));
  if (check.loose_threshold) {
    if (!text.empty()) text += ' ';
    text += std::isinf(*check.loose_threshold) ? std::string("(warn beyond)")
                                                : fmt::format("(warn ≤ {})", format_value(*check.loose_threshold));
  }
  return text;
}

std::string escape_markup(std::string_view text) {
  std::string escaped;
  escaped.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': escaped += "&amp;"; break;
      case '<': escaped += "&lt;"; break;
      case '>': escaped += "&gt;"; break;
      case '"': escaped += "&quot;"; break;
      case '\'': escaped += "&#39;"; break;
      default: escaped += forbidden_in_xml(c) ? std::string_view("\uFFFD") : std::string_view(&c, 1);
    }
  }
  return escaped;
}

void write_file_atomically(const std::filesystem::path& file, std::string_view contents) {
  std::filesystem::path temporary = file;
  temporary += fmt::format(".tmp-{}", getpid());
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.close();
    if (!out) {
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw std::runtime_error(fmt::format("cannot write {}", temporary.string()));
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, file, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw std::runtime_error(
        fmt::format("cannot rename {} to {}: {}", temporary.string(), file.string(), error.message()));
  }
}

std::string case_size_text(const CaseResult& result) {
  return result.width == 0 && result.height == 0 ? "—" : fmt::format("{}×{}", result.width, result.height);
}

std::string benchmark_size_text(const BenchmarkRow& row) {
  return row.dimensions == 3 ? fmt::format("{}³", row.size) : fmt::format("{}×{}", row.size, row.size);
}

std::string benchmark_time_text(const BenchmarkRow& row) { return row.note.empty() ? format_ms(row.median_ms) : "—"; }

std::string benchmark_rate_text(const BenchmarkRow& row) {
  return row.note.empty() ? format_value(row.mcell_iterations_per_s) : "—";
}

std::string benchmark_triangle_rate_text(const BenchmarkRow& row) {
  if (!row.note.empty()) return "—";
  return row.mtriangles_per_s ? format_value(*row.mtriangles_per_s) : "";
}

std::string benchmark_note_text(const BenchmarkRow& row) { return row.note.empty() ? "" : "not run: " + row.note; }

}  // namespace gt::report_detail

namespace gt {

void write_report_files(const Report& report, const std::filesystem::path& folder) {
  write_report_json(report, folder / "report.json");
  write_report_markdown(report, folder / "report.md");
  write_report_junit(report, folder / "junit.xml");
  write_report_html(report, folder / "index.html");
}

}  // namespace gt
