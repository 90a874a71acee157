// Report folders: atomic replacement, the ownership marker, clean-up after interruptions; see
// compare/output_folder.hpp.
#include "compare/output_folder.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <mutex>
#include <set>
#include <string>
#include <thread>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "core/json_keys.hpp"

namespace gt {
namespace {

constexpr const char* marker_name = ".groundtruth-report";

std::mutex staging_mutex;
std::filesystem::path active_staging;  // guarded by staging_mutex
std::mutex workers_mutex;
std::set<pid_t> running_workers;  // guarded by workers_mutex

std::filesystem::path normalised(const std::filesystem::path& out) {
  const auto absolute = std::filesystem::absolute(out).lexically_normal();
  return absolute.has_filename() ? absolute : absolute.parent_path();
}

// Fills `entries` with what the folder's marker lists; false when there is no readable marker.
bool read_marker(const std::filesystem::path& folder, std::set<std::string>& entries) {
  std::ifstream stream(folder / marker_name);
  if (!stream) return false;
  try {
    const auto listed = parse_json_bounded(stream, (folder / marker_name).string());
    for (const auto& entry : listed.at("entries")) entries.insert(entry.get<std::string>());
  } catch (const nlohmann::json::exception&) {
    return false;
  }
  return true;
}

void write_marker(const std::filesystem::path& folder) {
  nlohmann::json entries = nlohmann::json::array();
  for (const auto& entry : std::filesystem::directory_iterator(folder)) entries.push_back(entry.path().filename().string());
  std::ofstream(folder / marker_name) << nlohmann::json{{"written_by", "groundtruth"}, {"entries", entries}}.dump(1)
                                      << '\n';
}

// "<base>.tmp-<pid>" folders beside `target` whose process no longer runs.
void remove_stale_staging(const std::filesystem::path& target) {
  const std::string prefix = target.filename().string() + ".tmp-";
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(target.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0 || !entry.is_directory()) continue;
    const std::string digits = name.substr(prefix.size());
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid == getpid() || (kill(pid, 0) != 0 && errno == ESRCH)) std::filesystem::remove_all(entry.path(), error);
  }
}

void set_staging(const std::filesystem::path& staging) {
  const std::lock_guard lock(staging_mutex);
  active_staging = staging;
}

// The main thread goes on running while this thread cleans up, and may re-create the staging folder
// (a case's create_directories) while remove_all empties it: remove until it stays gone, then exit
// at once (the message is printed first so that nothing comes between the last check and _exit).
[[noreturn]] void clean_up_and_exit(int signal_number) {
  {
    const std::lock_guard lock(workers_mutex);
    for (const pid_t worker : running_workers) kill(-worker, SIGKILL);
  }
  fmt::print(stderr, "groundtruth: interrupted by signal {}; nothing was left in the output folder\n", signal_number);
  const std::lock_guard lock(staging_mutex);
  std::error_code ignored;
  for (int attempt = 0; attempt < 1000 && !active_staging.empty() && std::filesystem::exists(active_staging, ignored);
       ++attempt) {
    std::filesystem::remove_all(active_staging, ignored);
  }
  _exit(128 + signal_number);
}

}  // namespace

void add_running_worker(pid_t pid) {
  const std::lock_guard lock(workers_mutex);
  running_workers.insert(pid);
}

void remove_running_worker(pid_t pid) {
  const std::lock_guard lock(workers_mutex);
  running_workers.erase(pid);
}

void install_interrupt_cleanup() {
  sigset_t signals;
  sigemptyset(&signals);
  for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, signal_number);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // inherited by every later thread
  std::thread([signals] {
    int received = 0;
    if (sigwait(&signals, &received) == 0) clean_up_and_exit(received);
  }).detach();
}

void check_output_folder(const std::filesystem::path& out) {
  const auto target = normalised(out);
  const auto parent = target.parent_path();
  if (!std::filesystem::is_directory(parent)) {
    throw InputError(fmt::format("output folder {}: its parent {} does not exist; create it first", out.string(),
                                 parent.string()));
  }
  if (access(parent.c_str(), W_OK | X_OK) != 0) {
    throw InputError(fmt::format("output folder {}: its parent {} is not writable", out.string(), parent.string()));
  }
  std::error_code error;
  const auto status = std::filesystem::symlink_status(target, error);
  if (!std::filesystem::exists(status)) {
    if (std::filesystem::is_symlink(status)) {
      throw InputError(fmt::format("output {} is a dangling symbolic link; refusing to write through it", out.string()));
    }
    return;
  }
  if (!std::filesystem::is_directory(status)) {
    throw InputError(fmt::format("output {} exists and is not a folder; refusing to overwrite it", out.string()));
  }
  if (std::filesystem::is_empty(target)) return;
  std::set<std::string> ours;
  if (!read_marker(target, ours)) {
    throw InputError(fmt::format("output folder {} holds files that are not a groundtruth report; refusing to "
                                 "overwrite them (choose another --out)",
                                 out.string()));
  }
  for (const auto& entry : std::filesystem::directory_iterator(target)) {
    const std::string name = entry.path().filename().string();
    if (name != marker_name && !ours.contains(name)) {
      throw InputError(fmt::format("output folder {} is a groundtruth report, but {} was added to it since; refusing "
                                   "to delete it (move it, or choose another --out)",
                                   out.string(), name));
    }
  }
}

void write_folder_atomically(const std::filesystem::path& out,
                             const std::function<void(const std::filesystem::path&)>& fill) {
  const auto target = normalised(out);
  const std::filesystem::path staging = fmt::format("{}.tmp-{}", target.string(), getpid());
  // Known to the interruption's clean-up before it exists: a signal between creating the folder and
  // registering it left the folder behind (seen once under the sanitizer build's load).
  set_staging(staging);
  try {
    remove_stale_staging(target);
    std::filesystem::create_directory(staging);
  } catch (const std::filesystem::filesystem_error& error) {
    set_staging({});
    throw InputError(fmt::format("output folder {}: {}", out.string(), error.code().message()));
  }
  try {
    fill(staging);
    write_marker(staging);
    if (std::filesystem::exists(target)) {
      const std::filesystem::path previous = fmt::format("{}.old-{}", target.string(), getpid());
      std::filesystem::rename(target, previous);
      std::filesystem::rename(staging, target);
      std::filesystem::remove_all(previous);
    } else {
      std::filesystem::rename(staging, target);
    }
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(staging, ignored);
    set_staging({});
    throw;
  }
  set_staging({});
}

}  // namespace gt
