// Report folders under --out (issue 18): built under a temporary sibling name and renamed into
// place; a folder is replaced only when it is groundtruth's own; nothing is left behind by an
// interruption.
//
// - Beside <out> groundtruth keeps only hidden names of its own, which no user folder has by
//   chance: ".<name>.groundtruth-staging-<pid>" (the report being built),
//   ".<name>.groundtruth-previous-<pid>" (the report it replaces, for the moment of the swap) and
//   ".<name>.groundtruth-lock" (held with flock while a process writes <out>: a second run into
//   the same folder is refused, not silently raced; removed when the process ends).
// - A run interrupted by SIGINT, SIGTERM, SIGHUP (or SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM) removes
//   its staging folder, lock and helpers' temporary files and ends the worker and helper
//   processes it was waiting for, then exits with 128 + the signal (a thread waits for
//   the signals, so the clean-up runs outside a signal handler). A run killed outright (SIGKILL,
//   the memory killer) cannot clean up: the next run into the same parent folder removes staging
//   and previous folders of <out> whose process is gone.
// - A finished report folder holds ".groundtruth-report", the list of every file and folder
//   groundtruth wrote, every level down. An existing --out is replaced only when it is empty or
//   holds what that list names and nothing else: a file a user put anywhere in it (or a folder of
//   someone else's) is never deleted. The folder is looked at when the command starts and again
//   at the swap, so a file added while a run goes on is kept too (the run then ends with exit 2).
//   A marker from before the list went every level down ("entries", the top level) owns its
//   top-level entries whole.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <sys/types.h>

namespace gt {

// Throws InputError when `out`'s parent does not exist or cannot be written, when `out` exists and
// is not a folder, when it holds anything groundtruth did not write there, or when another process
// is writing it; then holds `out`'s lock until write_folder_atomically ends or the process exits.
void check_output_folder(const std::filesystem::path& out);

// Whether an output file the user named would replace an input: the same existing file (hard links
// included), or the same path once resolved (a file not written yet).
bool same_file(const std::filesystem::path& output, const std::filesystem::path& input);

// Throws InputError when `input`, a file or folder the command reads, is `out` or lies inside it:
// replacing `out` would delete it. `command` starts the message.
void refuse_input_inside_output(const std::filesystem::path& out, const std::filesystem::path& input,
                                const std::string& command);

// Writes into a fresh staging folder through `fill`, records the marker, then swaps it in place of
// `out`. Removes stale staging folders of `out` first. Filesystem failures become InputError.
void write_folder_atomically(const std::filesystem::path& out,
                             const std::function<void(const std::filesystem::path&)>& fill);

// Starts the thread that turns SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM
// (every signal whose default ends the process and that someone may send) into a clean exit (call once, first
// thing in main, before any other thread starts).
void install_interrupt_cleanup();

// For a host process that keeps its own signal handling (the Python module), from construction to
// destruction: SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2 and SIGALRM, where their disposition is
// still the default (which would end the process with the staging folder left behind), get the
// same clean-up and exit as the command line's; `scratch` (a temporary folder of the host's, or
// empty) is removed too. Dispositions the host set are left alone; the default is put back at the
// end of the scope.
// SIGINT stays the host's (Python raises KeyboardInterrupt when the call returns).
class EmbeddedInterruptCleanup {
 public:
  explicit EmbeddedInterruptCleanup(const std::filesystem::path& scratch);
  ~EmbeddedInterruptCleanup();
  EmbeddedInterruptCleanup(const EmbeddedInterruptCleanup&) = delete;
  EmbeddedInterruptCleanup& operator=(const EmbeddedInterruptCleanup&) = delete;

 private:
  std::filesystem::path scratch_;
  std::vector<int> taken_;  // the signals whose default disposition was replaced
  std::thread watcher_;     // waits for a signal number (or 0: the scope ended) on the self-pipe
};

// The child processes an interruption must also end, each the leader of its own process group
// (the whole group is killed): compare/worker.cpp's workers and compare/subprocess.cpp's helpers
// add and remove them.
void add_running_worker(pid_t pid);
void remove_running_worker(pid_t pid);

// Temporary files outside the output folder (a plot's input, a helper's log) that an interruption
// removes too; compare/subprocess.hpp's TemporaryFiles adds and removes them.
void add_interruption_leftover(const std::filesystem::path& path);
void remove_interruption_leftover(const std::filesystem::path& path);

}  // namespace gt
