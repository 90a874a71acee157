// Watertightness of a triangle mesh, established three ways: the raw index buffer, CGAL and
// OpenMesh. Used by the cave cases (CPU and GPU meshes) and by `groundtruth check-mesh`.
//
// Layers (each counts, none repairs the caller's mesh):
//   raw       the index buffer alone: indices out of range, non-finite corners, degenerate
//             triangles (a repeated index, or three distinct vertices on one line — CGAL's exact
//             collinear predicate), duplicates (same vertex set as an earlier triangle), and the
//             use of each undirected edge: once = border, more than twice = non-manifold, twice
//             in the same direction = misoriented (a consistently oriented surface uses each
//             interior edge once in each direction).
//   CGAL      on the usable triangles (three distinct in-range indices, finite corners):
//             is_polygon_soup_a_polygon_mesh; orient_polygon_soup with a visitor that counts the
//             non-manifold edges and vertices it meets, the faces it reverses and the vertices it
//             splits to make a manifold; then, on the Surface_mesh polygon_soup_to_polygon_mesh
//             builds from that oriented soup (isolated vertices removed): is_closed, border
//             halfedges, connected components (through edges), V - E + F, self_intersections
//             (intersecting face pairs; a degenerate face comes as (f, f) and is counted apart, and
//             so is a pair that only meets at a vertex CGAL split — CGAL sees such faces touch),
//             volume (when closed; its sign follows CGAL's orientation where it reversed faces),
//             area, does_bound_a_volume (when closed and free of degenerate, touching or
//             intersecting faces, where it is defined; it also accepts a surface whose outermost
//             shells all face inward) and is_outward_oriented (likewise, and only when CGAL
//             reversed nothing, so that the orientation is the input's).
//   OpenMesh  the same usable triangles in their own orientation, added one by one to a
//             TriMesh; add_face refuses a face that would make a complex edge or vertex (counted
//             as rejected). On what it accepted: boundary halfedges, boundary loops, connected
//             components (through shared vertices), Euler characteristic V - E + F over
//             non-isolated vertices, genus = (2C - chi - b) / 2 for C components and b boundary
//             loops (chi = 2 - 2g - b for each orientable component).
// The libraries agree when they give the same answers to the shared questions: closed, number
// of border edges, Euler characteristic, number of components. On a soup that is not a polygon
// mesh they see different surfaces (CGAL splits and reorients, OpenMesh refuses faces), so they
// may disagree there; the disagreement text says so.
//
// Watertight and oriented (is_watertight_and_oriented, check-mesh's exit status): no raw problems
// (out of range, non-finite, degenerate, duplicate), closed, manifold (no non-manifold edges or
// vertices), consistently oriented (no edge used twice in the same direction), no
// self-intersections, bounding a volume with outward normals (where CGAL defines it), and the
// libraries agree. An empty mesh passes vacuously.
#pragma once

#include <array>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compare/result.hpp"
#include "core/mesh.hpp"

namespace gt {

// Where a problem is, for `check-mesh --json` (the first located_cap of each kind): an edge by its
// two input vertex indices (lower first) and its midpoint, a pair of intersecting faces by each
// face's three input vertex indices and the midpoint of the two centroids.
inline constexpr std::size_t located_cap = 1000;

struct EdgeAt {
  std::array<std::uint32_t, 2> vertices;
  std::array<double, 3> at;
};

struct FacePairAt {
  std::array<std::array<std::size_t, 3>, 2> faces;
  std::array<double, 3> at;
};

struct RawMeshFacts {
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::size_t unreferenced_vertices = 0;
  std::size_t out_of_range_triangles = 0;    // an index >= vertices
  std::size_t nonfinite_triangles = 0;       // a corner with a NaN or infinite coordinate
  std::size_t repeated_index_triangles = 0;  // two corners name the same vertex
  std::size_t zero_area_triangles = 0;       // three distinct vertices on one line
  std::size_t duplicate_triangles = 0;       // same vertex set as an earlier triangle
  // Edge use, over the usable triangles (three distinct in-range indices, finite corners):
  std::size_t edges = 0;                     // distinct undirected edges
  std::size_t border_edges = 0;              // used by one triangle
  std::size_t non_manifold_edges = 0;        // used by more than two triangles
  std::size_t misoriented_edges = 0;         // used by two triangles in the same direction
  std::vector<EdgeAt> border_edges_at, non_manifold_edges_at, misoriented_edges_at;
};

struct CgalMeshFacts {
  bool soup_is_polygon_mesh = true;          // orient_polygon_soup found nothing to reverse, split or report
  std::size_t non_manifold_edges = 0;        // met by orient_polygon_soup
  std::size_t non_manifold_vertices = 0;
  std::size_t reversed_faces = 0;            // faces orient_polygon_soup reversed
  std::size_t split_vertices = 0;            // vertices it duplicated to make a manifold
  std::size_t vertices = 0;                  // of the Surface_mesh, without isolated vertices
  std::size_t edges = 0;
  std::size_t faces = 0;
  long euler_characteristic = 0;             // vertices - edges + faces
  bool closed = true;                        // CGAL::is_closed
  std::size_t border_edges = 0;              // border halfedges
  std::size_t components = 0;                // connected through edges
  std::size_t self_intersections = 0;        // intersecting pairs of distinct faces
  bool self_intersections_capped = false;    // the count stopped at self_intersection_cap
  std::size_t split_contacts = 0;            // pairs that meet only where CGAL split a vertex
  std::size_t degenerate_faces = 0;          // collinear corners, as self_intersections reports them
  std::optional<bool> bounds_volume;         // does_bound_a_volume, where it is defined
  std::optional<bool> outward;               // is_outward_oriented, where bounds_volume is defined
  std::optional<double> volume;              // when closed; negative when oriented inward
  double area = 0.0;
  std::vector<FacePairAt> self_intersections_at;
};

struct OpenMeshFacts {
  std::size_t rejected_faces = 0;            // faces add_face refused
  std::size_t vertices = 0;                  // non-isolated
  std::size_t edges = 0;
  std::size_t faces = 0;
  long euler_characteristic = 0;
  std::size_t boundary_halfedges = 0;
  std::size_t boundary_loops = 0;
  std::size_t components = 0;                // connected through shared vertices
  double genus = 0.0;                        // (2C - chi - b) / 2; a half-integer means non-orientable
};

struct MeshReport {
  RawMeshFacts raw;
  CgalMeshFacts cgal;
  OpenMeshFacts openmesh;
  bool libraries_agree = true;
  std::string disagreement;                  // which answers differ, empty when they agree
};

// Self-intersecting face pairs are counted up to this many (then cgal.self_intersections_capped).
inline constexpr std::size_t self_intersection_cap = 1'000'000;

MeshReport check_mesh(const Mesh& mesh);

// What is wrong, each with how much ("12 border edges (not closed)"); empty when watertight and
// oriented.
std::vector<std::string> mesh_problems(const MeshReport& report);

bool is_watertight_and_oriented(const MeshReport& report);

nlohmann::json to_json(const MeshReport& report);

// Where the problems are: {"border_edges", "non_manifold_edges", "misoriented_edges": [{"vertices":
// [a, b], "at": [x, y, z]}], "self_intersections": [{"faces": [[a, b, c], [d, e, f]], "at": [...]}],
// "listed_at_most": located_cap}, input vertex indices (0-based) and positions in the mesh's unit.
nlohmann::json locations_json(const MeshReport& report);

// One paragraph: size, verdict with the problems, topology, volume and area, agreement.
std::string describe(const MeshReport& report);

// Checks for a report, named mesh.<what>.<backend>. Failing ones (threshold 0): invalid (out of
// range or non-finite), degenerate, duplicates, manifold (non-manifold edges + vertices), oriented
// (edges used twice in the same direction), self_intersections, libraries_agree (differing
// answers); with expect_closed also closed (CGAL's border edges) and bounds_volume (0 when CGAL
// says it bounds a volume and faces outward, else 1; skip where undefined). Informative ones (no
// threshold): euler, genus, components, area, volume (skip when open), and border_edges when
// expect_closed is false (an open chunk).
std::vector<Check> mesh_checks(const MeshReport& report, const std::string& backend, bool expect_closed);

// CGAL's approximate one-sided Hausdorff distance from one surface to another: the farthest of the
// points sampled on a grid of `grid_spacing` over `from`'s faces (and its vertices and edges) from
// `to`. A lower bound of the true distance that approaches it as the spacing shrinks; deterministic
// (grid sampling). Only the usable triangles count (three distinct in-range indices, finite
// corners: a broken mesh gives a distance, not a crash); 0 when `from` is empty, infinity when
// only `to` is.
double approximate_one_sided_hausdorff_distance(const Mesh& from, const Mesh& to, double grid_spacing);

// The triangles the libraries are given, as index triples: three distinct in-range indices, finite
// corners.
std::vector<std::array<std::size_t, 3>> usable_triangles(const Mesh& mesh);

// For each vertex of `from` that a usable triangle uses, the Euclidean distance to the nearest
// point of `to`'s usable triangles and that point (CGAL's AABB tree, exact closest-point queries in
// double); unused vertices get NaN, and every used one +infinity when `to` has no usable triangle.
// Their largest is a lower bound of the one-sided Hausdorff distance, attained where the meshes
// differ at their vertices (`groundtruth compare-mesh` reports it beside the sampled one).
struct VertexDistance {
  double distance = 0.0;
  std::array<double, 3> nearest{};  // the closest point of the other surface
};
std::vector<VertexDistance> vertex_distances(const Mesh& from, const Mesh& to);

}  // namespace gt
