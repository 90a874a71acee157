// Benchmark plot for reports: median time per run and throughput over grid size, drawn by
// compare/report/plot_timings.py with matplotlib.
//
// The Python interpreter is GT_PYTHON_WITH_MATPLOTLIB (found at configure time, may be empty) and
// the script GT_SOURCE_DIR "/compare/report/plot_timings.py"; both are compile definitions.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/result.hpp"

namespace gt {

// Writes folder/timings.png (folder is the report folder and must exist) and returns it as the
// artifact {"timings.png", "plot", caption}. Returns std::nullopt and sets `reason` when there are
// no rows, no Python with matplotlib, or the script fails (its last line of output says why);
// the caller then shows "plot unavailable: <reason>" (writers.hpp: a plot with an empty path).
std::optional<Artifact> plot_benchmarks(const std::vector<BenchmarkRow>& rows, const std::filesystem::path& folder,
                                        std::string& reason);

}  // namespace gt
