// Progress of long runs on stderr: "[case 3/12] erosion.thermal.cardinal.volcano: gpu (4.2 s)".
// On a terminal the line is rewritten in place; otherwise (CI logs, pipes) one line is printed per
// case and another whenever a stage starts more than `heartbeat` after the last line, so a long
// case still shows signs of life. `quiet` silences both.
#pragma once

#include <chrono>
#include <string>

namespace gt {

class Progress {
 public:
  Progress(int total_cases, bool quiet);
  void start_case(int index, const std::string& name);
  void stage(const std::string& what);
  void finish();

 private:
  void draw(bool new_case);
  static constexpr std::chrono::seconds heartbeat{30};
  bool terminal_;
  bool quiet_;
  std::chrono::steady_clock::time_point last_line_;
  int total_cases_;
  int case_index_ = 0;
  std::string case_name_;
  std::string stage_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace gt
