// Mutants of the thermal twins (erosion.thermal, erosion.thermal_jako); see
// compare/mutants/mutants.hpp. Each runs on small cases of datasets/cases/erosion.thermal.json: the
// seeds' 3x3 worked examples (one iteration) and 32x32 noisy cones (16 iterations, 8 checkpoints).
//
// one_twin: bugs in the GPU shaders only, killed by the shadow-step parity
// (parity.shadow.max_abs.gpu_vs_float: the GPU loaded with ref<float>'s state and stepped one
// iteration beside it). Each moves a share of a transfer, far above the a-priori bound of
// compare/checks/error_model.hpp (a few float roundings per addition). A bug of one ulp in a
// division would hide under that bound, which allows GLSL's 2.5-ulp division: none is registered.
//
// both_twins: the same bug in ref<double>, ref<float> and the GPU, killed by checks against what
// was asked, computed on the host: spec.cells/spec.total (the worked examples), mass.relative_drift
// (the methods conserve material), mass.moved_first_iteration.cpu (the material the first
// iteration moves, against a host spec of the transfer from the thesis' equations) and
// spec.first_iteration_cells.cpu (that first iteration cell by cell: mirrored_slope runs on the
// probe cone and on the volcano, which is not symmetric) and spec.talus_eq_4_10 (eq. 4.10's
// threshold, which both twins read from core/params/thermal.cpp). The hardness map's two
// (hardness_of_the_cell, both twins; gpu_limit_of_opposite_pipe, the GPU alone) run on the probe
// cone and on the volcano, each with a banded hardness field; so does gpu_rate_folded_into_hardness,
// a GPU adapter that changes the read-only input it was handed (killed by
// state.hardness.unchanged.gpu, the runner's check of a read-only field, and by the shadow step).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> thermal_mutants() {
  const std::vector<std::string> hydra = {"erosion.thermal.spec.example_3x3", "erosion.thermal.mutant_probe.cone"};
  const std::vector<std::string> hydra_probe = {"erosion.thermal.mutant_probe.cone"};
  const std::vector<std::string> jako = {"erosion.thermal_jako.spec.example_3x3",
                                         "erosion.thermal_jako.mutant_probe.cone"};
  const std::vector<std::string> jako_probe = {"erosion.thermal_jako.mutant_probe.cone"};
  const std::vector<std::string> hardness = {"erosion.thermal_jako.hardness.mutant_probe.cone",
                                             "erosion.thermal_jako.hardness.volcano"};
  return {
      {"erosion.thermal.swapped_gather", MutantKind::one_twin,
       "thermal_transfer.comp pairs a cell's pipe k with the neighbour's request on its pipe k instead of the "
       "opposite pipe (k + 2) mod 4",
       hydra_probe},
      {"erosion.thermal.demand_total_three_pipes", MutantKind::one_twin,
       "thermal_requests.comp sums the demand of pipes 0-2 only (pipe 3 left out of Σdemand), so C_d is too large "
       "wherever pipe 3 demands",
       hydra_probe},
      {"erosion.thermal_jako.dropped_direction", MutantKind::one_twin,
       "thermal_jako_outflow.comp loops over 7 pipes: nothing ever leaves through pipe 7 (+1, -1)", jako_probe},
      {"erosion.thermal_jako.swapped_inflow", MutantKind::one_twin,
       "thermal_jako_gather.comp gathers what a neighbour sends down its pipe k instead of the opposite pipe "
       "(towards this cell)",
       jako_probe},
      // The calibrated pair of the shadow step's error model (compare/checks/error_model.hpp,
      // parity_bounds_same_arithmetic): on the probe cone an inflow 2^-13 too large lands at 4.7 times
      // the one-step bound (0.000128 m against 2.75e-05 m; 2^-10 gave 37 times) and must be killed;
      // one ulp off per cell, the rounding an honest twin may differ by, lands at 0.07 times it and
      // must survive.
      {"erosion.thermal.inflow_off_above_bound", MutantKind::one_twin,
       "thermal_transfer.comp takes in each inflow times 1 + 2^-13", hydra_probe},
      {.name = "erosion.thermal.one_ulp_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "thermal_transfer.comp leaves each height one ulp off (up on even cells, down on odd ones)",
       .cases = hydra_probe,
       .must_survive = true},
      {"erosion.thermal.talus_degree_off", MutantKind::both_twins,
       "both twins apply the talus slope of an angle one degree steeper than asked (reference and GPU block)", hydra},
      {"erosion.thermal.eq_4_10_unconverted_degrees", MutantKind::both_twins,
       "eq. 4.10's tan takes the talus angle in degrees as if radians (core/params/thermal.cpp, which both twins read)",
       {"erosion.thermal.spec.example_3x3"}},
      {"erosion.thermal.unconserved_transfer", MutantKind::both_twins,
       "Algorithm 11 in both twins adds the transfer to the receiving cell but never subtracts it from the giver",
       hydra},
      {"erosion.thermal.mirrored_slope", MutantKind::both_twins,
       "both twins read each pipe's slope from the neighbour across the opposite pipe (where that one is open), so "
       "material goes the mirrored way",
       {"erosion.thermal.mutant_probe.cone", "erosion.thermal.cardinal.volcano"}},
      {"erosion.thermal.doubled_rate", MutantKind::both_twins,
       "both twins use f_s = strength instead of strength/2 in the shares of Algorithm 10", hydra},
      {"erosion.thermal_jako.talus_degree_off", MutantKind::both_twins,
       "both twins apply the talus slope of an angle one degree steeper than asked (reference and GPU block)", jako},
      {"erosion.thermal_jako.unhalved_transfer", MutantKind::both_twins,
       "both twins move ΔS = rate·H instead of rate·H/2 (eq. 2.32's halving forgotten)", jako},
      {"erosion.thermal_jako.first_outflow_kept", MutantKind::both_twins,
       "both twins' gather subtracts the outflows of pipes 1-7 only: what leaves through pipe 0 is created", jako},
      {"erosion.thermal_jako.hardness_of_the_cell", MutantKind::both_twins,
       "both twins (core/params/thermal.cpp's jako_cell_constants) steepen the talus below a cell by its own "
       "hardness instead of the lower neighbour's (eq. 2.33's R(n))",
       hardness},
      {"erosion.thermal_jako.gpu_limit_of_opposite_pipe", MutantKind::one_twin,
       "thermal_jako_outflow.comp compares each drop with the threshold of the pipe pointing the other way: the same "
       "length, another neighbour's hardness",
       hardness},
      {"erosion.thermal_jako.gpu_rate_folded_into_hardness", MutantKind::one_twin,
       "the GPU stepper folds the rate into the hardness map it was loaded with (R <- rate·R in its copy), then steps "
       "with that map and hands it back",
       hardness},
  };
}

}  // namespace gt
