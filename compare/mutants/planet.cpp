// Mutants of seed 002's planet twins (planet.earth_like); see compare/mutants/mutants.hpp. Each runs
// on the small planet.mutant_probe.r12 case (R = 12, 20 plates), seeds_repeat on the same planet
// with seed 3 (its first seed draws repeat a region).
//
// one_twin: bugs in the GPU twin only, killed by the parity checks: parity.offsets.gpu_vs_float
// (any bit), parity.plates.gpu_vs_cpu (any region), parity.collision.gpu_vs_float (a sign flips a
// pressure term, far beyond the error model's per-region bound), parity.voronoi.gpu_vs_cpu (a label
// farther than the exact nearest centroid), parity.plate_cycles.gpu_vs_cpu (a count off by one),
// parity.noise.gpu_vs_float (the fBm sampled at the wrong frequency), parity.elevation.float_vs_double
// (ref<float>'s smoothing in place),
// image.psnr.gpu_vs_cpu (the rendered planet's colours),
// determinism.gpu (state carried from one run into the next), partition.empty_plates.gpu and
// partition.unassigned.gpu (the GPU's own partition: a plate left without a seed, a growth stopped
// on a count too high); and the calibrated pair of the float position model in both float twins,
// parity.positions.float_vs_double.
//
// both_twins: the same bug in the reference and the shader (or in the cube sphere both share),
// killed by checks against what was asked: spec.expansion_rate.cpu (rings per cycle average to the
// rate), spec.smoothing_constant.cpu (the mean of a constant), spec.pressure_symmetry.cpu (the
// pressure of a pair both ways), partition.edge_definition.cpu (is_edge against its definition,
// written apart), partition.disconnected_plates.* (a plate grows through its own neighbours only),
// partition.empty_plates.* (a seed placed on another's region), partition.unassigned.cpu (a fill
// stopped early; the elevation then refuses the partition), mesh.invalid.planet (an index past
// the vertices: the drawing then refuses the mesh, after the mesh checks have spoken),
// topology.* (neighbour counts and symmetry of the shared table, the map's round trip),
// mesh.*.planet (the planet mesh's orientation).
//
// The fault-line planet's (planet.fault_lines, on its probe R = 12 and on its default R = 50 beside
// the Earth): the GPU's dropped fault dies by parity.votes.gpu_vs_float; the float twins' dots
// nudged beyond their error model (one_twin as the position pair above: a bug of the float twins
// that ref<double> does not share) by parity.votes_beyond_flips.{float,gpu}_vs_double; both twins'
// faults that do not pass through the centre or never lower by spec.antipodal.cpu.
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> planet_mutants() {
  const std::vector<std::string> probe = {"planet.mutant_probe.r12"};
  const std::vector<std::string> fault_cases = {"planet.fault_lines.mutant_probe.r12", "planet.fault_lines.default"};
  return {
      {"planet.jitter.gpu_swapped_axes", MutantKind::one_twin,
       "jitter.comp draws offset a on b's counter and b on a's", probe},
      {"planet.plates.gpu_highest_index", MutantKind::one_twin,
       "plate_claim.comp gives an unassigned region the highest active neighbouring plate instead of the lowest",
       probe},
      {"planet.collision.gpu_neighbour_sign", MutantKind::one_twin,
       "elevation_collision.comp projects the neighbour's chord on d instead of −d", probe},
      // The calibrated pair of the float position model (parity.positions.float_vs_double: 32u =
      // 1.9e-06), in both float twins so that only the comparison with ref<double> can see it.
      {"planet.jitter.float_off_above_bound", MutantKind::one_twin,
       "ref<float>'s and the GPU's region positions times 1 + 2^-17", probe},
      {.name = "planet.jitter.float_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s and the GPU's region positions times 1 + 2^-23, one rounding",
       .cases = probe,
       .must_survive = true},
      // The calibrated pairs of the elevation's float model, stage by stage (parity.noise,
      // parity.collision and parity.elevation .float_vs_double: reference/planet/elevation.cpp's
      // calibration_factor), in both float twins; and of the GPU's 4u model (parity.noise.gpu_vs_float).
      {"planet.noise.float_off_above_bound", MutantKind::one_twin,
       "ref<float>'s and the GPU's noisy elevation E0 times 1 + 2^-12", probe},
      {.name = "planet.noise.float_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s and the GPU's noisy elevation E0 times 1 + 2^-23, one rounding",
       .cases = probe,
       .must_survive = true},
      {"planet.collision.float_off_above_bound", MutantKind::one_twin,
       "ref<float>'s and the GPU's collision term C·Σ pressure times 1 + 2^-9", probe},
      {.name = "planet.collision.float_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s and the GPU's collision term C·Σ pressure times 1 + 2^-23, one rounding",
       .cases = probe,
       .must_survive = true},
      {"planet.smoothing.float_off_above_bound", MutantKind::one_twin,
       "ref<float>'s and the GPU's smoothed mean times 1 + 2^-12", probe},
      {.name = "planet.smoothing.float_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "ref<float>'s and the GPU's smoothed mean times 1 + 2^-23, one rounding",
       .cases = probe,
       .must_survive = true},
      {"planet.noise.gpu_off_above_bound", MutantKind::one_twin,
       "elevation_noise.comp's E0 times 1 + 2^-14", probe},
      {.name = "planet.noise.gpu_off_below_bound",
       .kind = MutantKind::one_twin,
       .description = "elevation_noise.comp's E0 times 1 + 2^-23, one rounding",
       .cases = probe,
       .must_survive = true},
      {"planet.noise.gpu_frequency_dropped", MutantKind::one_twin,
       "elevation_noise.comp samples the fBm at the region's position instead of f times it", probe},
      {"planet.smoothing.float_in_place", MutantKind::one_twin,
       "ref<float>'s Jacobi smoothing reads the neighbours before the region from its own output (Gauss-Seidel)",
       probe},
      {"planet.plates.ceil_rate", MutantKind::both_twins,
       "both twins grow ceil(rate) rings a cycle (the extra ring's draw can never win)", probe},
      {"planet.plates.thesis_rate_as_code", MutantKind::both_twins,
       "asked for the thesis's rate formula at e > 1, both twins draw rates up to the code's 1 + e instead of e",
       {"planet.rate_formula.thesis_e2"}},
      {"planet.collision.neighbour_sign", MutantKind::both_twins,
       "both twins project the neighbour's chord on d instead of −d in the code's pressure", probe},
      {"planet.plates.seeds_repeat", MutantKind::both_twins,
       "both twins take each plate's first seed draw whether or not an earlier plate holds the region (§9.2's "
       "seeds are distinct): a later plate takes the region over and the earlier one is left empty",
       {"planet.mutant_probe.r12_seed3"}},
      {"planet.plates.seeds_counted_twice", MutantKind::both_twins,
       "both twins count the seeds as assigned twice when the fill starts: it stops with regions still without a "
       "plate",
       probe},
      {"planet.plates.edges_without_diagonals", MutantKind::both_twins,
       "both twins flag a region as an edge only from its 4 cardinal neighbours, not all 8", probe},
      {"planet.smoothing.count_without_self", MutantKind::both_twins,
       "both twins' Jacobi mean sums the region but divides by its neighbours' count only", probe},
      {"planet.mesh.flipped_front_face", MutantKind::both_twins,
       "the planet mesh winds the front face's triangles clockwise, against the other five faces", probe},
      {"planet.plates.gpu_last_seed_missing", MutantKind::one_twin,
       "plate_seeds.comp stops one plate short: the last plate gets no seed and no region", probe},
      {"planet.plates.gpu_counts_visits", MutantKind::one_twin,
       "plate_claim.comp adds to the assigned count for every region it visits without a plate, claimed or not: "
       "the host stops the growth with regions still unassigned",
       probe},
      {"planet.plates.gpu_cycles_carried_over", MutantKind::one_twin,
       "the GPU's growth-cycle count, which keys the expansion draws, is not reset between runs", probe},
      {"planet.plates.gpu_cycle_count_off_by_one", MutantKind::one_twin,
       "the GPU reports one flood-fill cycle more than it ran (the plates themselves are right)", probe},
      {"planet.render.gpu_darker_palette", MutantKind::one_twin,
       "render.frag darkens the palette by |e|/2 instead of |e|/4", probe},
      {"planet.voronoi.gpu_cell_centres", MutantKind::one_twin,
       "voronoi.comp measures distances to each cell's centre (Algorithm 1's massCenterOfCell) instead of the "
       "region's jittered centroid",
       probe},
      {"planet.mesh.key_without_z", MutantKind::both_twins,
       "the planet mesh welds its corners on (X, Y) alone: corners that differ only in Z become one vertex", probe},
      {"planet.mesh.index_after_push", MutantKind::both_twins,
       "the planet mesh gives a new corner the vertex count after adding it as its index, one past its own: the "
       "last corner's triangles name a vertex that does not exist",
       probe},
      {"planet.jitter.gpu_no_warp_as_tangent", MutantKind::one_twin,
       "jitter.comp places the centroids through eq. 3.4's tan(πt/4) when no warp is asked",
       {"planet.warp.none"}},
      {"planet.cube_sphere.tangent_eighth_turn", MutantKind::both_twins,
       "eq. 3.4's plain tangent warp takes θ = π/8 instead of π/4 (core/params/planet.cpp, which both twins share)",
       {"planet.warp.tangent"}},
      {"planet.cube_sphere.unwarp_over_tan", MutantKind::both_twins,
       "the inverse warp divides by tan θ instead of θ (core/planet/cube_sphere.cpp, which both twins share)", probe},
      {"planet.cube_sphere.overshoot_doubled", MutantKind::both_twins,
       "a neighbour across a face edge is folded twice as far down the next face (the shared neighbour table)", probe},
      {"planet.cube_sphere.no_wrap", MutantKind::both_twins,
       "the shared neighbour table leaves out neighbours across the cube's edges", probe},
      // The fault-line planet (planet.fault_lines).
      {"planet.fault_lines.gpu_last_fault_skipped", MutantKind::one_twin,
       "fault_lines.comp stops one fault early: every region's votes off by one", fault_cases},
      {"planet.fault_lines.raise_only", MutantKind::both_twins,
       "both twins raise the side a plane faces and never lower the other", fault_cases},
      {"planet.fault_lines.plane_off_centre", MutantKind::both_twins,
       "both twins cut with planes 0.05 off the centre (dot > 0.05): the regions near a plane are lowered on both "
       "sides",
       fault_cases},
      {"planet.fault_lines.float_dot_nudged", MutantKind::one_twin,
       "both float twins (ref<float>, the GPU) take each dot 2^-12·Σ|n_c·p_c| too high: more planes flip than the "
       "6u error model lets flip",
       fault_cases},
  };
}

}  // namespace gt
