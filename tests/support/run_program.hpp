// Running a program as a user runs it, for the command-line tests: posix_spawn with an argument
// vector (no shell), stdin from /dev/null, stdout and stderr captured through files, in a chosen
// working folder, with chosen changes to the environment.
#pragma once

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "tests/support/temporary_folder.hpp"

extern char** environ;

namespace gt::testing {

struct ProgramRun {
  int status = -1;  // exit status, 128 + signal, or -1 when the program could not start
  std::string out;  // stdout
  std::string err;  // stderr
  std::string output() const { return out + err; }
};

inline std::ostream& operator<<(std::ostream& stream, const ProgramRun& run) {
  return stream << "exit status " << run.status << "\n--- stdout ---\n" << run.out << "--- stderr ---\n" << run.err;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream stream(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

// Environment changes for the child: a value sets the variable, nullopt removes it.
using EnvChanges = std::map<std::string, std::optional<std::string>>;

// This process's environment with `changes` applied, as "NAME=value" strings.
inline std::vector<std::string> changed_environment(const EnvChanges& changes) {
  std::vector<std::string> variables;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string variable = *entry;
    if (!changes.contains(variable.substr(0, variable.find('=')))) variables.push_back(variable);
  }
  for (const auto& [name, value] : changes) {
    if (value) variables.push_back(name + "=" + *value);
  }
  return variables;
}

// posix_spawn's argument vector: pointers into `words` (which must outlive it), null-terminated.
inline std::vector<char*> argv_of(std::vector<std::string>& words) {
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  return argv;
}

// Runs `program` with `args` (argv[1...]) in the folder `cwd` (this process's when empty).
inline ProgramRun run_program(const std::string& program, const std::vector<std::string>& args,
                              const std::filesystem::path& cwd = {}, const EnvChanges& env = {}) {
  const TemporaryFolder capture("gt_program_capture");
  const std::string out_file = (capture.path() / "stdout").string();
  const std::string err_file = (capture.path() / "stderr").string();

  std::vector<std::string> arguments = {program};
  arguments.insert(arguments.end(), args.begin(), args.end());
  std::vector<char*> argv = argv_of(arguments);
  std::vector<std::string> variables = changed_environment(env);
  std::vector<char*> envp;
  for (auto& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!cwd.empty()) posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  ProgramRun run;
  if (spawned != 0) {
    run.err = "cannot start " + program + ": " + std::strerror(spawned);
    return run;
  }
  int wait_status = 0;
  while (waitpid(pid, &wait_status, 0) < 0) {
    if (errno != EINTR) {
      run.err = "waitpid failed";
      return run;
    }
  }
  run.status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
  run.out = read_text(out_file);
  run.err = read_text(err_file);
  return run;
}

}  // namespace gt::testing
