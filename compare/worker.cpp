// Worker processes through compare/subprocess.hpp spawn_child; see compare/worker.hpp.
#include "compare/worker.hpp"

#include <signal.h>
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
#include "compare/subprocess.hpp"

namespace gt {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  std::size_t task = 0;
  pid_t pid = 0;
  Clock::time_point started;
};

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Starts the task (compare/subprocess.hpp spawn_child: its own process group, the default signal
// mask, ended with this process); 0 when it could not start.
pid_t spawn(const WorkerTask& task) {
  std::vector<std::string> words = {std::filesystem::read_symlink("/proc/self/exe").string()};
  words.insert(words.end(), task.args.begin(), task.args.end());
  int ignored = 0;
  return spawn_child(words, task.log, task.environment, ignored);
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
  const char* parent = std::getenv(parent_pid_variable);
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
