// Report folders under --out (issue 18): built under a temporary sibling name and renamed into
// place; a folder is replaced only when it is groundtruth's own; nothing is left behind by an
// interruption.
//
// - The staging folder is "<out>.tmp-<pid>". A run interrupted by SIGINT, SIGTERM or SIGHUP
//   removes its staging folder and ends the worker processes it was waiting for, then exits with
//   128 + the signal (a thread waits for the signals, so the clean-up runs outside a signal
//   handler). A run killed outright (SIGKILL, the memory killer) cannot clean up: the next run
//   into the same parent folder removes "<out>.tmp-<pid>" folders whose process is gone.
// - A finished report folder holds ".groundtruth-report", the list of the entries groundtruth
//   wrote. An existing --out is replaced only when it is empty or has that list and nothing else:
//   a file a user put there (or a folder of someone else's) is never deleted.
#pragma once

#include <filesystem>
#include <functional>

#include <sys/types.h>

namespace gt {

// Throws InputError when `out`'s parent does not exist or cannot be written, when `out` exists and
// is not a folder, or when it holds anything groundtruth did not write there.
void check_output_folder(const std::filesystem::path& out);

// Writes into a fresh staging folder through `fill`, records the marker, then swaps it in place of
// `out`. Removes stale staging folders of `out` first. Filesystem failures become InputError.
void write_folder_atomically(const std::filesystem::path& out,
                             const std::function<void(const std::filesystem::path&)>& fill);

// Starts the thread that turns SIGINT, SIGTERM and SIGHUP into a clean exit (call once, first
// thing in main, before any other thread starts).
void install_interrupt_cleanup();

// The worker processes an interruption must also end; compare/worker.cpp adds and removes them.
void add_running_worker(pid_t pid);
void remove_running_worker(pid_t pid);

}  // namespace gt
