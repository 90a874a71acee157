// The symmetric Hausdorff distance of two keyed cave meshes of one lattice (their vertices carry
// lattice edge keys: cave_mesh.hpp), measured where the meshes differ (issue 17: CGAL's sampling
// of two whole 128³ meshes of 4.9 million triangles took 42 s).
//
// Inputs: meshes a and b with edge_keys, positions in lattice units. Output: the distance in
// lattice units, with its parts.
//
//   twins              a triangle in both meshes (the same key triple, cave_mesh.hpp's
//                      key_triangles) whose corners lie within moved_corner = 0.1 of its twin's:
//                      each of its points lies as close to the twin's point of the same barycentric
//                      coordinates, so the twins add at most their largest corner distance, an
//                      exact bound rather than a sample.
//   sampled triangles  the others (in one mesh only, or a twin whose corner moved farther: up to √3
//                      along a lattice edge where a sample sits at the threshold) are sampled by
//                      CGAL (approximate_one_sided_hausdorff_distance, grid spacing 0.1 lattice
//                      units, coarser to keep about 2·10⁵ samples) against the other mesh's
//                      triangles near them: those whose cube (triangle_cube) lies within reach = 2
//                      lattice units of a sampled triangle's cube. Each triangle lies in its cube
//                      (up to 0.25 of rounding, checked), so a nearest point within 1.5 of a sample
//                      belongs to such a triangle and is the one CGAL finds against the whole
//                      mesh; when a sample lies farther, or a mesh breaks the argument (a triangle
//                      without keys, or out of its cube), the whole other mesh is used.
// distance = max(twins' bound, both one-sided sampled distances): an upper bound where the meshes
// agree and CGAL's sampling where they do not. Empty against non-empty is infinite.
#pragma once

#include <cstddef>

#include "core/mesh.hpp"

namespace gt {

struct KeyedHausdorff {
  double distance = 0.0;
  double shared_bound = 0.0;          // the twins' largest corner distance
  double sampled_distance = 0.0;      // the larger one-sided distance of the sampled triangles
  std::size_t sampled_triangles = 0;  // of a plus of b
  double grid_spacing = 0.0;          // of CGAL's samples, lattice units
  bool whole_mesh_fallback = false;   // measured against a whole mesh on at least one side
};

KeyedHausdorff keyed_hausdorff(const Mesh& a, const Mesh& b);

}  // namespace gt
