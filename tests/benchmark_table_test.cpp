// The performance table beyond its timings: the derived columns (compare/benchmark_table.hpp:
// the memory-bound floor, "× peer", the scaling exponents), the bandwidth probe's GL copy
// (gpu/memory/copy_bandwidth.hpp), the peers (compare/peers/) and `groundtruth bench` with them.
// No test asserts a speed: the derived columns are checked on fabricated times, the real runs
// only for what they must hold whatever the machine.
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "compare/benchmark_table.hpp"
#include "compare/peers/vtk_isosurface.hpp"
#include "core/params.hpp"
#include "gpu/memory/copy_bandwidth.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace gt {
namespace {

using ::testing::HasSubstr;
using json = nlohmann::json;

BenchmarkRow timed(const std::string& algorithm, const std::string& backend, int size, double ms, int dimensions = 2,
                   int iterations = 1) {
  return {.algorithm = algorithm, .backend = backend, .size = size, .iterations = iterations, .reps = 3,
          .median_ms = ms, .device = backend == "gpu" ? "llvmpipe" : "Xeon", .dimensions = dimensions};
}

// ---- scaling ------------------------------------------------------------------------------------

// Times made exactly c · work^p (one rounding each): the least-squares slope of their logarithms
// is p up to the rounding of logarithms near 10 (~1e-15 each); 1e-12 leaves a margin of 1000.
TEST(ScalingFit, RecoversThePowerLawOfItsTimes) {
  for (const double power : {0.8, 1.0, 1.3}) {
    std::vector<BenchmarkRow> rows;
    for (const int size : {64, 128, 256, 512}) {
      rows.push_back(timed("erosion.thermal", "cpu", size, 0.01 * std::pow(double(size) * size * 10, power), 2, 10));
    }
    const auto fits = fit_scaling(rows);
    ASSERT_EQ(fits.size(), 1u);
    EXPECT_NEAR(fits[0].exponent, power, 1e-12);
    EXPECT_EQ(fits[0].sizes, (std::vector<int>{64, 128, 256, 512}));
    EXPECT_EQ(fits[0].linear(), power <= linear_exponent_limit);
  }
}

// A block's work is its voxels: times ∝ side³ scale linearly.
TEST(ScalingFit, CountsVoxelsAsTheWorkOfThreeDimensionalRows) {
  std::vector<BenchmarkRow> rows;
  for (const int side : {32, 64, 128, 256}) rows.push_back(timed("cave.marching_tetrahedra", "cpu", side, 1e-3 * side * side * side, 3));
  const auto fits = fit_scaling(rows);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_NEAR(fits[0].exponent, 1.0, 1e-12);
  EXPECT_EQ(fits[0].dimensions, 3);
}

// One fit per algorithm, backend, peer and device, only from rows that ran, and only with at
// least scaling_min_sizes sizes.
TEST(ScalingFit, FitsEachLineWithEnoughTimedSizes) {
  std::vector<BenchmarkRow> rows;
  for (const int size : {16, 32, 64, 128}) {
    rows.push_back(timed("noise.perlin3", "gpu", size, size * size * 1e-3));
    BenchmarkRow glm = timed("noise.perlin3", "peer", size, size * size * 2e-3);
    glm.peer = "GLM";
    BenchmarkRow libnoise = timed("noise.perlin3", "peer", size, size * size * 3e-3);
    libnoise.peer = "libnoise";
    rows.push_back(glm);
    rows.push_back(libnoise);
  }
  for (const int size : {16, 32, 64}) rows.push_back(timed("noise.perlin3", "cpu", size, 1.0));
  BenchmarkRow not_run = timed("noise.perlin3", "cpu", 128, 0.0);
  not_run.note = "did not fit";
  rows.push_back(not_run);

  const auto fits = fit_scaling(rows);
  ASSERT_EQ(fits.size(), 3u);
  EXPECT_EQ(fits[0].backend, "gpu");
  EXPECT_EQ(fits[1].peer, "GLM");
  EXPECT_EQ(fits[2].peer, "libnoise");
  for (const ScalingFit& fit : fits) EXPECT_NEAR(fit.exponent, 1.0, 1e-12);
}

// ---- floor and peers ----------------------------------------------------------------------------

// The probe copies 8 B per cell of 10⁶ cells in 2 ms: 4·10⁶ B/ms. A row of 10⁴ cells × 10
// iterations × 88 B then has a floor of 88·10⁵ / 4·10⁶ = 2.2 ms (exact up to rounding).
TEST(AnnotateBenchmarks, FloorIsTheRowsBytesAtTheProbesBandwidth) {
  BenchmarkRow probe = timed(bandwidth_probe_name, "cpu", 1000, 2.0);
  probe.bytes_per_cell = 8.0;
  BenchmarkRow counted = timed("erosion.thermal", "cpu", 100, 11.0, 2, 10);
  counted.bytes_per_cell = 88.0;
  BenchmarkRow uncounted = timed("erosion.thermal", "cpu", 200, 11.0, 2, 10);
  BenchmarkRow gpu_without_probe = timed("erosion.thermal", "gpu", 100, 1.0, 2, 10);
  gpu_without_probe.bytes_per_cell = 52.0;
  BenchmarkRow other_device = counted;
  other_device.device = "another CPU";
  std::vector<BenchmarkRow> rows = {probe, counted, uncounted, gpu_without_probe, other_device};

  annotate_benchmarks(rows);
  ASSERT_TRUE(rows[0].floor_ms);
  EXPECT_DOUBLE_EQ(*rows[0].floor_ms, 2.0);  // the probe is its own floor
  ASSERT_TRUE(rows[1].floor_ms);
  EXPECT_NEAR(*rows[1].floor_ms, 2.2, 1e-12);
  EXPECT_FALSE(rows[2].floor_ms);
  EXPECT_FALSE(rows[3].floor_ms);
  EXPECT_FALSE(rows[4].floor_ms);
}

TEST(AnnotateBenchmarks, ComparesOurRowsWithTheFastestPeerOfTheSameSize) {
  BenchmarkRow ours = timed("cave.marching_tetrahedra", "cpu", 64, 10.0, 3);
  BenchmarkRow ours_alone = timed("cave.marching_tetrahedra", "cpu", 128, 80.0, 3);
  BenchmarkRow slow_peer = timed("cave.marching_tetrahedra", "peer", 64, 5.0, 3);
  slow_peer.peer = "VTK vtkMarchingCubes";
  BenchmarkRow fast_peer = timed("cave.marching_tetrahedra", "peer", 64, 4.0, 3);
  fast_peer.peer = "VTK vtkFlyingEdges3D";
  BenchmarkRow peer_not_run = timed("cave.marching_tetrahedra", "peer", 64, 0.0, 3);
  peer_not_run.peer = "VTK";
  peer_not_run.note = "no VTK";
  BenchmarkRow other_size_peer = timed("cave.marching_tetrahedra", "peer", 256, 1.0, 3);
  other_size_peer.peer = "VTK vtkFlyingEdges3D";
  std::vector<BenchmarkRow> rows = {ours, ours_alone, slow_peer, fast_peer, peer_not_run, other_size_peer};

  annotate_benchmarks(rows);
  ASSERT_TRUE(rows[0].times_peer);
  EXPECT_DOUBLE_EQ(*rows[0].times_peer, 2.5);
  EXPECT_EQ(rows[0].fastest_peer, "VTK vtkFlyingEdges3D");
  EXPECT_FALSE(rows[1].times_peer);
  for (std::size_t peer = 2; peer < rows.size(); ++peer) EXPECT_FALSE(rows[peer].times_peer);
}

// ---- the probe's GL copy ------------------------------------------------------------------------

class CopyKernelTest : public testing::GlTest {};

TEST_F(CopyKernelTest, CopiesEveryElement) {
  // 70,000 floats, 17,500 vec4 invocations: 69 workgroups of 256, the last one partial.
  const std::size_t elements = 70000;
  const gpu::CopyKernel kernel(elements);
  kernel.run();
  std::vector<float> expected(elements);
  std::iota(expected.begin(), expected.end(), 0.0f);
  EXPECT_EQ(kernel.target(), expected);
  EXPECT_EQ(kernel.bytes_per_run(), 8.0 * elements);
}

TEST_F(CopyKernelTest, RefusesCountsThatAreNotWholeVectors) {
  EXPECT_THROW(gpu::CopyKernel(0), std::invalid_argument);
  EXPECT_THROW(gpu::CopyKernel(70001), std::invalid_argument);
}

// ---- peers --------------------------------------------------------------------------------------

std::vector<std::string> peer_names(const std::string& algorithm) {
  std::vector<std::string> names;
  for (const Peer& peer : find_algorithm(algorithm).peers) names.push_back(peer.name);
  return names;
}

TEST(Peers, NoiseFunctionsHaveTheirLibraryCounterparts) {
  using ::testing::ElementsAre;
  EXPECT_THAT(peer_names("noise.simplex2"), ElementsAre(HasSubstr("glm::simplex(dvec2)")));
  EXPECT_THAT(peer_names("noise.simplex3"), ElementsAre(HasSubstr("glm::simplex(dvec3)")));
  EXPECT_THAT(peer_names("noise.simplex4"), ElementsAre(HasSubstr("glm::simplex(dvec4)")));
  EXPECT_THAT(peer_names("noise.perlin3"),
              ElementsAre(HasSubstr("glm::perlin(dvec3)"), HasSubstr("GradientCoherentNoise3D")));
  EXPECT_THAT(peer_names("noise.fbm"), ElementsAre(HasSubstr("module::Perlin")));
  EXPECT_TRUE(peer_names("noise.ridged").empty());
}

TEST(Peers, EveryNoisePeerRunsOnTheDefaultParameters) {
  for (const Algorithm& algorithm : algorithms()) {
    for (const Peer& peer : algorithm.peers) {
      const auto resolved = resolve_params(algorithm.name, *algorithm.params, json::object());
      const auto work = peer.prepare(resolved, 8, 8);
      EXPECT_NO_THROW(work()) << peer.name;
    }
  }
}

// libnoise's module::Perlin takes a whole number of octaves: a fractional fbm has no peer.
TEST(Peers, LibnoiseRefusesAFractionalOctaveCount) {
  const Algorithm& fbm = find_algorithm("noise.fbm");
  const auto resolved = resolve_params(fbm.name, *fbm.params, {{"octaves", 2.5}});
  EXPECT_THROW(fbm.peers.at(0).prepare(resolved, 8, 8), std::invalid_argument);
}

// Flying edges and marching cubes share VTK's case table: on the same samples they make the same
// number of triangles, and a sphere of radius 8 inside the block makes some.
TEST(VtkPeer, BothFiltersMeshTheSameSphere) {
  Volume<double> sphere(24, 24, 24);
  for (int z = 0; z < 24; ++z) {
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 24; ++x) sphere.at(x, y, z) = std::hypot(x - 11.5, y - 11.5, z - 11.5) - 8.0;
    }
  }
  const auto runs = run_vtk_isosurface(sphere, 0.0, 2);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_THAT(runs[0].name, HasSubstr("vtkFlyingEdges3D"));
  EXPECT_THAT(runs[1].name, HasSubstr("vtkMarchingCubes"));
  EXPECT_GT(runs[0].triangles, 0u);
  EXPECT_EQ(runs[0].triangles, runs[1].triangles);
  for (const auto& run : runs) EXPECT_EQ(run.ms.size(), 2u);
}

// ---- groundtruth bench ---------------------------------------------------------------------------

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";

TEST(BenchCli, TableHasTheProbePeersFloorAndScaling) {
  const testing::TemporaryFolder out("gt_bench");
  const auto run = testing::run_program(groundtruth, {"bench", "noise.perlin3", "--sizes", "16,24,32,48", "--iterations",
                                                      "1", "--reps", "1", "--quiet", "--out", out.path().string()});
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_THAT(run.out, HasSubstr(" benchmark rows; report in ")) << "rows counted, not \"0 cases\"";
  const json report = json::parse(testing::read_text(out / "report.json"));
  int probes = 0, peers = 0, ours = 0;
  for (const json& row : report.at("benchmarks")) {
    if (row.at("algorithm") == bandwidth_probe_name) {
      ++probes;
      EXPECT_EQ(row.at("bytes_per_cell"), 8.0);
      EXPECT_DOUBLE_EQ(row.at("times_floor").get<double>(), 1.0);
    } else if (!row.at("peer").get<std::string>().empty()) {
      ++peers;
      EXPECT_EQ(row.at("backend"), "peer");
    } else {
      ++ours;
      EXPECT_EQ(row.at("algorithm"), "noise.perlin3");
      EXPECT_GT(row.at("floor_ms").get<double>(), 0.0) << row;
      EXPECT_GT(row.at("times_peer").get<double>(), 0.0) << row;
      EXPECT_THAT(row.at("fastest_peer").get<std::string>(), ::testing::AnyOf(HasSubstr("GLM"), HasSubstr("libnoise")));
    }
  }
  EXPECT_EQ(probes, 2);      // CPU and GL
  EXPECT_EQ(peers, 2 * 4);   // GLM and libnoise at each size
  EXPECT_EQ(ours, 2 * 4);    // CPU and GPU at each size
  std::vector<std::string> fitted;
  for (const json& fit : report.at("scaling")) {
    EXPECT_EQ(fit.at("sizes"), json({16, 24, 32, 48}));
    fitted.push_back(fit.at("backend").get<std::string>() + ":" + fit.at("peer").get<std::string>());
  }
  EXPECT_EQ(fitted.size(), 4u);
  const std::string markdown = testing::read_text(out / "report.md");
  EXPECT_THAT(markdown, HasSubstr("× floor"));
  EXPECT_THAT(markdown, HasSubstr("### Scaling"));
}

// A seed's published timings stand beside our rows of the same size, and only there: Hydra's
// Table 5.6 has 128 px (RTX 3080 1.80 ms, GTX 745 22 ms for 50 iterations) and no 64 px column.
TEST(BenchCli, PublishedFiguresStandBesideOurRowsOfTheirSize) {
  const testing::TemporaryFolder out("gt_bench");
  const auto run = testing::run_program(groundtruth, {"bench", "erosion.thermal", "--sizes", "64,128", "--iterations",
                                                      "1", "--reps", "1", "--quiet", "--out", out.path().string()});
  ASSERT_EQ(run.status, 0) << run;
  const json report = json::parse(testing::read_text(out / "report.json"));
  std::vector<double> published_ms;
  for (const json& row : report.at("benchmarks")) {
    if (row.at("backend") != "published") continue;
    EXPECT_EQ(row.at("algorithm"), "erosion.thermal");
    EXPECT_EQ(row.at("size"), 128) << row;
    EXPECT_EQ(row.at("iterations"), 50) << row;
    EXPECT_THAT(row.at("device").get<std::string>(), HasSubstr("Table 5.6"));
    published_ms.push_back(row.at("median_ms").get<double>());
  }
  EXPECT_THAT(published_ms, ::testing::UnorderedElementsAre(1.80, 22.0));
}

// Hydra's spacing study at 128 px: Table 5.3 alone has that side (spacing 16, with and without
// interpolation, on both GPUs), so the study times our GPU in those two variants and no other, and
// shows the four published rows beside them; Tables 5.4/5.5 (256 and 512 px) stay out.
TEST(BenchCli, TheSpacingStudyTimesTheVariantsThePublishedTablesHaveAtThatSide) {
  const testing::TemporaryFolder out("gt_bench");
  const auto run = testing::run_program(groundtruth, {"bench", "erosion.particle", "--sizes", "128", "--reps", "1",
                                                      "--quiet", "--out", out.path().string()});
  ASSERT_EQ(run.status, 0) << run;
  const json report = json::parse(testing::read_text(out / "report.json"));
  std::vector<std::string> study_backends, published_tables;
  for (const json& row : report.at("benchmarks")) {
    if (row.at("algorithm") != "erosion.particle") continue;
    const auto backend = row.at("backend").get<std::string>();
    const auto device = row.at("device").get<std::string>();
    if (backend.starts_with("gpu (")) study_backends.push_back(backend);
    if (backend == "published" && device.find("Table 5.1") == std::string::npos) {
      published_tables.push_back(device.substr(device.find("Table ")));
    }
  }
  EXPECT_THAT(study_backends, ::testing::UnorderedElementsAre("gpu (spacing 16)", "gpu (spacing 16, interpolated)"));
  EXPECT_THAT(published_tables,
              ::testing::UnorderedElementsAre("Table 5.3: spacing 16)", "Table 5.3: spacing 16)",
                                              "Table 5.3: spacing 16, interpolated)",
                                              "Table 5.3: spacing 16, interpolated)"));
}

TEST(BenchCli, APatternThatMatchesNoAlgorithmIsBadInput) {
  const testing::TemporaryFolder out("gt_bench");
  const auto run = testing::run_program(groundtruth, {"bench", "nothing.*", "--quiet", "--out", out.path().string()});
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("no algorithm of the performance table matches 'nothing.*'"));
}

}  // namespace
}  // namespace gt
