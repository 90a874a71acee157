// A droplet eroder (erosion.particle: Hydra's kernel; erosion.beyer: Beyer 2015) as a stepped twin
// that compare/stepped_case.hpp runs. What the twins can promise depends on the ordering of the
// droplets of a pass (core/params/droplets.hpp); this file says it in the runner's terms.
//
// State: {terrain}, in the input's own heights and vertical unit (m where it names none). The twins
//   see h_twin = (h − offset)/scale (seed 000's normalisation when the case asks; scale 1, offset 0
//   otherwise) and their steppers convert. The side maps (what the droplets standing on a texel
//   eroded and deposited) are not state: no droplet reads them, so a step resumes from the terrain
//   alone; they are drawn from a run of ref<double>.
// Steppers: ref<double> runs the droplets of a pass one after the other (the sequential truth),
//   ref<float> and the GPU in the case's ordering; the droplets of an iteration are numbered by the
//   iteration (Beyer's random directions), so a shadow step from a checkpoint draws what the walk
//   draws.
// Shadow bound of the terrain, per ordering:
//   batch     0: order-independent integer arithmetic on the state frozen at a pass's start
//   disjoint  same float operations in the same order at every cell: parity_bounds_same_arithmetic
//             of writes_per_cell_per_step·lifetime·spacing² additions an iteration, relative to the
//             input's height range (a bound over 1 % of the range is inconclusive)
//   race      none (informative): the GPU's droplets of a pass race for cells; determinism.gpu is
//             not applicable and the GPU's terrain is not described beside ref<double>'s
// Ledger terms, <term>.{cpu,cpu_float,gpu} (the GPU books no droplet ledger: not applicable there):
//   ledger.closure   |Σ after + sediment taken away + deposited outside − eroded outside − clamp −
//                    apply rounding − Σ before| / Σ|before|, in the twin's heights. Bound 1e-12 in
//                    double and in batch float (the terrain changes by exactly counted quanta);
//                    sequential float: roundings_per_step roundings of at most u·max|h| for every
//                    droplet step the run can take, and cell_roundings_per_iteration of at most
//                    2u·max|h| at each cell and iteration, random walk (strict) and worst case (loose)
//   ledger.quanta    batch: the same identity in integer quanta, exactly 0 (ref<double> counts none)
// Own checks (SteppedTwin::finish), the GPU's skipped by name without one:
//   batch.largest_cell_delta_quanta           ref<float>'s largest change of a cell in a pass
//   batch.{relative_rms,erosion_correlation}_vs_sequential   batch ref<float> against the truth
//   parity.cells_differing.gpu_vs_float       batch: the whole run, GPU against ref<float>, bound 0
//   race.*                                    race: the GPU against the sequential ref<float> over 5
//                                             or more runs, and by spacing 16..1 (reported: no error
//                                             model gives a race's distance before the run)
//   parity.batch_kernel.gpu_vs_float          race: what is order-independent, graded: one iteration of
//                                             the case's droplets in batch ordering, GPU against
//                                             ref<float>, bound 0 (at apart_spacing where the case's
//                                             spacing piles more into a cell than batch can count)
// Pictures and files beside the runner's: Hydra's depth and sediment maps of ref<double>'s run
// (depth_cpu.png, sediment_cpu.png, eroded_at_droplet_cpu, deposited_at_droplet_cpu), the batch
// result against the truth (batch_vs_sequential.png), the race by spacing (race_by_spacing.png).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/result.hpp"
#include "compare/stepped_case.hpp"
#include "core/grid.hpp"
#include "core/memory.hpp"
#include "core/params/droplets.hpp"
#include "reference/erosion/droplets.hpp"

namespace gt {

// What a run varies beside the case's own constants: the race-by-spacing and the benchmark's
// orderings run the same eroder with another spacing or ordering.
struct DropletSetup {
  int spacing = 4;
  DropletOrdering ordering = DropletOrdering::batch;
};

// The GPU eroder of one setup: load heights with `done` iterations behind them (the droplets are
// numbered on from there), step `count` iterations (not synchronised), download.
struct DropletGpu {
  std::function<void(const Grid<float>& heights, int done)> load;
  std::function<void(int count)> step;
  std::function<Grid<float>()> result;
};

// The twins' heights against a state's: h_twin = (h − offset)/scale.
struct HeightScale {
  double scale = 1.0;
  double offset = 0.0;

  // (h − offset)/scale in double on valid cells, as normalise_heights computes it, rounded once to
  // Real; 0 on the others (the twins never read them).
  template <class Real>
  Grid<Real> twin_heights(const State& state) const {
    Grid<Real> heights = state.grid.blank<Real>(Real(0), "1");
    for (std::size_t i = 0; i < heights.size(); ++i) {
      if (heights.is_valid(i)) heights.values[i] = static_cast<Real>((state.fields.at(0)[i] - offset) / scale);
    }
    return heights;
  }
  // h·scale + offset in double. A float comes back from twin_heights<float> as it was (the double
  // roundings are far below its spacing unless it lies within about 1e-16·offset/scale of 0).
  template <class Real>
  State state_of(const Grid<Real>& heights) const {
    State state{StateGrid::of(heights), {std::vector<double>(heights.size())}};
    for (std::size_t i = 0; i < heights.size(); ++i) {
      state.fields[0][i] = static_cast<double>(heights.values[i]) * scale + offset;
    }
    return state;
  }
};

struct DropletTwin {
  std::string algorithm;  // e.g. erosion.particle
  State initial;          // the input in its own heights
  std::string unit;       // their vertical unit
  Heightmap input;        // as the twins see it (normalised when the case asks)
  HeightScale own;        // the twins' heights against the state's
  DropletSetup setup;     // the case's
  int iterations = 0;
  int lifetime = 0;
  // The smallest spacing at which no two droplets of a pass read or write a common texel (twice the
  // droplet's reach, plus 1): disjoint ordering's least spacing.
  int apart_spacing = 0;
  // Float roundings per droplet step that can move material between the terrain and the sediment
  // (stores and sediment updates): the sequential float ledger's error model.
  double roundings_per_step = 0.0;
  // Writes one droplet step can make to one cell at most: the disjoint shadow step's error model.
  double writes_per_cell_per_step = 0.0;
  // Roundings at each cell per iteration outside the droplets (Beyer's blur blend of eq. 2.43: 8 sums
  // of its exchanges and the final add, 9; 0 without one): a term of both error models above. The
  // blend's exchanges cancel exactly in pairs, so only these sums move the float ledger.
  double cell_roundings_per_iteration = 0.0;
  // The references: `count` iterations from `heights`, the first numbered `first`; race and
  // disjoint run the droplets of a pass one after the other (the sequential truth).
  std::function<reference::DropletRun<double>(const Grid<double>& heights, int first, int count, DropletSetup setup)>
      reference_double;
  std::function<reference::DropletRun<float>(const Grid<float>& heights, int first, int count, DropletSetup setup)>
      reference_float;
  std::function<DropletGpu(DropletSetup setup)> make_gpu;  // called only with a current GL context
  std::vector<std::string> notes;  // decisions taken for the user, said in the output
  // Hydra's contrasts of its depth and sediment maps (§4.4.1: c_E, c_D): the pictures show
  // min(1, c·amount) as the add-on writes them; 0 draws the raw maps at their 99th percentile.
  double erosion_contrast = 0.0;
  double deposition_contrast = 0.0;
};

// The start state, the twins' input (normalised when `normalise`: seed 000's (h - min)/(max - min),
// with a note saying so) and the scale between them.
void set_droplet_input(DropletTwin& twin, const Heightmap& given, bool normalise);

// A hand-derived droplet in a case's "expect" (droplet_spec_shape()): {"droplet": {"start": [x, y]
// (the texel it starts in), "positions": [[x, y], ...] (after each completed step, the start first),
// "sediment": s (carried when it ended), "cells": [[x, y, h], ...] (heights after its life),
// "tolerance": t}}. add_droplet_spec_checks grades ref<double>'s trace of that droplet against it:
// spec.droplet.{positions,sediment,cells}.cpu, each against the tolerance the case states for its
// decimals (the hand derivation's, not the run's).
nlohmann::json droplet_spec_shape();
struct DropletTrace {
  std::vector<std::pair<double, double>> positions;
  double sediment = 0.0;
  Heightmap heights_after;
};
void add_droplet_spec_checks(const nlohmann::json& spec, const DropletTrace& trace, CaseResult& result);

// The eroder as the runner's twin: its state, steppers, shadow bounds, ledger terms and own checks.
SteppedTwin droplet_stepped_twin(std::shared_ptr<const DropletTwin> twin);

// What the runner keeps of a case of `iterations` on `cells` cells: ref<double>'s and ref<float>'s
// states (a double a cell each) at every shadow start and at the end.
MemoryEstimate droplet_checkpoint_memory(double cells, int iterations);

// One GPU performance row (needs a current GL context): the twin's droplets in `ordering` at its
// spacing, one outer iteration per timed run (the upload not timed), the median of `reps`.
BenchmarkRow droplet_gpu_row(const DropletTwin& twin, DropletOrdering ordering, int reps, const Environment& environment,
                             const std::string& backend);

// Performance rows for one grid side: ref<double> (sequential) and, with a GPU, its race and batch
// orderings, one outer iteration per timed run, the median of `reps`, in cell-iterations and droplet
// steps per second (steps from the references' ledgers: droplets may end early).
std::vector<BenchmarkRow> droplet_benchmark_rows(const DropletTwin& twin, int reps, bool gpu_available,
                                                 const Environment& environment);

}  // namespace gt
