// One instance of an outside model checked in a child process; see bmi_preflight.hpp.
#include "compare/external/bmi_preflight.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <exception>

#include <fmt/format.h>

#include "compare/external/bmi_config.hpp"
#include "compare/external/bmi_conformance.hpp"
#include "compare/subprocess.hpp"
#include "core/errors.hpp"

namespace gt {
namespace {

// What the child says back: its message, at most this many bytes.
constexpr std::size_t most_message_bytes = 64 * 1024;

[[noreturn]] void child(int pipe_out, const ExternalModel& external, const std::string& algorithm,
                        const StateDecl& decl, const StateGrid& grid, const std::filesystem::path& config) {
  std::string message;
  int status = 0;
  try {
    const auto model = external.make(config);
    check_bmi_conformance(*model, decl, grid, algorithm);
  } catch (const std::exception& error) {
    message = error.what();
    status = 2;
  }
  for (std::size_t written = 0; written < message.size();) {
    const ssize_t n = write(pipe_out, message.data() + written, message.size() - written);
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  _exit(status);
}

// Reads the child's message until it closes the pipe or the deadline passes; false on the deadline.
bool read_message(int pipe_in, std::chrono::steady_clock::time_point deadline, std::string& message) {
  char buffer[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd descriptor{pipe_in, POLLIN, 0};
    const int ready = poll(&descriptor, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return true;
    if (ready <= 0) continue;
    const ssize_t n = read(pipe_in, buffer, sizeof buffer);
    if (n <= 0) return true;
    if (message.size() < most_message_bytes) message.append(buffer, static_cast<std::size_t>(n));
  }
}

}  // namespace

void preflight_implementation(const ExternalModel& external, const std::string& algorithm,
                              const StateDecl& decl, const StateGrid& grid, const nlohmann::json& params,
                              const std::string& case_name, double timeout_seconds, bool isolated) {
  const TemporaryFiles scratch({temporary_path("groundtruth-bmi-preflight", ".txt")});
  const std::filesystem::path config = scratch.paths.front();
  write_bmi_config(config, algorithm, case_name, grid, params);
  if (!isolated) {
    try {
      const auto model = external.make(config);
      check_bmi_conformance(*model, decl, grid, algorithm);
    } catch (const std::exception& error) {
      throw InputError(fmt::format("case {}: {}", case_name, error.what()));
    }
    return;
  }
  int channel[2];
  if (pipe(channel) != 0) throw std::runtime_error(fmt::format("pipe: {}", std::strerror(errno)));
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(fmt::format("fork: {}", std::strerror(errno)));
  if (pid == 0) {
    close(channel[0]);
    child(channel[1], external, algorithm, decl, grid, config);
  }
  close(channel[1]);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  std::string message;
  const bool ended = read_message(channel[0], std::chrono::time_point_cast<std::chrono::steady_clock::duration>(deadline), message);
  close(channel[0]);
  if (!ended) kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  const std::string who = fmt::format("case {}: {}", case_name, external.label);
  if (!ended) {
    throw InputError(fmt::format("{}: registering, initialising and describing the model took over {} s (a hang?); "
                                 "it was stopped",
                                 who, timeout_seconds));
  }
  if (WIFSIGNALED(status)) {
    throw InputError(fmt::format("{}: the model crashed while it was registered, initialised and described "
                                 "(signal {}, {})",
                                 who, WTERMSIG(status), strsignal(WTERMSIG(status))));
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) != 0) throw InputError(fmt::format("case {}: {}", case_name, message));
}

}  // namespace gt
