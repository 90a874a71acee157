// Series of report.json values over revisions, where each first drifted, and the page that shows
// them: see report_history.hpp.
#include "compare/report_history.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <tuple>
#include <utility>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "compare/output_folder.hpp"
#include "compare/report/plots.hpp"
#include "compare/report/report_common.hpp"
#include "compare/report/report_read.hpp"
#include "compare/report_diff.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/names.hpp"
#include "core/wording.hpp"

namespace gt {

namespace {

using report_detail::escape_markup;

constexpr int search_depth = 2;                     // folders of report folders, one and two levels deep
constexpr double moved_share_of_threshold = 0.01;   // a value moving by 1 % of its bound has drifted
constexpr double moved_share_of_magnitude = 1e-9;   // ... or, below that, by this share of its size
const double timing_noise_factor = ReportDiff{}.timing_noise_factor;
constexpr std::array<const char*, 2> timing_keys = {"cpu_ms", "gpu_ms"};  // CaseHistory::timings, in this order

// ---- finding the reports

void collect_reports(const std::filesystem::path& folder, int depth_left, std::vector<std::filesystem::path>& found) {
  if (std::filesystem::is_regular_file(folder / "report.json")) {
    found.push_back(folder / "report.json");
    return;
  }
  if (depth_left == 0) return;
  std::vector<std::filesystem::path> subfolders;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_directory()) subfolders.push_back(entry.path());
  }
  std::sort(subfolders.begin(), subfolders.end());
  for (const auto& subfolder : subfolders) collect_reports(subfolder, depth_left - 1, found);
}

std::vector<std::filesystem::path> report_files(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::filesystem::path> found;
  for (const auto& input : inputs) {
    if (!std::filesystem::exists(input)) throw InputError(fmt::format("{} does not exist", input.string()));
    if (std::filesystem::is_directory(input)) {
      collect_reports(input, search_depth, found);
    } else {
      found.push_back(input);
    }
  }
  std::set<std::filesystem::path> seen;
  std::erase_if(found, [&](const auto& file) { return !seen.insert(std::filesystem::weakly_canonical(file)).second; });
  return found;
}

// ---- revisions

std::optional<double> positive(std::optional<double> number) {
  if (!number || !std::isfinite(*number) || *number <= 0.0) return std::nullopt;
  return number;
}

// "2026-12-02T04:13:46Z", as written by compare/provenance.cpp.
std::chrono::sys_seconds parse_utc(const std::string& text, const std::filesystem::path& file) {
  int year = 0;
  unsigned month = 0, day = 0, hour = 0, minute = 0, second = 0;
  const bool read = std::sscanf(text.c_str(), "%d-%u-%uT%u:%u:%u", &year, &month, &day, &hour, &minute, &second) == 6;
  const std::chrono::year_month_day date{std::chrono::year{year}, std::chrono::month{month}, std::chrono::day{day}};
  if (!read || !date.ok() || hour > 23 || minute > 59 || second > 60) {
    throw InputError(fmt::format("{}: environment.run_started \"{}\" is not an ISO 8601 UTC time", file.string(), text));
  }
  return std::chrono::sys_days{date} + std::chrono::hours{hour} + std::chrono::minutes{minute} +
         std::chrono::seconds{second};
}

std::chrono::sys_seconds modification_time(const std::filesystem::path& file) {
  return std::chrono::floor<std::chrono::seconds>(
      std::chrono::file_clock::to_sys(std::filesystem::last_write_time(file)));
}

HistoryRevision revision_of(const Environment& environment, const std::filesystem::path& file) {
  HistoryRevision revision;
  revision.path = file;
  revision.calibration_ms = positive(environment.calibration_ms);
  revision.time_from_file = environment.run_started.empty();
  revision.time = revision.time_from_file ? modification_time(file) : parse_utc(environment.run_started, file);
  const bool git_known = !environment.git.empty() && !environment.git.starts_with("unknown");
  revision.label = fmt::format("{} {:%Y-%m-%d %H:%M}{}", git_known ? environment.git : "unknown",
                               fmt::gmtime(std::chrono::system_clock::to_time_t(revision.time)),
                               environment.mutant.empty() ? "" : " mutant " + environment.mutant);
  return revision;
}

// ---- series

template <class Entry>
Entry* find_named(std::vector<Entry>& list, const std::string& name) {
  const auto found = std::find_if(list.begin(), list.end(), [&](const Entry& entry) { return entry.name == name; });
  return found == list.end() ? nullptr : &*found;
}

// The case's series, appended (absent at every revision) when first met.
CaseHistory& case_named(History& history, const std::string& name) {
  if (CaseHistory* found = find_named(history.cases, name)) return *found;
  const std::size_t revisions = history.revisions.size();
  CaseHistory& added = history.cases.emplace_back();
  added.name = name;
  added.status.resize(revisions);
  for (const char* key : timing_keys) added.timings.push_back({key, std::vector<std::optional<double>>(revisions), {}});
  return added;
}

CheckHistory& check_named(CaseHistory& series, const std::string& name) {
  if (CheckHistory* found = find_named(series.checks, name)) return *found;
  return series.checks.emplace_back(CheckHistory{name, std::vector<std::optional<CheckPoint>>(series.status.size()), {}});
}

void add_case(const CaseResult& result, std::size_t revision, History& history) {
  CaseHistory& series = case_named(history, result.name);
  series.status[revision] = result.status;
  for (const Check& check : result.checks) {
    check_named(series, check.name).points[revision] = CheckPoint{check.status, check.value, check.threshold};
  }
  series.timings[0].ms[revision] = positive(result.timings.cpu_ms);
  series.timings[1].ms[revision] = positive(result.timings.gpu_ms);
}

// ---- drift

// The first present point that differs from the previous present one; `change(before, after)`
// gives the texts of a difference between revisions `before` and `after`, or nothing.
template <class Point, class Change>
std::optional<HistoryDrift> first_drift(const std::vector<std::optional<Point>>& points, Change change) {
  std::optional<std::size_t> previous;
  for (std::size_t revision = 0; revision < points.size(); ++revision) {
    if (!points[revision]) continue;
    if (previous) {
      if (auto texts = change(*previous, revision)) return HistoryDrift{revision, texts->first, texts->second};
    }
    previous = revision;
  }
  return std::nullopt;
}

using ChangeTexts = std::optional<std::pair<std::string, std::string>>;

ChangeTexts status_change(Outcome before, Outcome after) {
  if (before == after) return std::nullopt;
  return std::pair{std::string(outcome_name(before)), std::string(outcome_name(after))};
}

bool value_moved(double before, double after, std::optional<double> threshold) {
  if (!std::isfinite(before) || !std::isfinite(after)) return !(before == after || (std::isnan(before) && std::isnan(after)));
  double tolerance = moved_share_of_magnitude * std::max(std::abs(before), std::abs(after));
  if (threshold && std::isfinite(*threshold) && *threshold > 0.0) {
    tolerance = std::max(tolerance, moved_share_of_threshold * *threshold);
  }
  return std::abs(after - before) > tolerance;
}

// Two values with the fewest significant digits (four at least) that still tell them apart: a
// drift may be 1e-9 of the value, and seventeen digits of every value bury the magnitudes a reader
// compares (report.json keeps them all).
std::pair<std::string, std::string> distinct_texts(double before, double after) {
  for (int digits = 4; digits < 17; ++digits) {
    std::string before_text = fmt::format("{:.{}g}", before, digits);
    std::string after_text = fmt::format("{:.{}g}", after, digits);
    if (before_text != after_text) return {std::move(before_text), std::move(after_text)};
  }
  return {fmt::format("{}", before), fmt::format("{}", after)};
}

ChangeTexts check_change(const CheckPoint& before, const CheckPoint& after) {
  if (auto texts = status_change(before.status, after.status)) return texts;
  if (!value_moved(before.value, after.value, after.threshold ? after.threshold : before.threshold)) return std::nullopt;
  return distinct_texts(before.value, after.value);
}

ChangeTexts timing_change(double before_ms, double after_ms, std::optional<double> before_unit,
                          std::optional<double> after_unit) {
  const bool normalised = before_unit && after_unit;
  const double before = normalised ? before_ms / *before_unit : before_ms;
  const double after = normalised ? after_ms / *after_unit : after_ms;
  const double factor = after / before;
  if (factor <= timing_noise_factor && factor >= 1.0 / timing_noise_factor) return std::nullopt;
  const char* unit = normalised ? "× calibration" : "ms (raw: a report has no calibration)";
  return std::pair{fmt::format("{:.3g} {}", before, unit),
                   fmt::format("{:.3g} {} ({:.2f}× {})", after, unit, factor, factor > 1.0 ? "slower" : "faster")};
}

void find_drifts(CaseHistory& series, const std::vector<HistoryRevision>& revisions) {
  series.status_drift = first_drift(series.status, [&](std::size_t a, std::size_t b) {
    return status_change(*series.status[a], *series.status[b]);
  });
  for (CheckHistory& check : series.checks) {
    check.drift = first_drift(check.points, [&](std::size_t a, std::size_t b) {
      return check_change(*check.points[a], *check.points[b]);
    });
  }
  for (TimingHistory& timing : series.timings) {
    timing.drift = first_drift(timing.ms, [&](std::size_t a, std::size_t b) {
      return timing_change(*timing.ms[a], *timing.ms[b], revisions[a].calibration_ms, revisions[b].calibration_ms);
    });
  }
}

}  // namespace

History read_history(const std::vector<std::filesystem::path>& inputs) {
  std::vector<std::pair<HistoryRevision, Report>> reports;
  for (const auto& file : report_files(inputs)) {
    Report report = read_report(file);
    reports.emplace_back(revision_of(report.environment, file), std::move(report));
  }
  if (reports.size() < 2) {
    throw InputError(fmt::format("a history needs at least 2 reports; found {} in the {} input{}", reports.size(),
                                 inputs.size(), inputs.size() == 1 ? "" : "s"));
  }
  std::sort(reports.begin(), reports.end(), [](const auto& a, const auto& b) {
    return std::tie(a.first.time, a.first.path) < std::tie(b.first.time, b.first.path);
  });
  History history;
  for (const auto& [revision, report] : reports) history.revisions.push_back(revision);
  for (std::size_t revision = 0; revision < reports.size(); ++revision) {
    for (const CaseResult& result : reports[revision].second.cases) add_case(result, revision, history);
  }
  for (CaseHistory& series : history.cases) find_drifts(series, history.revisions);
  return history;
}

namespace {

// ---- plots

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::vector<double> revision_numbers(std::size_t count) {
  std::vector<double> numbers(count);
  for (std::size_t revision = 0; revision < count; ++revision) numbers[revision] = static_cast<double>(revision + 1);
  return numbers;
}

bool has_threshold(const CheckHistory& check) {
  return std::any_of(check.points.begin(), check.points.end(),
                     [](const auto& point) { return point && point->threshold && *point->threshold > 0.0; });
}

// Each check's value divided by its threshold (nan where either is missing), and the bound at 1.
SeriesPlot threshold_panel(const CaseHistory& series, const std::vector<double>& x) {
  SeriesPlot panel{"checks against their bounds", "revision", "value / threshold", false, true, {}};
  for (const CheckHistory& check : series.checks) {
    if (!has_threshold(check)) continue;
    Series line{check.name, x, {}, false, ""};
    for (const auto& point : check.points) {
      line.y.push_back(point && point->threshold && *point->threshold > 0.0 ? point->value / *point->threshold : nan);
    }
    panel.series.push_back(std::move(line));
  }
  if (!panel.series.empty()) panel.series.push_back({"bound", x, std::vector<double>(x.size(), 1.0), true, ""});
  return panel;
}

SeriesPlot value_panel(const CaseHistory& series, const std::vector<double>& x) {
  SeriesPlot panel{"checks without a bound", "revision", "value", false, false, {}};
  for (const CheckHistory& check : series.checks) {
    if (has_threshold(check)) continue;
    Series line{check.name, x, {}, false, ""};
    for (const auto& point : check.points) line.y.push_back(point ? point->value : nan);
    panel.series.push_back(std::move(line));
  }
  return panel;
}

bool all_calibrated(const History& history) {
  return std::all_of(history.revisions.begin(), history.revisions.end(),
                     [](const HistoryRevision& revision) { return revision.calibration_ms.has_value(); });
}

SeriesPlot timing_panel(const CaseHistory& series, const History& history, const std::vector<double>& x) {
  const bool normalised = all_calibrated(history);
  SeriesPlot panel{"times", "revision",
                   normalised ? "time / calibration kernel" : "ms (raw: a report has no calibration)", false, true, {}};
  for (const TimingHistory& timing : series.timings) {
    if (std::none_of(timing.ms.begin(), timing.ms.end(), [](const auto& ms) { return ms.has_value(); })) continue;
    Series line{timing.key, x, {}, false, ""};
    for (std::size_t revision = 0; revision < timing.ms.size(); ++revision) {
      const auto& ms = timing.ms[revision];
      line.y.push_back(!ms ? nan : normalised ? *ms / *history.revisions[revision].calibration_ms : *ms);
    }
    panel.series.push_back(std::move(line));
  }
  return panel;
}

// The case's figure, or "plot unavailable: <reason>", as HTML.
std::string plot_html(const CaseHistory& series, const History& history, const std::filesystem::path& folder) {
  if (!is_dotted_identifier(series.name)) {
    return "<p class=\"note\">plot unavailable: the case's name is not a dotted identifier, so it cannot name a file</p>\n";
  }
  const auto x = revision_numbers(history.revisions.size());
  std::vector<SeriesPlot> panels;
  for (SeriesPlot panel : {threshold_panel(series, x), value_panel(series, x), timing_panel(series, history, x)}) {
    if (panel.series.empty()) continue;
    // "#k" as in the tables; the Revisions table names each (whole labels, rotated, left the panels a sliver).
    for (std::size_t index = 0; index < x.size(); ++index) panel.x_ticks.emplace_back(x[index], fmt::format("#{}", index + 1));
    panels.push_back(std::move(panel));
  }
  if (panels.empty()) return "<p class=\"note\">plot unavailable: no checks and no timings</p>\n";
  std::string reason;
  const auto plot = plot_series(panels, folder, series.name + ".png", series.name + " over revisions", reason);
  if (!plot) return fmt::format("<p class=\"note\">plot unavailable: {}</p>\n", escape_markup(reason));
  return fmt::format("<figure class=\"plot\"><img src=\"{0}\" alt=\"{1}\"><figcaption>{1}</figcaption></figure>\n",
                     escape_markup(plot->path), escape_markup(plot->caption));
}

// ---- the page

constexpr std::string_view style = R"(
body { font: 14px/1.45 system-ui, sans-serif; color: #222; max-width: 1280px; margin: 0 auto; padding: 1em 2em; }
table { border-collapse: collapse; margin: .6em 0 1em; }
th, td { border: 1px solid #ddd; padding: .25em .6em; text-align: left; vertical-align: top; }
th { background: #f3f3f3; }
td.pass { background: #e3f1e4; } td.fail { background: #f8d7d7; } td.warn { background: #fdf1c7; }
td.skip { background: #e6e6e6; } td.inconclusive { background: #dcecf7; } td.error { background: #eadcf0; }
td.flaky { background: #fde3cc; }
td.absent { color: #999; }
section.case { border-top: 2px solid #e4e4e4; margin-top: 2em; }
.note { color: #555; font-style: italic; }
figure { margin: 0; } figure img { width: 100%; max-width: 1100px; } figcaption { font-size: .9em; color: #444; }
)";

std::string revision_text(const History& history, std::size_t revision) {
  return fmt::format("#{} {}", revision + 1, history.revisions[revision].label);
}

std::string case_anchor(std::size_t index) { return fmt::format("case-{}", index); }

void append_revisions(std::string& out, const History& history) {
  out += "<h2>Revisions</h2>\n<table>\n<tr><th>#</th><th>revision</th><th>calibration ms</th><th>report</th></tr>\n";
  for (std::size_t index = 0; index < history.revisions.size(); ++index) {
    const HistoryRevision& revision = history.revisions[index];
    out += fmt::format("<tr><td>{}</td><td>{}{}</td><td>{}</td><td>{}</td></tr>\n", index + 1, escape_markup(revision.label),
                       revision.time_from_file ? " (file time: no run_started)" : "",
                       revision.calibration_ms ? fmt::format("{:.3g}", *revision.calibration_ms) : "—",
                       escape_markup(revision.path.string()));
  }
  out += "</table>\n";
}

struct SummaryRow {
  std::size_t case_index;
  std::string series;
  const HistoryDrift* drift;
};

// The drifted series of one kind (outcomes and values, or timings), earliest first.
std::vector<SummaryRow> summary_rows(const History& history, bool timings) {
  std::vector<SummaryRow> rows;
  for (std::size_t index = 0; index < history.cases.size(); ++index) {
    const CaseHistory& series = history.cases[index];
    if (timings) {
      for (const TimingHistory& timing : series.timings) {
        if (timing.drift) rows.push_back({index, "timings." + timing.key, &*timing.drift});
      }
      continue;
    }
    if (series.status_drift) rows.push_back({index, "case status", &*series.status_drift});
    for (const CheckHistory& check : series.checks) {
      if (check.drift) rows.push_back({index, check.name, &*check.drift});
    }
  }
  std::stable_sort(rows.begin(), rows.end(), [](const SummaryRow& a, const SummaryRow& b) {
    return a.drift->revision < b.drift->revision;
  });
  return rows;
}

void append_drift_table(std::string& out, const History& history, const std::vector<SummaryRow>& rows) {
  out += "<table>\n<tr><th>case</th><th>series</th><th>first drift</th><th>from</th><th>to</th></tr>\n";
  for (const SummaryRow& row : rows) {
    out += fmt::format("<tr><td><a href=\"#{}\">{}</a></td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                       case_anchor(row.case_index), escape_markup(history.cases[row.case_index].name),
                       escape_markup(row.series), escape_markup(revision_text(history, row.drift->revision)),
                       escape_markup(row.drift->from), escape_markup(row.drift->to));
  }
  out += "</table>\n";
}

// Outcomes and values first: timings on a shared machine move more often, and would bury them.
void append_summary(std::string& out, const History& history) {
  for (const bool timings : {false, true}) {
    out += timings ? "<h2>First drifts of timings</h2>\n" : "<h2>First drifts of outcomes and values</h2>\n";
    const auto rows = summary_rows(history, timings);
    if (!rows.empty()) {
      append_drift_table(out, history, rows);
    } else if (timings) {
      out += "<p>No timing moved beyond the noise factor from revision to revision.</p>\n";
    } else {
      out += "<p>No drift: every outcome and value stays within its tolerance from revision to revision.</p>\n";
    }
  }
}

// An outcome coloured by its kind, with `value` (when given) shown on hovering.
std::string status_cell(std::optional<Outcome> status, std::optional<double> value) {
  if (!status) return "<td class=\"absent\">—</td>";
  const std::string title = value ? fmt::format(" title=\"value {}\"", *value) : "";
  return fmt::format("<td class=\"{0}\"{1}>{0}</td>", outcome_name(*status), title);
}

void append_status_table(std::string& out, const CaseHistory& series, const History& history) {
  out += "<table>\n<tr><th>outcome</th>";
  for (std::size_t revision = 0; revision < history.revisions.size(); ++revision) {
    out += fmt::format("<th title=\"{}\">#{}</th>", escape_markup(history.revisions[revision].label), revision + 1);
  }
  out += "</tr>\n<tr><td>case</td>";
  for (const auto& status : series.status) out += status_cell(status, std::nullopt);
  out += "</tr>\n";
  for (const CheckHistory& check : series.checks) {
    out += fmt::format("<tr><td>{}</td>", escape_markup(check.name));
    for (const auto& point : check.points) {
      out += point ? status_cell(point->status, point->value) : status_cell(std::nullopt, std::nullopt);
    }
    out += "</tr>\n";
  }
  out += "</table>\n";
}

void append_case(std::string& out, std::size_t index, const History& history, const std::filesystem::path& folder) {
  const CaseHistory& series = history.cases[index];
  out += fmt::format("<section class=\"case\" id=\"{}\">\n<h2>{}</h2>\n", case_anchor(index), escape_markup(series.name));
  out += plot_html(series, history, folder);
  append_status_table(out, series, history);
  out += "</section>\n";
}

}  // namespace

void write_history_page(const History& history, const std::filesystem::path& folder) {
  std::string out = report_detail::page_head("groundtruth history", style) + fmt::format(
      "<h1>groundtruth history</h1>\n"
      "<p>{} revisions. A series drifts where its outcome changes, a check's value moves by more than {:g} % of its "
      "bound (or {:g} of its size), or a time changes by more than a factor {:g} as a ratio to each run's calibration "
      "kernel (raw ms where a report has none), each against the previous revision that has it.</p>\n",
      history.revisions.size(), 100.0 * moved_share_of_threshold, moved_share_of_magnitude, timing_noise_factor);
  append_summary(out, history);
  append_revisions(out, history);
  for (std::size_t index = 0; index < history.cases.size(); ++index) append_case(out, index, history, folder);
  out += "</body>\n</html>\n";
  write_file_atomically(folder / "index.html", out);
}

}  // namespace gt

namespace gt {

int history_command(const HistoryOptions& options) {
  for (const auto& input : options.inputs) refuse_input_inside_output(options.out, input, "history");
  const History history = read_history(options.inputs);
  check_output_folder(options.out);
  write_folder_atomically(options.out, [&](const std::filesystem::path& folder) { write_history_page(history, folder); });
  int drifts = 0;
  for (const auto& series : history.cases) {
    const auto print = [&](const std::string& what, const std::optional<HistoryDrift>& drift) {
      if (!drift) return;
      ++drifts;
      fmt::print("drift  {} {}: from {} to {} at {}\n", series.name, what, drift->from, drift->to,
                 history.revisions[drift->revision].label);
    };
    print("status", series.status_drift);
    for (const auto& check : series.checks) print(check.name, check.drift);
    for (const auto& timing : series.timings) print(timing.key, timing.drift);
  }
  fmt::print("groundtruth: {}, {}, {} drifted; history in {}\n", counted(history.revisions.size(), "report"),
             counted(history.cases.size(), "case"), counted(drifts, "series", "series"), (options.out / "index.html").string());
  return 0;
}

}  // namespace gt
