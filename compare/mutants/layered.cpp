// Mutants of seed 001's layered ground (erosion.layered); see compare/mutants/mutants.hpp. Each runs
// on the small probes of datasets/cases/erosion.layered.json: a steep 32×32 cone of loam over soft
// rock that comes to rest, and a 32×24 bare cliff of soft rock that falls and fragments.
//
// both_twins: the same bug in the reference (column.cpp, transfer.cpp, talus.cpp, weathering.cpp)
// and the shaders (apply.comp, talus_outflow.comp, weathering.comp), killed by checks against what
// was asked, computed on the host: ledger.materials (each material's volume, conversions counted),
// ledger.total and ledger.conversions (fragments hold the bedrock they come from), layers.invalid
// (the topsoil's maximum), layers.surface (the surface moves with the layers) and spec.repose (a
// resting slope below the repose slope of eq. 3.1, written apart).
//
// one_twin: a bug in the GPU twin alone, killed by parity.state.gpu_vs_float (bit for bit).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> layered_mutants() {
  const std::vector<std::string> cone = {"erosion.layered.mutant_probe.cone"};
  const std::vector<std::string> cliff = {"erosion.layered.mutant_probe.cliff"};
  return {
      {"erosion.layered.gpu_gather_reversed", MutantKind::one_twin,
       "apply.comp sums the arriving fluxes from neighbour 7 down to 0 instead of 0 up to 7: the same terms, other "
       "roundings, which only a bit-exact comparison sees",
       cone},
      {"erosion.layered.deposit_without_reserve", MutantKind::both_twins,
       "deposit_soil adds the arriving material to the topsoil without reserving room or pushing the excess down: "
       "the topsoil grows past its maximum",
       cone},
      {"erosion.layered.surface_not_lowered", MutantKind::both_twins,
       "remove_soil takes the material from the layers but leaves the surface height where it was", cone},
      {"erosion.layered.flux_components_shifted", MutantKind::both_twins,
       "the soil–rock flux delivers each component as the next one (organic as sand, ..., boulders as organic)", cone},
      {"erosion.layered.repose_doubled", MutantKind::both_twins,
       "talus takes every soil layer's repose slope twice as steep as eq. 3.1 gives", cone},
      {"erosion.layered.weathering_loses_organic", MutantKind::both_twins,
       "weathering takes the sand that roots turn organic out of the sand, counts it, and never adds it to the "
       "organic matter",
       cone},
      {"erosion.layered.fragments_without_boulders", MutantKind::both_twins,
       "fallen bedrock breaks into gravel and stones only: the boulders' share is lost", cliff},
  };
}

}  // namespace gt
