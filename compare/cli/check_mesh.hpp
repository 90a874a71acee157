// `groundtruth check-mesh FILE [--json]`: the mesh checks of compare/checks/mesh.hpp on a mesh
// file (OFF, OBJ, PLY, STL; core/io/mesh_io.hpp).
//
// Prints the report on stdout — a paragraph (with what the reader decided) or, with as_json, one
// JSON object {file, format, notes, report, locations: where each border, non-manifold and
// misoriented edge and each self-intersecting face pair is (compare/checks/mesh.hpp
// locations_json)} — and returns the exit status: 0 watertight and
// consistently oriented, 1 not (the paragraph says what is wrong and how much), 2 the file cannot
// be read or `annotate` cannot be written (the reason on stderr as "groundtruth: ...").
// With `annotate` (a .ply path, never the input), also writes the mesh with each vertex's count of
// located problems — an end of a border, non-manifold or misoriented edge, a corner of a
// self-intersecting face, each listed up to located_cap per kind — as the vertex property
// `problems` and as a heat-map colour (black none, white the most), for any mesh viewer
// (compare/checks/vertex_values_ply.hpp).
#pragma once

#include <filesystem>

namespace gt {

int check_mesh_command(const std::filesystem::path& file, bool as_json, const std::filesystem::path& annotate = {});

}  // namespace gt
