// Mutants of Beyer's droplet erosion twins (erosion.beyer); see compare/mutants/mutants.hpp. They
// run on datasets/cases/erosion.beyer.json's probe (a noisy 48x48 cone, batch droplets, 3
// iterations).
//
// one_twin: bugs in beyer_droplets.comp only, killed by the batch ordering's bit-for-bit parity
// (parity.shadow.terrain[.multi] and parity.cells_differing: the GPU against ref<float>, bound 0);
// brush_unnormalised also by the disjoint ordering's same-arithmetic bound (parity.shadow.terrain);
// gradient_swapped_corners also in race ordering, on the race probe and on the volcano (a real DEM),
// by the race's graded batch iteration (parity.batch_kernel: what of a race is order-independent).
//
// both_twins: the same bug in ref<double>, ref<float> and the GPU, killed by the droplet ledger
// (ledger.*: material neither created nor lost where the model does not say so), or, for a
// conserving error of the law (capacity_doubled, in the constants both twins read), by the
// hand-derived droplet of erosion.beyer.spec.tilted_plane (spec.droplet.*). A droplet that
// takes up nothing never fills and digs without bound: in batch ordering the probe's pass piles more
// into a cell than the GPU's counters hold and ref<float> refuses the run, so that mutant runs on
// the disjoint cone, whose references run the droplets one after the other. apply_scaled changes
// the terrain by more than the droplets moved, in both twins: ledger.closure books the excess as the
// apply pass's rounding, and ledger.apply_rounding holds that rounding to what one rounding of the
// count and one of the sum may add.
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> beyer_mutants() {
  const std::vector<std::string> probe = {"erosion.beyer.mutant_probe.batch"};
  const std::vector<std::string> blur_probe = {"erosion.beyer.blur_blend.mutant_probe.batch",
                                               "erosion.beyer.ab.blur_blend.volcano.b"};
  return {
      {"erosion.beyer.gradient_swapped_corners", MutantKind::one_twin,
       "beyer_droplets.comp takes eq. 2.35's y component from the corner pairs swapped: (h11 - h10)(1-u) + "
       "(h01 - h00)u",
       {"erosion.beyer.mutant_probe.batch", "erosion.beyer.mutant_probe.race", "erosion.beyer.race.volcano"}},
      {"erosion.beyer.brush_unnormalised", MutantKind::one_twin,
       "beyer_droplets.comp erodes amount·w at each brush sample, not amount·w/Σw (eq. 2.42's normalisation lost)",
       {"erosion.beyer.mutant_probe.batch", "erosion.beyer.disjoint.cone"}},
      {"erosion.beyer.deposit_at_new_position", MutantKind::one_twin,
       "beyer_droplets.comp deposits on the samples around the droplet's new position instead of its old one", probe},
      {"erosion.beyer.sediment_not_taken_on_erosion", MutantKind::both_twins,
       "both twins erode with the brush without adding what it takes to the droplet's sediment: material destroyed",
       {"erosion.beyer.disjoint.cone"}},
      {"erosion.beyer.apply_scaled", MutantKind::both_twins,
       "both twins' batch apply adds delta·quantum·(1 + 2^-10) to each cell, not delta·quantum", probe},
      // The calibrated pair of ledger.apply_rounding's bound (Σ u·(|change| + |height after|)).
      {"erosion.beyer.apply_scaled_above_bound", MutantKind::both_twins,
       "both twins' batch apply adds delta·quantum·(1 + 2^-15) to each cell", probe},
      {.name = "erosion.beyer.apply_scaled_below_bound",
       .kind = MutantKind::both_twins,
       .description = "both twins' batch apply adds delta·quantum·(1 + 2^-23) to each cell, one rounding",
       .cases = probe,
       .must_survive = true},
      {"erosion.beyer.capacity_doubled", MutantKind::both_twins,
       "both twins take the capacity factor c_c of eq. 2.39 twice: a conserving error of the law, which no ledger "
       "sees and the hand-derived droplet does",
       {"erosion.beyer.spec.tilted_plane"}},
      {"erosion.beyer.gpu_blur_truncated", MutantKind::one_twin,
       "blur_blend.comp counts each exchange of eq. 2.43's blend in batch as int(x) quanta (toward zero), not "
       "roundEven(x): the volume is still kept, the cells are not ref<float>'s",
       blur_probe},
      {"erosion.beyer.blur_renormalised_at_border", MutantKind::both_twins,
       "both twins blend with a box blur renormalised over the samples it finds (weight c_b/(1 + open neighbours)): "
       "at the border a cell gives its neighbour more than it takes back, and the volume drifts",
       {"erosion.beyer.blur_blend.mutant_probe.batch", "erosion.beyer.blur_blend.disjoint.cone",
        "erosion.beyer.ab.blur_blend.volcano.b"}},
      {"erosion.beyer.uphill_deposit_unbounded", MutantKind::both_twins,
       "both twins deposit the whole climb Δh uphill, not min(Δh, sediment), and clamp the sediment at 0: material "
       "created",
       probe},
  };
}

}  // namespace gt
