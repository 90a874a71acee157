// Running a helper program (the plot scripts, the peers' Python scripts) without a shell.
//
// run_logged(arguments, log) -> "" when arguments[0] (an absolute path) exited with status 0,
//   otherwise why not: "NAME failed (exit status N): <last non-blank line of its output>", where
//   NAME is the file name of arguments[1] (the script). Its stdout and stderr both go to `log`.
// temporary_path(prefix, suffix) -> a fresh path in the temporary directory, unique in this
//   process: "<prefix>-<pid>-<counter><suffix>"; nothing is created.
// TemporaryFiles removes its paths (files or folders) when it goes out of scope, or when an
// interruption ends the process first (compare/output_folder.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace gt {

std::string run_logged(const std::vector<std::string>& arguments, const std::filesystem::path& log);

std::filesystem::path temporary_path(std::string_view prefix, std::string_view suffix);

struct TemporaryFiles {
  std::vector<std::filesystem::path> paths;
  TemporaryFiles() = default;
  explicit TemporaryFiles(std::vector<std::filesystem::path> removed);
  TemporaryFiles(const TemporaryFiles&) = delete;
  TemporaryFiles& operator=(const TemporaryFiles&) = delete;
  ~TemporaryFiles();
};

}  // namespace gt
