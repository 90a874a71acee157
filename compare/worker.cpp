// Worker processes through posix_spawn; see compare/worker.hpp.
#include "compare/worker.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include <fmt/format.h>

#include "compare/output_folder.hpp"

extern char** environ;

namespace gt {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* parent_variable = "GROUNDTRUTH_PARENT_PID";

struct Running {
  std::size_t task = 0;
  pid_t pid = 0;
  Clock::time_point started;
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

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

// Starts the task in its own process group (so that a timeout or an interruption kills all of
// it) with the default signal mask (this process blocks the signals its clean-up thread waits
// for); 0 when it could not start.
pid_t spawn(const WorkerTask& task) {
  const auto program = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<std::string> words = {program};
  words.insert(words.end(), task.args.begin(), task.args.end());
  std::vector<char*> argv;
  for (auto& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, task.log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  posix_spawnattr_setpgroup(&attributes, 0);
  sigset_t no_signals;
  sigemptyset(&no_signals);
  posix_spawnattr_setsigmask(&attributes, &no_signals);
  auto overrides = task.environment;
  overrides.push_back(fmt::format("{}={}", parent_variable, getpid()));
  auto variables = environment_with(overrides);
  std::vector<char*> envp;
  for (auto& variable : variables) envp.push_back(variable.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, program.c_str(), &actions, &attributes, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) return 0;
  add_running_worker(pid);
  return pid;
}

WorkerResult result_of(int wait_status, const Running& running, bool timed_out) {
  WorkerResult result;
  result.timed_out = timed_out;
  result.seconds = seconds_since(running.started);
  if (WIFEXITED(wait_status)) {
    result.status = WEXITSTATUS(wait_status);
  } else {
    result.signal = timed_out ? 0 : WTERMSIG(wait_status);
    result.status = 128 + WTERMSIG(wait_status);
  }
  return result;
}

}  // namespace

std::vector<std::string> llvmpipe_share(int parallel) {
  if (std::getenv("LP_NUM_THREADS") != nullptr || parallel <= 1) return {};
  const long cores = std::max(1L, sysconf(_SC_NPROCESSORS_ONLN));
  return {fmt::format("LP_NUM_THREADS={}", std::max(1L, cores / parallel))};
}

void end_with_parent() {
  const char* parent = std::getenv(parent_variable);
  if (parent == nullptr) return;
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(getppid()) != parent) _exit(128 + SIGKILL);  // it died before the request
}

std::string signal_description(int signal_number) {
  const char* abbreviation = sigabbrev_np(signal_number);
  return abbreviation ? fmt::format("SIG{} (signal {})", abbreviation, signal_number) : fmt::format("signal {}", signal_number);
}

void run_workers(const std::vector<WorkerTask>& tasks, int parallel, double timeout_seconds,
                 const std::function<void(std::size_t)>& started,
                 const std::function<void(std::size_t, const WorkerResult&)>& finished) {
  std::vector<Running> running;
  std::size_t next = 0;
  while (next < tasks.size() || !running.empty()) {
    while (next < tasks.size() && static_cast<int>(running.size()) < parallel) {
      started(next);
      const pid_t pid = spawn(tasks[next]);
      if (pid == 0) {
        finished(next, WorkerResult{});
      } else {
        running.push_back({next, pid, Clock::now()});
      }
      ++next;
    }
    bool any_ended = false;
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      bool timed_out = false;
      pid_t ended = waitpid(it->pid, &status, WNOHANG);
      if (ended == 0 && seconds_since(it->started) > timeout_seconds) {
        timed_out = true;
        kill(-it->pid, SIGKILL);
        ended = waitpid(it->pid, &status, 0);
      }
      if (ended == 0) {
        ++it;
        continue;
      }
      remove_running_worker(it->pid);
      const Running done = *it;
      it = running.erase(it);
      any_ended = true;
      finished(done.task, result_of(status, done, timed_out));
    }
    if (!any_ended) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

WorkerResult run_worker(const std::vector<std::string>& args, const std::filesystem::path& log, double timeout_seconds) {
  WorkerResult result;
  run_workers({{args, log}}, 1, timeout_seconds, [](std::size_t) {},
              [&](std::size_t, const WorkerResult& ended) { result = ended; });
  return result;
}

}  // namespace gt
