// Mutants of the particle (droplet) erosion twins (erosion.particle); see compare/mutants/mutants.hpp.
// They run on datasets/cases/erosion.particle.json's probe (a noisy 48x48 cone, batch droplets at
// spacing 2, 3 iterations) and its hand-derived droplets (spec.ramp, spec.bounded_bite).
//
// one_twin: bugs in particle_droplets.comp only, killed by the batch ordering's bit-for-bit parity
// (parity.shadow.terrain[.multi], parity.cells_differing, for colour parity.colour.* and for the
// flow map parity.flow.*: the GPU against ref<float>, bound 0) and, on the disjoint cone, by the
// disjoint ordering's rounding bound (parity.shadow.terrain); fall_through_acceleration also in race
// ordering, on the race probe and on the volcano (a real DEM), by the race's graded batch iteration
// (parity.batch_kernel: what of a race is order-independent).
//
// both_twins: the same bug in ref<double>, ref<float> and the GPU, killed by checks against what
// was asked: the hand-derived droplet of the ramp (spec.droplet.*), the droplet ledger (ledger.*:
// material neither created nor lost where the kernel does not say so) and colour.created (blends
// stay within the colours they mix).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> particle_mutants() {
  const std::vector<std::string> probe = {"erosion.particle.mutant_probe.batch"};
  const std::vector<std::string> colour_probe = {"erosion.particle.mutant_probe.colour"};
  const std::vector<std::string> probe_and_spec = {"erosion.particle.mutant_probe.batch", "erosion.particle.spec.ramp"};
  return {
      {"erosion.particle.fall_through_acceleration", MutantKind::one_twin,
       "particle_droplets.comp accelerates as Algorithm 4 is printed (if/else-if fall-through) instead of upstream's "
       "nested branches: a droplet moving +x whose drop ahead exceeds drop_max accelerates towards -x",
       {"erosion.particle.mutant_probe.batch", "erosion.particle.mutant_probe.colour",
        "erosion.particle.mutant_probe.race", "erosion.particle.race.volcano"}},
      {"erosion.particle.deposit_beside", MutantKind::one_twin,
       "particle_droplets.comp deposits at the texel to the droplet's +x side instead of its own",
       {"erosion.particle.mutant_probe.batch", "erosion.particle.disjoint.cone"}},
      {"erosion.particle.corner_weights_swapped", MutantKind::one_twin,
       "particle_droplets.comp swaps the bilinear weights of the (+1, 0) and (0, +1) corners of Algorithm 6", probe},
      {"erosion.particle.colour_mixing_reversed", MutantKind::one_twin,
       "particle_droplets.comp picks up colour on erosion as (1 - f_col)·C(ipos) + f_col·col, eq. 4.9's weights "
       "swapped",
       colour_probe},
      {"erosion.particle.colour_deposit_unweighted", MutantKind::one_twin,
       "particle_droplets.comp blends each of Algorithm 8's 4 corners with f_col instead of f_col·w", colour_probe},
      {"erosion.particle.flow_corner_weights_swapped", MutantKind::one_twin,
       "flow_map_droplets.comp swaps the bilinear weights of the (+1, 0) and (0, +1) corners where a droplet leaves "
       "its concentration (eq. 4.12 over erode4's corners)",
       probe},
      {"erosion.particle.colour_kept_whole", MutantKind::both_twins,
       "both twins blend a colour deposit as C + col·factor, keeping all of the texel's colour: colour created",
       colour_probe},
      {"erosion.particle.rescaled_velocity", MutantKind::both_twins,
       "both twins rescale every non-zero velocity to v_max (Algorithm 5 as printed) instead of clamping it",
       probe_and_spec},
      {"erosion.particle.kept_sediment_on_deposit", MutantKind::both_twins,
       "both twins deposit without taking the deposit off the droplet's sediment: material created", probe_and_spec},
      {"erosion.particle.step_by_velocity", MutantKind::both_twins,
       "both twins move a droplet by its velocity instead of one texel along its direction", probe_and_spec},
      {"erosion.particle.unbounded_erosion", MutantKind::both_twins,
       "both twins erode bite·(capacity - sediment) without bounding it by the height above the lowest neighbour",
       {"erosion.particle.spec.bounded_bite"}},
  };
}

}  // namespace gt
