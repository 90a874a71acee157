// Helpers shared by the report writers, and write_report_files (all four formats at once).
#include "compare/report/report_common.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

std::array<LabelledField, 14> environment_fields(const Environment& environment) {
  return {{{"graded in the GPU twin's place", &environment.graded},
           {"GL renderer", &environment.gl_renderer},
           {"GL version", &environment.gl_version},
           {"GL platform", &environment.gl_platform},
           {"CPU", &environment.cpu},
           {"compiler", &environment.compiler},
           {"build type", &environment.build_type},
           {"build flags", &environment.build_flags},
           {"git", &environment.git},
           {"git revision", &environment.git_revision},
           {"configured from", &environment.git_at_configure},
           {"run started", &environment.run_started},
           {"command line", &environment.command_line},
           {"mutant", &environment.mutant}}};
}

std::vector<std::string> attempt_lines(const CaseResult& result) {
  std::vector<std::string> lines;
  for (std::size_t index = 0; index < result.earlier_attempts.size(); ++index) {
    const auto& attempt = result.earlier_attempts[index];
    std::string line = fmt::format("attempt {}: {}", index + 1, outcome_name(attempt.status));
    if (!attempt.error.empty()) line += ": " + attempt.error;
    for (const auto& check : attempt.failing_checks) line += "; " + check;
    lines.push_back(line);
  }
  if (result.status == Outcome::flaky) {
    lines.push_back(result.known_flake.empty() ? "a new flake: not on the flake list (fix it, or list it with a reason)"
                                               : "known flake: " + result.known_flake);
  }
  return lines;
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

std::string page_head(std::string_view title, std::string_view style) {
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{}</title>\n"
      "<style>{}</style>\n</head>\n<body>\n",
      escape_markup(title), style);
}

bool unreserved(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '.' ||
         c == '_' || c == '~';
}

std::string case_anchor(const std::string& case_name) {
  std::string id = "case-";
  for (char c : case_name) id += unreserved(c) ? c : '_';
  return id;
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

namespace {

bool file_named(const Artifact& artifact, std::string_view name) {
  const std::string_view path = artifact.path;
  return path == name || (path.size() > name.size() && path.ends_with(name) && path[path.size() - name.size() - 1] == '/');
}

bool ends_with(std::string_view text, std::string_view suffix) { return text.ends_with(suffix); }

// "0.0039 (1/255)": a channel difference with its 8-bit levels.
std::string channel_text(double value) {
  return std::isfinite(value) && value != 0.0 ? fmt::format("{} ({:.3g}/255)", format_value(value), 255.0 * value)
                                              : format_value(value);
}

std::string percent_text(double share) {
  return std::isfinite(share) ? fmt::format("{:.3g} %", 100.0 * share) : format_value(share);
}

}  // namespace

std::optional<ImageComparison> image_comparison(const CaseResult& result) {
  ImageComparison comparison;
  // A user's image graded in the GPU's place (run --candidate) has the same pictures under its name.
  if (std::any_of(result.artifacts.begin(), result.artifacts.end(),
                  [](const Artifact& artifact) { return file_named(artifact, "candidate.png"); })) {
    comparison.twin = "candidate";
  }
  const std::string& twin = comparison.twin;
  for (const Artifact& artifact : result.artifacts) {
    if (artifact.kind != "image") continue;
    if (!comparison.reference && file_named(artifact, "cpu.png")) {
      comparison.reference = &artifact;
    } else if (!comparison.gpu && file_named(artifact, twin + ".png")) {
      comparison.gpu = &artifact;
    } else if (!comparison.difference &&
               (file_named(artifact, twin + "_vs_cpu_heat.png") || file_named(artifact, twin + "_vs_cpu.png"))) {
      comparison.difference = &artifact;
    } else if (!comparison.mask && file_named(artifact, twin + "_vs_cpu_mask.png")) {
      comparison.mask = &artifact;
    } else {
      comparison.others.push_back(&artifact);
    }
  }
  for (const Check& check : result.checks) {
    if (!ends_with(check.name, "." + twin + "_vs_cpu")) continue;
    if (check.status == Outcome::skip) {
      if (comparison.gpu_missing_reason.empty()) comparison.gpu_missing_reason = check.detail;
    } else {
      comparison.metrics.push_back(&check);
    }
  }
  const bool gpu_ran = comparison.difference != nullptr;
  const bool gpu_skipped = !comparison.gpu && !comparison.gpu_missing_reason.empty();
  if (!comparison.reference || !(gpu_ran || gpu_skipped)) return std::nullopt;
  if (comparison.gpu) comparison.gpu_missing_reason.clear();
  return comparison;
}

MetricText metric_text(const Check& check) {
  const std::string& name = check.name;
  const std::optional<double>& bound = check.threshold;
  // "image.psnr.gpu_vs_cpu": the metric, and the twin compared with the reference.
  const auto last_dot = name.rfind('.');
  const std::string metric = name.substr(0, last_dot);
  const std::string pair = last_dot == std::string::npos ? "" : name.substr(last_dot + 1);
  const std::string twin = pair.substr(0, pair.find("_vs_"));
  if (metric == "image.psnr") {  // the value is -PSNR, the bound -(least PSNR)
    const double psnr = -check.value;
    return {"PSNR", std::isinf(psnr) && psnr > 0 ? "∞ dB (identical)" : fmt::format("{:.1f} dB", psnr),
            bound ? fmt::format("≥ {} dB", format_value(-*bound)) : ""};
  }
  const auto shown = [&](const std::string& label, std::string (*text)(double)) {
    return MetricText{label, text(check.value), bound ? "≤ " + text(*bound) : ""};
  };
  if (metric == "image.max_abs") return shown("max |" + twin + " − cpu|", channel_text);
  if (metric == "image.rms") return shown("RMS", format_value);
  if (metric == "image.share_beyond_tolerance") return shown("pixels beyond 4/255", percent_text);
  if (metric == "image.share_beyond_tolerance_outside_edges") return shown("beyond 4/255, edge shifts allowed", percent_text);
  std::string label = metric;
  for (const std::string_view kind : {"image.", "parity."}) {
    if (label.starts_with(kind)) label = label.substr(kind.size());
  }
  std::replace(label.begin(), label.end(), '_', ' ');
  return {label, format_value(check.value), format_bounds(check)};
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

std::string benchmark_note_text(const BenchmarkRow& row) {
  return row.note.empty() ? row.detail : "not run: " + row.note;
}

std::string benchmark_backend_text(const BenchmarkRow& row) {
  if (!row.peer.empty()) return "peer: " + row.peer;
  return row.backend == "published" ? "published: " + row.device : row.backend;
}

namespace {

std::string times_text(const std::optional<double>& ratio) {
  return ratio ? fmt::format("{:.3g}×", *ratio) : "";
}

}  // namespace

std::string benchmark_bytes_text(const BenchmarkRow& row) {
  return row.bytes_per_cell ? fmt::format("{:g}", *row.bytes_per_cell) : "";
}

std::string benchmark_floor_text(const BenchmarkRow& row) {
  return times_text(row.floor_ms ? std::optional<double>(row.median_ms / *row.floor_ms) : std::nullopt);
}

std::string benchmark_peer_text(const BenchmarkRow& row) {
  return row.times_peer ? fmt::format("{} {}", times_text(row.times_peer), row.fastest_peer) : "";
}

std::string benchmark_speedup_text(const std::vector<BenchmarkRow>& rows, const BenchmarkRow& row) {
  if (row.backend != "gpu" || !row.peer.empty() || !row.note.empty() || !(row.median_ms > 0.0)) return "";
  for (const BenchmarkRow& reference : rows) {
    if (reference.backend == "cpu" && reference.peer.empty() && reference.note.empty() &&
        reference.algorithm == row.algorithm && reference.size == row.size && reference.dimensions == row.dimensions &&
        reference.iterations == row.iterations && reference.median_ms > 0.0) {
      return times_text(reference.median_ms / row.median_ms);
    }
  }
  return "";
}

std::string benchmark_devices_once(const std::vector<BenchmarkRow>& rows) {
  std::map<std::string, std::set<std::string>> devices;  // by backend
  for (const BenchmarkRow& row : rows) {
    // A published figure names its own machine in its backend cell.
    if (row.backend != "published") devices[row.backend].insert(row.device.empty() ? "unknown device" : row.device);
  }
  std::vector<std::string> parts;
  for (const auto& [backend, names] : devices) {
    if (names.size() != 1) return "";
    parts.push_back(fmt::format("{}: {}", backend, *names.begin()));
  }
  return fmt::format("{}", fmt::join(parts, "; "));
}

std::string scaling_explanation() {
  return fmt::format("Exponent p of time ∝ (cells · iterations)^p, least squares over each line's sizes (at least {}); "
                     "above {} work that is linear in the cells scales worse than linearly. × floor: the median over "
                     "the memory-bound floor, the row's bytes per cell at the copy bandwidth memory.copy measured on "
                     "the same device.",
                     scaling_min_sizes, linear_exponent_limit);
}

std::string scaling_missing_text() { return fmt::format("No line was timed at {} sizes or more.", scaling_min_sizes); }

std::string scaling_line_text(const ScalingFit& fit) { return fit.peer.empty() ? fit.backend : "peer: " + fit.peer; }

std::string scaling_sizes_text(const ScalingFit& fit) {
  const auto side = [&](int size) { return fit.dimensions == 3 ? fmt::format("{}³", size) : fmt::format("{}²", size); };
  return fmt::format("{}–{} ({})", side(fit.sizes.front()), side(fit.sizes.back()), fit.sizes.size());
}

std::string scaling_exponent_text(const ScalingFit& fit) {
  return fit.linear() ? fmt::format("{:.2f} linear", fit.exponent)
                      : fmt::format("{:.2f} superlinear (> {})", fit.exponent, linear_exponent_limit);
}

namespace {

// Evenly spaced colours as a CSS gradient from left to right (grey when there are none).
std::string css_gradient(const std::vector<std::array<float, 3>>& colours) {
  if (colours.empty()) return "#999";
  std::vector<std::string> stops;
  const auto channel = [](float c) { return static_cast<int>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  for (std::size_t i = 0; i < colours.size(); ++i) {
    const double at = colours.size() == 1 ? 0.0 : 100.0 * double(i) / double(colours.size() - 1);
    stops.push_back(fmt::format("rgb({},{},{}) {:.4g}%", channel(colours[i][0]), channel(colours[i][1]),
                                channel(colours[i][2]), at));
  }
  return fmt::format("linear-gradient(to right, {})", fmt::join(stops, ", "));
}

}  // namespace

// A map's colour bar: the palette from its low end to its high end, the ends (and 0 of a
// diverging map) labelled in the map's unit.
std::string colour_bar(const std::optional<ColourScale>& scale) {
  if (!scale) return "";
  const std::string unit = scale->unit.empty() || scale->unit == "1" ? "" : " " + scale->unit;
  const auto label = [&](double value) {
    return escape_markup(fmt::format("{:.3g}{}", value == 0.0 ? 0.0 : value, unit));
  };
  if (scale->low == scale->high) {
    return fmt::format("<div class=\"colourbar\"><span class=\"ticks\"><span>every value {}</span></span></div>",
                       label(scale->low));
  }
  const bool centred = scale->low < 0.0 && scale->high == -scale->low;
  const std::string middle = centred ? fmt::format("<span>0{}</span>", escape_markup(unit)) : std::string();
  return fmt::format("<div class=\"colourbar\" title=\"{}\"><span class=\"ramp\" style=\"background: {}\"></span>"
                     "<span class=\"ticks\"><span>{}</span>{}<span>{}</span></span></div>",
                     escape_markup(scale->palette), css_gradient(scale->colours), label(scale->low), middle,
                     label(scale->high));
}

std::string scale_bar(const std::optional<double>& width_m) {
  if (!width_m || !std::isfinite(*width_m) || *width_m <= 0.0) return "";
  const double wanted = *width_m / 4.0;
  const double decade = std::pow(10.0, std::floor(std::log10(wanted)));
  double length = decade;
  for (const double step : {2.0, 5.0}) {
    if (step * decade <= wanted) length = step * decade;
  }
  const std::string label = length >= 1000.0 ? fmt::format("{:g} km", length / 1000.0) : fmt::format("{:g} m", length);
  return fmt::format("<div class=\"scalebar\" title=\"the map is {:.4g} m wide\"><span class=\"bar\" style=\"width: "
                     "{:.3f}%\"></span><span>{}</span></div>",
                     *width_m, 100.0 * length / *width_m, escape_markup(label));
}

}  // namespace gt::report_detail

namespace gt {

void write_report_files(const Report& report, const std::filesystem::path& folder) {
  write_report_json(report, folder / "report.json");
  write_report_markdown(report, folder / "report.md");
  write_report_junit(report, folder / "junit.xml");
  write_report_html(report, folder / "index.html");
}

}  // namespace gt
