// Running a field algorithm's twins on one input and checking them against each other.
//
// A field twin is an algorithm that maps a heightmap to a heightmap: the reference in double
// (the truth) and in float (the GPU's arithmetic), and the GPU version. run_field_twin runs all
// three, times the double reference and the GPU, writes the pictures and fields, and adds the
// checks of DESIGN.md to the case result:
//   mass.relative_drift.{cpu,cpu_float,gpu}   |Σ after - Σ before| / Σ|before|   (conserving algorithms)
//   parity.max_abs.gpu_vs_float, parity.rms.gpu_vs_float     relative to the input's height range
//                                                            (absolute for generated fields)
//   parity.max_abs.gpu_vs_double, parity.rms.gpu_vs_double
//   parity.max_abs.float_vs_double                           float precision of the method itself
//   determinism.gpu                                          cells differing between two GPU runs
//   spec.cells.{cpu,gpu}, spec.total.{cpu,gpu}               when the case lists expected values
// Without a GL context the GPU checks are `skip` with the reason and the CPU side still runs.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "compare/checks/error_model.hpp"
#include "compare/progress.hpp"
#include "compare/result.hpp"
#include "core/grid.hpp"

namespace gt {

// The GPU side keeps its buffers between repetitions: load (upload, not timed), run (all
// iterations, not synchronised: the caller brackets it with glFinish), result (download).
struct GpuFieldRunner {
  std::function<void(const Grid<float>&)> load;
  std::function<void()> run;
  std::function<Grid<float>()> result;
};

struct FieldTwin {
  std::function<Grid<double>(const Grid<double>&)> reference_double;
  std::function<Grid<float>(const Grid<float>&)> reference_float;
  std::function<GpuFieldRunner()> make_gpu;  // called only with a current GL context
  double additions_per_cell = 0.0;           // rounded additions into one height over the run
  // Largest change of one height, relative to the range, that a rounding can switch on or off:
  // 0 for a continuous method; for a threshold-triggered one (Jákó's talus test) the whole
  // transfer that the threshold gates. Loosens only the float-vs-double bounds.
  double largest_switched_transfer = 0.0;
  bool conserves_mass = true;
  // A generator (noise) makes a new field on the input's grid rather than changing the input: its
  // pictures show the output alone, and its parity bounds are absolute and given here rather than
  // derived from additions relative to the input's height range.
  struct GeneratedField {
    Bounds logic;      // GPU vs ref<float>
    Bounds precision;  // ref<float> and GPU vs ref<double>
  };
  std::optional<GeneratedField> generated;
};

struct RunOptions {
  int cpu_reps = 3;
  int gpu_reps = 5;
  bool gpu_available = false;
  std::string gpu_unavailable_reason;
  std::filesystem::path report_dir;  // artifacts go to report_dir / case name /
  Progress* progress = nullptr;
};

void run_field_twin(const FieldTwin& twin, const Heightmap& input, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result);

}  // namespace gt
