// Plots for reports, drawn with matplotlib: the benchmark plot (median time per run and throughput
// over grid size, compare/report/plot_timings.py) and generic x-y series (plot_series.py).
//
// The Python interpreter is GT_PYTHON_WITH_MATPLOTLIB (found at configure time, may be empty) and
// the script GT_SOURCE_DIR "/compare/report/plot_timings.py"; both are compile definitions.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "compare/result.hpp"

namespace gt {

struct RunOptions;

// Writes folder/timings.png (folder is the report folder and must exist) and returns it as the
// artifact {"timings.png", "plot", caption}. Returns std::nullopt and sets `reason` when there are
// no rows, no Python with matplotlib, or the script fails (its last line of output says why);
// the caller then shows "plot unavailable: <reason>" (writers.hpp: a plot with an empty path).
std::optional<Artifact> plot_benchmarks(const std::vector<BenchmarkRow>& rows, const std::filesystem::path& folder,
                                        std::string& reason);

// Any x-y plot drawn by compare/report/plot_series.py: one line per series, optional log axes.
struct Series {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  bool dashed = false;  // bounds and models dashed, measurements solid
  std::string group;    // series with the same non-empty group share a colour (a measurement and its twin)
};

struct SeriesPlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::vector<std::pair<double, std::string>> x_ticks;  // labelled ticks (revisions); empty: matplotlib's own
};

// Writes report_folder/relative_png (its folder must exist): the panels side by side in one
// figure (one panel: a plot of its own), and returns it as a "plot" artifact with `caption`;
// std::nullopt and `reason` as plot_benchmarks.
std::optional<Artifact> plot_series(const std::vector<SeriesPlot>& panels, const std::filesystem::path& report_folder,
                                    const std::string& relative_png, const std::string& caption, std::string& reason);

// A case's plot: draws options.report_dir/<case name>/<file> (creating the case's folder) and adds
// it to the case's artifacts, or, when it cannot be drawn, a note "<file> unavailable: <reason>".
// Nothing without a report folder, nor in a run without pictures (RunOptions::pictures).
void attach_plot(const std::vector<SeriesPlot>& panels, const RunOptions& options, const std::string& file,
                 const std::string& caption, CaseResult& result);

}  // namespace gt
