// Progress of long runs on a terminal: "[case 3/12] erosion.thermal.cardinal.volcano: gpu (4.2 s)"
// rewritten in place on stderr. Silent when stderr is not a terminal (CI logs, pipes).
#pragma once

#include <chrono>
#include <string>

namespace gt {

class Progress {
 public:
  explicit Progress(int total_cases);
  void start_case(int index, const std::string& name);
  void stage(const std::string& what);
  void finish();

 private:
  void draw();
  bool enabled_;
  int total_cases_;
  int case_index_ = 0;
  std::string case_name_;
  std::string stage_;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace gt
