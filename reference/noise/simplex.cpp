// Simplex noise (Perlin 2001, as written by Gustavson 2005 and ported by Eshelman; seed 004 digest
// §2.2.3 for 3-D, §2.2.4 for 2-D and 4-D), one generic n-dimensional routine:
//   1. skew: s = (Σ p_a)·F, cell origin i_a = floor(p_a + s);
//   2. unskew: d0_a = p_a - (i_a - (Σ i_a)·G), the offset from the cell's first corner;
//   3. rank the axes by d0 (largest first); corner m (0..n) steps +1 along the m highest-ranked
//      axes, its offset is d_m = (d0 - step_m) + m·G;
//   4. corner gradient g = table[perm[i_0+s_0 + perm[i_1+s_1 + ...]] % size] (innermost axis last);
//   5. value = scale · Σ_m t_m⁴ (g_m·d_m) with t_m = r2 - |d_m|², corners with t_m <= 0 giving 0.
// The analytic gradient differentiates step 5 inside one simplex:
//   ∇(t⁴ (g·d)) = -8 t³ (g·d) d + t⁴ g.
//
// Decisions where the sources are vague or wrong:
//   - True floor instead of Eshelman's fastfloor, which is wrong at 0 and negative integers (digest
//     §2.2.3 note; lattice_floor.hpp computes it without a libm call); the GLSL twin uses floor() too.
//   - Ties in the axis ranking follow the sources: 3-D ranks with >= (the lower axis wins, as
//     Gustavson's 3-D if/else chain), 2-D and 4-D with > (the higher axis wins, as the 2-D branch
//     and the 4-D comparison table). A tie puts p on a simplex face, where the 0.6 kernel is
//     discontinuous, so the choice decides the value there.
//   - Hash: perm[(i + step + h) & 255] on the 256-entry table, equal to the sources' doubled table
//     perm2[(i & 255) + step + h] because perm2[k] = perm[k mod 256].
//   - Operation order is Eshelman's, written out so that the float instantiation and the shader
//     agree rounding for rounding: sums left to right, t = ((r2 - d_0²) - d_1²) - ..., t⁴ =
//     (t·t)·(t·t), value term t⁴·(g·d), total = scale·((n_0 + n_1) + ...). In double this
//     reproduces the thesis's Figure 3.2 listing, whose signs at integer inputs are rounding noise.
//   - Corner 0 goes through the same formula (d0 - 0) + 0 as the others: the same value, only the
//     sign of a zero can differ from the sources.
//   - F, G and m·G are the exact values rounded once (simplex.hpp); the sources compute F2, G2, F4
//     and G4 with sqrt at run time, which in double is 1 ulp off for F2 and G2 and moves values by
//     up to 3.2e-14. With the sources' constants this code gives their doubles bit for bit.
#include "reference/noise/simplex.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "core/mutant.hpp"
#include "reference/noise/lattice_floor.hpp"

namespace gt::reference {
namespace {

template <class Real, std::size_t N>
using Vector = std::array<Real, N>;

template <std::size_t N>
using Lattice = std::array<int, N>;

// grad3 in Eshelman's order (digest §2.2.3): the 12 cube edge midpoints; 2-D uses its x, y parts.
constexpr std::array<Lattice<3>, 12> grad3{{{1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0},
                                            {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
                                            {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}}};

// grad4 in Gustavson's order: all permutations of (0, ±1, ±1, ±1), the zero moving from x to w.
constexpr std::array<Lattice<4>, 32> grad4{{
    {0, 1, 1, 1},  {0, 1, 1, -1},  {0, 1, -1, 1},  {0, 1, -1, -1},  {0, -1, 1, 1},  {0, -1, 1, -1},  {0, -1, -1, 1},
    {0, -1, -1, -1}, {1, 0, 1, 1},  {1, 0, 1, -1},  {1, 0, -1, 1},  {1, 0, -1, -1},  {-1, 0, 1, 1},  {-1, 0, 1, -1},
    {-1, 0, -1, 1}, {-1, 0, -1, -1}, {1, 1, 0, 1},  {1, 1, 0, -1},  {1, -1, 0, 1},  {1, -1, 0, -1},  {-1, 1, 0, 1},
    {-1, 1, 0, -1}, {-1, -1, 0, 1}, {-1, -1, 0, -1}, {1, 1, 1, 0},  {1, 1, -1, 0},  {1, -1, 1, 0},  {1, -1, -1, 0},
    {-1, 1, 1, 0},  {-1, 1, -1, 0}, {-1, -1, 1, 0}, {-1, -1, -1, 0},
}};

// What differs between the dimensions.
template <std::size_t N>
struct Variant;

template <>
struct Variant<2> {
  static constexpr const SimplexLattice& lattice = simplex_lattice2;
  static constexpr bool ties_to_lower_axis = false;
  static constexpr double scale = 70.0;
};

template <>
struct Variant<3> {
  static constexpr const SimplexLattice& lattice = simplex_lattice3;
  static constexpr bool ties_to_lower_axis = true;
  static constexpr double scale = 32.0;
};

template <>
struct Variant<4> {
  static constexpr const SimplexLattice& lattice = simplex_lattice4;
  static constexpr bool ties_to_lower_axis = false;
  static constexpr double scale = 27.0;
};

// grad3's entry for a hash. Mutant noise.simplex3.grad3_swapped (both twins): the
// table's first two entries exchanged, a transcription slip.
std::uint32_t grad3_index(std::uint32_t hash) {
  const std::uint32_t index = hash % 12;
  if (index < 2 && mutant_active("noise.simplex3.grad3_swapped")) return 1 - index;
  return index;
}

// The tables in precision Real, so that a corner costs no int-to-float conversion (their entries
// are 0 and ±1: exact either way).
template <class Real, std::size_t N, std::size_t Count>
constexpr std::array<Vector<Real, N>, Count> in_precision(const std::array<Lattice<N>, Count>& table) {
  std::array<Vector<Real, N>, Count> converted{};
  for (std::size_t entry = 0; entry < Count; ++entry) {
    for (std::size_t axis = 0; axis < N; ++axis) converted[entry][axis] = static_cast<Real>(table[entry][axis]);
  }
  return converted;
}

template <class Real>
constexpr auto grad3_in_precision = in_precision<Real>(grad3);
template <class Real>
constexpr auto grad4_in_precision = in_precision<Real>(grad4);

template <class Real, std::size_t N>
Vector<Real, N> corner_gradient(std::uint32_t hash) {
  if constexpr (N == 4) {
    return grad4_in_precision<Real>[hash % 32];
  } else {
    const Vector<Real, 3>& gradient = grad3_in_precision<Real>[grad3_index(hash)];
    Vector<Real, N> components{};
    for (std::size_t axis = 0; axis < N; ++axis) components[axis] = gradient[axis];
    return components;
  }
}

template <class Real, std::size_t N>
Real left_to_right_sum(const Vector<Real, N>& terms) {
  Real sum = terms[0];
  for (std::size_t axis = 1; axis < N; ++axis) sum = sum + terms[axis];
  return sum;
}

template <class Real, std::size_t N>
struct Cell {
  Lattice<N> origin;        // skewed lattice coordinates of the cell's first corner
  Vector<Real, N> offset;   // p minus that corner, unskewed
};

template <class Real, std::size_t N>
Cell<Real, N> locate_cell(const Vector<Real, N>& point) {
  const SimplexLattice& lattice = Variant<N>::lattice;
  const Real skew = left_to_right_sum(point) * static_cast<Real>(lattice.skew);
  Cell<Real, N> cell{};
  // 64 bits: the sum of N indices of up to 2^31 each (GLSL's int sum wraps; params keep the twins
  // below that, core/params/noise.cpp check_lattice_range, but the reference takes any point).
  std::int64_t origin_sum = 0;
  for (std::size_t axis = 0; axis < N; ++axis) {
    cell.origin[axis] = lattice_floor(point[axis] + skew);
    origin_sum += cell.origin[axis];
  }
  const Real unskew = static_cast<Real>(origin_sum) * static_cast<Real>(lattice.corner_unskew[1]);
  for (std::size_t axis = 0; axis < N; ++axis) {
    cell.offset[axis] = point[axis] - (static_cast<Real>(cell.origin[axis]) - unskew);
  }
  return cell;
}

// rank[a] = how many axes axis a precedes in the traversal order (largest offset first).
template <class Real, std::size_t N>
Lattice<N> axis_ranks(const Vector<Real, N>& offset) {
  Lattice<N> rank{};
  for (std::size_t first = 0; first < N; ++first) {
    for (std::size_t second = first + 1; second < N; ++second) {
      const bool first_leads =
          Variant<N>::ties_to_lower_axis ? offset[first] >= offset[second] : offset[first] > offset[second];
      ++rank[first_leads ? first : second];
    }
  }
  return rank;
}

// Corner m steps along the axes of rank >= n - m: none for m = 0, all for m = n.
template <std::size_t N>
Lattice<N> corner_step(const Lattice<N>& rank, std::size_t corner) {
  Lattice<N> step{};
  for (std::size_t axis = 0; axis < N; ++axis) step[axis] = rank[axis] >= static_cast<int>(N - corner) ? 1 : 0;
  return step;
}

template <std::size_t N>
std::uint32_t corner_hash(const Permutation& perm, const Lattice<N>& origin, const Lattice<N>& step) {
  std::uint32_t hash = 0;
  for (std::size_t axis = N; axis-- > 0;) {
    hash = perm[static_cast<std::uint32_t>(origin[axis] + step[axis] + static_cast<int>(hash)) & 255u];
  }
  return hash;
}

// What a sum computes: the value alone (1 component) or the value and its N derivatives. The
// value's operations are the same in both, so it is the same bits.
template <std::size_t N, bool WithGradient>
constexpr std::size_t components = WithGradient ? N + 1 : 1;

// {t⁴ (g·d), its derivatives along each axis (WithGradient)}; zeros outside the kernel.
template <class Real, std::size_t N, bool WithGradient>
Vector<Real, components<N, WithGradient>> corner_contribution(const Vector<Real, N>& gradient, const Vector<Real, N>& offset,
                                                              Real kernel_radius_squared) {
  Vector<Real, components<N, WithGradient>> contribution{};
  Real falloff = kernel_radius_squared;
  for (std::size_t axis = 0; axis < N; ++axis) falloff = falloff - (offset[axis] * offset[axis]);
  if (!(falloff > Real(0))) return contribution;
  Real along = gradient[0] * offset[0];
  for (std::size_t axis = 1; axis < N; ++axis) along = along + (gradient[axis] * offset[axis]);
  const Real falloff2 = falloff * falloff;
  const Real falloff4 = falloff2 * falloff2;
  contribution[0] = falloff4 * along;
  if constexpr (WithGradient) {
    const Real slope = (Real(-8) * (falloff2 * falloff)) * along;
    for (std::size_t axis = 0; axis < N; ++axis) {
      contribution[axis + 1] = (slope * offset[axis]) + (falloff4 * gradient[axis]);
    }
  }
  return contribution;
}

// {value} or {value, d/dx_0, ..., d/dx_{n-1}}.
template <class Real, std::size_t N, bool WithGradient>
Vector<Real, components<N, WithGradient>> simplex_sum(const Permutation& perm, const Vector<Real, N>& point,
                                                      Real kernel_radius_squared) {
  const Cell<Real, N> cell = locate_cell(point);
  const Lattice<N> rank = axis_ranks(cell.offset);
  Vector<Real, components<N, WithGradient>> total{};
  for (std::size_t corner = 0; corner <= N; ++corner) {
    const Lattice<N> step = corner_step(rank, corner);
    const Real unskew = static_cast<Real>(Variant<N>::lattice.corner_unskew[corner]);
    Vector<Real, N> offset{};
    for (std::size_t axis = 0; axis < N; ++axis) {
      offset[axis] = (cell.offset[axis] - static_cast<Real>(step[axis])) + unskew;
    }
    const Vector<Real, N> gradient = corner_gradient<Real, N>(corner_hash(perm, cell.origin, step));
    const auto contribution = corner_contribution<Real, N, WithGradient>(gradient, offset, kernel_radius_squared);
    for (std::size_t component = 0; component < total.size(); ++component) {
      total[component] = total[component] + contribution[component];
    }
  }
  for (Real& component : total) component = static_cast<Real>(Variant<N>::scale) * component;
  return total;
}

}  // namespace

template <class Real>
Real simplex2(const Permutation& perm, Real x, Real y) {
  return simplex_sum<Real, 2, false>(perm, {x, y}, Real(0.5))[0];
}

template <class Real>
Real simplex3(const Permutation& perm, Real x, Real y, Real z, Real kernel_radius_squared) {
  return simplex_sum<Real, 3, false>(perm, {x, y, z}, kernel_radius_squared)[0];
}

template <class Real>
Real simplex4(const Permutation& perm, Real x, Real y, Real z, Real w, Real kernel_radius_squared) {
  return simplex_sum<Real, 4, false>(perm, {x, y, z, w}, kernel_radius_squared)[0];
}

template <class Real>
std::array<Real, 3> simplex2_gradient(const Permutation& perm, Real x, Real y) {
  return simplex_sum<Real, 2, true>(perm, {x, y}, Real(0.5));
}

template <class Real>
std::array<Real, 4> simplex3_gradient(const Permutation& perm, Real x, Real y, Real z, Real kernel_radius_squared) {
  return simplex_sum<Real, 3, true>(perm, {x, y, z}, kernel_radius_squared);
}

#define GT_INSTANTIATE_SIMPLEX(Real)                                                                  \
  template Real simplex2(const Permutation&, Real, Real);                                             \
  template Real simplex3(const Permutation&, Real, Real, Real, Real);                                 \
  template Real simplex4(const Permutation&, Real, Real, Real, Real, Real);                           \
  template std::array<Real, 3> simplex2_gradient(const Permutation&, Real, Real);                     \
  template std::array<Real, 4> simplex3_gradient(const Permutation&, Real, Real, Real, Real);

GT_INSTANTIATE_SIMPLEX(float)
GT_INSTANTIATE_SIMPLEX(double)
#undef GT_INSTANTIATE_SIMPLEX

}  // namespace gt::reference
