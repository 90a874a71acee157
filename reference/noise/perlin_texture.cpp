// Gustavson's 2004 texture-based GLSL Perlin noise `float noise(vec3 P)` (digest 004 §2.1),
// reproduced operation by operation, with the texture reads emulated as GL specifies them.
//
// The shader, per corner (c_x, c_y, c_z) ∈ {0,1}³, with ONE = 1/256 and ONEHALF = 0.5/256:
//   Pi = ONE·floor(P) + ONEHALF,  Pf = P − floor(P)
//   perm  = texture(T, Pi.xy + ONE·(c_x, c_y)).a
//   grad  = texture(T, (perm, Pi.z + ONE·c_z)).rgb·4 − 1
//   n_c   = grad · (Pf − c)
//   value = lerp along x (fade(Pf.x)), then y, then z, as improved Perlin noise.
// Texture reads (GL 4.5 §8.14, §8.10): nearest texel = floor(s·256) mod 256 (GL_REPEAT), the same
// for t; a stored byte c reads as c/255 (unorm conversion), computed here as a correctly rounded
// division.
//
// Hazards (why this noise is not exact Perlin noise, and where GPUs may disagree):
//   1. Inexact gradient decode: a component −1, 0, 1 is stored as 0, 64, 128 and decodes to
//      c/255·4 − 1 = −1, 1/255 ≈ 0.00392, 257/255 ≈ 1.00784: g' = (256·g + 1)/255, so the noise is
//      (256/255)·N_int plus a bias (1/255)·Σ(t − fade(t)) (perlin_texture.hpp). In float the decoded
//      values are −1, 0.003921628, 1.0078433 whether the GPU divides by 255 or multiplies by
//      float(1/255) (checked for bytes 0, 64, 128).
//   2. The hash goes through the alpha channel as a texture coordinate: perm = v/255 lands in texel
//      floor(v·256/255) = v for v < 255, at a fraction v/255 of the texel (at least 1/255 from the
//      next edge, enough for 8 bits of sub-texel precision). v = 255 reads as exactly 1.0, which
//      GL_REPEAT wraps to column 0 (GL_CLAMP_TO_EDGE would give 255): the shader hashes 255 as 0.
//   3. The hash order is the texture's, not Perlin's: texel (column s, row t) holds
//      perm[(s + perm[t]) & 255], so the corner hash is perm[(a' + perm[Z]) & 255] with
//      a = perm[(X + perm[Y]) & 255] and a' = a (a < 255) or 0; the gradient is grad3_16[hash & 15].
//   4. The 2004 code uses mix() and dot(), whose operation order (and fusion) is up to the driver;
//      both twins write them out: mix as a + t·(b − a), dot as (g.x·d.x + g.y·d.y) + g.z·d.z.
//      fract(P) is written P − floor(P), its GLSL definition.
//   5. Pi and Pi + ONE are exact texel centres in float only while |floor(P)| < 2^23.
#include "reference/noise/perlin_texture.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "core/noise/perlin_texture_table.hpp"
#include "reference/noise/perlin.hpp"

namespace gt::reference {
namespace {

template <class Real>
constexpr Real texel_size = Real(0.00390625);  // ONE = 1/256

template <class Real>
constexpr Real half_texel = Real(0.001953125);  // ONEHALF = 0.5/256

// GL_NEAREST + GL_REPEAT: floor(coordinate·256) mod 256.
template <class Real>
std::size_t texel_index(Real coordinate) {
  const auto index = static_cast<long long>(std::floor(coordinate * Real(perlin_texture_size)));
  return static_cast<std::size_t>(((index % perlin_texture_size) + perlin_texture_size) % perlin_texture_size);
}

// GL's unorm conversion c/(2^8 − 1).
template <class Real>
Real unorm8(std::uint8_t byte) {
  return Real(byte) / Real(255);
}

// The texel texture(T, (s, t)) reads, as its four stored bytes.
template <class Real>
const std::uint8_t* fetch_texel(const std::vector<std::uint8_t>& rgba, Real s, Real t) {
  return &rgba[(texel_index(t) * perlin_texture_size + texel_index(s)) * 4];
}

template <class Real>
Real corner_shift(int c) {
  return c == 0 ? Real(0) : texel_size<Real>;
}

template <class Real>
struct Lattice {
  std::array<Real, 3> texel_centre;  // Pi
  std::array<Real, 3> local;         // Pf
};

template <class Real>
Lattice<Real> locate(Real x, Real y, Real z) {
  const std::array<Real, 3> point = {x, y, z};
  Lattice<Real> lattice{};
  for (int axis = 0; axis < 3; ++axis) {
    const Real lower = std::floor(point[axis]);
    lattice.texel_centre[axis] = texel_size<Real> * lower + half_texel<Real>;
    lattice.local[axis] = point[axis] - lower;
  }
  return lattice;
}

// n_c for the two corners (c_x, c_y, 0) and (c_x, c_y, 1), which share the alpha lookup.
template <class Real>
std::array<Real, 2> corner_pair(const std::vector<std::uint8_t>& rgba, const Lattice<Real>& lattice, int cx, int cy) {
  const Real permuted = unorm8<Real>(fetch_texel(rgba, lattice.texel_centre[0] + corner_shift<Real>(cx),
                                                  lattice.texel_centre[1] + corner_shift<Real>(cy))[3]);
  std::array<Real, 2> values{};
  for (int cz = 0; cz < 2; ++cz) {
    const std::uint8_t* texel = fetch_texel(rgba, permuted, lattice.texel_centre[2] + corner_shift<Real>(cz));
    const std::array<int, 3> corner = {cx, cy, cz};
    std::array<Real, 3> gradient{}, offset{};
    for (int axis = 0; axis < 3; ++axis) {
      gradient[axis] = perlin_texture_gradient_component<Real>(texel[axis]);
      offset[axis] = lattice.local[axis] - Real(corner[axis]);
    }
    values[cz] = gradient[0] * offset[0] + gradient[1] * offset[1] + gradient[2] * offset[2];
  }
  return values;
}

}  // namespace

template <class Real>
Real perlin_texture_gradient_component(std::uint8_t byte) {
  return unorm8<Real>(byte) * Real(4) - Real(1);
}

template <class Real>
Real perlin3_texture(const std::vector<std::uint8_t>& rgba, Real x, Real y, Real z) {
  if (rgba.size() != std::size_t{perlin_texture_size} * perlin_texture_size * 4) {
    throw std::invalid_argument("perlin3_texture needs the 256x256 RGBA8 table of perlin_texture_rgba");
  }
  const Lattice<Real> lattice = locate(x, y, z);
  const Real u = perlin_fade(lattice.local[0]);
  const Real v = perlin_fade(lattice.local[1]);
  const Real w = perlin_fade(lattice.local[2]);
  const auto x0y0 = corner_pair(rgba, lattice, 0, 0);
  const auto x1y0 = corner_pair(rgba, lattice, 1, 0);
  const auto x0y1 = corner_pair(rgba, lattice, 0, 1);
  const auto x1y1 = corner_pair(rgba, lattice, 1, 1);
  auto blend_z = [&](int cz) {
    return perlin_lerp(v, perlin_lerp(u, x0y0[cz], x1y0[cz]), perlin_lerp(u, x0y1[cz], x1y1[cz]));
  };
  return perlin_lerp(w, blend_z(0), blend_z(1));
}

template float perlin_texture_gradient_component(std::uint8_t);
template double perlin_texture_gradient_component(std::uint8_t);
template float perlin3_texture(const std::vector<std::uint8_t>&, float, float, float);
template double perlin3_texture(const std::vector<std::uint8_t>&, double, double, double);

}  // namespace gt::reference
