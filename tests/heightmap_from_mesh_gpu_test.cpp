// Seed 000's heightmap from a mesh: the GL pipeline (gpu/render/heightmap_from_mesh.hpp) against the
// reference rasterizer (reference/render/heightmap_from_mesh.hpp) on a tilted plane, a pyramid,
// overlapping triangles and the real bunny. Interior texels (3×3 covered on both sides) must agree
// within the float error model B(t) = 16u·(1 + s(t)·(W + H)) of compare/algorithms/render_heightmap.hpp
// (the GPU's positions, matrix, plane set-up and interpolation of z' are float, about 8.5u·s·(W + H)
// plus 6u; the reference is double), coverage may differ only on silhouette texels, and silhouette
// texels covered on both sides must hold a reference height of their 3×3 neighbourhood. Where every
// edge and pixel centre is exact in float, the GPU must cover exactly the reference's texels: that
// pins the tie rule (lower_left, Mesa's rule in framebuffer objects).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "compare/algorithms/render_heightmap.hpp"
#include "core/io/mesh_io.hpp"
#include "gpu/render/heightmap_from_mesh.hpp"
#include "reference/render/heightmap_from_mesh.hpp"
#include "tests/support/gl_test.hpp"

namespace {

struct Shape {
  std::string name;
  gt::Mesh mesh;
};

gt::Mesh tilted_plane() {
  // 12 x 9 quads of z = 0.3x - 0.2y + 0.05·sin(x·y), x ∈ [0, 3], y ∈ [0, 2].
  gt::Mesh mesh;
  const int columns = 12, rows = 9;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const double x = 3.0 * i / columns, y = 2.0 * j / rows;
      mesh.positions.push_back({x, y, 0.3 * x - 0.2 * y + 0.05 * std::sin(x * y)});
    }
  }
  const auto vertex = [&](int i, int j) { return std::uint32_t(j * (columns + 1) + i); };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1)});
      mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
    }
  }
  return mesh;
}

gt::Mesh pyramid() {
  // A square pyramid on a base slightly rotated off the axes, base included (no culling: it is
  // hidden by the depth test, not by its winding).
  gt::Mesh mesh;
  mesh.positions = {{0.1, -1.0, 0.0}, {1.0, 0.1, 0.0}, {-0.1, 1.0, 0.0}, {-1.0, -0.1, 0.0}, {0.05, 0.02, 1.3}};
  mesh.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 2, 1}, {0, 3, 2}};
  return mesh;
}

gt::Mesh overlapping_triangles() {
  // Three large triangles crossing each other at different slopes: the highest one changes along
  // lines where two of them intersect.
  gt::Mesh mesh;
  mesh.positions = {{-1.0, -1.0, 0.0}, {1.0, -0.8, 1.0}, {0.0, 1.0, 0.5},  {-1.0, 0.9, 1.0}, {0.9, 1.0, 0.0},
                    {0.2, -1.0, 0.6},  {-0.7, 0.0, 0.9}, {1.0, 0.3, 0.2}, {0.3, 0.8, 0.4}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  return mesh;
}

std::vector<Shape> shapes() {
  return {{"tilted_plane", tilted_plane()}, {"pyramid", pyramid()}, {"overlapping", overlapping_triangles()}};
}

class HeightmapFromMeshGpu : public gt::testing::GlTestWithParam<Shape> {};

void expect_parity(const gt::Mesh& mesh, int width, int height) {
  const auto cpu = gt::reference::heightmap_from_mesh(mesh, width, height);
  const gt::gpu::HeightmapFromMesh renderer(mesh, width, height);
  renderer.run();
  const auto gpu = renderer.result();
  const auto parity = gt::compare_mesh_heightmaps(cpu.heights, cpu.covered, gpu.heights, gpu.covered);
  EXPECT_GT(parity.interior_texels, 0u);
  EXPECT_LE(parity.interior_model_ratio, 1.0) << "largest interior difference " << parity.interior_max_abs;
  EXPECT_EQ(parity.coverage_differences_off_silhouette, 0u) << parity.coverage_differences << " coverage differences";
  EXPECT_EQ(parity.silhouette_beyond_one_texel, 0u);
  for (std::size_t texel = 0; texel < gpu.covered.size(); ++texel) {
    if (!gpu.covered.values[texel]) {
      EXPECT_EQ(gpu.heights.values[texel], 0.0f) << "uncovered texel " << texel;
    }
  }
}

TEST_P(HeightmapFromMeshGpu, InteriorMatchesWithinFloatErrorAndEdgesWithinOneTexel) {
  expect_parity(GetParam().mesh, 96, 64);
}

INSTANTIATE_TEST_SUITE_P(Shapes, HeightmapFromMeshGpu, ::testing::ValuesIn(shapes()),
                         [](const auto& info) { return info.param.name; });

class HeightmapFromMeshGpuRules : public gt::testing::GlTest {};

TEST_F(HeightmapFromMeshGpuRules, ExactEdgesCoverTheSameTexelsAsTheReference) {
  // The hypotenuse of z = x/4 + y over [0, 4] x [0, 2] passes through 16 texel centres of a 16 x 16
  // grid (tests/rasterizer_test.cpp); every coordinate is exact in float.
  gt::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {4, 0, 1}, {0, 2, 2}};
  mesh.triangles = {{0, 1, 2}};
  const auto cpu = gt::reference::heightmap_from_mesh(mesh, 16, 16, gt::gpu::HeightmapFromMesh::subpixel_bits());
  const gt::gpu::HeightmapFromMesh renderer(mesh, 16, 16);
  renderer.run();
  const auto gpu = renderer.result();
  EXPECT_EQ(gpu.covered.values, cpu.covered.values);
  for (std::size_t texel = 0; texel < cpu.heights.size(); ++texel) {
    EXPECT_NEAR(gpu.heights.values[texel], cpu.heights.values[texel], 4 * 0x1p-24) << "texel " << texel;
  }
}

TEST_F(HeightmapFromMeshGpuRules, BunnyInteriorMatchesAndEdgesWithinOneTexel) {
  const std::filesystem::path bunny = std::filesystem::path(GT_DATASET_DIR) / "real/meshes/bunny00.off";
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " is missing (datasets/fetch.sh fetches it)";
  expect_parity(gt::read_mesh(bunny).mesh, 128, 128);
}

}  // namespace
