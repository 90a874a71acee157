// Mutants of seed 001's layered ground (erosion.layered); see compare/mutants/mutants.hpp. Each runs
// on the small probes of datasets/cases/erosion.layered.json: a steep 32×32 cone of loam over soft
// rock that comes to rest, and a 32×24 bare cliff of soft rock that falls and fragments.
//
// both_twins: the same bug in the reference (column.cpp, transfer.cpp, talus.cpp, weathering.cpp,
// water.cpp, force_erosion.cpp, diffusion.cpp) and the GPU twin (apply.comp, talus_outflow.comp,
// weathering.comp, water_move.comp, diffusion.comp; the host's counting in
// gpu/erosion/layered/{water,force_erosion}.cpp), killed by checks against what was asked, computed
// on the host: ledger.materials (each material's volume, conversions counted),
// ledger.total and ledger.conversions (fragments hold the bedrock they come from), layers.invalid
// (the topsoil's maximum), layers.surface (the surface moves with the layers), spec.repose (a
// resting slope below the repose slope of eq. 3.1, written apart) and ledger.water (the water
// against rain, river and sinks). The water's mutants run on two more probes: a cone under rain
// and a plane with the river.
//
// one_twin: a bug in the GPU twin alone, killed by a parity.shadow.<field>.gpu_vs_float check (bit for
// bit) or the end of the run's parity.<field>.max_abs.gpu_vs_float (bit for bit); the water's two
// (previous_after_move, flux_unscaled) each change one field of the water state, previous_water or
// water_flux, in the step. The GPU's own ledgers and layers.invalid.gpu see those that break what
// was asked: flux_unscaled creates water and material, deposit_without_reserve overfills the
// topsoil; types_layers_reversed changes bedrock_type, a field no twin writes, on the GPU.
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> layered_mutants() {
  const std::vector<std::string> cone = {"erosion.layered.mutant_probe.cone"};
  const std::vector<std::string> cliff = {"erosion.layered.mutant_probe.cliff"};
  const std::vector<std::string> rain = {"erosion.layered.mutant_probe.rain"};
  const std::vector<std::string> schedule = {"erosion.layered.mutant_probe.water_schedule"};
  const std::vector<std::string> river = {"erosion.layered.mutant_probe.river"};
  return {
      {"erosion.layered.gpu_gather_reversed", MutantKind::one_twin,
       "apply.comp sums the arriving fluxes from neighbour 7 down to 0 instead of 0 up to 7: the same terms, other "
       "roundings, which only a bit-exact comparison sees",
       cone},
      {"erosion.layered.gpu_deposit_without_reserve", MutantKind::one_twin,
       "column.glsl's deposit_soil (the GPU alone) adds the arriving material to the topsoil without reserving room "
       "or pushing the excess down",
       cone},
      {"erosion.layered.gpu_types_layers_reversed", MutantKind::one_twin,
       "the host uploads the bedrock layers' types to the GPU bottom layer first: the soft rock on top reads as the "
       "hard rock below it",
       cone},
      {"erosion.layered.deposit_without_reserve", MutantKind::both_twins,
       "deposit_soil adds the arriving material to the topsoil without reserving room or pushing the excess down: "
       "the topsoil grows past its maximum",
       cone},
      {"erosion.layered.surface_not_lowered", MutantKind::both_twins,
       "remove_soil takes the material from the layers but leaves the surface height where it was", cone},
      {"erosion.layered.flux_components_shifted", MutantKind::both_twins,
       "the soil–rock flux delivers each component as the next one (organic as sand, ..., boulders as organic)", cone},
      {"erosion.layered.diagonal_arrivals_dropped", MutantKind::both_twins,
       "talus and creep gather what arrives from the 4 edge neighbours only: what the diagonal ones send is lost",
       cone},
      // The calibrated pair of the float ledger's model (S·R·2u of the volume, 72u a dry step), in both
      // float twins so that only their ledgers against what was asked can see it: a creep and a talus
      // pass a step lose 2·2^-16 of the volume (7.1 times the bound) or 2·2^-22 (0.11 times).
      {"erosion.layered.float_leak_above_bound", MutantKind::one_twin,
       "ref<float> and the GPU keep 1 − 2^-16 of every stored thickness after each creep and talus pass", cone},
      {.name = "erosion.layered.float_leak_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float> and the GPU keep 1 − 2^-22 of every stored thickness after each creep and talus pass",
       .cases = cone,
       .must_survive = true},
      // The calibrated pair of ledger.conversions' model (32u of what was converted out and in):
      // fragments 2^-16 short are 2^-16/64u = 4 times it where fragmentation is all that converts.
      {"erosion.layered.fragments_short_above_bound", MutantKind::one_twin,
       "ref<float> and the GPU break fallen rock into 1 − 2^-16 of its volume", cliff},
      {.name = "erosion.layered.fragments_short_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float> and the GPU break fallen rock into 1 − 2^-22 of its volume",
       .cases = cliff,
       .must_survive = true},
      {"erosion.layered.repose_doubled", MutantKind::both_twins,
       "talus takes every soil layer's repose slope twice as steep as eq. 3.1 gives", cone},
      {"erosion.layered.weathering_loses_organic", MutantKind::both_twins,
       "weathering takes the sand that roots turn organic out of the sand, counts it, and never adds it to the "
       "organic matter",
       cone},
      {"erosion.layered.fragments_without_boulders", MutantKind::both_twins,
       "fallen bedrock breaks into gravel and stones only: the boulders' share is lost", cliff},
      {"erosion.layered.gpu_previous_after_move", MutantKind::one_twin,
       "water_move.comp records the depth after the move as the previous depth, not the depth before it", rain},
      {"erosion.layered.gpu_flux_unscaled", MutantKind::one_twin,
       "water_flux.comp never scales the fluxes down to what a column holds (no column is drained)", rain},
      {"erosion.layered.gpu_drained_keeps_rest", MutantKind::one_twin,
       "water_move.comp ignores that a column was drained and keeps the rounding residue of q − Σ q·f_k, as the "
       "reference does not",
       rain},
      {"erosion.layered.sediment_stays_behind", MutantKind::both_twins,
       "the pipe flow sends what the water carries out of each column with the water, but no column gathers it", rain},
      {"erosion.layered.rain_uncounted", MutantKind::both_twins,
       "the rain falls on every column, and the ledger is never told", rain},
      {"erosion.layered.drain_water_uncounted", MutantKind::both_twins,
       "the drain empties every column, and the ledger is told of the sediment but not of the water", schedule},
      {"erosion.layered.gpu_rain_past_its_steps", MutantKind::one_twin,
       "water_sources.comp lets the rain fall on every step, past rain_steps", schedule},
      {"erosion.layered.breakdown_uncounted", MutantKind::both_twins,
       "force erosion breaks larger fragments into smaller suspended ones without counting the conversion", rain},
      {"erosion.layered.impact_never_delivered", MutantKind::both_twins,
       "impact erosion takes the bank's material into its pipes toward the water that hit it, and the water never "
       "receives it",
       rain},
      {"erosion.layered.gpu_diffusion_skips_regolith", MutantKind::one_twin,
       "diffusion.comp diffuses the suspended sediment but never the regolith, which regolith_diffusion asks for", rain},
      {"erosion.layered.diffusion_sent_kept", MutantKind::both_twins,
       "sediment diffusion sends each column's shares to its neighbours and keeps them as well: material is created",
       rain},
      {"erosion.layered.sinks_uncounted", MutantKind::both_twins,
       "the river's sink rows take the water's sediment out of the ground without counting it", river},
  };
}

}  // namespace gt
