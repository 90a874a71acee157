// Report folders: atomic replacement, the ownership marker, clean-up after interruptions; see
// compare/output_folder.hpp.
#include "compare/output_folder.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/report/report_common.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/json_keys.hpp"

namespace gt {
namespace {

constexpr const char* marker_name = ".groundtruth-report";

// Every signal whose default ends the process and that someone may send.
constexpr int ending_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM};

std::mutex staging_mutex;
std::filesystem::path active_staging;  // guarded by staging_mutex
std::mutex workers_mutex;
std::set<pid_t> running_workers;  // guarded by workers_mutex
std::mutex leftovers_mutex;
std::set<std::filesystem::path> leftovers;  // guarded by leftovers_mutex

// A lock this process holds on an output folder: the open lock file and who opened it (a forked
// child inherits the list but not the right to remove the file).
struct HeldLock {
  std::filesystem::path file;
  int descriptor = -1;
  pid_t owner = 0;
};
std::mutex locks_mutex;
std::vector<HeldLock> held_locks;  // guarded by locks_mutex

std::filesystem::path normalised(const std::filesystem::path& out) {
  const auto absolute = std::filesystem::absolute(out).lexically_normal();
  return absolute.has_filename() ? absolute : absolute.parent_path();
}

// A hidden sibling of `target` that belongs to groundtruth: ".<name>.groundtruth-<role>".
std::filesystem::path sibling(const std::filesystem::path& target, const std::string& role) {
  return target.parent_path() / fmt::format(".{}.groundtruth-{}", target.filename().string(), role);
}

// The entries of `folder` as paths relative to it ('/'-separated), every level down; symbolic
// links are listed, never followed.
std::set<std::string> entries_below(const std::filesystem::path& folder) {
  std::set<std::string> entries;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
    entries.insert(entry.path().lexically_relative(folder).generic_string());
  }
  return entries;
}

// What the folder's marker lists. A marker written before markers listed every level (it has
// "entries", the top level, and no "files") owns each listed top-level entry whole. nullopt when
// there is no readable marker.
struct Marker {
  std::set<std::string> entries;
  bool every_level = false;
};
std::optional<Marker> read_marker(const std::filesystem::path& folder) {
  std::ifstream stream(folder / marker_name);
  if (!stream) return std::nullopt;
  try {
    const auto listed = parse_json_bounded(stream, (folder / marker_name).string());
    Marker marker;
    marker.every_level = listed.contains("files");
    for (const auto& entry : listed.at(marker.every_level ? "files" : "entries")) {
      marker.entries.insert(entry.get<std::string>());
    }
    return marker;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

void write_marker(const std::filesystem::path& folder) {
  const nlohmann::json document = {{"written_by", "groundtruth"}, {"files", entries_below(folder)}};
  write_file_atomically(folder / marker_name, document.dump(1) + '\n');
}

// The first entry of `folder` that its marker does not list ("" when every one is groundtruth's).
std::string first_stranger(const std::filesystem::path& folder, const Marker& marker) {
  const auto entries = marker.every_level ? entries_below(folder) : [&] {
    std::set<std::string> top;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) top.insert(entry.path().filename().string());
    return top;
  }();
  for (const std::string& entry : entries) {
    if (entry != marker_name && !marker.entries.contains(entry)) return entry;
  }
  return "";
}

// Throws InputError unless `folder` (an existing folder) is empty or groundtruth's report with
// nothing added; `out` is the name the user gave, `when` says when the folder was looked at.
void check_ours(const std::filesystem::path& folder, const std::filesystem::path& out, const std::string& when) {
  if (std::filesystem::is_empty(folder)) return;
  const auto marker = read_marker(folder);
  if (!marker) {
    throw InputError(fmt::format("output folder {} holds files that are not a groundtruth report{}; refusing to "
                                 "overwrite them (choose another --out)",
                                 out.string(), when));
  }
  const std::string stranger = first_stranger(folder, *marker);
  if (!stranger.empty()) {
    throw InputError(fmt::format("output folder {} is a groundtruth report, but {} was added to it{}; refusing to "
                                 "delete it (move it, or choose another --out)",
                                 out.string(), stranger, when));
  }
}

// Removes this process's lock files and lets go of the locks (a forked child's inherited entries
// are left to their owner). Safe to call from the interruption's thread and at exit.
void release_output_locks() {
  const std::lock_guard lock(locks_mutex);
  std::erase_if(held_locks, [](const HeldLock& held) {
    if (held.owner != getpid()) return false;
    unlink(held.file.c_str());
    close(held.descriptor);
    return true;
  });
}

// Holds an exclusive lock on `target` for this process: flock on its hidden lock file beside it.
// Another process holding it is a refusal; the file is removed by release_output_locks. Opening a
// file its holder removes meanwhile is retried on the new one (the inode check).
void lock_output_folder(const std::filesystem::path& target, const std::filesystem::path& out) {
  static std::once_flag at_exit;
  std::call_once(at_exit, [] { std::atexit(release_output_locks); });
  const std::lock_guard lock(locks_mutex);
  const auto file = sibling(target, "lock");
  for (const HeldLock& held : held_locks) {
    if (held.file == file && held.owner == getpid()) return;
  }
  for (int attempt = 0; attempt < 10; ++attempt) {
    const int descriptor = open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (descriptor < 0) {
      throw InputError(fmt::format("output folder {}: cannot create its lock file {}: {}", out.string(), file.string(),
                                   std::strerror(errno)));
    }
    if (flock(descriptor, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      close(descriptor);
      if (error == EWOULDBLOCK) {
        throw InputError(fmt::format("output folder {} is being written by another groundtruth run; wait for it to "
                                     "end or choose another --out",
                                     out.string()));
      }
      throw InputError(fmt::format("output folder {}: cannot lock {}: {}", out.string(), file.string(),
                                   std::strerror(error)));
    }
    struct stat held {}, named {};
    if (fstat(descriptor, &held) == 0 && stat(file.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      held_locks.push_back({file, descriptor, getpid()});
      return;
    }
    close(descriptor);
  }
  throw InputError(fmt::format("output folder {}: cannot take its lock {}", out.string(), file.string()));
}

// Stale folders beside `target`: staging or previous folders ("." name ".groundtruth-staging-"
// or "-previous-" and a pid) whose process no longer runs.
void remove_stale_staging(const std::filesystem::path& target) {
  const std::string staging = sibling(target, "staging-").filename().string();
  const std::string previous = sibling(target, "previous-").filename().string();
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(target.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    const std::string& prefix = name.rfind(staging, 0) == 0 ? staging : previous;
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
  release_output_locks();
  {
    const std::lock_guard lock(leftovers_mutex);
    std::error_code ignored;
    for (const auto& path : leftovers) std::filesystem::remove_all(path, ignored);
  }
  const std::lock_guard lock(staging_mutex);
  std::error_code ignored;
  for (int attempt = 0; attempt < 1000 && !active_staging.empty() && std::filesystem::exists(active_staging, ignored);
       ++attempt) {
    std::filesystem::remove_all(active_staging, ignored);
  }
  _exit(128 + signal_number);
}

// Puts `staging` in place of `target`. What the user added to `target` while the run went on stays:
// the folder is looked at again before it is moved aside and once more after (nothing can reach
// it under its hidden name), and put back if anything was added.
void replace_folder(const std::filesystem::path& target, const std::filesystem::path& staging,
                    const std::filesystem::path& out) {
  const std::string when = " while this run went on (this run's report is not kept)";
  std::error_code error;
  if (!std::filesystem::exists(std::filesystem::symlink_status(target, error))) {
    std::filesystem::rename(staging, target);
    return;
  }
  if (!std::filesystem::is_directory(std::filesystem::symlink_status(target))) {
    throw InputError(fmt::format("output {} was replaced by something that is not a folder{}", out.string(), when));
  }
  check_ours(target, out, when);
  const auto previous = sibling(target, fmt::format("previous-{}", getpid()));
  std::filesystem::rename(target, previous);
  try {
    check_ours(previous, out, when);
  } catch (const InputError&) {
    std::filesystem::rename(previous, target);
    throw;
  }
  std::filesystem::rename(staging, target);
  std::filesystem::remove_all(previous);
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

void add_interruption_leftover(const std::filesystem::path& path) {
  const std::lock_guard lock(leftovers_mutex);
  leftovers.insert(path);
}

void remove_interruption_leftover(const std::filesystem::path& path) {
  const std::lock_guard lock(leftovers_mutex);
  leftovers.erase(path);
}

namespace {

// The self-pipe of EmbeddedInterruptCleanup: the handler writes the signal's number, the only
// async-signal-safe thing it does; the watcher thread reads it and cleans up outside the handler.
// One scope at a time (two Python threads may run cases at once): a nested one takes nothing.
int embedded_pipe[2] = {-1, -1};
std::atomic<bool> embedded_active{false};

void forward_to_watcher(int signal_number) {
  const int saved_errno = errno;
  const auto byte = static_cast<unsigned char>(signal_number);
  [[maybe_unused]] const ssize_t written = write(embedded_pipe[1], &byte, 1);
  errno = saved_errno;
}

}  // namespace

EmbeddedInterruptCleanup::EmbeddedInterruptCleanup(const std::filesystem::path& scratch) : scratch_(scratch) {
  if (embedded_active.exchange(true)) return;
  if (pipe2(embedded_pipe, O_CLOEXEC) != 0) {  // without the pipe the host's dispositions stay
    embedded_active = false;
    return;
  }
  if (!scratch_.empty()) add_interruption_leftover(scratch_);
  watcher_ = std::thread([] {
    unsigned char byte = 0;
    while (read(embedded_pipe[0], &byte, 1) < 0 && errno == EINTR) {
    }
    if (byte != 0) clean_up_and_exit(byte);
  });
  for (const int signal_number : ending_signals) {
    struct sigaction current {};
    if (signal_number == SIGINT || sigaction(signal_number, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) {
      continue;
    }
    struct sigaction forward {};
    forward.sa_handler = forward_to_watcher;
    sigemptyset(&forward.sa_mask);
    if (sigaction(signal_number, &forward, nullptr) == 0) taken_.push_back(signal_number);
  }
}

EmbeddedInterruptCleanup::~EmbeddedInterruptCleanup() {
  if (!watcher_.joinable()) return;
  struct sigaction by_default {};
  by_default.sa_handler = SIG_DFL;
  sigemptyset(&by_default.sa_mask);
  for (const int signal_number : taken_) sigaction(signal_number, &by_default, nullptr);
  const unsigned char end = 0;
  [[maybe_unused]] const ssize_t written = write(embedded_pipe[1], &end, 1);
  watcher_.join();
  close(embedded_pipe[0]);
  close(embedded_pipe[1]);
  embedded_pipe[0] = embedded_pipe[1] = -1;
  if (!scratch_.empty()) remove_interruption_leftover(scratch_);
  embedded_active = false;
}

void install_interrupt_cleanup() {
  sigset_t signals;
  sigemptyset(&signals);
  for (int signal_number : ending_signals) {
    sigaddset(&signals, signal_number);
  }
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);  // inherited by every later thread
  std::thread([signals] {
    int received = 0;
    if (sigwait(&signals, &received) == 0) clean_up_and_exit(received);
  }).detach();
}

void check_output_folder(const std::filesystem::path& out) {
  if (out.empty()) throw InputError("--out is empty: name the output folder");
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
  } else if (!std::filesystem::is_directory(status)) {
    throw InputError(fmt::format("output {} exists and is not a folder; refusing to overwrite it", out.string()));
  } else {
    check_ours(target, out, "");
  }
  lock_output_folder(target, out);
}

bool same_file(const std::filesystem::path& output, const std::filesystem::path& input) {
  std::error_code equivalent_error, output_error, input_error;
  if (std::filesystem::equivalent(output, input, equivalent_error)) return true;
  const auto resolved_output = std::filesystem::weakly_canonical(output, output_error);
  const auto resolved_input = std::filesystem::weakly_canonical(input, input_error);
  return !output_error && !input_error && resolved_output == resolved_input;
}

void refuse_input_inside_output(const std::filesystem::path& out, const std::filesystem::path& input,
                                const std::string& command) {
  std::error_code error;
  const auto target = std::filesystem::weakly_canonical(normalised(out), error);
  const auto given = std::filesystem::weakly_canonical(std::filesystem::absolute(input), error);
  if (error) return;  // the reader names what is wrong with the input
  const auto inside = given.lexically_relative(target);
  if (!inside.empty() && *inside.begin() != "..") {
    throw InputError(fmt::format("{}: --out {} would replace {}, which it reads; choose another --out", command,
                                 out.string(), input.string()));
  }
}

void write_folder_atomically(const std::filesystem::path& out,
                             const std::function<void(const std::filesystem::path&)>& fill) {
  const auto target = normalised(out);
  lock_output_folder(target, out);
  const auto staging = sibling(target, fmt::format("staging-{}", getpid()));
  // However the write ends, the interruption's clean-up forgets the staging folder and the lock is
  // let go.
  struct EndOfWrite {
    ~EndOfWrite() {
      set_staging({});
      release_output_locks();
    }
  } end_of_write;
  // Known to the interruption's clean-up before it exists: a signal between creating the folder and
  // registering it left the folder behind (seen once under the sanitizer build's load).
  set_staging(staging);
  try {
    remove_stale_staging(target);
    std::filesystem::create_directory(staging);
  } catch (const std::filesystem::filesystem_error& error) {
    throw InputError(fmt::format("output folder {}: {}", out.string(), error.code().message()));
  }
  try {
    fill(staging);
    write_marker(staging);
    replace_folder(target, staging, out);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove_all(staging, ignored);
    throw;
  }
}

}  // namespace gt
