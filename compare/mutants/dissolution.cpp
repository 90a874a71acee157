// Mutants of Beneš's dissolution erosion (erosion.dissolution); see compare/mutants/mutants.hpp.
// Each runs on small cases of datasets/cases/erosion.dissolution.json: the worked pair examples (2x1,
// one iteration), a 32x32 noisy cone (16 iterations, 8 checkpoints) and the volcano, a real DEM, on
// which every one-twin mutant runs too.
//
// one_twin: bugs in the GPU shaders only, killed by the shadow step (parity.shadow.<field>.gpu_vs_float,
// the GPU loaded with ref<float>'s state and stepped one iteration beside it, against the step's
// rounding-interval bounds). The first two conserve water and material, so no ledger sees them;
// evaporated_uncounted is seen by the GPU's water ledger as well. float_evaporated_uncounted is the
// same bug in both float twins (ref<float> and the GPU agree): their own water ledgers
// (mass.water_balance.cpu_float, .gpu) see it.
//
// both_twins: the same bug in ref<double>, ref<float> and the GPU, killed by checks against what was
// asked: the pair examples (spec.cells), the host's spec of one iteration (spec.step.<field>.cpu) and
// the material ledger (mass.material_drift).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> dissolution_mutants() {
  const std::vector<std::string> probe = {"erosion.dissolution.mutant_probe.cone"};
  const std::vector<std::string> probe_and_real = {"erosion.dissolution.mutant_probe.cone",
                                                   "erosion.dissolution.mutant_probe.volcano"};
  // The pair examples, and the one that dissolves and evaporates: a one-twin bug there is seen by the
  // one-step shadow that is the whole run (graded with its multi-step twin: one iteration).
  const std::vector<std::string> pairs = {"erosion.dissolution.spec.pair_level", "erosion.dissolution.spec.pair_all_down",
                                          "erosion.dissolution.mutant_probe.cone"};
  const std::vector<std::string> worked_and_real = {"erosion.dissolution.spec.pair_dissolving",
                                                    "erosion.dissolution.mutant_probe.volcano"};
  return {
      {"erosion.dissolution.dropped_pipe", MutantKind::one_twin,
       "dissolution_outflow.comp loops over 7 pipes: no water (and no dissolved material) ever leaves through pipe 7 "
       "(+1, -1), the rest is shared among the other lower neighbours",
       probe_and_real},
      {"erosion.dissolution.dissolved_left_behind", MutantKind::one_twin,
       "dissolution_gather.comp moves the water but not the material dissolved in it", worked_and_real},
      {"erosion.dissolution.float_evaporated_uncounted", MutantKind::one_twin,
       "ref<float> and the GPU book kept − remaining as evaporated (what e^{-K_e} took unrecorded): the float twins' "
       "water ledgers against ref<double>'s",
       worked_and_real},
      {"erosion.dissolution.evaporated_uncounted", MutantKind::one_twin,
       "dissolution_local.comp books kept − remaining as evaporated instead of rained − remaining: what e^{-K_e} took "
       "goes unrecorded (the water itself is right)",
       worked_and_real},
      // The calibrated pair of the shadow step's per-cell bounds (the step in rounding-interval
      // arithmetic): on the probe cone water taken in 2^-15 too large lands at 4.3 times the bound
      // (3.6e-05 m against 8.5e-06 m; 2^-14 gave 8.6 times) and must be killed; one ulp off per cell,
      // the rounding an honest twin may differ by, lands at 0.018 times it and must survive.
      {"erosion.dissolution.inflow_off_above_bound", MutantKind::one_twin,
       "dissolution_gather.comp takes in each neighbour's water times 1 + 2^-15", probe},
      {.name = "erosion.dissolution.one_ulp_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "dissolution_gather.comp leaves each water depth one ulp off (up on even cells, down on odd ones)",
       .cases = probe,
       .must_survive = true},
      {"erosion.dissolution.unhalved_pair", MutantKind::both_twins,
       "both twins let a neighbour take min(d, Δh) instead of min(d, Δh/2): eq. 2.9's levelling of the pair "
       "overshoots",
       pairs},
      {"erosion.dissolution.threshold_ignored", MutantKind::both_twins,
       "both twins keep d·e^{-K_e} whole: eq. 2.3's threshold T is never subtracted, so water never dries up", probe},
      {"erosion.dissolution.deposition_kept", MutantKind::both_twins,
       "both twins lay dissolved material down on the terrain but leave it in the water too: material is created "
       "wherever water deposits",
       probe},
  };
}

}  // namespace gt
