#include "compare/subprocess.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "compare/output_folder.hpp"

extern char** environ;

namespace gt {
namespace {

std::string last_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  std::string last;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  }
  return last;
}

}  // namespace

TemporaryFiles::TemporaryFiles(std::vector<std::filesystem::path> removed) : paths(std::move(removed)) {
  for (const auto& path : paths) add_interruption_leftover(path);
}

TemporaryFiles::~TemporaryFiles() {
  std::error_code ignored;
  for (const auto& path : paths) {
    std::filesystem::remove_all(path, ignored);
    remove_interruption_leftover(path);
  }
}

std::filesystem::path temporary_path(std::string_view prefix, std::string_view suffix) {
  static std::atomic<int> counter = 0;
  return std::filesystem::temp_directory_path() / fmt::format("{}-{}-{}{}", prefix, getpid(), counter++, suffix);
}

std::string run_logged(const std::vector<std::string>& arguments, const std::filesystem::path& log) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  // Its own process group, known to the interruption's clean-up, which ends it with the run.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawn_error != 0) return fmt::format("cannot run {}: {}", arguments[0], std::strerror(spawn_error));
  add_running_worker(child);

  int status = 0;
  int waited = 0;
  while ((waited = waitpid(child, &status, 0)) < 0 && errno == EINTR) {
  }
  remove_running_worker(child);
  if (waited < 0) return fmt::format("waiting for {} failed: {}", arguments[0], std::strerror(errno));
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  const std::string exit = WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                             : fmt::format("signal {}", WTERMSIG(status));
  const std::string output = last_line(log);
  const std::string name = std::filesystem::path(arguments.size() > 1 ? arguments[1] : arguments[0]).filename().string();
  return output.empty() ? fmt::format("{} failed ({})", name, exit) : fmt::format("{} failed ({}): {}", name, exit, output);
}

}  // namespace gt
