// `groundtruth compare-mesh A B [--json] [--out DIR] [--tolerance T] [--spacing S]`: how and where
// two triangle mesh files differ (OFF, OBJ, PLY, STL; core/io/mesh_io.hpp) — a user's mesher against
// ours, two versions of one, a mesh before and after a repair.
//
// Compares:
//   topology   each mesh's check-mesh facts (compare/checks/mesh.hpp): watertight and oriented,
//              closed, components, genus, Euler characteristic; the ones that differ are listed
//   distance   CGAL's approximate one-sided Hausdorff distance both ways (grid sampling every S,
//              by default 1/200 of the larger bounding-box diagonal) and the symmetric one (the
//              larger), beside the exact distance of every vertex to the other surface
//              (compare/checks/mesh.hpp vertex_distances)
//   where      the ten vertices of each mesh farthest from the other surface: index, position,
//              distance and the nearest point there; with --out DIR, DIR/a_to_b.ply and
//              DIR/b_to_a.ply, each mesh coloured by its vertices' distance (heat map, white at
//              the symmetric distance) with the distance as a vertex property, for any mesh viewer
// Prints a paragraph on stdout, or with as_json one object with every number. DIR is written as a
// report folder is (compare/output_folder.hpp): staged, renamed, never over a user's files.
// Exit status: 0 the topology agrees and (with a tolerance) the symmetric distance is at most T;
// 1 not; 2 bad input (unreadable file, no faces, a bad --out), the reason on stderr.
#pragma once

#include <filesystem>
#include <optional>

namespace gt {

struct CompareMeshOptions {
  std::filesystem::path a, b;
  bool as_json = false;
  std::filesystem::path out;        // folder for the coloured meshes; empty: none
  std::optional<double> tolerance;  // on the symmetric distance, in the meshes' unit
  std::optional<double> spacing;    // CGAL's sampling grid, in the meshes' unit
};

int compare_mesh_command(const CompareMeshOptions& options);

}  // namespace gt
