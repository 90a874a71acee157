// Progress of long runs on stderr, what a run finds as it goes (issue 35):
//
//   groundtruth: [case 3/148] erosion.thermal.cardinal.volcano
//   groundtruth: fail erosion.thermal.cardinal.volcano in 4.2 s [3/148: 2 pass, 1 fail; 41 s, ETA 12 min]
//       mass.relative_drift.gpu = 0.1 (bound 1e-06)
//   groundtruth: still running erosion.layered.long.terrain256: gpu (stage 1 min 30 s, case 4 min 2 s) [...]
//
// Each case's outcome is printed when it ends, with its own time, its failing checks, the counts so
// far and an ETA: the cases still to run at their expected times (compare/case_seconds.hpp; a case
// without one at the mean of the others), scaled by how the cases that ended compared with theirs,
// over the cases run at once. Without expected times the mean of the ended cases stands in.
// On a terminal the running line is rewritten in place; otherwise (CI logs, pipes) a stage change
// prints a line only when none was printed for `heartbeat`, and a thread prints a "still running"
// line whenever `heartbeat` passes without one, so a 9-minute stage shows signs of life in a log.
// `quiet` silences all of it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "compare/case_seconds.hpp"
#include "compare/result.hpp"

namespace gt {

struct ProgressOptions {
  bool quiet = false;
  int workers = 1;                       // cases running at once
  std::vector<std::string> planned;      // the cases to run, for the ETA (may be empty)
  CaseSeconds expected;                  // their expected seconds, where known
  std::chrono::milliseconds heartbeat{30000};
  std::FILE* sink = stderr;
  std::optional<bool> terminal;          // unset: whether `sink` is a terminal
  // What to add after an ended case's outcome, e.g. "(expected failure: ...)" from the expectation
  // list; unset or empty: nothing.
  std::function<std::string(const CaseResult&)> remark;
};

class Progress {
 public:
  Progress(int total_cases, ProgressOptions options);
  explicit Progress(int total_cases, bool quiet) : Progress(total_cases, ProgressOptions{.quiet = quiet}) {}
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  void start_case(const std::string& name);
  // The stage of the case running in this process (the last one started).
  void stage(const std::string& what);
  // A case ended: its outcome (none for a benchmark row), wall seconds and failing checks
  // ("name = value (bound b)"), printed at once.
  void end_case(const std::string& name, std::optional<Outcome> outcome, double seconds,
                const std::vector<std::string>& failing_checks = {}, const std::string& remark = "");
  // A case's result: its outcome, seconds, failing checks, and its error first when it has one.
  void end_case(const CaseResult& result);
  void finish();

  // The estimate of the seconds left (std::nullopt before anything can be estimated).
  std::optional<double> eta_seconds() const;

 private:
  using Clock = std::chrono::steady_clock;
  struct Running {
    Clock::time_point started;
    std::string stage;
    Clock::time_point stage_started;
  };
  void print_line(const std::string& text, bool permanent);
  std::string tally() const;
  std::optional<double> eta_locked(Clock::time_point now) const;
  void heartbeat_loop();

  ProgressOptions options_;
  bool terminal_;
  int total_cases_;
  int started_count_ = 0;
  Clock::time_point run_started_;
  Clock::time_point last_line_;
  std::map<std::string, Running> running_;
  std::string current_;                            // the case stage() describes
  std::map<std::string, int> started_index_;
  std::map<std::string, double> ended_seconds_;    // every ended case's wall seconds
  std::map<Outcome, int> outcome_counts_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread heartbeat_thread_;
};

// "4.2 s", "1 min 30 s", "1 h 2 min": a duration for a progress line.
std::string human_duration(double seconds);

}  // namespace gt
