// Running a helper program (the plot scripts, the peers' Python scripts) without a shell.
//
// run_logged(arguments, log) -> "" when arguments[0] (an absolute path) exited with status 0,
//   otherwise why not: "NAME failed (exit status N): <last non-blank line of its output>", where
//   NAME is the file name of arguments[1] (the script). Its stdout and stderr both go to `log`.
// spawn_child(arguments, log, overrides) -> the pid of arguments[0] (an absolute path) started in
//   its own process group (a timeout or an interruption kills all of it, compare/output_folder.hpp
//   knows it until the caller waits for it), stdin from /dev/null, stdout and stderr to `log`
//   (created or replaced), the default signal mask (this process blocks the signals its clean-up
//   thread waits for) and default SIGPIPE and SIGXFSZ (which this process ignores), and this
//   process's environment with `overrides` ("NAME=value") and
//   GROUNDTRUTH_PARENT_PID=<this pid> (compare/worker.hpp end_with_parent: the child ends with
//   its parent). 0 when it could not start, with the reason in `error` (errno's value).
// temporary_path(prefix, suffix) -> a fresh path in the temporary directory, unique in this
//   process: "<prefix>-<pid>-<counter><suffix>"; nothing is created.
// TemporaryFiles removes its paths (files or folders) when it goes out of scope, or when an
// interruption ends the process first (compare/output_folder.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <sys/types.h>

namespace gt {

pid_t spawn_child(const std::vector<std::string>& arguments, const std::filesystem::path& log,
                  const std::vector<std::string>& overrides, int& error);

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
