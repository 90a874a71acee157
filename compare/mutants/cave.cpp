// Mutants of the cave twins; see compare/mutants/mutants.hpp. The bugs live in
// gpu/shaders/cave/{tetrahedra,lattice}.glsl (#ifdef GT_MUTANT_CAVE_...) and, for both_twins, also
// in reference/cave/{marching_tetrahedra,lattice_cubes}.cpp (mutant_active("cave....")). Cases are
// the small probe blocks of datasets/cases/cave.json (8³ to 12³ cells: CGAL and OpenMesh on a few
// thousand triangles per backend).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> cave_mutants() {
  return {
      // One twin (the GPU shaders): the GPU mesh leaves ref<float>'s, parity.*.gpu_vs_float fails.
      {"cave.marching_tetrahedra.gpu_case_flipped", MutantKind::one_twin,
       "GLSL case table: code 1's triangle written (e01, e03, e02) instead of (e01, e02, e03), wound into the rock",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {"cave.marching_tetrahedra.gpu_t_from_upper", MutantKind::one_twin,
       "GLSL edge parameter t = (θ - v_b)/(v_a - v_b) measured from the upper end but applied from the lower",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {"cave.marching_tetrahedra.gpu_threshold_inclusive", MutantKind::one_twin,
       "GLSL rock test density <= threshold instead of < (samples exactly at the threshold become rock)",
       {"cave.marching_tetrahedra.open.block12"}},
      {"cave.marching_tetrahedra.gpu_normals_forward_difference", MutantKind::one_twin,
       "GLSL central_normals.comp differences f(p + h) − f(p) (forward) instead of f(p + h) − f(p − h)",
       {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.open.block12"}},
      {"cave.marching_tetrahedra.gpu_kuhn_vertex", MutantKind::one_twin,
       "GLSL Kuhn split: tetrahedron T0 written {0,1,5,7} (T1's corners) instead of {0,1,3,7}",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      // The calibrated pair of the float density's a-priori bound (parity.density.float_vs_double:
      // the noise module's float model, 0.00707 on this probe, kernel 0.6): the float samples off by
      // 2^-5 (0.0313: 4.4 times the bound) are killed; divided by the scale instead of multiplied by
      // its float reciprocal, an honest variant within a rounding, they survive.
      {"cave.marching_tetrahedra.float_density_off_above_bound", MutantKind::one_twin,
       "ref<float>'s density samples, which the GPU meshes too, 2^-5 above the noise",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {.name = "cave.marching_tetrahedra.float_density_divided_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s density divides the coordinates by the scale instead of multiplying them by its "
                      "float reciprocal",
       .cases = {"cave.marching_tetrahedra.mutant_probe.solid8"},
       .must_survive = true},
      // The calibrated pair of the vertex model (parity.vertex_model.float_vs_double: the float
      // roundings of t and of the position against ref<double>'s mesher on the same samples): t
      // 2^-18 too large is killed; one ulp too large, an honest rounding, survives.
      {"cave.marching_tetrahedra.float_t_off_above_bound", MutantKind::one_twin,
       "ref<float> places each vertex at t + 2^-18 along its edge",
       {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.open.block12"}},
      {.name = "cave.marching_tetrahedra.float_t_one_ulp_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float> places each vertex one ulp of t further along its edge",
       .cases = {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.open.block12"},
       .must_survive = true},
      // Both twins: they agree; a mesh invariant (mesh.*) or the vertices against the field
      // (spec.vertex_crossing.cpu) fails.
      {"cave.marching_tetrahedra.winding_reversed", MutantKind::both_twins,
       "every triangle's corners taken 0, 2, 1 in both twins: normals point into the rock",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {"cave.marching_tetrahedra.complement_unreversed", MutantKind::both_twins,
       "case 9 = 15 - 6 copied from case 6 without reversing its quad in both twins",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {"cave.marching_tetrahedra.quad_half", MutantKind::both_twins,
       "case 5's quad emits only its first triangle in both twins (triangle count 1): holes",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      {"cave.marching_tetrahedra.triangle_doubled", MutantKind::both_twins,
       "code 1's triangle emitted twice in both twins (its fan runs one step too far, from the start again)",
       {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.open.block12"}},
      {"cave.marching_tetrahedra.fan_one_too_many", MutantKind::both_twins,
       "code 1's fan runs one step too far in both twins: a second triangle (first, last, last), a repeated corner",
       {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.open.block12"}},
      {"cave.marching_tetrahedra.threshold_negated", MutantKind::both_twins,
       "the threshold's sign flipped in both meshers (rock iff density < -θ)",
       {"cave.marching_tetrahedra.mutant_probe.solid8_threshold"}},
      {"cave.marching_tetrahedra.vertex_numbers_from_one", MutantKind::both_twins,
       "the triangles' vertex indices counted from 1 (as an OBJ file counts them) in a 0-based buffer, in both twins",
       {"cave.marching_tetrahedra.mutant_probe.solid8", "cave.marching_tetrahedra.solid.block12"}},
      {"cave.marching_tetrahedra.vertex_wrong_end", MutantKind::both_twins,
       "the vertex placed at 1 - t, measured from the upper end of its edge, in both twins",
       {"cave.marching_tetrahedra.mutant_probe.solid8"}},
      // Midpoint placement (the seed's marching cubes' choice, offered to the tetrahedra).
      {"cave.marching_tetrahedra.gpu_midpoint_off", MutantKind::one_twin,
       "lattice.glsl places a midpoint vertex a quarter along its edge", {"cave.marching_tetrahedra.mutant_probe.solid8_midpoint"}},
      {"cave.marching_tetrahedra.midpoint_off", MutantKind::both_twins,
       "both twins place a midpoint vertex a quarter along its edge",
       {"cave.marching_tetrahedra.mutant_probe.solid8_midpoint"}},
  };
}

}  // namespace gt
