// Running a field algorithm's twins on one input and checking them against each other.
//
// A field twin is an algorithm that maps a heightmap to a heightmap: the reference in double
// (the truth) and in float (the GPU's arithmetic), and the GPU version. run_field_twin runs all
// three, times the double reference and the GPU, writes the pictures and fields, and adds the
// checks of DESIGN.md to the case result:
//   mass.relative_drift.{cpu,cpu_float,gpu}   |Σ after - Σ before| / Σ|before|   (conserving algorithms)
//   determinism.gpu                           cells differing between two GPU runs
//   spec.cells.{cpu,gpu}, spec.total.{cpu,gpu}               when the case lists expected values
// A generator (`generated`: noise) is judged on its whole output, with the bounds it gives:
//   parity.max_abs.gpu_vs_float, parity.rms.gpu_vs_float     (logic bounds)
//   parity.max_abs.{gpu,float}_vs_double, parity.rms.*       (precision bounds)
// An iterative twin (`stepping`: erosion) is judged by shadow steps: at 8 checkpoints along the run
// (every iteration of a shorter run) ref<float>'s state is loaded into the GPU, which takes one and
// then up to 4 iterations (none for a run of none: load and download alone), compared cell by cell
// with ref<float> stepped from the same state:
//   parity.shadow.max_abs.gpu_vs_float         one iteration, max over the checkpoints, relative to
//                                              the input's height range; bound parity_bounds_same_arithmetic
//   parity.shadow.max_abs_multi.gpu_vs_float   up to 4 iterations, the same model over their passes
//   parity.shadow.cells_differing.gpu_vs_float cells differing in any bit after one iteration (informative)
//   mass.moved_first_iteration.cpu             material the double reference moved in its first
//                                              iteration against the twin's host spec of that iteration
// Over a whole run the method amplifies rounding differences by an amount no model gives before the
// run (ties on a cone's apex break either way), so the end-of-run distances are informative:
//   parity.{max_abs,rms}.gpu_vs_float, parity.{max_abs,rms}.{gpu,float}_vs_double,
//   parity.growth_per_iteration.{gpu,float}_vs_double   fitted growth of the distance from
//                                              ref<double> over the checkpoints (also plotted)
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
// Iterative twins also give step(first, count): `count` iterations from the current state, the
// first of them numbered `first` (the number of iterations the state has behind it).
struct GpuFieldRunner {
  std::function<void(const Grid<float>&)> load;
  std::function<void()> run;
  std::function<Grid<float>()> result;
  std::function<void(int first, int count)> step;  // empty for generators
};

struct FieldTwin {
  std::function<Grid<double>(const Grid<double>&)> reference_double;
  std::function<Grid<float>(const Grid<float>&)> reference_float;
  std::function<GpuFieldRunner()> make_gpu;  // called only with a current GL context
  double additions_per_cell = 0.0;           // rounded additions into one height over the run
  bool conserves_mass = true;
  // A generator (noise) makes a new field on the input's grid rather than changing the input: its
  // pictures show the output alone, and its parity bounds are absolute and given here rather than
  // derived from additions relative to the input's height range.
  struct GeneratedField {
    Bounds logic;      // GPU vs ref<float>
    Bounds precision;  // ref<float> and GPU vs ref<double>
  };
  std::optional<GeneratedField> generated;
  // An iterative method that can be stepped from any state (every twin that is not generated):
  // the references from `state`, which has `first` iterations behind it, run `count` more; the GPU
  // runner's step() does the same.
  struct Stepping {
    int iterations = 0;                    // of the whole run
    double additions_per_iteration = 0.0;  // rounded additions into one height per iteration
    std::function<Grid<double>(const Grid<double>& state, int first, int count)> reference_double;
    std::function<Grid<float>(const Grid<float>& state, int first, int count)> reference_float;
    // Optional: the heights after the first iteration from `input`, computed on the host in double
    // from the method's equations, written apart from the twins (a spec of the transfer).
    std::function<Grid<double>(const Grid<double>& input)> first_iteration_spec;
  };
  std::optional<Stepping> stepping;
};

struct RunOptions {
  int cpu_reps = 3;
  int gpu_reps = 5;
  bool gpu_available = false;
  std::string gpu_unavailable_reason;
  std::filesystem::path report_dir;  // artifacts go to report_dir / case name /
  std::filesystem::path dataset_dir; // datasets/: the real DEM that case descriptors are shown beside
  Progress* progress = nullptr;
};

// The "expect" keys run_field_twin reads (spec vectors of the field: expected cells, their total, a
// tolerance); an algorithm's Algorithm::expect_shape starts from it and adds its own.
nlohmann::json field_spec_shape();

void run_field_twin(const FieldTwin& twin, const Heightmap& input, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result);

}  // namespace gt
