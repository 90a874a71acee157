// Running a generated field's twins on one grid and checking them against each other.
//
// A generated field (noise) samples a function on the input's grid: the reference in double (the
// truth) and in float (the GPU's arithmetic), and the GPU version — or a user's field file in its
// place (RunOptions::candidate, `run --candidate`: checks named candidate_vs_float/_vs_double,
// a double file graded against ref<double> alone, determinism not applicable). run_field_twin runs all three,
// times the double reference and the GPU, writes the pictures and fields, and adds the checks of
// DESIGN.md, judged on the whole output with the bounds the twin gives:
//   parity.max_abs.gpu_vs_float, parity.rms.gpu_vs_float     (logic bounds)
//   parity.max_abs.{gpu,float}_vs_double, parity.rms.*       (precision bounds)
//   determinism.gpu                                         cells differing between two GPU runs
//   spec.cells.{cpu,gpu}, spec.total.{cpu,gpu}               when the case lists expected values
// Without a GL context the GPU checks are `skip` with the reason and the CPU side still runs.
// Iterative twins are stepped by compare/stepped_case.hpp instead.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/checks/error_model.hpp"
#include "compare/external/bmi_model.hpp"
#include "compare/progress.hpp"
#include "compare/result.hpp"
#include "core/grid.hpp"
#include "core/mesh.hpp"

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
  // The parity bounds, absolute: GPU vs ref<float> (logic) and ref<float> and GPU vs ref<double>.
  struct GeneratedField {
    Bounds logic;
    Bounds precision;
    // Samples the precision bounds do not cover, fixed before any twin runs (1 = left out: a function
    // that jumps where a rounding may move its argument across a boundary, compare/checks/
    // noise_error_model.hpp lattice_jump_samples), and why: left out of the *_vs_double checks and
    // counted in their detail. Empty: none.
    std::vector<std::uint8_t> precision_excused;
    std::string precision_excused_why;
  };
  GeneratedField bounds;
};

// A user's output to grade where the GPU twin's stands (`run --candidate FILE`,
// compare/external/candidate.hpp): a field read from a .npy or EXR file, on the case's grid; a
// mesh of a cave block; a rendered image of the case's size.
struct CandidateField {
  std::filesystem::path file;
  Grid<double> values;
  bool double_precision = false;  // a float64 .npy
};

struct CandidateMesh {
  std::filesystem::path file;
  Mesh mesh;
  std::vector<std::string> notes;  // what the reader decided (core/io/mesh_io.hpp)
};

struct CandidateImage {
  std::filesystem::path file;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 bytes a pixel, rows top first
  std::vector<std::string> notes; // conversions made for the user
};

// At most one of them, by the case's algorithm (compare/algorithm.hpp CandidateOutput).
struct CandidateOutputs {
  std::optional<CandidateField> field;
  std::optional<CandidateMesh> mesh;
  std::optional<CandidateImage> image;
};

struct RunOptions {
  int cpu_reps = 3;
  int gpu_reps = 5;
  // States along a stepped run the shadow steps start from (--checkpoints); 0: the algorithm's own.
  int checkpoints = 0;
  bool gpu_available = false;
  std::string gpu_unavailable_reason;
  std::filesystem::path report_dir;  // artifacts go to report_dir / case name /
  std::filesystem::path dataset_dir; // datasets/: the real DEM that case descriptors are shown beside
  Progress* progress = nullptr;
  // A cheap run (the Python module's pictures=False, descriptors=False): the runners draw no
  // pictures of the fields and compute no terrain descriptors; checks and field files stay.
  bool pictures = true;
  bool descriptors = true;
  // An outside implementation graded where the GPU twin stands (stepped cases; --implementation,
  // or a Python model): compare/external/bmi_model.hpp.
  std::optional<ExternalModel> external;
  CandidateOutputs candidate;
};

// Listed cells as a case's "expect" gives them: [[x, y, value], ...] (core/json_keys.hpp shapes).
nlohmann::json cell_values_shape();

// The "expect" keys run_field_twin reads (spec vectors of the field: expected cells, their total, a
// tolerance); an algorithm's Algorithm::expect_shape starts from it and adds its own.
nlohmann::json field_spec_shape();

// spec.cells.<backend> and spec.total.<backend> of `output` when `expect` lists expected cells or a total.
void add_field_spec_checks(const nlohmann::json& expect, const Grid<double>& output, const std::string& backend,
                           CaseResult& result);

// The names add_field_spec_checks gives for `expect` and `backend`.
std::vector<std::string> field_spec_names(const nlohmann::json& expect, const std::string& backend);

void run_field_twin(const FieldTwin& twin, const Heightmap& grid, const nlohmann::json& expect,
                    const RunOptions& options, CaseResult& result);

}  // namespace gt
