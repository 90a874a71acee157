// Reading and writing triangle meshes as OFF, OBJ, PLY and STL files.
//
// read_mesh keeps the file's index buffer as it is: no welding, no reorientation, no dropping of
// faces, whatever the surface looks like — the mesh checks (compare/checks/mesh.hpp) must see what
// the file holds. It reads through CGAL's polygon-soup readers (CGAL::IO::read_OFF, read_OBJ,
// read_PLY, read_STL of CGAL/IO/polygon_soup_io.h), picked by the extension (case-insensitive):
//   .off  OFF, COFF, NOFF, 4OFF, nOFF and binary OFF; colours and normals ignored
//   .obj  `v` and `f` lines (texture and normal indices ignored, negative indices relative)
//   .ply  ASCII and binary, little or big endian; faces as a `vertex_indices` or `vertex_index`
//         list; other elements and properties ignored
//   .stl  ASCII or binary, decided by the size: binary is exactly 84 + 50·N bytes for the N
//         triangles of its header; anything else must be ASCII (first word "solid", any blank
//         after it). STL stores three corners per triangle and no shared vertices: CGAL's reader
//         merges corners at identical coordinates into one vertex (a note says so)
// Polygons with more than three corners are triangulated as a fan around their first corner
// (v0 v1 v2, v0 v2 v3, ...), which keeps their orientation; a note says how many there were.
// InputError, naming the file, for: an unknown extension, a missing or unreadable file, a file
// CGAL's reader rejects (no header, counts the data does not match, truncated, not that format),
// an OFF or PLY header, an OFF face or a PLY list whose counts cannot fit in the file's size
// (checked before anything is allocated), an OFF face index that is not a plain decimal integer
// below the vertex count ("2.7", "18446744073709551615"), a face with fewer than three corners, a vertex index out of range, a non-finite coordinate, no
// faces at all, or more vertices than 32-bit indices address.
//
// write_mesh writes .ply (binary little-endian, float64 coordinates, int32 indices), .obj or .off
// (ASCII with 17 significant digits, so doubles round-trip exactly), picked by the extension. The
// index buffer is written as it is, valid or not. The file is written under a temporary name in
// the same folder and renamed, so a failed write leaves nothing behind; any other extension, or a
// failed write, throws InputError. edge_keys are not stored.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/mesh.hpp"

namespace gt {

struct MeshFile {
  Mesh mesh;
  std::string format;              // "off", "obj", "ply" or "stl"
  std::vector<std::string> notes;  // what the reader decided (fan triangulation, STL corner merging)
};

MeshFile read_mesh(const std::filesystem::path& path);

void write_mesh(const Mesh& mesh, const std::filesystem::path& path);

}  // namespace gt
