#include "compare/progress.hpp"

#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

namespace gt {

Progress::Progress(int total_cases, bool quiet)
    : terminal_(isatty(STDERR_FILENO) != 0),
      quiet_(quiet),
      last_line_(std::chrono::steady_clock::now()),
      total_cases_(total_cases),
      started_(std::chrono::steady_clock::now()) {}

void Progress::start_case(int index, const std::string& name) {
  case_index_ = index;
  case_name_ = name;
  stage_.clear();
  draw(true);
}

void Progress::stage(const std::string& what) {
  stage_ = what;
  draw(false);
}

void Progress::finish() {
  if (terminal_ && !quiet_) fmt::print(stderr, "\r\033[K");
}

void Progress::draw(bool new_case) {
  if (quiet_) return;
  const auto now = std::chrono::steady_clock::now();
  if (!terminal_ && !new_case && now - last_line_ < heartbeat) return;
  last_line_ = now;
  const std::chrono::duration<double> elapsed = now - started_;
  fmt::print(stderr, "{}[case {}/{}] {}{}{} ({:.1f} s){}", terminal_ ? "\r\033[K" : "groundtruth: ", case_index_,
             total_cases_, case_name_, stage_.empty() ? "" : ": ", stage_, elapsed.count(), terminal_ ? "" : "\n");
  std::fflush(stderr);
}

}  // namespace gt
