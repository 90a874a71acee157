// perlin_texture_rgba: the bytes of Gustavson's 2004 permutation/gradient texture (see the header).
#include "core/noise/perlin_texture_table.hpp"

#include <cstddef>

namespace gt {
namespace {

std::uint8_t encode_component(int component) { return static_cast<std::uint8_t>(component * 64 + 64); }

}  // namespace

const std::array<std::array<int, 3>, 16>& perlin_texture_gradients() {
  static const std::array<std::array<int, 3>, 16> gradients = {{
      {0, 1, 1}, {0, 1, -1}, {0, -1, 1}, {0, -1, -1},
      {1, 0, 1}, {1, 0, -1}, {-1, 0, 1}, {-1, 0, -1},
      {1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0},
      {1, 0, -1}, {-1, 0, -1}, {0, -1, 1}, {0, 1, 1},
  }};
  return gradients;
}

std::vector<std::uint8_t> perlin_texture_rgba(const Permutation& permutation) {
  constexpr std::size_t size = perlin_texture_size;
  std::vector<std::uint8_t> rgba(size * size * 4);
  for (std::size_t row = 0; row < size; ++row) {
    for (std::size_t column = 0; column < size; ++column) {
      const std::uint8_t value = permutation[(column + permutation[row]) & 255];
      const auto& gradient = perlin_texture_gradients()[value & 15];
      std::uint8_t* texel = &rgba[(row * size + column) * 4];
      for (int axis = 0; axis < 3; ++axis) texel[axis] = encode_component(gradient[axis]);
      texel[3] = value;
    }
  }
  return rgba;
}

}  // namespace gt
