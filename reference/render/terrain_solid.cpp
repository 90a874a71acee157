// A heightmap as a closed solid (surface, skirts, base); conventions and decisions in
// terrain_solid.hpp.
#include "reference/render/terrain_solid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace gt::reference {
namespace {

constexpr std::uint32_t unused = std::numeric_limits<std::uint32_t>::max();

void check_options(const Heightmap& heights, const TerrainSolidOptions& options) {
  for (const double size : {heights.cell_size_x, heights.cell_size_y}) {
    if (!(std::isfinite(size) && size > 0.0)) {
      throw InputError(fmt::format("terrain solid: cell sizes must be positive and finite, not {} x {}",
                                   heights.cell_size_x, heights.cell_size_y));
    }
  }
  if (!(std::isfinite(options.vertical_scale) && options.vertical_scale > 0.0)) {
    throw InputError(fmt::format("terrain solid: vertical scale {} must be positive and finite", options.vertical_scale));
  }
  if (!(std::isfinite(options.base_depth) && options.base_depth >= 0.0)) {
    throw InputError(fmt::format("terrain solid: base depth {} must be >= 0 and finite", options.base_depth));
  }
  if (heights.values.size() != heights.size() || (heights.has_mask() && heights.valid.size() != heights.size())) {
    throw InputError("terrain solid: the grid's values or mask do not match its size");
  }
}

// Quads (qi, qj), qi in [0, W-1), qj in [0, H-1), of four valid samples.
struct Quads {
  int columns = 0, rows = 0;
  std::vector<std::uint8_t> kept;

  bool at(int qi, int qj) const {
    return qi >= 0 && qj >= 0 && qi < columns && qj < rows && kept[std::size_t(qj) * std::size_t(columns) + std::size_t(qi)];
  }
  void drop(int qi, int qj) { kept[std::size_t(qj) * std::size_t(columns) + std::size_t(qi)] = 0; }
};

Quads valid_quads(const Heightmap& heights) {
  Quads quads{std::max(heights.width - 1, 0), std::max(heights.height - 1, 0), {}};
  quads.kept.assign(std::size_t(quads.columns) * std::size_t(quads.rows), 0);
  for (int qj = 0; qj < quads.rows; ++qj) {
    for (int qi = 0; qi < quads.columns; ++qi) {
      quads.kept[std::size_t(qj) * std::size_t(quads.columns) + std::size_t(qi)] =
          heights.is_valid(qi, qj) && heights.is_valid(qi + 1, qj) && heights.is_valid(qi, qj + 1) &&
          heights.is_valid(qi + 1, qj + 1);
    }
  }
  return quads;
}

// Drops the later quad of every diagonal pair that meets only at a corner, until none is left.
std::size_t remove_pinches(Quads& quads) {
  std::size_t dropped = 0;
  for (bool changed = true; changed;) {
    changed = false;
    // Sample (i, j) with 1 <= i <= W-2, 1 <= j <= H-2 is the corner of quads (i-1, j-1) = a,
    // (i, j-1) = b, (i-1, j) = c and (i, j) = d.
    for (int j = 1; j < quads.rows; ++j) {
      for (int i = 1; i < quads.columns; ++i) {
        const bool a = quads.at(i - 1, j - 1), b = quads.at(i, j - 1), c = quads.at(i - 1, j), d = quads.at(i, j);
        if (a && d && !b && !c) {
          quads.drop(i, j);
        } else if (b && c && !a && !d) {
          quads.drop(i - 1, j);
        } else {
          continue;
        }
        ++dropped;
        changed = true;
      }
    }
  }
  return dropped;
}

}  // namespace

TerrainSolid terrain_solid(const Heightmap& heights, const TerrainSolidOptions& options) {
  check_options(heights, options);
  check_finite(heights, "terrain solid");
  Quads quads = valid_quads(heights);
  TerrainSolid solid;
  solid.dropped_quads = remove_pinches(quads);
  solid.kept_quads = std::size_t(std::count(quads.kept.begin(), quads.kept.end(), std::uint8_t{1}));
  if (solid.kept_quads == 0) {
    throw InputError(fmt::format("terrain solid: the {}x{} grid has no 2x2 block of valid samples to mesh",
                                 heights.width, heights.height));
  }

  // Surface vertices of the samples that kept quads use.
  const std::size_t samples = heights.size();
  std::vector<std::uint32_t> vertex(samples, unused);
  for (int qj = 0; qj < quads.rows; ++qj) {
    for (int qi = 0; qi < quads.columns; ++qi) {
      if (!quads.at(qi, qj)) continue;
      for (int b = 0; b <= 1; ++b) {
        for (int a = 0; a <= 1; ++a) vertex[heights.index(qi + a, qj + b)] = 0;
      }
    }
  }
  const auto used = std::size_t(std::count(vertex.begin(), vertex.end(), 0u));
  if (2 * used >= std::size_t(unused)) {
    throw InputError(fmt::format("terrain solid: {} vertices are more than 32-bit indices address", 2 * used));
  }
  Mesh& mesh = solid.mesh;
  mesh.positions.reserve(2 * used);
  const double centre_x = 0.5 * double(heights.width - 1), centre_z = 0.5 * double(heights.height - 1);
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (int j = 0; j < heights.height; ++j) {
    for (int i = 0; i < heights.width; ++i) {
      std::uint32_t& index = vertex[heights.index(i, j)];
      if (index == unused) continue;
      index = std::uint32_t(mesh.positions.size());
      const double y = options.vertical_scale * heights.at(i, j);
      low = std::min(low, y);
      high = std::max(high, y);
      mesh.positions.push_back({(double(i) - centre_x) * heights.cell_size_x, y, (double(j) - centre_z) * heights.cell_size_y});
    }
  }
  const double extent = std::max(double(heights.width - 1) * heights.cell_size_x,
                                 double(heights.height - 1) * heights.cell_size_y);
  solid.base_depth = options.base_depth > 0.0 ? options.base_depth : std::max(0.2 * (high - low), 0.02 * extent);
  solid.base_y = low - solid.base_depth;
  if (!(solid.base_y < low)) {
    throw InputError(fmt::format("terrain solid: base depth {} vanishes below heights of {}", solid.base_depth, low));
  }
  for (std::size_t k = 0; k < used; ++k) {
    const auto& p = mesh.positions[k];
    mesh.positions.push_back({p[0], solid.base_y, p[2]});
  }
  const auto base = [used](std::uint32_t top) { return std::uint32_t(top + used); };

  const auto corner = [&](int i, int j) { return vertex[heights.index(i, j)]; };
  // Surface, facing +y (x east, z south: (p00, p11, p10) and (p00, p01, p11) are counter-clockwise
  // seen from above), then the base reversed.
  for (int pass = 0; pass < 2; ++pass) {
    for (int qj = 0; qj < quads.rows; ++qj) {
      for (int qi = 0; qi < quads.columns; ++qi) {
        if (!quads.at(qi, qj)) continue;
        const std::uint32_t p00 = corner(qi, qj), p10 = corner(qi + 1, qj), p01 = corner(qi, qj + 1),
                            p11 = corner(qi + 1, qj + 1);
        if (pass == 0) {
          mesh.triangles.push_back({p00, p11, p10});
          mesh.triangles.push_back({p00, p01, p11});
        } else {
          mesh.triangles.push_back({base(p00), base(p10), base(p11)});
          mesh.triangles.push_back({base(p00), base(p11), base(p01)});
        }
      }
    }
  }
  solid.surface_triangles = solid.base_triangles = 2 * solid.kept_quads;

  // Skirts: a -> b is the boundary edge as the surface triangle runs it; the wall runs it b -> a
  // on top and base(a) -> base(b) at the bottom, the reverse of the base triangle's direction.
  const auto wall = [&](std::uint32_t a, std::uint32_t b) {
    mesh.triangles.push_back({b, a, base(a)});
    mesh.triangles.push_back({b, base(a), base(b)});
  };
  for (int qj = 0; qj < quads.rows; ++qj) {
    for (int qi = 0; qi < quads.columns; ++qi) {
      if (!quads.at(qi, qj)) continue;
      const std::uint32_t p00 = corner(qi, qj), p10 = corner(qi + 1, qj), p01 = corner(qi, qj + 1),
                          p11 = corner(qi + 1, qj + 1);
      if (!quads.at(qi, qj - 1)) wall(p10, p00);  // north side, run p10 -> p00 by (p00, p11, p10)
      if (!quads.at(qi + 1, qj)) wall(p11, p10);  // east side
      if (!quads.at(qi, qj + 1)) wall(p01, p11);  // south side, run by (p00, p01, p11)
      if (!quads.at(qi - 1, qj)) wall(p00, p01);  // west side
    }
  }
  solid.skirt_triangles = mesh.triangles.size() - solid.surface_triangles - solid.base_triangles;
  return solid;
}

}  // namespace gt::reference
