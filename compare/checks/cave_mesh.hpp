// Comparisons of cave meshes whose vertices carry global lattice edge keys (reference/cave/
// lattice_cubes.hpp, core/params/cave.hpp): the parity, seam and volume checks of issue 5.
//
// A keyed mesh names each triangle by the keys of its three vertices, so two meshes (two
// backends, two precisions, neighbouring chunks) compare exactly without matching positions:
//   key_triangles      each triangle as its key triple, rotated so the smallest key comes first
//                      (orientation kept), sorted; triangle_difference counts the symmetric
//                      difference of two such multisets.
//   compare_vertices   vertices of equal key: how many in both or one only, largest distance,
//                      and the largest distance relative to a per-vertex bound.
//   border_edges       edges used by one triangle, as directed vertex pairs.
//   border_edges_off_box   border edges whose two vertices do not lie on one face plane of the
//                      lattice box [low, high] (for an open chunk, the only border allowed is on
//                      the box's faces). A vertex lies on the plane axis = c when its edge lies in
//                      that plane: lower point's coordinate c and no step along the axis.
// Volume against the field (volume_bound_from_field): the mesh of a solid block partitions every
// cube of the padded lattice into rock and air, so the mesh volume inside a cube lies in [0, 1]
// (lattice units³). Counting the cube's rock corners k gives the estimate k/8, off by at most
// max(k, 8 - k)/8 for a cube the surface cuts and exactly 0 for a cube it does not (all corners
// alike: marching tetrahedra puts no triangle there). Summed over cubes the estimate is the number
// of rock samples (each sample is a corner of 8 cubes; pad samples are air) and the bound is
// Σ max(k, 8 - k)/8 over cut cubes: about (surface area) · spacing, so it shrinks with the spacing.
// Vertices against the field (vertex_crossings): the mesh's specification says where each vertex
// sits, and the check asks the field, not a mesher: a vertex keyed to lattice edge a -> b = a + d
// must lie on an edge the surface crosses (exactly one endpoint rock: value < threshold, samples
// outside the volume are the air pad) at the crossing of the linear interpolant,
//   c = a + t*·d,  t* = (θ - v_a)/(v_b - v_a)      (both endpoints samples, linear placement)
//   c = a + d/2                                    (an endpoint in the pad, or midpoint placement)
// A mesher in double may stand off c (∞-norm, lattice units) by at most
//   δ (the clamp to [δ, 1 - δ], core/params/cave.hpp edge_margin; linear placement only)
//   + 3u (t's subtraction, subtraction and division) + u·(m + 1) (the position's rounding)
//   + 3u + u·(m + 1) (this check's own t* and c)
// for m the largest |coordinate| of the edge and u = 2^-53; vertex_crossing_bound doubles the
// rounding terms for slack: 8u·(m + 2). A vertex placed from the wrong end of its edge (1 - t*) or
// meshed at another threshold stands off by a sizeable fraction of its edge. Only meshes in double
// are held to it (a float mesh's density errs by ε, parity.vertex_model's business).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "core/mesh.hpp"
#include "core/params/cave.hpp"
#include "core/volume.hpp"

namespace gt {

using KeyTriangle = std::array<std::uint64_t, 3>;

// The key key_triangles gives a corner whose index names no vertex (a broken GPU mesh): no lattice
// edge has it (keys use 63 bits), so such a triangle differs from every real one.
inline constexpr std::uint64_t missing_vertex_key = ~std::uint64_t{0};

// One triangle as its key triple, rotated so that the smallest key comes first (orientation kept).
template <class Real>
KeyTriangle key_triangle(const TriangleMesh<Real>& mesh, const std::array<std::uint32_t, 3>& triangle);

template <class Real>
std::vector<KeyTriangle> key_triangles(const TriangleMesh<Real>& mesh);

std::size_t triangle_difference(const std::vector<KeyTriangle>& a, const std::vector<KeyTriangle>& b);

// The triangles in one multiset only.
std::vector<KeyTriangle> triangles_in_one_only(const std::vector<KeyTriangle>& a, const std::vector<KeyTriangle>& b);

struct LatticeBox;

// The lattice points of the cube a mesher made the triangle in: the bounding box of its three
// edges, widened to both cubes along an axis where the edges are flat (a triangle on a cube face).
LatticeBox triangle_cube(const KeyTriangle& triangle);

template <class Real>
Mesh to_double_mesh(const TriangleMesh<Real>& mesh);

struct VertexComparison {
  std::size_t matched = 0;
  std::size_t only_in_a = 0;
  std::size_t only_in_b = 0;
  std::size_t bit_differences = 0;  // matched vertices whose coordinates differ at all
  double max_distance = 0.0;        // Euclidean, over matched vertices
  double max_bound_ratio = 0.0;     // max distance / bound(key), when a bound is given
};

// bound(key) > 0 gives each vertex its allowed distance; an empty function: no bound.
template <class RealA, class RealB>
VertexComparison compare_vertices(const TriangleMesh<RealA>& a, const TriangleMesh<RealB>& b,
                                  const std::function<double(std::uint64_t)>& bound = {});

template <class Real>
std::vector<std::array<std::uint32_t, 2>> border_edges(const TriangleMesh<Real>& mesh);

// Whether the vertex on lattice edge `key` lies on the plane where coordinate `axis` is `value`.
bool key_on_plane(std::uint64_t key, int axis, std::int64_t value);

struct LatticeBox {
  std::array<std::int64_t, 3> low;
  std::array<std::int64_t, 3> high;
  bool contains(const std::array<std::int64_t, 3>& point) const {
    for (int axis = 0; axis < 3; ++axis) {
      if (point[axis] < low[axis] || point[axis] > high[axis]) return false;
    }
    return true;
  }
};

template <class Real>
std::size_t border_edges_off_box(const TriangleMesh<Real>& mesh, const LatticeBox& box);

// The lattice points a block of CaveParams spans: origin .. origin + size per axis.
LatticeBox lattice_box(const CaveParams& params);

// Largest distance a GPU vertex may lie from ref<float>'s when both run the same float operations
// and GLSL's division errs by up to 2.5 ulp: 3u in t plus one rounding of a position of magnitude
// up to `magnitude`, on three axes: √3·u·(3 + 2·(magnitude + 1)). 0 would do on llvmpipe.
double gpu_vertex_bound(double magnitude);

// Writes `mesh` as report_dir/<case>/<file> and lists it among the case's artifacts (nothing
// without a report folder).
void write_mesh_artifact(const Mesh& mesh, const std::string& file, const std::string& caption,
                         const RunOptions& options, CaseResult& result);

struct FieldVolume {
  double rock_samples = 0.0;  // the estimate, lattice units³
  double bound = 0.0;         // Σ max(k, 8 - k)/8 over the cubes the surface cuts
  std::size_t cut_cubes = 0;
};

// For a solid (air-padded) block: rock iff value < threshold, pad samples air.
FieldVolume volume_bound_from_field(const Volume<double>& density, double threshold);

// The exact volume the mesh of a solid block must enclose (issue 38's a-priori cave bound): the
// union over the padded lattice's Kuhn tetrahedra (6 a cube, each the path 0 → e_a → e_a + e_b →
// (1,1,1)) of the part of the tetrahedron that is rock under the mesher's own rule, the crossing of
// each cut edge at t = (θ − v_a)/(v_b − v_a) clamped to [δ, 1 − δ] (edge_margin), or its midpoint
// with midpoint placement or a pad endpoint. With k rock corners: the corner tetrahedron cut at the
// crossings (k = 1), the whole less the air corner's (k = 3), or the prism between the two rock
// corners' cut triangles (k = 2, three tetrahedra). A quad whose corners are not coplanar (an edge
// to the pad at its midpoint beside interpolated ones, a clamped t) encloses a volume that depends
// on the diagonal it is split along: the digest's table's (seed 004 §2.6: from the first rock
// vertex's crossing towards the first air vertex, in its tetrahedra's vertex order). Computed in each
// cube's own coordinates (no large numbers), summed compensated; lattice units³.
struct PiecewiseLinearVolume {
  double volume = 0.0;
  std::size_t cut_tetrahedra = 0;  // with 1 to 3 rock corners
};
PiecewiseLinearVolume piecewise_linear_volume(const Volume<double>& density, double threshold,
                                              const std::array<std::int64_t, 3>& origin, bool linear_placement);

// The volume a closed mesh encloses, Σ det(p0 − o, p1 − o, p2 − o)/6 over its triangles with o the
// lattice point `origin` (so the determinants see the block's extent, not its distance from the
// noise's origin), summed compensated.
double enclosed_volume(const Mesh& mesh, const std::array<std::int64_t, 3>& origin);

struct VertexCrossings {
  std::size_t vertices = 0;
  std::size_t unkeyed = 0;          // on no lattice edge (missing_vertex_key): not judged here
  std::size_t not_crossing = 0;     // keyed to an edge whose endpoints are both rock or both air
  std::size_t excused = 0;          // on an edge whose crossing the density error leaves open
  std::size_t off_crossing = 0;     // on a crossing edge, farther than its bound from c
  double max_distance = 0.0;        // largest ∞-norm distance from c over crossing edges (lattice units)
  double max_bound_ratio = 0.0;     // largest distance / its bound
};

// How far a mesher's vertices may stand off the crossing c, beyond the edge margin δ: 8u·(m + 2)
// for its arithmetic's unit roundoff u (2^-53 for the references in double, 2^-24 for a float
// mesher), and for a mesher that samples the density itself (a user's candidate mesh) its samples'
// a-priori error ε (parity.density.float_vs_double's) plus the float rounding of the threshold,
// e = ε + u_float·|θ|. An edge with an endpoint within e of θ may cross in its samples or not, and
// its vertex lies anywhere on it (excused); on any other edge each endpoint value errs by at most e,
// so t* moves by at most 2e / (|v_b - v_a| - 2e) (first order in e; the endpoints differ by more
// than 2e since they lie on opposite sides of θ, each farther than e).
struct CrossingModel {
  double unit_roundoff = 0x1p-53;
  double density_error = 0.0;  // e as above; 0: the mesher meshes these very samples
};

// The bound of the file comment for a mesh in double: the edge's margin (linear placement with
// both endpoints samples, else 0) + 8u·(m + 2).
double vertex_crossing_bound(double margin, double magnitude, double unit_roundoff = 0x1p-53);

// Every vertex of `mesh` (keyed) against the field: sample (0, 0, 0) of `density` is global lattice
// point `origin`; `linear_placement` false: midpoints everywhere.
VertexCrossings vertex_crossings(const Mesh& mesh, const Volume<double>& density, double threshold,
                                 const std::array<std::int64_t, 3>& origin, bool linear_placement,
                                 const CrossingModel& model = {});

// Keys a mesh that carries no edge keys (a user's file) by the lattice edges of the Kuhn
// decomposition its vertices lie on, and returns how many lie on none. A vertex lies on edge
// a -> a + d (d's components 0 or 1, not all 0) when every coordinate is within τ of an integer
// (that of a) except those along d, whose fractional parts agree within τ; τ = δ/4 for the edge
// margin δ of its neighbourhood (core/params/cave.hpp edge_margin): far above a float position's
// rounding, far below the margin every honest vertex keeps from a lattice point. A vertex on no
// such edge, on a lattice point, or beyond the keys' range gets missing_vertex_key.
std::size_t key_by_lattice_edges(Mesh& mesh);

// The symmetric Hausdorff bound of a mesh that passes key_by_lattice_edges, vertex_crossings and
// parity.crossing_edges against the truth `truth` (see compare/algorithms/cave.cpp). Each triangle
// of a marching-tetrahedra mesh lies in one cube (diameter √3) and each vertex on a lattice edge
// (length at most √3), so:
//   triangles at edges both meshes must cross (no endpoint may change side) lie within 2√3 of each
//     other (a vertex on the same edge in the other mesh);
//   a candidate's triangle at a sample s that may change side lies within 2√3 + D_any(s) of the
//     truth, D_any the distance from s to the truth's nearest vertex;
//   a truth triangle at such a sample (s ends one of the truth's crossing edges) lies within 3√3 +
//     D_shared(s) of the candidate, D_shared the distance from s to the truth's nearest vertex on an
//     edge with no changing endpoint, which the candidate has too.
// The bound is the largest of these; vertices are searched up to `search_radius` points away, and
// a sample with none there makes it infinite. Inputs: the truth mesh (keyed), the samples that may
// change side (global lattice points). Fixed before any candidate is read.
double keyed_hausdorff_bound(const Mesh& truth, const std::vector<std::array<std::int64_t, 3>>& changing_samples,
                             int search_radius = 8);

// The lattice edges (keys) in one mesh only, without an endpoint among `changing_samples`: edges
// that must cross in both meshes or in neither (each lattice edge crossing the threshold carries
// one vertex of a marching-tetrahedra mesh, whichever way its quads are split).
std::size_t crossing_edges_unexplained(const Mesh& a, const Mesh& b,
                                       const std::vector<std::array<std::int64_t, 3>>& changing_samples);

}  // namespace gt
