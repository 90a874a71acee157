// Improved Perlin noise in 3-D (Perlin 2002; digest 002 §4.4.3), value and analytic gradient.
//
// As Perlin's reference ImprovedNoise.java:
//   cell (X, Y, Z) = floor(p) & 255, local d = p − floor(p), weights u, v, w = fade(d);
//   corner c ∈ {0,1}³ hashes to h_c = P[P[P[X + c_x] + Y + c_y] + Z + c_z] with P the table doubled
//   to 512 entries (written here as perm[i & 255], the same for every i < 512);
//   corner value n_c = Grad(h_c, d − c) with h = h_c & 15, u = h < 8 ? d_x : d_y,
//   v = h < 4 ? d_y : (h == 12 || h == 14 ? d_x : d_z), Grad = (h & 1 ? −u : u) + (h & 2 ? −v : v);
//   value = lerp(w, lerp(v, lerp(u, n000, n100), lerp(u, n010, n110)),
//                   lerp(v, lerp(u, n001, n101), lerp(u, n011, n111))).
// Decisions:
//   - lerp is a + t·(b − a) (Perlin's form), the same in the shader; fade is Perlin's Horner form.
//   - The gradient differentiates the same lerp tree: along axis a with weight s = fade(d_a),
//     lerp(s, A, B) has derivative lerp(s, A', B') in every component plus fade'(d_a)·(B − A) in
//     component a, where fade'(t) = (t·t)·(t·(t·30 − 60) + 30). Corner gradients are Grad's
//     selected axes with signs ±1, so corner values and their derivatives are exact.
//   - d − c is written as d − 1 or d − 0 (exact), as the reference does.
#include "reference/noise/perlin.hpp"

#include "reference/noise/lattice_floor.hpp"

namespace gt::reference {
namespace {

template <class Real>
struct Cell {
  std::array<int, 3> lattice;  // floor(p) & 255
  std::array<Real, 3> local;   // p − floor(p)
};

template <class Real>
Cell<Real> locate(Real x, Real y, Real z) {
  const std::array<Real, 3> point = {x, y, z};
  Cell<Real> cell{};
  for (int axis = 0; axis < 3; ++axis) {
    const int lower = lattice_floor(point[axis]);
    cell.lattice[axis] = lower & 255;
    cell.local[axis] = point[axis] - static_cast<Real>(lower);
  }
  return cell;
}

int permuted(const Permutation& permutation, int index) { return permutation[index & 255]; }

template <class Real>
int corner_hash(const Permutation& permutation, const Cell<Real>& cell, int cx, int cy, int cz) {
  const int hash_x = permuted(permutation, cell.lattice[0] + cx);
  const int hash_xy = permuted(permutation, hash_x + cell.lattice[1] + cy);
  return permuted(permutation, hash_xy + cell.lattice[2] + cz);
}

// Grad's selection for h = hash & 15: the axes of u and v and their signs, as a table, so that a
// corner value needs no branch on the hash (random from sample to sample at high frequencies,
// where fbm's upper octaves mispredict such branches). Multiplying by ±1 is exact, so
// sign·u + sign·v is Grad's (±u) + (±v) bit for bit.
struct GradientChoice {
  std::array<int, 2> axes;     // u's axis, v's axis
  std::array<double, 2> signs;  // −1 where h & 1 (u), h & 2 (v)
};
using GradientChoices = std::array<GradientChoice, 16>;

// `second_x`: the second h whose v is x (14 in Perlin's Grad).
constexpr GradientChoices gradient_choices(int second_x) {
  GradientChoices choices{};
  for (int h = 0; h < 16; ++h) {
    const int u_axis = h < 8 ? 0 : 1;
    const int v_axis = h < 4 ? 1 : (h == 12 || h == second_x ? 0 : 2);
    choices[h] = {{u_axis, v_axis}, {(h & 1) != 0 ? -1.0 : 1.0, (h & 2) != 0 ? -1.0 : 1.0}};
  }
  return choices;
}

constexpr GradientChoices perlin_choices = gradient_choices(14);
// Mutant noise.perlin3.grad_select (both twins): 13 where 14 belongs, a typo that moves
// two of Perlin's 16 gradients.
constexpr GradientChoices grad_select_mutant_choices = gradient_choices(13);

const GradientChoices& active_choices() {
  return mutant_active("noise.perlin3.grad_select") ? grad_select_mutant_choices : perlin_choices;
}

template <class Real>
std::array<Real, 3> corner_offset(const Cell<Real>& cell, int cx, int cy, int cz) {
  return {cell.local[0] - Real(cx), cell.local[1] - Real(cy), cell.local[2] - Real(cz)};
}

template <class Real>
Real grad(const GradientChoice& choice, const std::array<Real, 3>& offset) {
  return Real(choice.signs[0]) * offset[choice.axes[0]] + Real(choice.signs[1]) * offset[choice.axes[1]];
}

template <class Real>
Real corner_value(const Permutation& permutation, const GradientChoices& choices, const Cell<Real>& cell, int cx,
                  int cy, int cz) {
  return grad(choices[corner_hash(permutation, cell, cx, cy, cz) & 15], corner_offset(cell, cx, cy, cz));
}

template <class Real>
std::array<Real, 4> corner_sample(const Permutation& permutation, const GradientChoices& choices, const Cell<Real>& cell,
                                  int cx, int cy, int cz) {
  const GradientChoice& choice = choices[corner_hash(permutation, cell, cx, cy, cz) & 15];
  std::array<Real, 4> sample = {grad(choice, corner_offset(cell, cx, cy, cz)), Real(0), Real(0), Real(0)};
  sample[1 + choice.axes[0]] = Real(choice.signs[0]);
  sample[1 + choice.axes[1]] = Real(choice.signs[1]);
  return sample;
}

template <class Real>
Real fade_derivative(Real t) {
  return t * t * (t * (t * Real(30) - Real(60)) + Real(30));
}

// lerp(s, a, b) of value and gradient, s = fade(t) along `axis`.
template <class Real>
std::array<Real, 4> lerp_along(int axis, Real t, const std::array<Real, 4>& a, const std::array<Real, 4>& b) {
  const Real weight = perlin_fade(t);
  std::array<Real, 4> blended{};
  for (int k = 0; k < 4; ++k) blended[k] = perlin_lerp(weight, a[k], b[k]);
  blended[1 + axis] = blended[1 + axis] + fade_derivative(t) * (b[0] - a[0]);
  return blended;
}

}  // namespace

template <class Real>
Real perlin3(const Permutation& permutation, Real x, Real y, Real z) {
  const Cell<Real> cell = locate(x, y, z);
  const Real u = perlin_fade(cell.local[0]);
  const Real v = perlin_fade(cell.local[1]);
  const Real w = perlin_fade(cell.local[2]);
  const GradientChoices& choices = active_choices();
  auto along_x = [&](int cy, int cz) {
    return perlin_lerp(u, corner_value(permutation, choices, cell, 0, cy, cz),
                       corner_value(permutation, choices, cell, 1, cy, cz));
  };
  return perlin_lerp(w, perlin_lerp(v, along_x(0, 0), along_x(1, 0)), perlin_lerp(v, along_x(0, 1), along_x(1, 1)));
}

template <class Real>
std::array<Real, 4> perlin3_gradient(const Permutation& permutation, Real x, Real y, Real z) {
  const Cell<Real> cell = locate(x, y, z);
  const GradientChoices& choices = active_choices();
  auto along_x = [&](int cy, int cz) {
    return lerp_along(0, cell.local[0], corner_sample(permutation, choices, cell, 0, cy, cz),
                      corner_sample(permutation, choices, cell, 1, cy, cz));
  };
  auto along_y = [&](int cz) { return lerp_along(1, cell.local[1], along_x(0, cz), along_x(1, cz)); };
  return lerp_along(2, cell.local[2], along_y(0), along_y(1));
}

template float perlin3(const Permutation&, float, float, float);
template double perlin3(const Permutation&, double, double, double);
template std::array<float, 4> perlin3_gradient(const Permutation&, float, float, float);
template std::array<double, 4> perlin3_gradient(const Permutation&, double, double, double);

}  // namespace gt::reference
