// The algorithms the driver knows: name, where it comes from, its parameter declarations and how
// to run a case of it. `groundtruth list` prints this table.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/benchmark.hpp"
#include "compare/field_twin.hpp"
#include "compare/inputs.hpp"
#include "compare/peers/peer.hpp"
#include "compare/result.hpp"
#include "compare/stepped_case.hpp"
#include "core/grid.hpp"
#include "core/memory.hpp"
#include "core/params.hpp"

namespace gt {

// A case's run, for algorithms that run the whole case themselves (meshes, renders, planets):
// `expect` is the case's, checks and artifacts go into the result.
using CaseRun = std::function<void(const nlohmann::json& expect, const RunOptions& options, CaseResult& result)>;

// `first`, then `second`, into the same result (a case's extra checks of two kinds).
CaseRun in_turn(CaseRun first, CaseRun second);

// A generator's twins (noise) and the grid they sample.
struct GeneratedCase {
  FieldTwin twin;
  Heightmap grid;
};

// The three kinds of case the driver runs: a generated field (compare/field_twin.hpp), an
// iterative twin stepped by the one runner (compare/stepped_case.hpp), or a custom run.
enum class CaseKind { generated, stepped, custom };

// An algorithm's twins set up for one input and parameter set.
struct PreparedTwin {
  std::variant<GeneratedCase, SteppedTwin, CaseRun> kind;
  // Checks that belong to the algorithm rather than to the runner (spec vectors of its formulas,
  // sweeps); they may add artifacts under options.report_dir / result.name.
  CaseRun extra_checks;
};

// What an ad-hoc run's --input names: a heightmap (erosion; noise samples on its grid, or on a
// --size grid without one), a mesh file (mesh.check), a volume file or nothing (the cave meshes a
// .npy volume when given one, else the seed's noise), or nothing at all (the endless cave).
enum class AdHocInput { heightmap, mesh, optional_volume, optional_global_grid, none };

// What `run --candidate FILE` takes in the GPU twin's place (compare/external/candidate.hpp): a
// sampled field, a mesh or a rendered image; none for algorithms that step (an outside model
// plugs in through the BMI instead) or that have no candidate path yet.
enum class CandidateOutput { none, field, mesh, image };

// Bytes read plus written per cell (voxel, sample) and iteration by each backend's passes at the
// default parameters, as counted in the comment beside the kernels; unset where not counted. The
// performance table divides them by the measured copy bandwidth: its floor column.
struct MemoryTraffic {
  std::optional<double> cpu;
  std::optional<double> gpu;
};

struct Algorithm {
  std::string name;     // e.g. erosion.thermal
  std::string summary;  // one line
  std::string source;   // seed / paper and equations
  const ParamSpecs* params = nullptr;
  // `resolved` holds every parameter (defaults filled in, ranges checked).
  std::function<PreparedTwin(const nlohmann::json& resolved, const LoadedInput& input)> prepare;
  // Which of PreparedTwin's kinds prepare() gives: a stepped algorithm changes its input over
  // `iterations` (or steps) and needs one; a generated one samples a grid (a flat one by default).
  CaseKind kind = CaseKind::stepped;
  AdHocInput ad_hoc_input = AdHocInput::heightmap;
  // The input fields prepare() reads (LoadedInput::fields); a case giving any other is refused.
  std::vector<InputFieldSpec> input_fields;
  CandidateOutput candidate = CandidateOutput::none;
  // The algorithm's own rows of the performance table (cave meshing: voxels and triangles per
  // second); unset: the generic timing of compare/benchmark.cpp, or none for custom cases.
  std::function<std::vector<BenchmarkRow>(const BenchmarkOptions& options, bool gpu_available,
                                          const Environment& environment)>
      benchmark = {};
  MemoryTraffic traffic;
  // Figures published for the same work (a seed's timing tables, backend "published"): the
  // performance table shows each beside ours at the sizes it times.
  std::vector<BenchmarkRow> published;
  // Other libraries' implementations of the same work, timed beside the generic field-twin rows.
  std::vector<Peer> peers;
  // The keys a case's "expect" may hold (core/json_keys.hpp require_shape): what this algorithm's
  // checks read. Any other key is bad input, so a typo cannot silently drop a check.
  nlohmann::json expect_shape = nlohmann::json::object();
  // The peak memory a case needs beyond the process's fixed cost (core/memory.hpp), from its
  // resolved parameters and loaded input. Each algorithm's file states the bytes per cell, voxel,
  // triangle or pixel it measured (peak RSS of `groundtruth run` on both backends, report
  // included, at two sizes: the difference over the difference in size) and rounds them up. The
  // driver checks it before preparing the case.
  std::function<MemoryEstimate(const nlohmann::json& resolved, const LoadedInput& input)> memory;
};

const std::vector<Algorithm>& algorithms();

// Throws InputError listing the known names.
const Algorithm& find_algorithm(const std::string& name);

// What `groundtruth list --json` and the Python module say of an algorithm: {"name", "summary",
// "source", "input" (heightmap, mesh, optional_volume, optional_global_grid or none), "kind"
// (generated, stepped or custom), "params": [core/params.hpp to_json]}, and for a stepped one
// "state": its declared fields at the default parameters ({"name", "unit", "meaning", "extent",
// "components", "component_names", "conserved", "read_only", "standard_name"}: compare/stepper.hpp).
nlohmann::json algorithm_json(const Algorithm& algorithm);

// Throws InputError naming the first of input.fields that `algorithm` does not read (its
// input_fields), with the ones it reads: a field no algorithm reads would be silently ignored.
void require_known_fields(const Algorithm& algorithm, const LoadedInput& input);

// Defined by each file of compare/algorithms/.
Algorithm thermal_algorithm();
Algorithm thermal_jako_algorithm();
Algorithm dissolution_algorithm();
Algorithm pipe_algorithm();
Algorithm particle_algorithm();
Algorithm beyer_algorithm();
Algorithm layered_algorithm();
std::vector<Algorithm> noise_algorithms();
std::vector<Algorithm> cave_algorithms();
Algorithm cave_endless_algorithm();
Algorithm planet_algorithm();
Algorithm fault_lines_algorithm();
Algorithm mesh_check_algorithm();
Algorithm render_heightmap_algorithm();
Algorithm render_phong_algorithm();
Algorithm render_terrain_algorithm();

}  // namespace gt
