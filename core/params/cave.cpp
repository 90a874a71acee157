// Cave block parameters (table, ranges, JSON) and lattice edge keys; see cave.hpp.
//
// Ranges: origin within ±500,000 and size up to 512 cells keep every lower edge endpoint, padding
// included (origin - 1 .. origin + size), inside the keys' ±2^19; 512³ cells is also about the
// largest block whose double density (8·513³ bytes ≈ 1.1 GB) is reasonable to hold. The kernel is
// limited to the two values of the digest's choice (§2.2.5) and what lies between.
#include "core/params/cave.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/params/noise.hpp"

namespace gt {
namespace {

constexpr std::int64_t key_offset = std::int64_t{1} << 19;
constexpr int coordinate_bits = 20;
constexpr int direction_bits = 3;
constexpr std::uint64_t coordinate_mask = (std::uint64_t{1} << coordinate_bits) - 1;
constexpr std::uint64_t direction_mask = (std::uint64_t{1} << direction_bits) - 1;

constexpr const char* origin_names[3] = {"origin_x", "origin_y", "origin_z"};
constexpr const char* size_names[3] = {"size_x", "size_y", "size_z"};

bool key_holds(std::int64_t coordinate) {
  return coordinate >= lattice_coordinate_min && coordinate <= lattice_coordinate_max;
}

}  // namespace

const ParamTable<CaveParams>& cave_param_table() {
  using P = CaveParams;
  static const ParamTable<P> table = [] {
    ParamTable<P> rows = {
        real_param("scale", &P::scale, 1e-3, 1e6, "world unit",
                   "world units per noise unit (the seed's SCALE_FACTOR): density = simplex3(p / scale)"),
        real_param("threshold", &P::threshold, -1.0, 1.0, "1", "rock where the density is below it (TRESHOLD)"),
        real_param("kernel", &P::kernel_radius_squared, 0.5, 0.6, "noise unit²",
                   "simplex kernel radius²: 0.6 as seed 004 (slightly discontinuous), 0.5 corrected"),
        integer_param("seed", &P::seed, 0, 4294967295.0, "1",
                      "permutation: 0 = Perlin's reference table (the seed's), otherwise a shuffle by the counter RNG"),
        boolean_param("solid", &P::solid,
                      "pad the block with air so the rock is capped at its faces and the mesh is closed; false: open "
                      "chunk"),
    };
    for (std::size_t axis = 0; axis < 3; ++axis) {
      rows.push_back(integer_param(origin_names[axis], element(&P::origin, axis), -500000, 500000, "lattice unit",
                                   "lattice coordinate of the block's first sample (1 lattice unit = 1 world unit)"));
    }
    for (std::size_t axis = 0; axis < 3; ++axis) {
      rows.push_back(integer_param(size_names[axis], element(&P::size, axis), 1, 512, "count",
                                   "cells along the axis (the seed's BIG_CUBE_SIZE; samples = cells + 1)"));
    }
    return rows;
  }();
  return table;
}

const ParamSpecs& cave_param_specs() {
  static const ParamSpecs specs = param_specs(cave_param_table());
  return specs;
}

// The density samples simplex3 at p / scale: every sample of the block, its pad and up to 2000
// slabs of an endless path beyond it must stay within the noise's largest lattice coordinate.
void require_noise_range(const CaveParams& params) {
  constexpr double largest_path = 2002.0;  // slabs (at most 2000) and the pad
  double largest = 0.0;
  for (int axis = 0; axis < 3; ++axis) {
    largest = std::max(largest, (std::abs(static_cast<double>(params.origin[axis])) + params.size[axis] + largest_path) /
                                    params.scale);
  }
  if (largest > largest_lattice_coordinate) {
    throw InputError(fmt::format("the cave's density samples simplex noise up to {:.3g} noise units (origin and size "
                                 "over scale {}), beyond {:.3g}, where the twins' lattice indices overflow 32 bits; "
                                 "raise the scale or move the origin",
                                 largest, params.scale, largest_lattice_coordinate));
  }
}

CaveParams cave_params_from_json(const nlohmann::json& resolved) {
  const CaveParams params = params_from_json(cave_param_table(), resolved);
  require_noise_range(params);
  return params;
}

std::uint64_t lattice_edge_key(const std::array<std::int64_t, 3>& lower_point, int direction) {
  std::uint64_t key = static_cast<std::uint64_t>(direction) & direction_mask;
  for (int axis = 0; axis < 3; ++axis) {
    const auto biased = static_cast<std::uint64_t>(lower_point[axis] + key_offset) & coordinate_mask;
    key |= biased << (direction_bits + coordinate_bits * axis);
  }
  return key;
}

double edge_margin(const std::array<std::int64_t, 3>& lower_point, int direction) {
  std::uint64_t largest = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const std::int64_t upper = lower_point[axis] + ((direction >> axis) & 1);
    largest = std::max({largest, static_cast<std::uint64_t>(std::abs(lower_point[axis])),
                        static_cast<std::uint64_t>(std::abs(upper))});
  }
  constexpr int float_mantissa_bits = 23;
  const int exponent = static_cast<int>(std::bit_width(largest + 1)) - 1;  // 2^exponent <= largest + 1
  return std::ldexp(1.0, std::max(-10, exponent + 2 - float_mantissa_bits));
}

void require_checkable_block(const CaveParams& params) {
  std::int64_t cubes = 1;
  for (int axis = 0; axis < 3; ++axis) cubes *= std::int64_t{params.size[axis]} + (params.solid ? 2 : 0);
  if (cubes > largest_checked_cubes) {
    throw InputError(fmt::format("a cave block of {}x{}x{} cells has {} cubes{}; the mesh checks hold about 1.8 kB per "
                                 "cube, so a case takes at most {} cubes (161³); time larger blocks with `groundtruth "
                                 "bench`",
                                 params.size[0], params.size[1], params.size[2], cubes, params.solid ? " with its pad" : "",
                                 largest_checked_cubes));
  }
}

LatticeEdge lattice_edge_from_key(std::uint64_t key) {
  LatticeEdge edge{};
  edge.direction = static_cast<int>(key & direction_mask);
  for (int axis = 0; axis < 3; ++axis) {
    const std::uint64_t biased = (key >> (direction_bits + coordinate_bits * axis)) & coordinate_mask;
    edge.lower_point[axis] = static_cast<std::int64_t>(biased) - key_offset;
  }
  return edge;
}

bool lattice_range_fits(const std::array<std::int64_t, 3>& origin, const std::array<std::int64_t, 3>& samples,
                        bool padded) {
  const std::int64_t pad = padded ? 1 : 0;
  for (int axis = 0; axis < 3; ++axis) {
    if (!key_holds(origin[axis] - pad) || !key_holds(origin[axis] + samples[axis] - 1 + pad)) return false;
  }
  return true;
}

}  // namespace gt
