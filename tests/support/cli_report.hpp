// The groundtruth executable as a user runs it, and what its report says, for the command-line
// tests of one algorithm (planet_cli_test, layered_cli_test): run it, read <out>/report.json, list
// a case's check names. Needs GT_BINARY_DIR (tests/CMakeLists.txt defines it for every test).
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run_program.hpp"

namespace gt::testing {

// Runs build/…/groundtruth with `args` (argv[1...]) in the folder `cwd`.
inline ProgramRun run_groundtruth(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  return run_program(GT_BINARY_DIR "/groundtruth", args, cwd);
}

// The report.json a run wrote into `out`.
inline nlohmann::json report_of(const std::filesystem::path& out) {
  std::ifstream stream(out / "report.json");
  return nlohmann::json::parse(stream);
}

// The names of a report case's checks, in the report's order.
inline std::vector<std::string> check_names(const nlohmann::json& report_case) {
  std::vector<std::string> names;
  for (const auto& check : report_case["checks"]) names.push_back(check["name"]);
  return names;
}

}  // namespace gt::testing
