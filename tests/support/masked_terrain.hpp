// A small float terrain for the twins' unit tests: 40 m of counter-RNG relief on a 500 m base,
// 2 m cells, sides 37 x 23 (not multiples of the shaders' 16-wide groups), and a round no-data
// blob of squared radius `blob_radius2` cells at (blob_x, blob_y).
#pragma once

#include <cstdint>

#include "core/grid.hpp"
#include "core/rng.hpp"

namespace gt::testing {

inline Grid<float> masked_terrain(std::uint32_t seed, int blob_x, int blob_y, int blob_radius2) {
  Grid<float> field(37, 23);
  field.cell_size_x = field.cell_size_y = 2.0;
  field.valid.assign(field.size(), 1);
  for (int y = 0; y < field.height; ++y) {
    for (int x = 0; x < field.width; ++x) {
      const auto bits = random_u32(seed, static_cast<std::uint32_t>(field.index(x, y)), 0, 0);
      field.at(x, y) = 500.0f + 40.0f * uniform01(bits);
      if ((x - blob_x) * (x - blob_x) + (y - blob_y) * (y - blob_y) < blob_radius2) field.valid[field.index(x, y)] = 0;
    }
  }
  return field;
}

}  // namespace gt::testing
