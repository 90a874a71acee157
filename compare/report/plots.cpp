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
constexpr const char* script = GT_SOURCE_DIR "/compare/report/plot_timings.py";
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
  return output.empty() ? fmt::format("plot_timings.py failed ({})", exit)
                        : fmt::format("plot_timings.py failed ({}): {}", exit, output);
}

void write_rows(const std::vector<BenchmarkRow>& rows, const std::filesystem::path& file) {
  std::ofstream out(file);
  out << report_detail::benchmarks_to_json(rows).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", file.string()));
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
  if (std::string_view(python).empty()) {
    reason = "no Python with matplotlib was found when the build was configured";
    return std::nullopt;
  }
  const std::filesystem::path rows_file = temporary_path(".json");
  const std::filesystem::path log = temporary_path(".log");
  const TemporaryFiles temporaries{{rows_file, log}};
  write_rows(rows, rows_file);
  const std::filesystem::path png = folder / plot_file;
  std::error_code ignored;
  std::filesystem::remove(png, ignored);  // so a stale plot cannot pass for a new one
  reason = run_logged({python, script, rows_file.string(), png.string()}, log);
  if (!reason.empty()) return std::nullopt;
  if (!std::filesystem::exists(png)) {
    reason = fmt::format("plot_timings.py exited normally but wrote no {}", png.string());
    return std::nullopt;
  }
  return Artifact{plot_file, "plot", caption(rows)};
}

}  // namespace gt
