// Worker processes: `groundtruth mutants` runs each mutant's cases in a child process of the same
// executable, so that a mutant that crashes, hangs or corrupts memory ends only its own run.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gt {

struct WorkerResult {
  int status = -1;         // exit status; 128 + signal when killed; -1 when it could not start
  bool timed_out = false;  // killed after the time limit
  double seconds = 0.0;
};

// Runs this executable (/proc/self/exe) with `args`, stdin from /dev/null, stdout and stderr into
// `log` (created or replaced), killed with its process group after `timeout_seconds`.
WorkerResult run_worker(const std::vector<std::string>& args, const std::filesystem::path& log, double timeout_seconds);

}  // namespace gt
