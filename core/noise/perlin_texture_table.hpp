// The 256x256 RGBA8 permutation/gradient texture of Gustavson's 2004 texture-based GLSL Perlin noise,
// the noise seed 004's fragment shader uses for its solid texture (digest 004 §2.1). Shared data of
// the two twins of that noise: reference/noise/perlin_texture.hpp reads these bytes as the shader's
// texture unit would, gpu/noise/perlin_texture.hpp uploads them.
//
// Layout exactly as Gustavson's initPermTexture: texel (column j, row i) sits at byte offset
// (i·256 + j)·4 (row i = texture coordinate t, column j = s, rows bottom-up as glTexImage2D reads
// them) and holds, with value = perm[(j + perm[i]) & 255],
//   R, G, B = grad3_16[value & 15]·64 + 64   (components −1, 0, 1 stored as 0, 64, 128)
//   A       = value.
// grad3_16 is the 12 cube-edge vectors followed by the 4 duplicates (1,0,−1), (−1,0,−1), (0,−1,1),
// (0,1,1) (digest 004 §2.1).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/noise/permutation.hpp"

namespace gt {

inline constexpr int perlin_texture_size = 256;

// Gradient table of the texture, in Gustavson's order.
const std::array<std::array<int, 3>, 16>& perlin_texture_gradients();

// 256·256·4 bytes.
std::vector<std::uint8_t> perlin_texture_rgba(const Permutation& permutation);

}  // namespace gt
