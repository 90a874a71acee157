// Runs plot_timings.py on the benchmark rows (see plots.hpp).
//
// The rows go to a temporary JSON file (the "benchmarks" array of report.json); the script runs
// through posix_spawn with an argument vector (no shell), its stdout and stderr captured in a
// temporary log whose last line becomes the reason when it fails. Both temporaries are removed.
#include "compare/report/plots.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <set>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compare/report/report_common.hpp"

#if !defined(GT_PYTHON_WITH_MATPLOTLIB) || !defined(GT_SOURCE_DIR)
#error "compare/report/plots.cpp needs the compile definitions GT_PYTHON_WITH_MATPLOTLIB and GT_SOURCE_DIR"
#endif

extern char** environ;

namespace gt {

namespace {

constexpr const char* python = GT_PYTHON_WITH_MATPLOTLIB;
constexpr const char* timings_script = GT_SOURCE_DIR "/compare/report/plot_timings.py";
constexpr const char* series_script = GT_SOURCE_DIR "/compare/report/plot_series.py";
constexpr const char* plot_file = "timings.png";

// Removes its files when it goes out of scope.
struct TemporaryFiles {
  std::vector<std::filesystem::path> paths;
  ~TemporaryFiles() {
    std::error_code ignored;
    for (const auto& path : paths) std::filesystem::remove(path, ignored);
  }
};

std::filesystem::path temporary_path(std::string_view suffix) {
  static std::atomic<int> counter = 0;
  return std::filesystem::temp_directory_path() / fmt::format("gt-plot-{}-{}{}", getpid(), counter++, suffix);
}

std::string last_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  std::string last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

// Runs argv with stdout and stderr going to `log`; returns "" on exit status 0, otherwise why not.
std::string run_logged(const std::vector<std::string>& arguments, const std::filesystem::path& log) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) return fmt::format("cannot run {}: {}", arguments[0], std::strerror(spawn_error));

  int status = 0;
  while (waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return fmt::format("waiting for {} failed: {}", arguments[0], std::strerror(errno));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const std::string exit = WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                             : fmt::format("signal {}", WTERMSIG(status));
  const std::string output = last_line(log);
  const std::string name = std::filesystem::path(arguments[1]).filename().string();
  return output.empty() ? fmt::format("{} failed ({})", name, exit) : fmt::format("{} failed ({}): {}", name, exit, output);
}

void write_json(const nlohmann::json& document, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
}

// Runs `script` on `document` to draw `png`; "" on success, otherwise why not.
std::string draw(const char* script, const nlohmann::json& document, const std::filesystem::path& png) {
  if (std::string_view(python).empty()) return "no Python with matplotlib was found when the build was configured";
  const std::filesystem::path input = temporary_path(".json");
  const std::filesystem::path log = temporary_path(".log");
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

void attach_plot(const std::vector<SeriesPlot>& panels, const std::filesystem::path& report_folder, const std::string& file,
                 const std::string& caption, CaseResult& result) {
  if (report_folder.empty()) return;
  std::filesystem::create_directories(report_folder / result.name);
  std::string reason;
  if (auto artifact = plot_series(panels, report_folder, result.name + "/" + file, caption, reason)) {
    result.artifacts.push_back(*artifact);
  } else {
    result.notes.push_back(file + " unavailable: " + reason);
  }
}

}  // namespace gt
