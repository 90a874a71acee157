// Mutants of the render twins; see compare/mutants/mutants.hpp. Each runs on small probe cases of
// datasets/cases/render.json and render.terrain.json (64-pixel images of a quad, a tent and a cone;
// closed-form answers in compare/algorithms/render_probe.hpp):
//   one twin (killed by image.* or parity.*): a GLSL constant or rule changed in the shader only, or
//     the reference rasterizer's edge rule mirrored;
//   both twins (killed by spec.*): the same bug in the reference and the shader, caught by the
//     closed-form colours of the quad (spec.phong_quad.*) or heights and footprint of the tent
//     (spec.tent_*).
#include "compare/mutants/mutants.hpp"

namespace gt {

std::vector<Mutant> render_mutants() {
  const std::vector<std::string> quad = {"render.phong.mutant_probe.quad"};
  const std::vector<std::string> tent = {"render.heightmap_from_mesh.mutant_probe.tent"};
  return {
      {"render.phong.specular_exponent_gpu", MutantKind::one_twin,
       "GLSL Phong only: specular exponent 10 instead of the seed's 5 (highlights narrower and dimmer)", quad},
      {"render.phong.no_falloff_gpu", MutantKind::one_twin,
       "GLSL Phong only: irradiance = light power, the 1/d² falloff dropped", quad},
      {"render.phong.cave_moss_threshold_gpu", MutantKind::one_twin,
       "GLSL cave look only: moss on normals with n_y > 0.5 instead of n_y > 0",
       {"render.phong.mutant_probe.cave_quad"}},
      {"render.terrain.ramp_reversed_gpu", MutantKind::one_twin,
       "GLSL terrain look only: the height ramp read from the top (h -> 1 - h), snow at the foot",
       {"render.terrain.mutant_probe.cone"}},
      {"render.heightmap_from_mesh.draw_order_gpu", MutantKind::one_twin,
       "GLSL heightmap only: every fragment writes depth 0, so the first surface drawn stays instead of the highest",
       tent},
      {"render.heightmap_from_mesh.right_edges_owned", MutantKind::one_twin,
       "reference rasterizer only: pixel centres on an edge belong to the triangle on its left (right edges owned) "
       "instead of GL's left-edge rule as llvmpipe applies it",
       tent},
      // On a real mesh: the first third of the bunny's triangles leaves whole patches of its
      // footprint uncovered, far from any silhouette (the tent's base alone covers its footprint).
      {"render.heightmap_from_mesh.gpu_count_in_triangles", MutantKind::one_twin,
       "GPU only: glDrawElements given the triangle count where it wants the index count (a third is drawn)",
       {"render.heightmap_from_mesh.bunny00"}},
      {"render.phong.no_ambient", MutantKind::both_twins,
       "both twins: the ambient term K_a = 0.1 dropped", quad},
      {"render.phong.specular_exponent", MutantKind::both_twins,
       "both twins: specular exponent 10 instead of the seed's 5", quad},
      {"render.phong.facing_reversed", MutantKind::both_twins,
       "both twins: the two-sided normal turned away from the viewer instead of towards it", quad},
      {"render.phong.vertical_flip", MutantKind::both_twins,
       "both twins: the picture upside down (reference rows read bottom first, GL clip y negated)", quad},
      // The camera inside the cave must see rock on 95 % of the picture (image.uncovered_share.cpu):
      // looking back along the tunnel it sees out of the block.
      {"render.phong.camera_faces_away", MutantKind::both_twins,
       "both twins: the look-at's forward direction taken from the target to the eye (the camera looks away)",
       {"render.cave.tunnel.start"}},
      {"render.heightmap_from_mesh.lowest_surface", MutantKind::both_twins,
       "both twins: the depth is 1 - z' (the box seen from below), so the lowest surface is kept", tent},
      {"render.heightmap_from_mesh.rows_flipped", MutantKind::both_twins,
       "both twins: grid row 0 is the smallest y (north and south swapped)", tent},
  };
}

}  // namespace gt
