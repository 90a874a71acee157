// Mutants of the pipe twins (erosion.pipe); see compare/mutants/mutants.hpp. Each runs on the
// small probe cases of datasets/cases/erosion.pipe.json (48×48 cells, 40 steps, 8 checkpoints).
//
// one_twin: bugs in the GPU shaders only, killed by the shadow-step parity (parity.shadow.*: the
// GPU loaded with ref<float>'s state and stepped beside it), on the probe and on a real DEM. Each
// changes a field by a share of its own size in one step, far above the per-cell a-priori bound of
// compare/checks/pipe_error_model.hpp (the roundings of the step at that cell). A bug of a few ulps
// (a biased division) would hide under that bound, which allows GLSL's 2.5-ulp division: none is
// registered.
//
// both_twins: the same bug in ref<double>, ref<float> and the GPU, killed by checks against what
// was asked, computed on the host: mass.water_added.* (rain, rain map and sources asked for),
// mass.evaporation.* (K_e·Δt of the water held), mass.material_drift.* (the flux form
// conserves material), mass.water_balance.* (the water held against what was added, evaporated and
// let out), stability.max_cfl.* (the K scaling keeps Δt·|u|/l at most 1) and
// stability.pipe_wave_number (the scheme's gravity waves, from the constants alone). Bugs that
// conserve water and material (a capacity twice K_c, K_s and K_d exchanged, the tilt's central
// difference over l instead of 2l) pass every ledger: spec.step.* kills them, ref<double>'s step held
// cell by cell to a host spec of the step (compare/algorithms/pipe_spec.hpp), on the probe and on
// the volcano (whose equal K_s and K_d hide the exchange: the probe alone shows it).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> pipe_mutants() {
  const std::vector<std::string> flux_probe = {"erosion.pipe.mutant_probe.flux"};
  const std::vector<std::string> semi_lagrangian_probe = {"erosion.pipe.mutant_probe.semi_lagrangian"};
  // The one-twin mutants also on a real DEM (its per-cell shadow bounds, not a probe's, must see them).
  const std::vector<std::string> flux_probe_and_dem = {"erosion.pipe.mutant_probe.flux", "erosion.pipe.seed001.volcano"};
  const std::vector<std::string> semi_lagrangian_probe_and_dem = {"erosion.pipe.mutant_probe.semi_lagrangian",
                                                                  "erosion.pipe.semi_lagrangian.volcano_open"};
  const std::vector<std::string> flux_probe_and_volcano = {"erosion.pipe.mutant_probe.flux", "erosion.pipe.flux.volcano"};
  // MacCormack transport: its probe, and the volcano's A/B pair (whose B side runs it).
  const std::vector<std::string> maccormack_probe_and_dem = {"erosion.pipe.mutant_probe.maccormack",
                                                             "erosion.pipe.ab.maccormack.volcano_open.b"};
  return {
      {"erosion.pipe.gpu_maccormack_unhalved", MutantKind::one_twin,
       "pipes_maccormack.comp adds the whole difference φ − φ̌ to the backtrace instead of half of it",
       maccormack_probe_and_dem},
      {"erosion.pipe.maccormack_correction_negated", MutantKind::both_twins,
       "both twins subtract MacCormack's correction ½(φ − φ̌) from the backtrace instead of adding it (reference and "
       "pipes_maccormack.comp); the limiter keeps the result in range, and no ledger bounds a transport that does not "
       "conserve",
       maccormack_probe_and_dem},
      {"erosion.pipe.gpu_drops_bottom_pipe", MutantKind::one_twin,
       "pipes_outflow.comp never gives the B pipe a flux (a loop bound or a skipped direction)", flux_probe_and_dem},
      {"erosion.pipe.gpu_velocity_without_half", MutantKind::one_twin,
       "pipes_flow.comp takes ΔW_X = (f_in,L − f_L) + (f_R − f_in,R) without Mei's ½, doubling u, v and the capacity",
       flux_probe_and_dem},
      {"erosion.pipe.gpu_gather_wrong_pipe", MutantKind::one_twin,
       "pipes_sediment.comp gathers the sediment a neighbour sent down its pipe k instead of the opposite pipe "
       "(towards this cell)",
       flux_probe_and_dem},
      {"erosion.pipe.gpu_backtrace_downstream", MutantKind::one_twin,
       "pipes_sediment.comp backtraces the semi-Lagrangian sediment along +u·Δt (downstream) instead of −u·Δt",
       semi_lagrangian_probe_and_dem},
      // The calibrated pair of the shadow steps' interval model (compare/checks/pipe_error_model.hpp):
      // on the probe a GPU u 2^-16 too large lands at 4.3 times the bound of
      // parity.shadow.velocity_x.gpu_vs_float (2^-15: 8.6 times; seed001.volcano: 1.4 times) and
      // must be killed; u one ulp high lands at 0.11 times it (seed001.volcano: 0.18) and must survive.
      {"erosion.pipe.velocity_off_above_bound", MutantKind::one_twin,
       "pipes_flow.comp scales u by 1 + 2^-16", flux_probe_and_dem},
      {.name = "erosion.pipe.velocity_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "pipes_flow.comp leaves u one ulp high (times 1 + 2^-23)",
       .cases = flux_probe_and_dem,
       .must_survive = true},
      {"erosion.pipe.unscaled_outflow", MutantKind::both_twins,
       "the outflow is never scaled by K (eq. 2.12 skipped): a cell may send more water than it holds (ref "
       "update_outflow, pipes_outflow.comp)",
       flux_probe},
      {"erosion.pipe.gravity_in_cgs", MutantKind::both_twins,
       "g taken in cm/s² (981) where the pipe model works in metres (core/params/hydraulic.cpp, which both twins read)",
       flux_probe},
      {"erosion.pipe.half_rain", MutantKind::both_twins,
       "the rain pass adds Δt·(r + r_map)/2 (ref add_water, pipes_water.comp)", flux_probe},
      {"erosion.pipe.double_evaporation", MutantKind::both_twins,
       "evaporation keeps d·(1 − 2·K_e·Δt) (ref evaporate, pipes_sediment.comp)", flux_probe},
      {"erosion.pipe.source_over_length", MutantKind::both_twins,
       "a point source's depth is rate·Δt/l_x instead of rate·Δt/(l_x·l_y) (both twins' source_depths)",
       flux_probe},
      {"erosion.pipe.sediment_gain_doubled", MutantKind::both_twins,
       "erosion adds 2·k_s·(C − s) to the sediment while the bed loses k_s·(C − s) (ref erode_and_deposit, "
       "pipes_flow.comp)",
       flux_probe},
      {"erosion.pipe.capacity_doubled", MutantKind::both_twins,
       "the capacity constant is taken as 2·K_c (core/params/hydraulic.cpp's pipe_constants, which both twins read): "
       "twice the erosion, material still conserved",
       flux_probe_and_volcano},
      {"erosion.pipe.rates_swapped", MutantKind::both_twins,
       "K_s and K_d exchanged in pipe_constants: dissolving at the deposition rate and depositing at the dissolving "
       "rate, material still conserved",
       flux_probe},
      {"erosion.pipe.tilt_unhalved", MutantKind::both_twins,
       "the tilt's central difference b(x+1) − b(x−1) divided by l, not 2l (core/params/hydraulic.cpp's tilt_span, "
       "which both twins read): sin α about twice too large on gentle slopes, material still conserved",
       flux_probe_and_volcano},
      {"erosion.pipe.regolith_deepest", MutantKind::both_twins,
       "r_max = max(d_B, K_r) instead of min (ref regolith_exchange, pipes_flow.comp): the water loosens the bed "
       "down to its own depth, material still conserved",
       {"erosion.pipe.seed001.volcano"}},
      // Šťava's layers: a GPU-only bug of where the deposit settles, on the probe of three layers and
      // on the volcano; and eq. 2.29 left out of both twins' walk, which conserves material: only the
      // spec of the step sees it.
      {"erosion.pipe.gpu_deposit_on_bottom_layer", MutantKind::one_twin,
       "pipes_flow.comp puts the deposit k_d·(s − T_N) on layer 1 instead of the top layer N",
       {"erosion.pipe.layers.mutant_probe", "erosion.pipe.ab.layer_erosion.volcano.a"}},
      {"erosion.pipe.layers_above_ignored", MutantKind::both_twins,
       "both twins compare T_k with s instead of T̂_k = T_k − Σ_{i>k} b_i (eq. 2.29 left out; ref layered_exchange, "
       "pipes_flow.comp): the water erodes deeper layers at their full capacity, material still conserved",
       {"erosion.pipe.layers.mutant_probe", "erosion.pipe.ab.layer_erosion.volcano.a"}},
      // The calibrated pair of the spec step's error model (rounding-interval widths at double's
      // unit): on the probe a capacity 2^-41 too large lands at 5.3 times the bound of
      // spec.step.terrain.cpu (2^-40: 10 times, 2^-38: 42 times) and must be killed; 2^-52, one
      // ulp of K_c, lands at 0.33 times it (the honest run: 0.37) and must survive.
      {"erosion.pipe.capacity_off_above_bound", MutantKind::both_twins,
       "the capacity constant is taken as K_c·(1 + 2^-41) in pipe_constants", flux_probe},
      {.name = "erosion.pipe.capacity_off_below_bound",
       .kind = MutantKind::both_twins,
       .description = "the capacity constant is taken as K_c·(1 + 2^-52), one ulp off, in pipe_constants",
       .cases = flux_probe,
       .must_survive = true},
  };
}

}  // namespace gt
