// Runs plot_timings.py on the benchmark rows (see plots.hpp).
//
// The rows go to a temporary JSON file (the "benchmarks" array of report.json); the script runs
// through run_logged (compare/subprocess.hpp). Both temporaries are removed.
#include "compare/report/plots.hpp"

#include <fstream>
#include <set>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/field_twin.hpp"
#include "compare/report/report_common.hpp"
#include "compare/subprocess.hpp"

#if !defined(GT_PYTHON_WITH_MATPLOTLIB) || !defined(GT_SOURCE_DIR)
#error "compare/report/plots.cpp needs the compile definitions GT_PYTHON_WITH_MATPLOTLIB and GT_SOURCE_DIR"
#endif

namespace gt {

namespace {

constexpr const char* python = GT_PYTHON_WITH_MATPLOTLIB;
constexpr const char* timings_script = GT_SOURCE_DIR "/compare/report/plot_timings.py";
constexpr const char* series_script = GT_SOURCE_DIR "/compare/report/plot_series.py";
constexpr const char* plot_file = "timings.png";

void write_json(const nlohmann::json& document, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

// Runs `script` on `document` to draw `png`; "" on success, otherwise why not.
std::string draw(const char* script, const nlohmann::json& document, const std::filesystem::path& png) {
  if (std::string_view(python).empty()) return "no Python with matplotlib was found when the build was configured";
  const std::filesystem::path input = temporary_path("gt-plot", ".json");
  const std::filesystem::path log = temporary_path("gt-plot", ".log");
  const TemporaryFiles temporaries{{input, log}};
  write_json(document, input);
  std::error_code ignored;
  std::filesystem::remove(png, ignored);  // so a stale plot cannot pass for a new one
  const std::string failure = run_logged({python, script, input.string(), png.string()}, log);
  if (!failure.empty()) return failure;
  if (!std::filesystem::exists(png)) return fmt::format("{} exited normally but wrote no {}", script, png.string());
  return "";
}

std::string caption(const std::vector<BenchmarkRow>& rows) {
  std::set<std::string> devices;
  for (const BenchmarkRow& row : rows) devices.insert(row.device);
  return fmt::format("Median time per run and Mcell-iterations/s over grid size; devices: {}",
                     fmt::join(devices, "; "));
}

}  // namespace

std::optional<Artifact> plot_benchmarks(const std::vector<BenchmarkRow>& rows, const std::filesystem::path& folder,
                                        std::string& reason) {
  if (rows.empty()) {
    reason = "no benchmark rows";
    return std::nullopt;
  }
  reason = draw(timings_script, report_detail::benchmarks_to_json(rows), folder / plot_file);
  if (!reason.empty()) return std::nullopt;
  return Artifact{plot_file, "plot", caption(rows)};
}

namespace {

nlohmann::json panel_json(const SeriesPlot& plot) {
  nlohmann::json document = {{"title", plot.title},   {"x_label", plot.x_label}, {"y_label", plot.y_label},
                             {"log_x", plot.log_x},   {"log_y", plot.log_y},     {"series", nlohmann::json::array()}};
  for (const Series& series : plot.series) {
    document["series"].push_back({{"label", series.label},
                                  {"x", series.x},
                                  {"y", series.y},
                                  {"dashed", series.dashed},
                                  {"group", series.group}});
  }
  if (!plot.x_ticks.empty()) document["x_ticks"] = plot.x_ticks;
  return document;
}

}  // namespace

std::optional<Artifact> plot_series(const std::vector<SeriesPlot>& panels, const std::filesystem::path& report_folder,
                                    const std::string& relative_png, const std::string& caption, std::string& reason) {
  nlohmann::json document = {{"panels", nlohmann::json::array()}};
  for (const SeriesPlot& panel : panels) document["panels"].push_back(panel_json(panel));
  reason = draw(series_script, document, report_folder / relative_png);
  if (!reason.empty()) return std::nullopt;
  return Artifact{relative_png, "plot", caption};
}

void attach_plot(const std::vector<SeriesPlot>& panels, const RunOptions& options, const std::string& file,
                 const std::string& caption, CaseResult& result) {
  const std::filesystem::path& report_folder = options.report_dir;
  if (report_folder.empty() || !options.pictures) return;
  std::filesystem::create_directories(report_folder / result.name);
  std::string reason;
  if (auto artifact = plot_series(panels, report_folder, result.name + "/" + file, caption, reason)) {
    result.artifacts.push_back(*artifact);
  } else {
    result.notes.push_back(file + " unavailable: " + reason);
  }
}

}  // namespace gt
