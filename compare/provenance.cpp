// Provenance of a run; see compare/provenance.hpp.
#include "compare/provenance.hpp"

#include <chrono>
#include <cstdio>
#include <memory>

#include <fmt/chrono.h>
#include <fmt/format.h>

#include "core/sha256.hpp"
#include "gpu/shader_program.hpp"

namespace gt {
namespace {

std::string shell_quoted(const std::string& word) {
  if (!word.empty() && word.find_first_of(" \t\n'\"\\$`*?[]{}()<>|&;#~") == std::string::npos) return word;
  std::string quoted = "'";
  for (char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct CommandOutput {
  int status = -1;
  std::string text;  // stdout, trailing newline removed
};

// A git command on the source tree, its stderr discarded.
CommandOutput git(const std::string& arguments) {
  const std::string command = fmt::format("git -C {} {} 2>/dev/null", shell_quoted(GT_SOURCE_DIR), arguments);
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  CommandOutput output;
  if (!pipe) return output;
  char buffer[256];
  while (fgets(buffer, sizeof buffer, pipe.get()) != nullptr) output.text += buffer;
  while (!output.text.empty() && output.text.back() == '\n') output.text.pop_back();
  output.status = pclose(pipe.release());
  return output;
}

std::string utc_now() {
  return fmt::format("{:%Y-%m-%dT%H:%M:%SZ}", fmt::gmtime(std::chrono::system_clock::to_time_t(std::chrono::system_clock::now())));
}

}  // namespace

std::string command_line_of(int argc, char** argv) {
  std::string line;
  for (int index = 0; index < argc; ++index) line += (index == 0 ? "" : " ") + shell_quoted(argv[index]);
  return line;
}

void add_run_provenance(Environment& environment, const std::string& command_line) {
  environment.run_started = utc_now();
  environment.command_line = command_line;
  environment.build_type = GT_BUILD_TYPE;
  environment.build_flags = GT_BUILD_FLAGS;
  environment.git_at_configure = GT_GIT_DESCRIBE;
  const auto revision = git("rev-parse HEAD");
  if (revision.status != 0 || revision.text.empty()) {
    environment.git = environment.git_revision =
        fmt::format("unknown: git cannot read {} (not a checkout, or no git)", GT_SOURCE_DIR);
    return;
  }
  environment.git_revision = revision.text;
  environment.git = git("describe --always --dirty").text;
  environment.git_dirty = environment.git.ends_with("-dirty");
}

std::string version_line() {
  const auto described = git("describe --always --dirty");
  const bool known = described.status == 0 && !described.text.empty();
  return fmt::format("groundtruth {} ({} build, configured at {})", known ? described.text : GT_GIT_DESCRIBE,
                     GT_BUILD_TYPE, GT_GIT_DESCRIBE);
}

void add_digests(Environment& environment, const std::vector<std::filesystem::path>& data_files) {
  for (const auto& [stage, digest] : compiled_shader_digests()) environment.shaders[stage] = digest;
  for (const auto& file : data_files) environment.data[file.string()] = sha256_file_hex(file);
}

void merge_digests(Environment& environment, const Environment& worker) {
  environment.shaders.insert(worker.shaders.begin(), worker.shaders.end());
  environment.data.insert(worker.data.begin(), worker.data.end());
}

}  // namespace gt
