// When a drift started (issue 15): `groundtruth history REPORT...` reads a run's report.json files
// over revisions and draws, per case, every check's value and both timings over them, with the
// first revision where each series drifted.
//
// Inputs: paths, each a report.json, a report folder (its report.json), or a folder of report
// folders (report.json searched one and two levels deep: reports/2026-11-30/report.json,
// reports/ci/2026-11-30/report.json; a folder holding a report.json is a report folder and is not
// searched further). The same file reached twice is read once.
// Revisions: the reports ordered by environment.run_started (ISO 8601 UTC, "2026-12-02T04:13:46Z"),
// or the file's modification time where a report has none; ties by path. Each is labelled by
// environment.git ("unknown" when absent or unknown) and its time, "d010547-dirty 2026-12-02 04:13".
// Series, each a value per revision, absent where the report has no such case or check:
//   a case's status; each check's status, value and threshold; each case's cpu_ms and gpu_ms.
// Drift: comparing each present point with the previous present one (an absent revision is
// skipped, a series appearing is not a drift), the first revision where
//   a status changed (pass -> fail, pass -> skip, ...);
//   a check's value moved by more than max(1 % of its threshold, 1e-9 of the larger magnitude)
//   (a non-finite value moved unless both are the same: nan and nan, inf and inf);
//   a time changed by more than diff-reports' noise factor (ReportDiff::timing_noise_factor, 1.25)
//   either way, as a ratio to each run's calibration kernel when both reports have one, else in
//   raw milliseconds (the drift's text says which).
// Throws InputError when an input does not exist, a file is not a groundtruth report of schema 1
// (read_report_json), a case or check is malformed (report_from_json), run_started is not an
// ISO 8601 UTC time, or fewer than 2 reports are found.
#pragma once

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/result.hpp"

namespace gt {

struct HistoryOptions {
  std::vector<std::filesystem::path> inputs;  // report.json files, report folders, folders of them
  std::filesystem::path out;                  // the folder the page goes to
};

struct HistoryRevision {
  std::string label;                     // "<git> <YYYY-MM-DD HH:MM>" (UTC)
  std::filesystem::path path;            // the report.json read
  std::chrono::sys_seconds time;         // environment.run_started, or the file's modification time
  bool time_from_file = false;           // the report has no run_started
  std::optional<double> calibration_ms;  // environment.calibration_ms; absent when missing or not positive
};

// Where a series first changed beyond noise.
struct HistoryDrift {
  std::size_t revision = 0;  // index into History::revisions of the first revision that differs from its predecessor
  std::string from;          // the predecessor's status, value or time as text
  std::string to;            // the same at `revision`
};

struct CheckPoint {
  Outcome status = Outcome::pass;
  double value = 0.0;                // nan, inf or -inf where the report wrote null with a value_text
  std::optional<double> threshold;
};

struct CheckHistory {
  std::string name;
  std::vector<std::optional<CheckPoint>> points;  // one per revision
  std::optional<HistoryDrift> drift;
};

struct TimingHistory {
  std::string key;                         // "cpu_ms" or "gpu_ms"
  std::vector<std::optional<double>> ms;   // one per revision, raw; absent where missing or not positive
  std::optional<HistoryDrift> drift;
};

struct CaseHistory {
  std::string name;
  std::vector<std::optional<Outcome>> status;      // one per revision
  std::optional<HistoryDrift> status_drift;
  std::vector<CheckHistory> checks;                // in the order first met, oldest revision first
  std::vector<TimingHistory> timings;              // cpu_ms, gpu_ms
};

struct History {
  std::vector<HistoryRevision> revisions;  // oldest first
  std::vector<CaseHistory> cases;          // in the order first met, oldest revision first
};

History read_history(const std::vector<std::filesystem::path>& inputs);

// Writes folder/index.html (folder must exist) and folder/<case name>.png for each case whose name
// is a dotted identifier (core/names.hpp), drawn by plot_series (compare/report/plots.hpp): panels
// over the revisions (ticks labelled with their git and time; the table of revisions lists them) with each check's
// value / threshold (log y), the values of checks without a threshold, and the case's times as
// ratios to the calibration kernel (raw ms when a revision has no calibration; the axis says so).
// Where a plot cannot be drawn the page says "plot unavailable: <reason>".
// The page: on top a summary of every series that drifted (case, series, first revision, from ->
// to; earliest first), then the table of revisions, then per case its plot and a table of outcomes
// per revision (cells coloured by outcome).
void write_history_page(const History& history, const std::filesystem::path& folder);

}  // namespace gt

namespace gt {

// `groundtruth history`: read_history, then the page written atomically into options.out
// (compare/output_folder.hpp), and one line per drift on stdout. Returns 0.
int history_command(const HistoryOptions& options);

}  // namespace gt
