// The GPU marching tetrahedra (gpu/cave/marching_tetrahedra.hpp) against its CPU twin
// (reference/cave/marching_tetrahedra.hpp on reference/cave/density.hpp's float density): the
// same triangle index buffer, the same edge keys and bitwise the same positions, which llvmpipe
// must give because every float operation, the division included, is the reference's and is
// correctly rounded there; the same for an uploaded volume (a clipped sphere's distance field with
// samples exactly at the threshold) against the reference on that volume. Also the multi-level
// scan on its own (gpu/cave/exclusive_scan.hpp) against std::exclusive_scan, determinism, empty
// meshes and refused blocks.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/params/cave.hpp"
#include "core/volume.hpp"
#include "gpu/buffer.hpp"
#include "gpu/cave/exclusive_scan.hpp"
#include "gpu/cave/marching_tetrahedra.hpp"
#include "gpu/cave/normals.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_tetrahedra.hpp"
#include "reference/cave/normals.hpp"
#include "tests/support/gl_test.hpp"

namespace {

namespace ref = gt::reference;

using FloatMesh = gt::TriangleMesh<float>;

constexpr std::uint32_t test_seed = 20140520;  // a seeded permutation, not Perlin's table

gt::CaveParams cave_params(std::array<int, 3> origin, std::array<int, 3> size, bool solid, double kernel = 0.6) {
  gt::CaveParams params;
  params.origin = origin;
  params.size = size;
  params.solid = solid;
  params.kernel_radius_squared = kernel;
  params.seed = test_seed;
  return params;
}

FloatMesh reference_mesh(const gt::CaveParams& params, ref::EdgePlacement placement = ref::EdgePlacement::linear) {
  return ref::marching_tetrahedra(ref::cave_density<float>(params), static_cast<float>(params.threshold), params.solid,
                                  {params.origin[0], params.origin[1], params.origin[2]}, placement);
}

FloatMesh gpu_mesh(const gt::CaveParams& params, gt::gpu::EdgePlacement placement = gt::gpu::EdgePlacement::linear) {
  gt::gpu::MarchingTetrahedra mesher(params, placement);
  mesher.run();
  return mesher.result();
}

std::array<std::uint32_t, 3> position_bits(const std::array<float, 3>& position) {
  return {std::bit_cast<std::uint32_t>(position[0]), std::bit_cast<std::uint32_t>(position[1]),
          std::bit_cast<std::uint32_t>(position[2])};
}

// Equal index buffers, edge keys and position bits; the message names the first difference.
::testing::AssertionResult same_mesh(const FloatMesh& expected, const FloatMesh& actual) {
  if (expected.triangles.size() != actual.triangles.size() || expected.positions.size() != actual.positions.size() ||
      actual.edge_keys.size() != actual.positions.size()) {
    return ::testing::AssertionFailure() << "sizes differ: expected " << expected.triangles.size() << " triangles, "
                                         << expected.positions.size() << " vertices; got " << actual.triangles.size()
                                         << ", " << actual.positions.size() << " (" << actual.edge_keys.size()
                                         << " keys)";
  }
  for (std::size_t triangle = 0; triangle < expected.triangles.size(); ++triangle) {
    if (expected.triangles[triangle] != actual.triangles[triangle]) {
      const auto& want = expected.triangles[triangle];
      const auto& got = actual.triangles[triangle];
      return ::testing::AssertionFailure() << "triangle " << triangle << ": expected (" << want[0] << ", " << want[1]
                                           << ", " << want[2] << "), got (" << got[0] << ", " << got[1] << ", "
                                           << got[2] << ")";
    }
  }
  for (std::size_t vertex = 0; vertex < expected.positions.size(); ++vertex) {
    if (expected.edge_keys[vertex] != actual.edge_keys[vertex]) {
      return ::testing::AssertionFailure() << "edge key of vertex " << vertex << ": expected "
                                           << expected.edge_keys[vertex] << ", got " << actual.edge_keys[vertex];
    }
    if (position_bits(expected.positions[vertex]) != position_bits(actual.positions[vertex])) {
      const auto& want = expected.positions[vertex];
      const auto& got = actual.positions[vertex];
      return ::testing::AssertionFailure() << std::hexfloat << "position of vertex " << vertex << ": expected ("
                                           << want[0] << ", " << want[1] << ", " << want[2] << "), got (" << got[0]
                                           << ", " << got[1] << ", " << got[2] << ")";
    }
  }
  return ::testing::AssertionSuccess();
}

struct Block {
  const char* name;
  std::array<int, 3> origin;
  bool solid;
  double kernel;
};

void PrintTo(const Block& block, std::ostream* out) { *out << block.name; }

const Block blocks[] = {
    {"origin0_solid_kernel06", {0, 0, 0}, true, 0.6},     {"origin0_open_kernel06", {0, 0, 0}, false, 0.6},
    {"origin0_solid_kernel05", {0, 0, 0}, true, 0.5},     {"origin0_open_kernel05", {0, 0, 0}, false, 0.5},
    {"shifted_solid_kernel06", {-20, 7, 33}, true, 0.6},  {"shifted_open_kernel06", {-20, 7, 33}, false, 0.6},
    {"shifted_solid_kernel05", {-20, 7, 33}, true, 0.5},  {"shifted_open_kernel05", {-20, 7, 33}, false, 0.5},
};

class GpuMarchingTetrahedra : public gt::testing::GlTestWithParam<Block> {};

TEST_P(GpuMarchingTetrahedra, GivesTheFloatReferenceMeshBitForBit) {
  const Block& block = GetParam();
  const auto params = cave_params(block.origin, {12, 12, 12}, block.solid, block.kernel);
  const FloatMesh expected = reference_mesh(params);
  ASSERT_GT(expected.triangles.size(), 100u) << "a nearly empty block proves little";
  EXPECT_TRUE(same_mesh(expected, gpu_mesh(params)));
}

// The seed's central-difference normals (gpu/cave/normals.hpp) at the mesh's vertices: the same
// float operations as reference/cave/normals.hpp's central_difference_normals<float> (each shifted
// coordinate one addition, each noise point one multiplication, the normalisation's sqrt and
// divisions correctly rounded on llvmpipe), so the same bits.
TEST_P(GpuMarchingTetrahedra, CentralDifferenceNormalsAreTheFloatReferencesBitForBit) {
  const Block& block = GetParam();
  const auto params = cave_params(block.origin, {12, 12, 12}, block.solid, block.kernel);
  const FloatMesh mesh = reference_mesh(params);
  const auto gpu_normals = gt::gpu::central_difference_normals(mesh.positions, params);
  EXPECT_EQ(gpu_normals, ref::central_difference_normals<float>(mesh, params));
  EXPECT_TRUE(gt::gpu::central_difference_normals({}, params).empty());
}

INSTANTIATE_TEST_SUITE_P(Blocks12, GpuMarchingTetrahedra, ::testing::ValuesIn(blocks),
                         [](const auto& info) { return std::string(info.param.name); });

class GpuMarchingTetrahedraCases : public gt::testing::GlTest {};

// Unequal axes catch a swapped stride; midpoints are the reference's other placement.
TEST_F(GpuMarchingTetrahedraCases, UnequalAxesAndMidpointPlacementMatchTheReference) {
  const auto solid = cave_params({3, -5, 2}, {13, 7, 10}, true);
  EXPECT_TRUE(same_mesh(reference_mesh(solid), gpu_mesh(solid)));
  EXPECT_TRUE(same_mesh(reference_mesh(solid, ref::EdgePlacement::midpoint),
                        gpu_mesh(solid, gt::gpu::EdgePlacement::midpoint)));
  const auto open = cave_params({-9, 4, 1}, {6, 11, 9}, false, 0.5);
  EXPECT_TRUE(same_mesh(reference_mesh(open, ref::EdgePlacement::midpoint),
                        gpu_mesh(open, gt::gpu::EdgePlacement::midpoint)));
}

// 64³ cubes (262,145 scanned values with the totals' slot): the scans need two levels, the cube
// index spans many workgroups, and the mesh is large enough to meet most tet cases.
TEST_F(GpuMarchingTetrahedraCases, A64CubedBlockMatchesTheReference) {
  const auto params = cave_params({-31, 17, -2}, {64, 64, 64}, false);
  const FloatMesh expected = reference_mesh(params);
  ASSERT_GT(expected.triangles.size(), 100000u);
  EXPECT_TRUE(same_mesh(expected, gpu_mesh(params)));
}

// The endless cave moves one slab mesher along its path: each position must give the mesh a fresh
// mesher and the reference give there, including across the power of two where δ grows (2047).
TEST_F(GpuMarchingTetrahedraCases, MovedMesherMatchesTheReferenceAtEachOrigin) {
  auto params = cave_params({2040, -3, 0}, {1, 9, 9}, false);
  gt::gpu::MarchingTetrahedra mesher(params);
  for (const int x : {2040, 2046, 2047, 2048, -2049}) {
    params.origin = {x, -3, 0};
    mesher.move_to(params.origin);
    mesher.run();
    EXPECT_TRUE(same_mesh(reference_mesh(params), mesher.result())) << "slab at x = " << x;
  }
  EXPECT_THROW(mesher.move_to({600000, 0, 0}), gt::InputError);
}

// Outputs past GL_MAX_SHADER_STORAGE_BLOCK_SIZE (a 256³ block on llvmpipe) are emitted chunk by
// chunk through buffer windows; small windows split a 24³ block (about 40 KB of triangles) into
// many chunks, whose bases, alignment and spare vertex slot must give the same mesh bit for bit.
TEST_F(GpuMarchingTetrahedraCases, OutputsSplitIntoWindowsGiveTheSameMesh) {
  const auto params = cave_params({7, -3, 11}, {24, 24, 24}, true);
  const FloatMesh expected = reference_mesh(params);
  for (const std::size_t window_bytes : {std::size_t{4096}, std::size_t{20000}}) {
    gt::gpu::MarchingTetrahedra mesher(params);
    mesher.limit_output_windows(window_bytes);
    mesher.run();
    EXPECT_TRUE(same_mesh(expected, mesher.result())) << "windows of " << window_bytes << " bytes";
  }
  gt::gpu::MarchingTetrahedra mesher(params);
  EXPECT_THROW(mesher.limit_output_windows(100), std::invalid_argument) << "less than one cube's triangles";
}

TEST_F(GpuMarchingTetrahedraCases, RunsTwiceAndTwoMeshersGiveTheSameBits) {
  const auto params = cave_params({5, 5, 5}, {20, 20, 20}, true);
  gt::gpu::MarchingTetrahedra mesher(params);
  mesher.run();
  const FloatMesh first = mesher.result();
  mesher.run();
  EXPECT_TRUE(same_mesh(first, mesher.result()));
  EXPECT_TRUE(same_mesh(first, gpu_mesh(params)));
}

TEST_F(GpuMarchingTetrahedraCases, AllAirAndOpenAllRockGiveAnEmptyMesh) {
  for (const bool solid : {true, false}) {
    auto params = cave_params({0, 0, 0}, {12, 12, 12}, solid);
    params.threshold = -10.0;
    const FloatMesh air = gpu_mesh(params);
    EXPECT_TRUE(air.triangles.empty() && air.positions.empty() && air.edge_keys.empty()) << "solid " << solid;
  }
  auto rock = cave_params({0, 0, 0}, {12, 12, 12}, false);
  rock.threshold = 10.0;
  EXPECT_TRUE(gpu_mesh(rock).triangles.empty());
}

// All rock in a solid block: only the pad's cap, every vertex at an edge midpoint outside the block.
TEST_F(GpuMarchingTetrahedraCases, SolidAllRockGivesTheReferenceCap) {
  auto params = cave_params({-3, 2, 8}, {4, 5, 3}, true);
  params.threshold = 10.0;
  const FloatMesh expected = reference_mesh(params);
  ASSERT_FALSE(expected.triangles.empty());
  EXPECT_TRUE(same_mesh(expected, gpu_mesh(params)));
}

TEST_F(GpuMarchingTetrahedraCases, RefusesBlocksOutsideTheEdgeKeyRange) {
  const auto params = cave_params({static_cast<int>(gt::lattice_coordinate_max), 0, 0}, {1, 1, 1}, false);
  EXPECT_THROW(gt::gpu::MarchingTetrahedra{params}, gt::InputError);
}

// A block whose density alone passes the driver's limit is refused before anything is allocated.
TEST_F(GpuMarchingTetrahedraCases, RefusesBuffersPastTheStorageBlockLimit) {
  GLint64 limit = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &limit);
  const auto params = cave_params({0, 0, 0}, {512, 512, 512}, true);
  const std::int64_t density_bytes = std::int64_t{513} * 513 * 513 * 4;
  if (density_bytes <= limit) GTEST_SKIP() << "this GL allows storage blocks of " << limit << " bytes";
  try {
    gt::gpu::MarchingTetrahedra mesher(params);
    FAIL() << "no error for " << density_bytes << " bytes of density";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos) << error.what();
  }
}

// Distance to the lattice point (4, 3, 3), in float, over 9 x 8 x 6 samples: the sphere of radius
// 3 is clipped by the face z = 5, and the 29 samples at a distance of exactly 3 (such as (7, 3, 3)
// and (6, 5, 4); (4, 3, 6) lies past the clip) sit exactly on the threshold.
gt::Volume<float> clipped_sphere_distance() {
  gt::Volume<float> volume(9, 8, 6);
  for (int z = 0; z < volume.nz; ++z) {
    for (int y = 0; y < volume.ny; ++y) {
      for (int x = 0; x < volume.nx; ++x) {
        volume.at(x, y, z) = std::sqrt(static_cast<float>((x - 4) * (x - 4) + (y - 3) * (y - 3) + (z - 3) * (z - 3)));
      }
    }
  }
  return volume;
}

constexpr float sphere_radius = 3.0f;

class GpuMarchingTetrahedraVolume : public gt::testing::GlTest {};

TEST_F(GpuMarchingTetrahedraVolume, UploadedVolumeGivesTheFloatReferenceMeshBitForBit) {
  const gt::Volume<float> volume = clipped_sphere_distance();
  ASSERT_EQ(std::count(volume.values.begin(), volume.values.end(), sphere_radius), 29);
  const std::array<int, 3> origin{-40, 17, 1030};
  for (const bool solid : {true, false}) {
    for (const auto& [gpu_placement, reference_placement, name] :
         {std::tuple{gt::gpu::EdgePlacement::linear, ref::EdgePlacement::linear, "linear"},
          std::tuple{gt::gpu::EdgePlacement::midpoint, ref::EdgePlacement::midpoint, "midpoint"}}) {
      const FloatMesh expected = ref::marching_tetrahedra(volume, sphere_radius, solid,
                                                          {origin[0], origin[1], origin[2]}, reference_placement);
      ASSERT_GT(expected.triangles.size(), 100u);
      gt::gpu::MarchingTetrahedra mesher(volume, sphere_radius, solid, origin, gpu_placement);
      mesher.run();
      EXPECT_TRUE(same_mesh(expected, mesher.result())) << (solid ? "solid, " : "open, ") << name;
    }
  }
}

// move_to keeps the uploaded samples and places them at the new origin.
TEST_F(GpuMarchingTetrahedraVolume, MovedUploadedVolumeMatchesTheReferenceThere) {
  const gt::Volume<float> volume = clipped_sphere_distance();
  gt::gpu::MarchingTetrahedra mesher(volume, sphere_radius, false, {0, 0, 0});
  for (const int x : {2040, -2049}) {
    mesher.move_to({x, 5, -7});
    mesher.run();
    EXPECT_TRUE(same_mesh(ref::marching_tetrahedra(volume, sphere_radius, false, {x, 5, -7}), mesher.result()))
        << "at x = " << x;
  }
}

TEST_F(GpuMarchingTetrahedraVolume, RefusesNonFiniteSamplesAndVolumesWithoutACube) {
  gt::Volume<float> volume = clipped_sphere_distance();
  volume.at(2, 5, 1) = std::numeric_limits<float>::quiet_NaN();
  try {
    gt::gpu::MarchingTetrahedra mesher(volume, sphere_radius, true, {0, 0, 0});
    FAIL() << "no error for a NaN sample";
  } catch (const gt::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("(2, 5, 1)"), std::string::npos) << error.what();
  }
  const gt::Volume<float> one_slice(4, 4, 1, 1.0f);
  EXPECT_THROW((gt::gpu::MarchingTetrahedra{one_slice, 0.0f, true, {0, 0, 0}}), gt::InputError);
  gt::Volume<float> short_values(4, 4, 4, 1.0f);
  short_values.values.pop_back();
  EXPECT_THROW((gt::gpu::MarchingTetrahedra{short_values, 0.0f, true, {0, 0, 0}}), std::invalid_argument);
}

class GpuExclusiveScan : public gt::testing::GlTest {};

// Sizes around the 1024-value block and past 1024² values, which needs three levels.
TEST_F(GpuExclusiveScan, MatchesStdExclusiveScanOnRandomCounts) {
  const std::size_t largest = 1024 * 1024 + 1025;
  const gt::gpu::ExclusiveScan scan(largest);
  std::mt19937 random(7);
  std::uniform_int_distribution<std::uint32_t> count(0, 12);
  for (const std::size_t size : {std::size_t{1}, std::size_t{5}, std::size_t{1023}, std::size_t{1024},
                                 std::size_t{1025}, std::size_t{262145}, largest}) {
    std::vector<std::uint32_t> values(size);
    std::generate(values.begin(), values.end(), [&] { return count(random); });
    std::vector<std::uint32_t> expected(size);
    std::exclusive_scan(values.begin(), values.end(), expected.begin(), std::uint32_t{0});
    const auto buffer = gt::StorageBuffer::from(values);
    scan.run(buffer, size);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    EXPECT_EQ(buffer.download<std::uint32_t>(size), expected) << size << " values";
  }
}

// Only the first `count` values change.
TEST_F(GpuExclusiveScan, LeavesValuesPastTheCountAlone) {
  const gt::gpu::ExclusiveScan scan(4096);
  const std::vector<std::uint32_t> values(3000, 1);
  const auto buffer = gt::StorageBuffer::from(values);
  scan.run(buffer, 2000);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto scanned = buffer.download<std::uint32_t>(values.size());
  EXPECT_EQ(scanned[1999], 1999u);
  EXPECT_EQ(scanned[2000], 1u);
  EXPECT_EQ(scanned.back(), 1u);
  EXPECT_THROW(scan.run(buffer, 4097), std::invalid_argument);
}

}  // namespace
