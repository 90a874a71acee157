// Mutants of the noise twins; see compare/mutants/mutants.hpp. The bugs live in
// gpu/shaders/noise/*.glsl (#ifdef GT_MUTANT_NOISE_...) and, for both_twins, also in
// reference/noise/* (mutant_active("noise....")); the float precision model's calibrated pair is in
// both float twins (ref<float> and the GPU), graded against ref<double>. Cases are the small ones of
// datasets/cases/noise.json (at most 160 x 128 samples, one GPU dispatch each).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> noise_mutants() {
  return {
      // One twin (the GPU shader): the twins disagree, parity.*.gpu_vs_float fails.
      {"noise.simplex3.gpu_skew", MutantKind::one_twin,
       "GLSL 3-D simplex skews with the 2-D factor (sqrt(3) - 1)/2 instead of 1/3",
       {"noise.simplex3.spec.digest_vectors"}},
      {"noise.simplex2.gpu_kernel", MutantKind::one_twin,
       "GLSL 2-D simplex uses seed 004's 3-D kernel radius² 0.6 instead of 0.5",
       {"noise.simplex2.near_origin"}},
      {"noise.perlin3.gpu_smoothstep_fade", MutantKind::one_twin,
       "GLSL improved Perlin fades with Perlin 1985's 3t² - 2t³ instead of 6t⁵ - 15t⁴ + 10t³",
       {"noise.perlin3.near_origin"}},
      {"noise.perlin3_texture.gpu_decode", MutantKind::one_twin,
       "GLSL texture Perlin decodes gradients as rgb·2 - 1 (the usual unorm decode) instead of rgb·4 - 1",
       {"noise.perlin3_texture.near_origin"}},
      {"noise.hetero_terrain.gpu_tile_shift_by_width", MutantKind::one_twin,
       "GLSL's tileable blend takes the samples above one grid width up instead of one grid height",
       {"terrain.hetero_terrain.seed001_tileable"}},
      {"noise.fbm.gpu_octave_shift", MutantKind::one_twin,
       "GLSL fBm starts at p·lacunarity: every octave one lacunarity too high",
       {"noise.fbm.perlin3"}},
      {"noise.voronoi.gpu_jitter_uncentred", MutantKind::one_twin,
       "GLSL places each cell's feature point at P/256 instead of (P + 1/2)/256: every point half a 1/256 step "
       "towards the cell's corner",
       {"noise.voronoi_f1.near_origin", "terrain.hetero_terrain.voronoi_f2f1"}},
      {"noise.cell.gpu_unit_interval", MutantKind::one_twin,
       "GLSL cell noise returns the unsigned value (P + 1/2)/256 instead of 2·that − 1",
       {"noise.cell_noise.near_origin"}},
      // The calibrated pair of the float precision model (parity.max_abs.float_vs_double: 4.42e-05
      // on this case): both float twins' samples 2^-13 high (1.22e-04, 2.8 times the bound) are
      // killed; 2^-17 high (7.6e-06 on top of the honest 4.1e-06) survive.
      {"noise.perlin3.float_off_above_bound", MutantKind::one_twin,
       "ref<float>'s and the GPU's samples 2^-13 above the noise", {"noise.perlin3.near_origin"}},
      {.name = "noise.perlin3.float_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s and the GPU's samples 2^-17 above the noise",
       .cases = {"noise.perlin3.near_origin"},
       .must_survive = true},
      // Both twins: they agree, a spec check against published values or an invariant fails.
      {"noise.hetero_terrain.tile_weights_mirrored", MutantKind::both_twins,
       "both twins' tileable blend weighs the sample one grid to the right by c_x and its own by 1 − c_x: the field "
       "no longer repeats",
       {"terrain.hetero_terrain.seed001_tileable"}},
      {"noise.simplex3.grad3_swapped", MutantKind::both_twins,
       "grad3's first two entries (1,1,0) and (-1,1,0) exchanged in both twins (2-D and 3-D simplex)",
       {"noise.simplex3.spec.digest_vectors"}},
      {"noise.perlin3.grad_select", MutantKind::both_twins,
       "Grad's second axis is x for h = 12 or 13 (typo for 14) in both twins: two of Perlin's gradients move",
       {"noise.perlin3.near_origin"}},
      {"noise.perlin3.fade_square", MutantKind::both_twins,
       "the fade curve has t² where t³ belongs (t²(6t² - 15t + 10)) in both twins",
       {"noise.perlin3.near_origin"}},
      {"noise.perlin3.unit_interval", MutantKind::both_twins,
       "both twins store v/2 + 1/2, the texture convention, instead of the noise v centred on 0",
       {"noise.perlin3.near_origin"}},
      {"noise.fbm.gain_before_sample", MutantKind::both_twins,
       "fBm multiplies the amplitude by the gain before adding its octave in both twins (octave k weighs gain^(k+1))",
       {"noise.fbm.perlin3"}},
      {"noise.ridged.unclamped_weight", MutantKind::both_twins,
       "the ridged multifractal's weight feedback signal·gain is not clamped to [0, 1] in both twins",
       {"noise.ridged.perlin3"}},
      {"noise.voronoi.squared_distance", MutantKind::both_twins,
       "both twins rank and return squared distances to the feature points (Blender's \"distance squared\" metric "
       "taken for the Euclidean one)",
       {"noise.voronoi_f2.near_origin", "terrain.hetero_terrain.voronoi_f2f1"}},
      {"noise.cell.value_from_jitter_hash", MutantKind::both_twins,
       "both twins read cell noise's value from the entry of the feature point's x jitter, P[h], instead of its own, "
       "P[h + 128]",
       {"noise.cell_noise.near_origin"}},
  };
}

}  // namespace gt
