// What the two cave meshers share (seed 004 digest §2.5–2.7): cube walk, optional air pad, rock test, vertex, welding.
//
// The meshers: marching_tetrahedra.hpp and marching_cubes.hpp. The GPU twin must reproduce every
// rule below; marching_tetrahedra.hpp states them as one specification.
// CaveMeshBuilder(algorithm, density, threshold, solid, lattice_origin, placement): first_cube() and
//   cube_counts() (the cube walk), rock_corners(cube) (bit c set iff corner c of the cube with lower
//   corner `cube` is rock), add_triangle(cube, edges) (appends the triangle through the vertices on
//   the three given edges of the cube), take_mesh().
// for_each_cube(builder, visit) -> calls visit(cube) for every cube of the builder in output order
//   (x fastest, then y, then z).
// corner_offset(corner) -> (dx, dy, dz) of corner c.
//
// Local sample (x, y, z) of the density is global lattice point lattice_origin + (x, y, z); world
// positions are global lattice coordinates (spacing 1; the meshers ignore density.origin and
// density.spacing, which for the cave are the same lattice).
// Cube corners: corner c = dx + 2·dy + 4·dz sits at the cube's lower corner + (dx, dy, dz).
// Cubes: named by their lower corner in local sample coordinates, from `first` to `first + count
// - 1` per axis, visited x fastest, then y, then z. Open: first 0, count n - 1 (no cube when an
// axis has one sample). Solid: the volume is padded with one layer of air samples on every side,
// first -1, count n + 1.
// Rock: a sample inside the volume is rock iff value < threshold (strict; a value equal to the
// threshold is air). Pad samples are air.
// Vertex on the edge from lower point a to upper point b = a + d (d in {0, 1}³, the meshers only
// use edges whose endpoints differ by such a d, so "lower" is the endpoint with the smaller
// global coordinates):
//   t = clamp((threshold - v_a) / (v_b - v_a), δ, 1 - δ)   linear placement, both endpoints inside
//                                                (δ = edge_margin(global a, d) of core/params/cave.hpp)
//   t = 0.5                                      midpoint placement, or either endpoint a pad sample
//   position_c = Real(a_c) + t·Real(d_c)         per axis c, a_c the global coordinate
// (= P_a + t·(P_b - P_a), whose difference d is exact). t is computed from the canonically ordered
// edge, so every cube and every chunk that shares the edge gets the same bits. On a crossing edge
// one value is below the threshold and the other not, so v_b ≠ v_a and 0 <= t <= 1 (rounding is
// monotonic); t = 0 or 1 when a value equals the threshold exactly, which the clamp to [δ, 1 - δ]
// keeps off the lattice points (otherwise: zero-area triangles and touching faces).
// Welding: the first time a triangle uses an edge, the edge gets the next vertex index and its key
// lattice_edge_key(global a, d-bits) goes to edge_keys; later uses share that index. Vertices are
// therefore numbered in order of first use over the triangles in output order, corner by corner.
// Lookup (how, not what): an edge's lower point lies in the cube's z layer or the next, so the
// builder keeps the vertex indices of two z slabs of lower points, 7 directions each, and drops
// the older slab when the walk moves up a layer. Memory is two slabs, time constant per lookup:
// the cost per voxel does not grow with the block (a global hash map's did, by cache misses).
//
// Inputs:  density (Volume<Real>), threshold, solid (pad with air), lattice_origin (global lattice
//          coordinates of sample (0, 0, 0)), placement (linear or midpoint); `algorithm` names the
//          mesher in messages. Cubes must arrive at add_triangle in non-decreasing z, as for_each_cube
//          gives them.
// Outputs: the welded TriangleMesh<Real> with edge_keys (take_mesh).
// Units:   world units (global lattice coordinates, spacing 1).
// Throws:  InputError from the constructor for a non-finite sample or a block whose lattice points
//          (pad included) lie outside the edge keys' range (core/params/cave.hpp); std::logic_error from
//          add_triangle when a cube comes with a lower z than an earlier one.
// Twin:    gpu/shaders/cave/lattice.glsl and cave_block.glsl (the GPU mesher gpu/cave/marching_tetrahedra.hpp).
// Decisions: pad: the cap of a solid block crosses every edge to the pad at its midpoint, half a
//   lattice unit outside the block's faces, independent of the values: simple, exact in float, and
//   the same on both twins. (Treating the pad as a value such as threshold + 1 would move the cap
//   with the boundary values and put vertices at t = 0 for infinite values.)
#pragma once

#include <array>
#include <cstdint>
#include <vector>
#include <utility>

#include "core/mesh.hpp"
#include "core/volume.hpp"

namespace gt::reference {

enum class EdgePlacement { linear, midpoint };

using LatticePoint = std::array<int, 3>;

// A cube edge by its two corners (lower first: the lower corner's bits are a subset of the upper's).
using CornerPair = std::array<int, 2>;

constexpr LatticePoint corner_offset(int corner) { return {corner & 1, (corner >> 1) & 1, corner >> 2}; }

template <class Real>
class CaveMeshBuilder {
 public:
  // Throws InputError for a non-finite sample or a block whose lattice points (pad included) lie
  // outside the edge keys' range (core/params/cave.hpp). `algorithm` names the mesher in messages.
  CaveMeshBuilder(const char* algorithm, const Volume<Real>& density, Real threshold, bool solid,
                  const std::array<std::int64_t, 3>& lattice_origin, EdgePlacement placement);

  int first_cube() const { return solid_ ? -1 : 0; }
  LatticePoint cube_counts() const;

  // Bit c set iff corner c of the cube with lower corner `cube` is rock.
  unsigned rock_corners(const LatticePoint& cube) const;

  // Appends the triangle through the vertices on the three given edges of the cube.
  void add_triangle(const LatticePoint& cube, const std::array<CornerPair, 3>& edges);

  TriangleMesh<Real> take_mesh() { return std::move(mesh_); }

 private:
  bool is_pad(const LatticePoint& point) const;
  bool is_rock(const LatticePoint& point) const;
  std::uint32_t edge_vertex(const LatticePoint& cube, const CornerPair& edge);
  std::array<Real, 3> vertex_position(const LatticePoint& lower, const LatticePoint& upper, int direction) const;

  const Volume<Real>& density_;
  Real threshold_;
  bool solid_;
  std::array<std::int64_t, 3> lattice_origin_;
  EdgePlacement placement_;
  // Vertex index of each (lower point, direction) of z slabs slab_z_ and slab_z_ + 1, or
  // no_vertex; laid out [slab][y][x][direction - 1] over the cubes' lower points and one more.
  static constexpr std::uint32_t no_vertex = 0xFFFFFFFFu;
  std::uint32_t& slab_vertex(const LatticePoint& lower, int direction);
  int slab_z_ = 0;
  std::array<std::size_t, 2> slab_extent_{};  // points per slab along x and y
  std::vector<std::uint32_t> slab_vertices_;
  TriangleMesh<Real> mesh_;
};

// Calls visit(cube) for every cube of the builder in output order (x fastest, then y, then z).
template <class Real, class Visit>
void for_each_cube(const CaveMeshBuilder<Real>& builder, Visit&& visit) {
  const LatticePoint counts = builder.cube_counts();
  const int first = builder.first_cube();
  for (int z = first; z < first + counts[2]; ++z) {
    for (int y = first; y < first + counts[1]; ++y) {
      for (int x = first; x < first + counts[0]; ++x) visit(LatticePoint{x, y, z});
    }
  }
}

}  // namespace gt::reference
