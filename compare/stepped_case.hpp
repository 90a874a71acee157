// The one runner of iterative twins: everything a stepped case does that is not the algorithm's own.
//
// Inputs:  a SteppedTwin: the declared state, the start state, the three steppers (ref<double>,
//          ref<float>, the GPU; compare/stepper.hpp), the error model of a shadow step per field
//          and the ledger terms; the case's `expect` and the run options.
// Outputs: checks, timings, pictures, plots and field files added to the CaseResult.
// Checks, <f> every declared field (over all its components), backends cpu = ref<double>,
// cpu_float = ref<float>, gpu:
//   parity.shadow.<f>.gpu_vs_float        at each checkpoint ref<float>'s state is loaded into the
//                                         GPU, both take one iteration: max |gpu − ref<float>| in the
//                                         field's unit, the worst checkpoint against its bound, which
//                                         the algorithm's error model gives from that state before
//                                         stepping (ShadowBound; informative where it has none)
//   parity.shadow.<f>.multi.gpu_vs_float  the same after shadow_length iterations
//   parity.<f>.{max_abs,rms}.{gpu_vs_float,gpu_vs_double,float_vs_double}   at the end of the run,
//                                         informative: over a run the method amplifies rounding by an
//                                         amount no model gives before it (the shadow steps grade)
//   parity.<f>.growth_per_iteration.{gpu,float}_vs_double   fitted factor per iteration of the
//                                         distance from ref<double> over the checkpoints (plotted;
//                                         not applicable where fewer than two distances are above 0)
//   determinism.gpu                       values differing in any bit, every field, between a GPU run
//                                         stepped through the checkpoints and one in one go: bound 0
//   <term>.{cpu,cpu_float,gpu}            each ledger term on each backend's whole run
//   spec.cells.{cpu,gpu}, spec.total.{cpu,gpu}   the shown field (or expect.field) against the case's expected values
//                                         (the "expect" keys of field_spec_shape)
// Without a GPU every check the GPU half makes is there by the same name as `skip` with the reason
// (gpu_check_names): the harness, not each algorithm, decides what is skipped.
// Schedule: the shadow steps start after k·N/C iterations, k = 0..C−1 (C = checkpoints: the run's
// --checkpoints, else the algorithm's; every iteration of a run of fewer; 0 alone for a run of none,
// whose shadow is a load and a download); the runs keep their states there and at the end, and the
// memory they need is estimated before the first step (InputError when it is not there).
// Files: every component of every field for the input and each backend, <f>_<backend>.exr/.npy;
// pictures of the shown field before and after, its change and the GPU's difference, and each
// other field at the end of ref<double>'s run; the divergence plot.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "compare/stepper.hpp"

namespace gt {

// The bound on one field's shadow distance, in the field's unit, fixed before the step.
struct ShadowBound {
  double strict = 0.0;
  std::optional<double> loose;
  // A bound for each value of the field (the state's layout: cell by cell, components within a
  // cell) where the model gives one; the check then fails where any value exceeds its own bound,
  // and `strict` is ignored (the report quotes the bound where the distance came closest to it,
  // and judges tellability by the bounds' 90th percentile over valid cells).
  std::vector<double> per_value;
  // The field's own size in that state: a bound wider than tellable_share of its largest size over
  // the checkpoints cannot tell a bug from rounding, and a pass under it is `inconclusive`.
  double scale = 1.0;
  double tellable_share = 0.01;
  bool graded = true;  // false: the distance is informative
  std::string why_not_graded = "the model is too wide to grade";  // for the report, where graded is false
  std::string model;   // one line for the report
};

// One backend's whole run, as a ledger term reads it.
struct LedgerRun {
  const State& initial;
  const State& final;
  const std::vector<LedgerRecord>& records;  // the stepper's ledger() after the run
  const std::string& backend;                // cpu, cpu_float or gpu
};

// A conservation or balance check of one backend's run: its name is <check>.<backend>.
struct LedgerTerm {
  std::string check;  // e.g. mass.relative_drift
  std::function<Check(const LedgerRun& run)> evaluate;
  // Whether it reads the records (else the states alone): a backend that books none (an outside
  // model) has such a term as not applicable where the references book some.
  bool reads_records = true;
};

// One backend's end of run, for the algorithm's own checks and pictures.
struct BackendEnd {
  std::string backend;  // cpu, cpu_float or gpu
  const State& final;
  const std::vector<LedgerRecord>& records;  // the stepper's ledger() after the run
};

struct SteppedTwin {
  std::string algorithm;
  StateDecl fields;
  State initial;  // in double; the float twins start from it rounded to float
  int iterations = 0;
  int checkpoints = 8;
  int shadow_length = 4;
  std::function<std::unique_ptr<Stepper>()> reference_double;
  std::function<std::unique_ptr<Stepper>()> reference_float;
  std::function<std::unique_ptr<Stepper>()> make_gpu;  // called only with a current GL context
  // The GPU stepper that is timed, where it differs (one that keeps no ledger); unset: make_gpu.
  std::function<std::unique_ptr<Stepper>()> make_timed_gpu;
  // A slow model (minutes a run): ref<double>'s walk through the checkpoints is its one timed run,
  // and the GPU's run in one go (determinism's second run, or make_timed_gpu's) its one; otherwise
  // RunOptions' cpu_reps and gpu_reps.
  bool time_walks = false;
  // Why two GPU runs of one state may differ (droplets racing for a cell); empty: they may not, and
  // determinism.gpu grades it (bound 0). Where it is set determinism.gpu is not applicable.
  std::string gpu_nondeterminism;
  // The GPU does ref<float>'s float operations in the same order (a bit-exact twin): the whole run's
  // parity.<f>.max_abs.gpu_vs_float is graded, bound 0, as every shadow step is; otherwise it is
  // informative (rounding differences grow along a run by an amount no model gives before it).
  bool gpu_bit_exact = false;
  // Why the GPU's end of run is not described beside ref<double>'s (it runs another model than the
  // truth, and parity.descriptors.gpu_vs_double would grade that); empty: it is, and that check grades
  // it. Where it is set the descriptors show the references alone, and a note says why.
  std::string gpu_not_described;
  // The bounds after `count` iterations from `from` (ref<float>'s state), one per declared field
  // that is not read-only, in order (the runner bounds a read-only field at 0).
  std::function<std::vector<ShadowBound>(const State& from, int count)> shadow_bounds;
  std::vector<LedgerTerm> ledger;
  // Optional: the algorithm's own checks and pictures of the backends' ends (ends[0] ref<double>,
  // ends[1] ref<float>, ends[2] the GPU when it ran). A check it adds for the GPU alone is named in
  // finish_gpu_checks, so that a run without a GPU has it as `skip` by the same name.
  std::function<void(const std::vector<BackendEnd>& ends, const nlohmann::json& expect, const RunOptions& options,
                     CaseResult& result)>
      finish;
  std::function<std::vector<std::string>(const nlohmann::json& expect)> finish_gpu_checks;
  // Drawn before and after, held to spec vectors (unless expect.field names another), described as terrain.
  std::size_t shown_field = 0;
};

// The field the case's spec vectors ("cells", "total") are read against: expect's "field" by name
// (InputError naming the declared fields when there is none of that name), else the shown field.
std::size_t expected_field(const SteppedTwin& twin, const nlohmann::json& expect);
// field_spec_shape() and "field": the expect keys of a stepped twin whose spec vectors may hold
// another field than the shown one.
nlohmann::json stepped_spec_shape();

// The iterations the shadow steps start from.
std::vector<int> shadow_starts(int iterations, int checkpoints);

// Every check the GPU half of this case makes, by name (run_stepped_case adds these as `skip`
// when the GPU cannot run; the terrain descriptors skip theirs themselves).
std::vector<std::string> gpu_check_names(const SteppedTwin& twin, const nlohmann::json& expect);

void run_stepped_case(const SteppedTwin& twin, const nlohmann::json& expect, const RunOptions& options,
                      CaseResult& result);

}  // namespace gt
