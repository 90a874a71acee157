#include "compare/subprocess.hpp"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <signal.h>
#include <fstream>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "compare/output_folder.hpp"
#include "compare/worker.hpp"

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

namespace {

// This process's environment with `overrides` ("NAME=value") added or replacing the same names.
std::vector<std::string> environment_with(const std::vector<std::string>& overrides) {
  std::vector<std::string> variables;
  const auto name_of = [](const std::string& entry) { return entry.substr(0, entry.find('=')); };
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string variable = *entry;
    const bool replaced = std::any_of(overrides.begin(), overrides.end(),
                                      [&](const std::string& override) { return name_of(override) == name_of(variable); });
    if (!replaced) variables.push_back(variable);
  }
  variables.insert(variables.end(), overrides.begin(), overrides.end());
  return variables;
}

std::vector<char*> pointers_to(std::vector<std::string>& words) {
  std::vector<char*> pointers;
  for (auto& word : words) pointers.push_back(word.data());
  pointers.push_back(nullptr);
  return pointers;
}

}  // namespace

pid_t spawn_child(const std::vector<std::string>& arguments, const std::filesystem::path& log,
                  const std::vector<std::string>& overrides, int& error) {
  std::vector<std::string> words = arguments;
  std::vector<std::string> variables = environment_with([&] {
    auto all = overrides;
    all.push_back(fmt::format("{}={}", parent_pid_variable, getpid()));
    return all;
  }());
  const std::vector<char*> argv = pointers_to(words), envp = pointers_to(variables);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t no_signals, ignored_here;
  sigemptyset(&no_signals);
  posix_spawnattr_setsigmask(&attributes, &no_signals);
  sigemptyset(&ignored_here);  // main ignores these two (compare/cli/main.cpp); a child starts with the default
  sigaddset(&ignored_here, SIGPIPE);
  sigaddset(&ignored_here, SIGXFSZ);
  posix_spawnattr_setsigdefault(&attributes, &ignored_here);
  pid_t child = 0;
  error = posix_spawn(&child, argv[0], &actions, &attributes, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (error != 0) return 0;
  add_running_worker(child);
  return child;
}

std::string run_logged(const std::vector<std::string>& arguments, const std::filesystem::path& log) {
  int spawn_error = 0;
  const pid_t child = spawn_child(arguments, log, {}, spawn_error);
  if (child == 0) return fmt::format("cannot run {}: {}", arguments[0], std::strerror(spawn_error));

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
