// The comparison driver behind `groundtruth run`, `report` and `bench`: selects cases, loads and
// checks every input before anything runs (bad input -> InputError, exit 2, nothing written),
// makes the GL context, runs the cases, and writes the report folder atomically.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/benchmark.hpp"
#include "compare/result.hpp"
#include "gpu/context/context.hpp"

namespace gt {

enum class Backends { cpu, gpu, both };

struct AdHocCase {
  std::string algorithm;
  std::string input;                     // a heightmap file; empty for a generator (noise) on a
  int width = 256;                       //   width x height grid of cell_size
  int height = 256;
  double cell_size = 1.0;
  std::vector<std::string> assignments;  // "name=value"
};

struct DriverOptions {
  std::vector<std::string> patterns;     // case-name globs
  std::optional<AdHocCase> ad_hoc;
  Backends backends = Backends::both;
  GlBackend gl = GlBackend::egl;
  std::filesystem::path out;
  std::filesystem::path dataset_dir;
  int cpu_reps = 3;
  int gpu_reps = 5;
  std::optional<BenchmarkOptions> benchmark;
};

// Runs everything and writes the report; returns the process exit status (0 nothing unexpected
// failed, 1 something did). Throws InputError for bad usage or input before writing anything.
int run_driver(const DriverOptions& options);

// Folder handling: throws InputError when `out`'s parent does not exist or `out` exists and is
// neither empty nor a groundtruth report folder (one holding report.json): never overwrite a
// user's files.
void check_output_folder(const std::filesystem::path& out);

// Writes into a fresh sibling folder through `fill`, then swaps it in place of `out`.
void write_folder_atomically(const std::filesystem::path& out,
                             const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace gt
