// The three layers of mesh.hpp: raw index-buffer counts, CGAL (orient_polygon_soup,
// Surface_mesh, Polygon_mesh_processing) and OpenMesh (TriMesh), their comparison, and the report
// forms (problems, JSON, paragraph, checks).
#include "compare/checks/mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <numeric>
#include <optional>
#include <set>
#include <utility>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <boost/iterator/function_output_iterator.hpp>
#include <fmt/format.h>

#include "compare/checks/threshold.hpp"

namespace gt {

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using SoupTriangle = std::array<std::size_t, 3>;
using DistanceTree = CGAL::AABB_tree<CGAL::AABB_traits<CGAL::Exact_predicates_inexact_constructions_kernel,
                                                       CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
};
using OpenTriMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

// ---- raw index buffer ----

enum class TriangleKind { usable, out_of_range, repeated_index, nonfinite };

bool is_finite(const std::array<double, 3>& position) {
  return std::isfinite(position[0]) && std::isfinite(position[1]) && std::isfinite(position[2]);
}

Point point_of(const std::array<double, 3>& position) { return {position[0], position[1], position[2]}; }

TriangleKind kind_of(const Mesh& mesh, const std::array<std::uint32_t, 3>& triangle) {
  const auto [a, b, c] = triangle;
  if (std::max({a, b, c}) >= mesh.positions.size()) return TriangleKind::out_of_range;
  if (a == b || b == c || c == a) return TriangleKind::repeated_index;
  if (!is_finite(mesh.positions[a]) || !is_finite(mesh.positions[b]) || !is_finite(mesh.positions[c])) {
    return TriangleKind::nonfinite;
  }
  return TriangleKind::usable;
}

bool has_zero_area(const Mesh& mesh, const SoupTriangle& triangle) {
  return CGAL::collinear(point_of(mesh.positions[triangle[0]]), point_of(mesh.positions[triangle[1]]),
                         point_of(mesh.positions[triangle[2]]));
}

void count_triangle_kinds(const Mesh& mesh, RawMeshFacts& facts) {
  for (const auto& triangle : mesh.triangles) {
    switch (kind_of(mesh, triangle)) {
      case TriangleKind::out_of_range: ++facts.out_of_range_triangles; break;
      case TriangleKind::repeated_index: ++facts.repeated_index_triangles; break;
      case TriangleKind::nonfinite: ++facts.nonfinite_triangles; break;
      case TriangleKind::usable: break;
    }
  }
}

void count_duplicates_and_references(const Mesh& mesh, RawMeshFacts& facts) {
  std::vector<std::array<std::uint32_t, 3>> vertex_sets;
  std::vector<bool> referenced(mesh.positions.size(), false);
  for (auto triangle : mesh.triangles) {
    if (kind_of(mesh, triangle) == TriangleKind::out_of_range) continue;
    for (const std::uint32_t index : triangle) referenced[index] = true;
    std::sort(triangle.begin(), triangle.end());
    vertex_sets.push_back(triangle);
  }
  std::sort(vertex_sets.begin(), vertex_sets.end());
  facts.duplicate_triangles = static_cast<std::size_t>(
      vertex_sets.end() - std::unique(vertex_sets.begin(), vertex_sets.end()));
  facts.unreferenced_vertices = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), false));
}

// Each use of an undirected edge as (key = lower << 32 | higher, forward = lower comes first).
struct EdgeUse {
  std::uint64_t key;
  bool forward;
  bool operator<(const EdgeUse& other) const { return key < other.key; }
};

// The edge of `key` (lower << 32 | higher) with its midpoint, kept while the list is short.
void locate_edge(const Mesh& mesh, std::uint64_t key, std::vector<EdgeAt>& list) {
  if (list.size() >= located_cap) return;
  const auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key & 0xffffffffu);
  EdgeAt edge{{a, b}, {}};
  for (int axis = 0; axis < 3; ++axis) {
    edge.at[static_cast<std::size_t>(axis)] = 0.5 * (static_cast<double>(mesh.positions[a][axis]) +
                                                    static_cast<double>(mesh.positions[b][axis]));
  }
  list.push_back(edge);
}

void count_edge_uses(const Mesh& mesh, const std::vector<SoupTriangle>& triangles, RawMeshFacts& facts) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * triangles.size());
  for (const SoupTriangle& triangle : triangles) {
    for (int corner = 0; corner < 3; ++corner) {
      const std::uint64_t from = triangle[corner], to = triangle[(corner + 1) % 3];
      uses.push_back({std::min(from, to) << 32 | std::max(from, to), from < to});
    }
  }
  std::sort(uses.begin(), uses.end());
  for (auto first = uses.begin(); first != uses.end();) {
    const auto last = std::find_if(first, uses.end(), [&](const EdgeUse& use) { return use.key != first->key; });
    const auto count = last - first;
    const auto forward = std::count_if(first, last, [](const EdgeUse& use) { return use.forward; });
    ++facts.edges;
    if (count == 1) ++facts.border_edges, locate_edge(mesh, first->key, facts.border_edges_at);
    if (count > 2) ++facts.non_manifold_edges, locate_edge(mesh, first->key, facts.non_manifold_edges_at);
    if (count == 2 && forward != 1) ++facts.misoriented_edges, locate_edge(mesh, first->key, facts.misoriented_edges_at);
    first = last;
  }
}

RawMeshFacts raw_facts(const Mesh& mesh, const std::vector<SoupTriangle>& usable) {
  RawMeshFacts facts;
  facts.vertices = mesh.positions.size();
  facts.triangles = mesh.triangles.size();
  count_triangle_kinds(mesh, facts);
  facts.zero_area_triangles = static_cast<std::size_t>(
      std::count_if(usable.begin(), usable.end(), [&](const SoupTriangle& t) { return has_zero_area(mesh, t); }));
  count_duplicates_and_references(mesh, facts);
  count_edge_uses(mesh, usable, facts);
  return facts;
}

// ---- CGAL ----

// CGAL's mesh of the usable triangles, and for each of its vertices the input vertex it stands
// for (a different one only where orient_polygon_soup split a vertex).
struct CgalSurface {
  SurfaceMesh mesh;
  std::vector<std::size_t> input_vertex;
};

// Counts what orient_polygon_soup meets; it copies its visitor, so the counts live outside.
struct OrientationCounts : PMP::Default_orientation_visitor {
  CgalMeshFacts* facts;
  std::set<std::pair<std::size_t, std::size_t>>* non_manifold_edges;
  std::vector<std::size_t>* input_vertex;

  void non_manifold_edge(std::size_t from, std::size_t to, std::size_t) {
    non_manifold_edges->insert(std::minmax(from, to));
  }
  void non_manifold_vertex(std::size_t, std::size_t) { ++facts->non_manifold_vertices; }
  // Copies are appended to the points in order, so the copy's index is input_vertex's size.
  void duplicated_vertex(std::size_t original, std::size_t) {
    ++facts->split_vertices;
    input_vertex->push_back(original);
  }
  void polygon_orientation_reversed(std::size_t) { ++facts->reversed_faces; }
};

// The soup was a polygon mesh (is_polygon_soup_a_polygon_mesh: manifold edges and vertices,
// neighbours oriented alike) when orient_polygon_soup found nothing to reverse, split or report:
// asking is_polygon_soup_a_polygon_mesh itself, before and after, took 21 s of a 5-million-triangle
// cave mesh's 41 (issue 17), its std::set of directed edges mostly.
CgalSurface oriented_surface(const Mesh& mesh, std::vector<SoupTriangle> triangles, CgalMeshFacts& facts) {
  std::vector<Point> points;
  points.reserve(mesh.positions.size());
  for (const auto& position : mesh.positions) {
    points.push_back(is_finite(position) ? point_of(position) : Point(CGAL::ORIGIN));  // unused when not finite
  }
  CgalSurface surface;
  surface.input_vertex.resize(points.size());
  std::iota(surface.input_vertex.begin(), surface.input_vertex.end(), std::size_t{0});
  std::set<std::pair<std::size_t, std::size_t>> non_manifold_edges;
  PMP::orient_polygon_soup(
      points, triangles,
      CGAL::parameters::visitor(OrientationCounts{{}, &facts, &non_manifold_edges, &surface.input_vertex}));
  facts.non_manifold_edges = non_manifold_edges.size();
  facts.soup_is_polygon_mesh = facts.non_manifold_edges + facts.non_manifold_vertices + facts.reversed_faces +
                                   facts.split_vertices == 0;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface.mesh);
  PMP::remove_isolated_vertices(surface.mesh);  // marks them removed: vertex i stays point i
  return surface;
}

// Faces that share no vertex of CGAL's mesh but share an input vertex: they meet where CGAL split
// a non-manifold vertex, and CGAL sees them touch there.
bool meet_at_split_vertex(const CgalSurface& surface, SurfaceMesh::Face_index f, SurfaceMesh::Face_index g) {
  const auto f_vertices = vertices_around_face(surface.mesh.halfedge(f), surface.mesh);
  const auto g_vertices = vertices_around_face(surface.mesh.halfedge(g), surface.mesh);
  bool share_input_vertex = false;
  for (const auto u : f_vertices) {
    for (const auto v : g_vertices) {
      if (u == v) return false;
      share_input_vertex |= surface.input_vertex[u] == surface.input_vertex[v];
    }
  }
  return share_input_vertex;
}

// Sorts reported pairs: (f, f) a degenerate face, (f, g) meeting at a split vertex, or crossing.
struct IntersectionCounter {
  const CgalSurface* surface;
  CgalMeshFacts* facts;
  std::size_t* reported;
  // A crossing pair by its faces' input vertices, at the midpoint of their centroids.
  FacePairAt locate(const std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>& pair) const {
    FacePairAt located{};
    int k = 0;
    for (const auto face : {pair.first, pair.second}) {
      int corner = 0;
      for (const auto vertex : CGAL::vertices_around_face(surface->mesh.halfedge(face), surface->mesh)) {
        if (corner < 3) located.faces[static_cast<std::size_t>(k)][static_cast<std::size_t>(corner)] = surface->input_vertex[vertex];
        const auto& point = surface->mesh.point(vertex);
        located.at[0] += CGAL::to_double(point.x()) / 6.0;
        located.at[1] += CGAL::to_double(point.y()) / 6.0;
        located.at[2] += CGAL::to_double(point.z()) / 6.0;
        ++corner;
      }
      ++k;
    }
    return located;
  }
  void operator()(const std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>& pair) const {
    ++*reported;
    if (pair.first == pair.second) {
      ++facts->degenerate_faces;
    } else if (meet_at_split_vertex(*surface, pair.first, pair.second)) {
      ++facts->split_contacts;
    } else {
      ++facts->self_intersections;
      if (facts->self_intersections_at.size() < located_cap) facts->self_intersections_at.push_back(locate(pair));
    }
  }
};

void count_self_intersections(const CgalSurface& surface, CgalMeshFacts& facts) {
  std::size_t reported = 0;
  PMP::self_intersections(surface.mesh,
                          boost::make_function_output_iterator(IntersectionCounter{&surface, &facts, &reported}),
                          CGAL::parameters::maximum_number(static_cast<unsigned int>(self_intersection_cap)));
  facts.self_intersections_capped = reported >= self_intersection_cap;
}

void count_elements(const SurfaceMesh& mesh, CgalMeshFacts& facts) {
  facts.vertices = mesh.number_of_vertices();
  facts.edges = mesh.number_of_edges();
  facts.faces = mesh.number_of_faces();
  facts.euler_characteristic =
      static_cast<long>(facts.vertices) - static_cast<long>(facts.edges) + static_cast<long>(facts.faces);
  facts.closed = CGAL::is_closed(mesh);
  const auto all_halfedges = halfedges(mesh);
  facts.border_edges = static_cast<std::size_t>(std::count_if(
      all_halfedges.begin(), all_halfedges.end(), [&](auto halfedge) { return CGAL::is_border(halfedge, mesh); }));
}

// does_bound_a_volume and is_outward_oriented are undefined on open, degenerate or
// self-intersecting meshes; the orientation is the input's only where CGAL reversed nothing.
void measure_volume(const SurfaceMesh& mesh, CgalMeshFacts& facts) {
  if (!facts.closed) return;
  facts.volume = PMP::volume(mesh);
  if (facts.self_intersections + facts.split_contacts + facts.degenerate_faces > 0 || mesh.is_empty()) return;
  facts.bounds_volume = PMP::does_bound_a_volume(mesh);
  if (facts.reversed_faces == 0) facts.outward = PMP::is_outward_oriented(mesh);
}

CgalMeshFacts cgal_facts(const Mesh& mesh, const std::vector<SoupTriangle>& usable) {
  CgalMeshFacts facts;
  CgalSurface surface = oriented_surface(mesh, usable, facts);
  count_elements(surface.mesh, facts);
  auto component_of = surface.mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:component", 0).first;
  facts.components = PMP::connected_components(surface.mesh, component_of);
  count_self_intersections(surface, facts);
  measure_volume(surface.mesh, facts);
  facts.area = PMP::area(surface.mesh);
  return facts;
}

// ---- OpenMesh ----

// add_face reports each refusal on OpenMesh's error stream; the refusals are counted instead. The
// stream is global and meshes may be checked on two threads at once (a cave case checks its CPU
// mesh beside the GPU's): the first user silences it, the last restores it.
class QuietOpenMeshErrors {
 public:
  QuietOpenMeshErrors() {
    const std::lock_guard lock(mutex_);
    if (users_++ == 0) {
      was_enabled_ = ::omerr().is_enabled();
      ::omerr().disable();
    }
  }
  ~QuietOpenMeshErrors() {
    const std::lock_guard lock(mutex_);
    if (--users_ == 0 && was_enabled_) ::omerr().enable();
  }
  QuietOpenMeshErrors(const QuietOpenMeshErrors&) = delete;
  QuietOpenMeshErrors& operator=(const QuietOpenMeshErrors&) = delete;

 private:
  static inline std::mutex mutex_;
  static inline int users_ = 0;
  static inline bool was_enabled_ = true;
};

OpenTriMesh open_tri_mesh(const Mesh& mesh, const std::vector<SoupTriangle>& triangles, OpenMeshFacts& facts) {
  OpenTriMesh open_mesh;
  open_mesh.reserve(mesh.positions.size(), 3 * triangles.size() / 2, triangles.size());
  for (const auto& position : mesh.positions) open_mesh.add_vertex({position[0], position[1], position[2]});
  const QuietOpenMeshErrors quiet;
  for (const SoupTriangle& triangle : triangles) {
    const auto face = open_mesh.add_face(open_mesh.vertex_handle(static_cast<unsigned>(triangle[0])),
                                         open_mesh.vertex_handle(static_cast<unsigned>(triangle[1])),
                                         open_mesh.vertex_handle(static_cast<unsigned>(triangle[2])));
    if (!face.is_valid()) ++facts.rejected_faces;
  }
  return open_mesh;
}

std::size_t count_boundary_loops(const OpenTriMesh& open_mesh) {
  std::vector<bool> walked(open_mesh.n_halfedges(), false);
  std::size_t loops = 0;
  for (const auto start : open_mesh.halfedges()) {
    if (!open_mesh.is_boundary(start) || walked[start.idx()]) continue;
    ++loops;
    for (auto halfedge = start; !walked[halfedge.idx()]; halfedge = open_mesh.next_halfedge_handle(halfedge)) {
      walked[halfedge.idx()] = true;
    }
  }
  return loops;
}

std::size_t count_vertex_components(const OpenTriMesh& open_mesh) {
  std::vector<bool> reached(open_mesh.n_vertices(), false);
  std::vector<OpenTriMesh::VertexHandle> pending;
  std::size_t components = 0;
  for (const auto seed : open_mesh.vertices()) {
    if (open_mesh.is_isolated(seed) || reached[seed.idx()]) continue;
    ++components;
    reached[seed.idx()] = true;
    pending.push_back(seed);
    while (!pending.empty()) {
      const auto vertex = pending.back();
      pending.pop_back();
      for (const auto neighbour : open_mesh.vv_range(vertex)) {
        if (!reached[neighbour.idx()]) {
          reached[neighbour.idx()] = true;
          pending.push_back(neighbour);
        }
      }
    }
  }
  return components;
}

OpenMeshFacts openmesh_facts(const Mesh& mesh, const std::vector<SoupTriangle>& usable) {
  OpenMeshFacts facts;
  const OpenTriMesh open_mesh = open_tri_mesh(mesh, usable, facts);
  const auto all_vertices = open_mesh.vertices();
  facts.vertices = static_cast<std::size_t>(std::count_if(all_vertices.begin(), all_vertices.end(),
                                                          [&](auto vertex) { return !open_mesh.is_isolated(vertex); }));
  facts.edges = open_mesh.n_edges();
  facts.faces = open_mesh.n_faces();
  facts.euler_characteristic =
      static_cast<long>(facts.vertices) - static_cast<long>(facts.edges) + static_cast<long>(facts.faces);
  const auto all_halfedges = open_mesh.halfedges();
  facts.boundary_halfedges = static_cast<std::size_t>(std::count_if(
      all_halfedges.begin(), all_halfedges.end(), [&](auto halfedge) { return open_mesh.is_boundary(halfedge); }));
  facts.boundary_loops = count_boundary_loops(open_mesh);
  facts.components = count_vertex_components(open_mesh);
  facts.genus = (2.0 * static_cast<double>(facts.components) - static_cast<double>(facts.euler_characteristic) -
                 static_cast<double>(facts.boundary_loops)) / 2.0;
  return facts;
}

// ---- agreement ----

// "12 border edges" / "1 border edge".
std::string counted(std::size_t count, const char* singular, const char* plural) {
  return fmt::format("{} {}", count, count == 1 ? singular : plural);
}

struct SharedAnswer {
  const char* question;
  std::string cgal;
  std::string openmesh;
};

std::string yes_no(bool answer) { return answer ? "yes" : "no"; }

std::vector<SharedAnswer> shared_answers(const CgalMeshFacts& cgal, const OpenMeshFacts& openmesh) {
  return {{"closed", yes_no(cgal.closed), yes_no(openmesh.boundary_halfedges == 0)},
          {"border edges", std::to_string(cgal.border_edges), std::to_string(openmesh.boundary_halfedges)},
          {"Euler characteristic", std::to_string(cgal.euler_characteristic),
           std::to_string(openmesh.euler_characteristic)},
          {"components", std::to_string(cgal.components), std::to_string(openmesh.components)}};
}

std::size_t count_disagreements(const MeshReport& report) {
  const auto answers = shared_answers(report.cgal, report.openmesh);
  return static_cast<std::size_t>(
      std::count_if(answers.begin(), answers.end(), [](const SharedAnswer& a) { return a.cgal != a.openmesh; }));
}

std::string disagreement_of(const MeshReport& report) {
  std::string text;
  for (const SharedAnswer& answer : shared_answers(report.cgal, report.openmesh)) {
    if (answer.cgal == answer.openmesh) continue;
    text += fmt::format("{}{}: CGAL {}, OpenMesh {}", text.empty() ? "" : "; ", answer.question, answer.cgal,
                        answer.openmesh);
  }
  if (!text.empty() && !report.cgal.soup_is_polygon_mesh) {
    text += fmt::format(" (the triangles do not form a polygon mesh as they are: CGAL reversed {} and split {}, "
                        "OpenMesh refused {})",
                        counted(report.cgal.reversed_faces, "face", "faces"),
                        counted(report.cgal.split_vertices, "vertex", "vertices"),
                        counted(report.openmesh.rejected_faces, "face", "faces"));
  }
  return text;
}

// ---- report forms ----

std::string number(double value) { return fmt::format("{:.10g}", value); }

nlohmann::json edges_json(const std::vector<EdgeAt>& edges) {
  nlohmann::json list = nlohmann::json::array();
  for (const EdgeAt& edge : edges) list.push_back({{"vertices", edge.vertices}, {"at", edge.at}});
  return list;
}

nlohmann::json optional_json(const auto& value) { return value ? nlohmann::json(*value) : nlohmann::json(nullptr); }

nlohmann::json raw_json(const RawMeshFacts& raw) {
  return {{"vertices", raw.vertices},
          {"triangles", raw.triangles},
          {"unreferenced_vertices", raw.unreferenced_vertices},
          {"out_of_range_triangles", raw.out_of_range_triangles},
          {"nonfinite_triangles", raw.nonfinite_triangles},
          {"repeated_index_triangles", raw.repeated_index_triangles},
          {"zero_area_triangles", raw.zero_area_triangles},
          {"duplicate_triangles", raw.duplicate_triangles},
          {"edges", raw.edges},
          {"border_edges", raw.border_edges},
          {"non_manifold_edges", raw.non_manifold_edges},
          {"misoriented_edges", raw.misoriented_edges}};
}

nlohmann::json cgal_json(const CgalMeshFacts& cgal) {
  return {{"soup_is_polygon_mesh", cgal.soup_is_polygon_mesh},
          {"non_manifold_edges", cgal.non_manifold_edges},
          {"non_manifold_vertices", cgal.non_manifold_vertices},
          {"reversed_faces", cgal.reversed_faces},
          {"split_vertices", cgal.split_vertices},
          {"vertices", cgal.vertices},
          {"edges", cgal.edges},
          {"faces", cgal.faces},
          {"euler_characteristic", cgal.euler_characteristic},
          {"closed", cgal.closed},
          {"border_edges", cgal.border_edges},
          {"components", cgal.components},
          {"self_intersections", cgal.self_intersections},
          {"self_intersections_capped", cgal.self_intersections_capped},
          {"split_contacts", cgal.split_contacts},
          {"degenerate_faces", cgal.degenerate_faces},
          {"bounds_volume", optional_json(cgal.bounds_volume)},
          {"outward", optional_json(cgal.outward)},
          {"volume", optional_json(cgal.volume)},
          {"area", cgal.area}};
}

nlohmann::json openmesh_json(const OpenMeshFacts& openmesh) {
  return {{"rejected_faces", openmesh.rejected_faces},
          {"vertices", openmesh.vertices},
          {"edges", openmesh.edges},
          {"faces", openmesh.faces},
          {"euler_characteristic", openmesh.euler_characteristic},
          {"boundary_halfedges", openmesh.boundary_halfedges},
          {"boundary_loops", openmesh.boundary_loops},
          {"components", openmesh.components},
          {"genus", openmesh.genus}};
}

void add_problem(std::vector<std::string>& problems, std::size_t count, const char* singular, const char* plural,
                 const std::string& remark = "") {
  if (count > 0) problems.push_back(counted(count, singular, plural) + remark);
}

// "OpenMesh: 1 component, Euler characteristic 2, genus 0; CGAL: volume 1, area 6".
std::string topology_of(const MeshReport& report) {
  const OpenMeshFacts& om = report.openmesh;
  std::string text = fmt::format("OpenMesh: {}, Euler characteristic {}, genus {}",
                                 counted(om.components, "component", "components"), om.euler_characteristic,
                                 number(om.genus));
  if (om.boundary_halfedges > 0) {
    text += fmt::format(", {} in {}", counted(om.boundary_halfedges, "border edge", "border edges"),
                        counted(om.boundary_loops, "boundary loop", "boundary loops"));
  }
  text += "; CGAL: ";
  if (report.cgal.volume) text += fmt::format("volume {}, ", number(*report.cgal.volume));
  return text + fmt::format("area {}", number(report.cgal.area));
}

Check zero_check(std::string name, std::size_t value, std::string detail) {
  return bounded_check(std::move(name), static_cast<double>(value), 0.0, std::nullopt, std::move(detail));
}

Check bounds_volume_check(const MeshReport& report, const std::string& name) {
  if (!report.cgal.bounds_volume) {
    return not_applicable_check(name, "not defined: the mesh is open, empty, degenerate or self-intersecting");
  }
  const std::optional<bool> outward = report.cgal.outward;
  return zero_check(name, *report.cgal.bounds_volume && outward == true ? 0 : 1,
                    fmt::format("0 when CGAL's does_bound_a_volume and is_outward_oriented hold; they say {} and {}",
                                yes_no(*report.cgal.bounds_volume),
                                outward ? yes_no(*outward) : "not evaluated (CGAL reversed faces)"));
}

}  // namespace

MeshReport check_mesh(const Mesh& mesh) {
  const std::vector<SoupTriangle> usable = usable_triangles(mesh);
  MeshReport report;
  report.raw = raw_facts(mesh, usable);
  report.cgal = cgal_facts(mesh, usable);
  report.openmesh = openmesh_facts(mesh, usable);
  report.libraries_agree = count_disagreements(report) == 0;
  report.disagreement = disagreement_of(report);
  return report;
}

std::vector<std::string> mesh_problems(const MeshReport& report) {
  const RawMeshFacts& raw = report.raw;
  const CgalMeshFacts& cgal = report.cgal;
  std::vector<std::string> problems;
  add_problem(problems, raw.out_of_range_triangles, "triangle with an index out of range",
              "triangles with an index out of range");
  add_problem(problems, raw.nonfinite_triangles, "triangle with a non-finite corner",
              "triangles with a non-finite corner");
  add_problem(problems, raw.repeated_index_triangles, "triangle with a repeated vertex",
              "triangles with a repeated vertex");
  add_problem(problems, raw.zero_area_triangles, "zero-area triangle", "zero-area triangles");
  add_problem(problems, raw.duplicate_triangles, "duplicate triangle", "duplicate triangles");
  add_problem(problems, cgal.border_edges, "border edge", "border edges", " (not closed)");
  add_problem(problems, raw.non_manifold_edges, "non-manifold edge", "non-manifold edges");
  add_problem(problems, cgal.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices");
  add_problem(problems, raw.misoriented_edges, "edge used twice in the same direction",
              "edges used twice in the same direction",
              fmt::format(" (not consistently oriented; CGAL reversed {})",
                          counted(cgal.reversed_faces, "face", "faces")));
  add_problem(problems, cgal.self_intersections, "self-intersecting face pair", "self-intersecting face pairs",
              cgal.self_intersections_capped ? " (counting stopped there)" : "");
  if (cgal.bounds_volume == false) problems.push_back("does not bound a volume (shells nested or oriented wrongly)");
  if (cgal.bounds_volume == true && cgal.outward == false) problems.push_back("oriented inward (normals face in)");
  if (!report.libraries_agree) problems.push_back("CGAL and OpenMesh disagree: " + report.disagreement);
  return problems;
}

bool is_watertight_and_oriented(const MeshReport& report) { return mesh_problems(report).empty(); }

nlohmann::json to_json(const MeshReport& report) {
  return {{"watertight_and_oriented", is_watertight_and_oriented(report)},
          {"problems", mesh_problems(report)},
          {"raw", raw_json(report.raw)},
          {"cgal", cgal_json(report.cgal)},
          {"openmesh", openmesh_json(report.openmesh)},
          {"libraries_agree", report.libraries_agree},
          {"disagreement", report.disagreement}};
}

std::string describe(const MeshReport& report) {
  const std::vector<std::string> problems = mesh_problems(report);
  std::string verdict = "watertight and consistently oriented";
  if (!problems.empty()) {
    verdict = "NOT watertight and consistently oriented: " + problems.front();
    for (std::size_t i = 1; i < problems.size(); ++i) verdict += "; " + problems[i];
  }
  return fmt::format("{} on {}: {}. {}.{}", counted(report.raw.triangles, "triangle", "triangles"),
                     counted(report.raw.vertices, "vertex", "vertices"), verdict, topology_of(report),
                     report.libraries_agree
                         ? " CGAL and OpenMesh agree on closed, border edges, Euler characteristic and components."
                         : "");
}

std::vector<Check> mesh_checks(const MeshReport& report, const std::string& backend, bool expect_closed) {
  const RawMeshFacts& raw = report.raw;
  const CgalMeshFacts& cgal = report.cgal;
  const OpenMeshFacts& om = report.openmesh;
  const auto name = [&](const char* what) { return fmt::format("mesh.{}.{}", what, backend); };
  std::vector<Check> checks;
  checks.push_back(zero_check(name("invalid"), raw.out_of_range_triangles + raw.nonfinite_triangles,
                              fmt::format("triangles with an index out of range ({}) or a non-finite corner ({})",
                                          raw.out_of_range_triangles, raw.nonfinite_triangles)));
  checks.push_back(zero_check(name("degenerate"), raw.repeated_index_triangles + raw.zero_area_triangles,
                              fmt::format("triangles with a repeated vertex ({}) or of zero area ({})",
                                          raw.repeated_index_triangles, raw.zero_area_triangles)));
  checks.push_back(zero_check(name("duplicates"), raw.duplicate_triangles,
                              "triangles with the vertex set of an earlier triangle"));
  if (expect_closed) {
    checks.push_back(zero_check(name("closed"), cgal.border_edges,
                                fmt::format("CGAL's border edges (OpenMesh: {} boundary halfedges in {} loops)",
                                            om.boundary_halfedges, om.boundary_loops)));
  }
  checks.push_back(zero_check(name("manifold"), raw.non_manifold_edges + cgal.non_manifold_vertices,
                              fmt::format("edges used by more than two triangles ({}) plus CGAL's non-manifold "
                                          "vertices ({})",
                                          raw.non_manifold_edges, cgal.non_manifold_vertices)));
  checks.push_back(zero_check(name("oriented"), raw.misoriented_edges,
                              fmt::format("edges used twice in the same direction (CGAL reversed {} faces to orient "
                                          "the surface)",
                                          cgal.reversed_faces)));
  if (expect_closed) checks.push_back(bounds_volume_check(report, name("bounds_volume")));
  checks.push_back(zero_check(name("self_intersections"), cgal.self_intersections,
                              cgal.self_intersections_capped ? "intersecting face pairs (CGAL; counting stopped here)"
                                                             : "intersecting face pairs (CGAL)"));
  checks.push_back(zero_check(name("libraries_agree"), count_disagreements(report),
                              report.libraries_agree ? "CGAL and OpenMesh give the same closed, border edges, Euler "
                                                       "characteristic and components"
                                                     : report.disagreement));
  if (!expect_closed) {
    checks.push_back(informative_check(name("border_edges"), static_cast<double>(cgal.border_edges),
                                 "border edges of an open chunk (CGAL)"));
  }
  checks.push_back(informative_check(name("euler"), static_cast<double>(om.euler_characteristic),
                               "V - E + F (OpenMesh, non-isolated vertices)"));
  checks.push_back(informative_check(name("genus"), om.genus, "(2C - chi - b) / 2 (OpenMesh)"));
  checks.push_back(informative_check(name("components"), static_cast<double>(om.components), "OpenMesh"));
  checks.push_back(informative_check(name("area"), cgal.area, "CGAL"));
  checks.push_back(cgal.volume ? informative_check(name("volume"), *cgal.volume, "CGAL; negative when oriented inward")
                               : not_applicable_check(name("volume"), "the mesh is open"));
  return checks;
}

namespace {

// The surface sampled: only the usable triangles (a broken mesh, a GPU bug, must give a distance,
// not a crash), oriented into a polygon mesh so that shared vertices and edges are sampled once.
SurfaceMesh sampled_surface(const Mesh& mesh) {
  std::vector<Point> points;
  points.reserve(mesh.positions.size());
  for (const auto& position : mesh.positions) points.push_back(point_of(position));
  std::vector<SoupTriangle> triangles = usable_triangles(mesh);
  PMP::orient_polygon_soup(points, triangles);
  SurfaceMesh surface;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, surface);
  return surface;
}

// The surface measured to: each usable triangle with corners of its own. A distance needs no
// connectivity, and unshared corners need no orientation (orienting a target of millions of
// triangles took seconds).
SurfaceMesh target_surface(const Mesh& mesh) {
  SurfaceMesh surface;
  for (const SoupTriangle& triangle : usable_triangles(mesh)) {
    surface.add_face(surface.add_vertex(point_of(mesh.positions[triangle[0]])),
                     surface.add_vertex(point_of(mesh.positions[triangle[1]])),
                     surface.add_vertex(point_of(mesh.positions[triangle[2]])));
  }
  return surface;
}

}  // namespace

std::vector<SoupTriangle> usable_triangles(const Mesh& mesh) {
  std::vector<SoupTriangle> usable;
  usable.reserve(mesh.triangles.size());
  for (const auto& triangle : mesh.triangles) {
    if (kind_of(mesh, triangle) == TriangleKind::usable) usable.push_back({triangle[0], triangle[1], triangle[2]});
  }
  return usable;
}

double approximate_one_sided_hausdorff_distance(const Mesh& from, const Mesh& to, double grid_spacing) {
  if (from.triangles.empty()) return 0.0;
  if (to.triangles.empty()) return std::numeric_limits<double>::infinity();
  return PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(
      sampled_surface(from), target_surface(to),
      CGAL::parameters::use_grid_sampling(true).grid_spacing(grid_spacing), CGAL::parameters::default_values());
}

std::vector<VertexDistance> vertex_distances(const Mesh& from, const Mesh& to) {
  constexpr double unused = std::numeric_limits<double>::quiet_NaN();
  std::vector<VertexDistance> distances(from.positions.size(), VertexDistance{unused, {unused, unused, unused}});
  const SurfaceMesh target = target_surface(to);
  const bool reachable = target.number_of_faces() > 0;
  std::optional<DistanceTree> tree;
  if (reachable) {
    tree.emplace(faces(target).first, faces(target).second, target);
    tree->accelerate_distance_queries();
  }
  for (const SoupTriangle& triangle : usable_triangles(from)) {
    for (const std::size_t vertex : triangle) {
      if (!std::isnan(distances[vertex].distance)) continue;  // measured from an earlier triangle
      if (!reachable) {
        distances[vertex].distance = std::numeric_limits<double>::infinity();
        continue;
      }
      const Point query = point_of(from.positions[vertex]);
      const Point nearest = tree->closest_point(query);
      distances[vertex] = {std::sqrt(CGAL::squared_distance(query, nearest)), {nearest.x(), nearest.y(), nearest.z()}};
    }
  }
  return distances;
}

nlohmann::json locations_json(const MeshReport& report) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const FacePairAt& pair : report.cgal.self_intersections_at) pairs.push_back({{"faces", pair.faces}, {"at", pair.at}});
  return {{"border_edges", edges_json(report.raw.border_edges_at)},
          {"non_manifold_edges", edges_json(report.raw.non_manifold_edges_at)},
          {"misoriented_edges", edges_json(report.raw.misoriented_edges_at)},
          {"self_intersections", pairs},
          {"listed_at_most", located_cap}};
}

}  // namespace gt
