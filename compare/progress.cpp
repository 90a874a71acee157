#include "compare/progress.hpp"

#include <cstdio>
#include <unistd.h>

#include <fmt/format.h>

namespace gt {

Progress::Progress(int total_cases)
    : enabled_(isatty(STDERR_FILENO) != 0), total_cases_(total_cases), started_(std::chrono::steady_clock::now()) {}

void Progress::start_case(int index, const std::string& name) {
  case_index_ = index;
  case_name_ = name;
  stage_.clear();
  draw();
}

void Progress::stage(const std::string& what) {
  stage_ = what;
  draw();
}

void Progress::finish() {
  if (enabled_) fmt::print(stderr, "\r\033[K");
}

void Progress::draw() {
  if (!enabled_) return;
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - started_;
  fmt::print(stderr, "\r\033[K[case {}/{}] {}{}{} ({:.1f} s)", case_index_, total_cases_, case_name_,
             stage_.empty() ? "" : ": ", stage_, elapsed.count());
  std::fflush(stderr);
}

}  // namespace gt
