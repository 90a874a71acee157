// Provenance of a run (issue 15): when it started, the command, the source tree's revision and
// dirty state at run time (the shaders are read from the source tree when the run starts, so the
// configure-time revision alone can be stale), the build's flags, and SHA-256 digests of every
// shader stage compiled (after #include expansion) and every data file read.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/result.hpp"

namespace gt {

// argv as one line a shell would read back: words with spaces or quotes are single-quoted.
std::string command_line_of(int argc, char** argv);

// Fills run_started, command_line, git, git_revision, git_dirty, git_at_configure, build_type and
// build_flags. Git is asked about GT_SOURCE_DIR; when it cannot answer (no git, not a checkout)
// git and git_revision say "unknown: <why>".
void add_run_provenance(Environment& environment, const std::string& command_line);

// `groundtruth --version`: "groundtruth <git describe --always --dirty of the source tree>
// (<build type>, configured at <describe then>)", or the configure-time revision alone when git
// cannot answer.
std::string version_line();

// Adds the digests of the shaders compiled so far by this process and of `data_files`.
void add_digests(Environment& environment, const std::vector<std::filesystem::path>& data_files);

// Folds the digests of a worker's environment into `environment` (the parent's).
void merge_digests(Environment& environment, const Environment& worker);

}  // namespace gt
