// Worker processes: a run with -j N (or --case-timeout) runs each case, and `groundtruth mutants`
// each mutant's cases, in a child process of the same executable, so that a case that crashes,
// hangs or corrupts memory ends only its own process, and N of them run at once.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gt {

struct WorkerResult {
  int status = -1;         // exit status; 128 + signal when killed; -1 when it could not start
  int signal = 0;          // the signal that ended it (0: it exited, or was killed for its time)
  bool timed_out = false;  // killed after the time limit
  double seconds = 0.0;
};

// "SIGSEGV (signal 11)" for a signal number.
std::string signal_description(int signal_number);

// The variable through which a child learns its parent's pid (compare/subprocess.hpp spawn_child).
inline constexpr const char* parent_pid_variable = "GROUNDTRUTH_PARENT_PID";

// In a worker (a process whose environment names its parent in GROUNDTRUTH_PARENT_PID, as
// run_workers starts them): asks the kernel to kill it when its parent dies, so that workers of a
// run killed outright (SIGKILL, the memory killer) do not run on; exits at once when the parent
// is already gone. Nothing outside a worker. Call first thing in main.
void end_with_parent();

struct WorkerTask {
  std::vector<std::string> args;  // after the executable's name
  std::filesystem::path log;      // stdout and stderr (created or replaced)
  std::vector<std::string> environment;  // "NAME=value" added to (or replacing) this process's environment
};

// Runs this executable (/proc/self/exe) once per task, at most `parallel` at a time, each with
// stdin from /dev/null and killed with its process group after `timeout_seconds`. Calls
// `started(index)` when task `index` starts and `finished(index, result)` when it ends, both from
// the calling thread. An interruption of this process ends the running workers too
// (compare/output_folder.hpp).
void run_workers(const std::vector<WorkerTask>& tasks, int parallel, double timeout_seconds,
                 const std::function<void(std::size_t)>& started,
                 const std::function<void(std::size_t, const WorkerResult&)>& finished);

// llvmpipe starts a rendering thread per core in every context: N workers would run N times as
// many threads as cores, and the run gets slower than -j 1. "LP_NUM_THREADS=<cores / parallel>"
// for a task's environment, or nothing when the user set LP_NUM_THREADS or parallel is 1.
std::vector<std::string> llvmpipe_share(int parallel);

// One task, waited for.
WorkerResult run_worker(const std::vector<std::string>& args, const std::filesystem::path& log, double timeout_seconds);

}  // namespace gt
