// Running a droplet eroder's twins on one input and checking them (erosion.particle: Hydra's
// kernel; erosion.beyer: Beyer 2015). Droplets are not a field twin: the GPU may race, so what the
// twins can promise depends on the ordering of the droplets of a pass (core/params/droplets.hpp).
//
// run_droplet_case runs ref<double> in sequential ordering (the truth), ref<float> and the GPU in
// the case's ordering, and adds:
//   ledger.closure.{cpu,cpu_float}     the droplet ledger of reference/erosion/droplets.hpp: terrain
//                                      after + sediment the droplets took away + deposits lost outside
//                                      - erosion credited outside - clamp - apply rounding = terrain
//                                      before, relative to Σ|before|
//   ledger.quanta.cpu_float            batch: the same identity in integer quanta, exactly 0
//   parity.shadow.*.gpu_vs_float       disjoint, batch: the GPU loaded with ref<float>'s state at up
//                                      to 8 checkpoints, stepped one iteration beside it
//   parity.cells_differing.gpu_vs_float  batch: the whole run, bit for bit (disjoint: informative)
//   determinism.gpu                    disjoint, batch: two GPU runs, bit for bit
//   race.*                             race: the GPU against the sequential ref<float> over 5 or more
//                                      runs, reported, not bounded (no error model gives a race's
//                                      distance before the run), and by spacing 16..1
//   batch.*_vs_sequential              batch: how far the batch result lands from the sequential truth
// and the pictures: the terrain before and after, the change, the side maps, the GPU's difference.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/grid.hpp"
#include "core/params/droplets.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt {

// What a run varies beside the case's own constants: the race-by-spacing and the benchmark's
// orderings run the same eroder with another spacing or ordering.
struct DropletSetup {
  int spacing = 4;
  DropletOrdering ordering = DropletOrdering::batch;
};

struct DropletTwin {
  std::string algorithm;  // e.g. erosion.particle
  Heightmap input;        // as the twins see it (normalised when the case asks)
  DropletSetup setup;     // the case's
  int iterations = 0;
  int lifetime = 0;
  // Float roundings per droplet step that can move material between the terrain and the sediment
  // (stores and sediment updates): the float ledger's error model.
  double roundings_per_step = 0.0;
  // Writes one droplet step can make to one cell at most: the disjoint parity's error model.
  double writes_per_cell_per_step = 0.0;
  // The references from `heights` for `iterations` outer iterations; race and disjoint run the
  // droplets of a pass one after the other (the sequential truth).
  std::function<reference::DropletRun<double>(const Grid<double>& heights, int iterations, DropletSetup setup)>
      reference_double;
  std::function<reference::DropletRun<float>(const Grid<float>& heights, int iterations, DropletSetup setup)>
      reference_float;
  // The GPU twin (called only with a current GL context); its step(first, count) runs `count`
  // outer iterations.
  std::function<GpuFieldRunner(DropletSetup setup)> make_gpu;
  std::vector<std::string> notes;  // decisions taken for the user, said in the output
  // Hydra's contrasts of its depth and sediment maps (§4.4.1: c_E, c_D): the pictures show
  // min(1, c·amount) as the add-on writes them; 0 draws the raw maps at their 99th percentile.
  double erosion_contrast = 0.0;
  double deposition_contrast = 0.0;
  // The input's own heights from the twins' (h_own = h·height_scale + height_offset): the terrain
  // descriptors are measured in the input's units, not in the normalised [0, 1] the kernel sees.
  double height_scale = 1.0;
  double height_offset = 0.0;
  std::string height_unit;  // the input's vertical unit, when normalised
};

// The twins' input with normalised heights when `normalise` (seed 000's (h - min)/(max - min)),
// and the scale and offset that undo it for the descriptors, with a note saying so.
void set_droplet_input(DropletTwin& twin, const Heightmap& given, bool normalise);

// Returns ref<float>'s terrain after the run (in the case's ordering): what a flow map is drawn on.
Grid<float> run_droplet_case(const DropletTwin& twin, const nlohmann::json& expect, const RunOptions& options,
                             CaseResult& result);

// Performance rows for one grid side: ref<double> (sequential) and, with a GPU, its race and batch
// orderings, one outer iteration per timed run, the median of `reps`, in cell-iterations and droplet
// steps per second (steps from the references' ledgers: droplets may end early).
std::vector<BenchmarkRow> droplet_benchmark_rows(const DropletTwin& twin, int reps, bool gpu_available,
                                                 const Environment& environment);

}  // namespace gt
