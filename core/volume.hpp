// Volume<T>: a scalar field sampled on a regular 3-D lattice (the cave's density, digest 004 §2.4).
//
// Conventions
//   - value(x, y, z) with x fastest: index = (z·ny + y)·nx + x; lattice point (x, y, z) sits at
//     origin + (x, y, z)·spacing in world units (the seed: spacing 1, origin integer).
//   - Solid = value < threshold (rock below the threshold, air above; digest 004 §2.3).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace gt {

template <class T>
struct Volume {
  int nx = 0;
  int ny = 0;
  int nz = 0;
  std::array<double, 3> origin{};
  double spacing = 1.0;
  std::vector<T> values;

  Volume() = default;
  Volume(int nx_, int ny_, int nz_, T fill = T{})
      : nx(nx_), ny(ny_), nz(nz_),
        values(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_), fill) {}

  std::size_t index(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(ny) + static_cast<std::size_t>(y)) *
               static_cast<std::size_t>(nx) + static_cast<std::size_t>(x);
  }
  T& at(int x, int y, int z) { return values[index(x, y, z)]; }
  const T& at(int x, int y, int z) const { return values[index(x, y, z)]; }

  // Same lattice; values converted to U (rounded to nearest when U is narrower).
  template <class U>
  Volume<U> cast() const {
    Volume<U> out;
    out.nx = nx;
    out.ny = ny;
    out.nz = nz;
    out.origin = origin;
    out.spacing = spacing;
    out.values.assign(values.begin(), values.end());
    return out;
  }
};

}  // namespace gt
