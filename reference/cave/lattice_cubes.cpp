// The cube walk, air pad, rock test, vertex placement and edge-key welding shared by the cave
// meshers; the rules are stated in lattice_cubes.hpp.
#include "reference/cave/lattice_cubes.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/params/cave.hpp"

namespace gt::reference {
namespace {

template <class Real>
void require_finite(const char* algorithm, const Volume<Real>& density) {
  for (int z = 0; z < density.nz; ++z) {
    for (int y = 0; y < density.ny; ++y) {
      for (int x = 0; x < density.nx; ++x) {
        if (!std::isfinite(density.at(x, y, z))) {
          throw InputError(fmt::format("{}: density sample ({}, {}, {}) is {}; the density must be finite", algorithm,
                                       x, y, z, static_cast<double>(density.at(x, y, z))));
        }
      }
    }
  }
}

void require_keyed_range(const char* algorithm, const std::array<std::int64_t, 3>& origin,
                         const std::array<std::int64_t, 3>& samples, bool solid) {
  if (!lattice_range_fits(origin, samples, solid)) {
    throw InputError(fmt::format(
        "{}: block at lattice ({}, {}, {}) with {}x{}x{} samples{} leaves the edge-key range [{}, {}] per axis",
        algorithm, origin[0], origin[1], origin[2], samples[0], samples[1], samples[2], solid ? " and a pad" : "",
        lattice_coordinate_min, lattice_coordinate_max));
  }
}

}  // namespace

template <class Real>
CaveMeshBuilder<Real>::CaveMeshBuilder(const char* algorithm, const Volume<Real>& density, Real threshold, bool solid,
                                       const std::array<std::int64_t, 3>& lattice_origin, EdgePlacement placement)
    : density_(density),
      // The both-twins mutant threshold_negated: the threshold's sign flipped (gpu/shaders/cave/lattice.glsl alike).
      threshold_(mutant_active("cave.marching_tetrahedra.threshold_negated") ? -threshold : threshold),
      solid_(solid),
      lattice_origin_(lattice_origin),
      placement_(placement) {
  require_finite(algorithm, density);
  require_keyed_range(algorithm, lattice_origin, {density.nx, density.ny, density.nz}, solid);
  const LatticePoint counts = cube_counts();
  slab_z_ = first_cube();
  slab_extent_ = {static_cast<std::size_t>(counts[0]) + 1, static_cast<std::size_t>(counts[1]) + 1};
  slab_vertices_.assign(2 * slab_extent_[0] * slab_extent_[1] * 7, no_vertex);
}

template <class Real>
std::uint32_t& CaveMeshBuilder<Real>::slab_vertex(const LatticePoint& lower, int direction) {
  if (lower[2] < slab_z_) throw std::logic_error("CaveMeshBuilder: cubes must come in non-decreasing z");
  const std::size_t slab_size = slab_extent_[0] * slab_extent_[1] * 7;
  while (lower[2] > slab_z_ + 1) {  // the walk moved up: the lower slab's edges are done with
    std::copy(slab_vertices_.begin() + static_cast<std::ptrdiff_t>(slab_size), slab_vertices_.end(),
              slab_vertices_.begin());
    std::fill(slab_vertices_.begin() + static_cast<std::ptrdiff_t>(slab_size), slab_vertices_.end(), no_vertex);
    ++slab_z_;
  }
  const int first = first_cube();
  const std::size_t point = (static_cast<std::size_t>(lower[2] - slab_z_) * slab_extent_[1] +
                             static_cast<std::size_t>(lower[1] - first)) * slab_extent_[0] +
                            static_cast<std::size_t>(lower[0] - first);
  return slab_vertices_[point * 7 + static_cast<std::size_t>(direction - 1)];
}

template <class Real>
LatticePoint CaveMeshBuilder<Real>::cube_counts() const {
  const int extra = solid_ ? 1 : -1;
  const auto count = [extra](int samples) { return samples > 0 ? std::max(samples + extra, 0) : 0; };
  return {count(density_.nx), count(density_.ny), count(density_.nz)};
}

template <class Real>
bool CaveMeshBuilder<Real>::is_pad(const LatticePoint& point) const {
  return point[0] < 0 || point[1] < 0 || point[2] < 0 || point[0] >= density_.nx || point[1] >= density_.ny ||
         point[2] >= density_.nz;
}

template <class Real>
bool CaveMeshBuilder<Real>::is_rock(const LatticePoint& point) const {
  return !is_pad(point) && density_.at(point[0], point[1], point[2]) < threshold_;
}

template <class Real>
unsigned CaveMeshBuilder<Real>::rock_corners(const LatticePoint& cube) const {
  unsigned bits = 0;
  for (int corner = 0; corner < 8; ++corner) {
    const LatticePoint offset = corner_offset(corner);
    if (is_rock({cube[0] + offset[0], cube[1] + offset[1], cube[2] + offset[2]})) bits |= 1u << corner;
  }
  return bits;
}

template <class Real>
void CaveMeshBuilder<Real>::add_triangle(const LatticePoint& cube, const std::array<CornerPair, 3>& edges) {
  // Mutant (both twins): the indices counted from 1, as an OBJ file counts them, in a 0-based buffer.
  const std::uint32_t base = mutant_active("cave.marching_tetrahedra.vertex_numbers_from_one") ? 1 : 0;
  const std::uint32_t first = edge_vertex(cube, edges[0]), second = edge_vertex(cube, edges[1]);
  mesh_.triangles.push_back({first + base, second + base, edge_vertex(cube, edges[2]) + base});
}

template <class Real>
std::uint32_t CaveMeshBuilder<Real>::edge_vertex(const LatticePoint& cube, const CornerPair& edge) {
  const LatticePoint lower_offset = corner_offset(edge[0]);
  const LatticePoint upper_offset = corner_offset(edge[1]);
  const LatticePoint lower{cube[0] + lower_offset[0], cube[1] + lower_offset[1], cube[2] + lower_offset[2]};
  const LatticePoint upper{cube[0] + upper_offset[0], cube[1] + upper_offset[1], cube[2] + upper_offset[2]};
  const int direction = edge[1] - edge[0];
  std::uint32_t& vertex = slab_vertex(lower, direction);
  if (vertex == no_vertex) {
    vertex = static_cast<std::uint32_t>(mesh_.positions.size());
    mesh_.positions.push_back(vertex_position(lower, upper, direction));
    mesh_.edge_keys.push_back(lattice_edge_key(
        {lattice_origin_[0] + lower[0], lattice_origin_[1] + lower[1], lattice_origin_[2] + lower[2]}, direction));
  }
  return vertex;
}

// The calibrated pair of the vertex model (parity.vertex_model.float_vs_double's rounding-only
// bound): ref<float>'s t 2^-18 too large (above the bound), or one ulp too large (below it).
namespace {
template <class Real>
Real calibrated_float_t(Real t) {
  if constexpr (std::is_same_v<Real, float>) {
    if (mutant_active("cave.marching_tetrahedra.float_t_off_above_bound")) return t + 0x1p-18f;
    if (mutant_active("cave.marching_tetrahedra.float_t_one_ulp_below_bound")) return std::nextafter(t, 2.0f);
  }
  return t;
}
}  // namespace

template <class Real>
std::array<Real, 3> CaveMeshBuilder<Real>::vertex_position(const LatticePoint& lower, const LatticePoint& upper,
                                                           int direction) const {
  Real t = Real(0.5);
  // The both-twins mutant midpoint_off: midpoint placement a quarter along the edge (lattice.glsl alike).
  if (placement_ == EdgePlacement::midpoint && !is_pad(lower) && !is_pad(upper) &&
      mutant_active("cave.marching_tetrahedra.midpoint_off")) {
    t = Real(0.25);
  }
  if (placement_ == EdgePlacement::linear && !is_pad(lower) && !is_pad(upper)) {
    const Real lower_value = density_.at(lower[0], lower[1], lower[2]);
    const Real upper_value = density_.at(upper[0], upper[1], upper[2]);
    const auto margin = static_cast<Real>(edge_margin(
        {lattice_origin_[0] + lower[0], lattice_origin_[1] + lower[1], lattice_origin_[2] + lower[2]}, direction));
    t = std::clamp((threshold_ - lower_value) / (upper_value - lower_value), margin, Real(1) - margin);
    // The both-twins mutant vertex_wrong_end: t measured from the upper end (gpu/shaders/cave/lattice.glsl alike).
    if (mutant_active("cave.marching_tetrahedra.vertex_wrong_end")) t = Real(1) - t;
    t = calibrated_float_t(t);
  }
  const LatticePoint step = corner_offset(direction);
  std::array<Real, 3> position{};
  for (int axis = 0; axis < 3; ++axis) {
    position[axis] = static_cast<Real>(lattice_origin_[axis] + lower[axis]) + t * static_cast<Real>(step[axis]);
  }
  return position;
}

template class CaveMeshBuilder<float>;
template class CaveMeshBuilder<double>;

}  // namespace gt::reference
