// The GPU Earth-like planet generator (gpu/planet/generator.hpp) against its CPU reference with
// Real = float (reference/planet/), step by step as core/params/planet.hpp specifies: jitter offsets
// bit for bit and positions within tan's licence; plates, cycles and edges region for region; plate
// motion and every elevation stage within an error model fed the same positions and partition; the
// whole chain run() against the same; and the CPU-only modes refused.
//
// Error model (u = 2^−24, float's unit roundoff). Both twins run the same float operations in the
// same order, so they differ only where GLSL licenses the GPU to round differently from C++:
//   - division within 2.5 ulp and sqrt within 3 ulp (GLSL 4.50 §4.7.1: sqrt inherited from
//     1/inversesqrt), llvmpipe rounding both correctly. A normalise (1/sqrt, a product) of the same
//     vector then differs by at most unit_vector_licence per component;
//   - tan, which GLSL leaves implementation-defined: Mesa lowers it to sin/cos; we assume both
//     within 2^−20 absolute on [−θ, θ] (an assumption: CUDA documents 2^−21.41 for its hardware
//     __sinf/__cosf on [−π, π]; Vulkan licenses 2^−11);
//   - the plate centre sums, whose order the spec leaves open: the reference may add in index order
//     in float (each of n additions errs by <= u·Σ|x|), the GPU adds exactly in 64-bit fixed point
//     (gpu/shaders/planet/fixed_point.glsl: < N·2^−40 + 2^−33 + 2u·|sum|).
// Operations without a division, sqrt or tan (offsets, base elevations, the noise E0) are exact
// twins: the same bits.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/checks/planet_error_model.hpp"
#include "core/errors.hpp"
#include "core/params/fault_planet.hpp"
#include "core/params/planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "core/rng.hpp"
#include "core/planet/sphere_mesh.hpp"
#include "gpu/planet/fault_lines.hpp"
#include "gpu/planet/generator.hpp"
#include "gpu/planet/render.hpp"
#include "gpu/planet/voronoi.hpp"
#include "reference/planet/elevation.hpp"
#include "reference/planet/fault_lines.hpp"
#include "reference/planet/jitter.hpp"
#include "reference/planet/plates.hpp"
#include "reference/planet/render.hpp"
#include "reference/planet/voronoi.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/refusal.hpp"

namespace {

using gt::testing::refusal;

constexpr double u = 0x1p-24;
constexpr double tan_theta = 1.1822866855;              // tan θ
constexpr double sec_squared_theta = 1.0 + tan_theta * tan_theta;  // tan's slope at θ
constexpr double cos_theta = 0.6458;                    // cos θ, rounded down
constexpr double sin_cos_licence = 0x1p-20;             // the assumed sin/cos absolute error
// A normalise of the same vector: sqrt 3 ulp + division 2.5 ulp + each side's product, with margin.
constexpr double unit_vector_licence = 16.0 * u;

gt::PlanetParams planet_params(int resolution, int plates, double expansion_range, std::uint32_t seed) {
  gt::PlanetParams params;
  params.resolution = resolution;
  params.plates = plates;
  params.expansion_range = expansion_range;
  params.seed = seed;
  return params;
}

double max_abs_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) largest = std::max(largest, std::abs(double(a[i]) - double(b[i])));
  return largest;
}

// ---------------------------------------------------------------------------------------------
// Step 1.

// |Δ position component| on a unit sphere: a = (x + o)/R errs by 3u (division), so 2a − 1 by 7u and
// θ(2a − 1) by 7u; tan amplifies that by sec²θ and adds its own sin/cos error,
// ε(1 + tan θ)/(cos θ − ε) (a quotient of two perturbed values), plus the quotient's 3u; dividing
// by tan θ (another 3u) gives |Δf|. The cube point moves by at most √2·|Δf| (two warped
// coordinates), its normalisation (|w| >= 1) by no more, plus the normalise's own licence.
constexpr double position_bound() {
  const double tan_error =
      sec_squared_theta * 7.0 * u + sin_cos_licence * (1.0 + tan_theta) / (cos_theta - sin_cos_licence) + 3.0 * u * tan_theta;
  const double warped_error = tan_error / tan_theta + 3.0 * u;
  return 1.4143 * warped_error + unit_vector_licence;
}

// Each jitter j through the optimised warp, and the other warps of the `warp` parameter at j = 0.5.
// Through any warp the GPU's centroids lie within the position bound of ref<float>'s (the optimised
// warp's bound holds for the others, whose slopes are smaller); through another warp than the
// optimised one they lie far from the optimised warp's, so the warp asked reached the GPU.
struct JitterCase {
  double jitter;
  gt::PlanetWarp warp;
};

void PrintTo(const JitterCase& jitter_case, std::ostream* out) {
  *out << "j" << jitter_case.jitter << "_" << gt::planet_warp_name(jitter_case.warp);
}

class PlanetJitterGpu : public gt::testing::GlTestWithParam<JitterCase> {};

TEST_P(PlanetJitterGpu, OffsetsAreTheReferenceBitsAndPositionsWithinTansLicence) {
  auto params = planet_params(9, 5, 0.5, 17);
  params.jitter = GetParam().jitter;
  params.warp = GetParam().warp;
  const gt::CubeSphere sphere(params.resolution);
  gt::gpu::PlanetGenerator gpu(sphere, params);
  const auto on_gpu = gpu.jitter();
  const auto reference = gt::reference::jitter_regions<float>(sphere, params);
  ASSERT_EQ(on_gpu.offsets.size(), reference.offsets.size());
  ASSERT_EQ(on_gpu.positions.size(), reference.positions.size());
  EXPECT_EQ(on_gpu.offsets, reference.offsets) << "0.5 + (U − 0.5)·j: no division, the same bits";
  EXPECT_LE(max_abs_difference(on_gpu.positions, reference.positions), position_bound());
  if (params.warp == gt::PlanetWarp::optimised) return;
  auto optimised = params;
  optimised.warp = gt::PlanetWarp::optimised;
  EXPECT_GT(max_abs_difference(on_gpu.positions, gt::reference::jitter_regions<float>(sphere, optimised).positions), 0.01);
}

INSTANTIATE_TEST_SUITE_P(Jitters, PlanetJitterGpu,
                         ::testing::Values(JitterCase{0.0, gt::PlanetWarp::optimised},
                                           JitterCase{0.5, gt::PlanetWarp::optimised},
                                           JitterCase{1.0, gt::PlanetWarp::optimised},
                                           JitterCase{0.5, gt::PlanetWarp::none},
                                           JitterCase{0.5, gt::PlanetWarp::tangent}));

// ---------------------------------------------------------------------------------------------
// Steps 2–3: integers and exact float comparisons of the same draws, so region for region.

struct PlateCase {
  int resolution;
  int plates;
  double expansion_range;
  std::uint32_t seed;
};

void PrintTo(const PlateCase& plate_case, std::ostream* out) {
  *out << "R" << plate_case.resolution << "_P" << plate_case.plates << "_e" << plate_case.expansion_range << "_seed"
       << plate_case.seed;
}

class PlanetPlatesGpu : public gt::testing::GlTestWithParam<PlateCase> {};

TEST_P(PlanetPlatesGpu, PartitionCyclesAndEdgesEqualTheReference) {
  const auto& plate_case = GetParam();
  const auto params =
      planet_params(plate_case.resolution, plate_case.plates, plate_case.expansion_range, plate_case.seed);
  const gt::CubeSphere sphere(params.resolution);
  gt::gpu::PlanetGenerator gpu(sphere, params);
  const auto on_gpu = gpu.grow_plates();
  const auto reference = gt::reference::grow_plates(sphere, params);
  EXPECT_EQ(on_gpu.plate, reference.plate);
  EXPECT_EQ(on_gpu.cycles, reference.cycles);
  EXPECT_EQ(on_gpu.is_edge, reference.is_edge);
  EXPECT_EQ(std::count(on_gpu.plate.begin(), on_gpu.plate.end(), -1), 0) << "every region has a plate";
}

INSTANTIATE_TEST_SUITE_P(Cases, PlanetPlatesGpu,
                         ::testing::Values(PlateCase{1, 6, 0.5, 1},     // every region a seed: 0 cycles
                                           PlateCase{10, 10, 0.5, 7},   //
                                           PlateCase{25, 50, 0.5, 3},   // the thesis's default shape
                                           PlateCase{25, 50, 2.5, 11},  // 4 sub-steps per cycle
                                           PlateCase{12, 40, 5.0, 5},   // rates from 1/256 to 6
                                           PlateCase{4, 90, 0.5, 2},    // 96 regions: many rejected draws
                                           PlateCase{40, 500, 0.5, 4},  // the most plates: 33,000 seed steps
                                           PlateCase{110, 50, 0.5, 4}));  // N > 65,535 invocations

// ---------------------------------------------------------------------------------------------
// Steps 4–9 from the reference's own positions and partition (the driver's shadow parity).

// Per plate, the licensed difference of the centre (per component) and of the shift.
struct MotionBounds {
  std::vector<double> centre;
  std::vector<double> shift;
};

// The centre: the sum errs by n·u·Σ|x| (reference, any order) + the fixed point's error (GPU), per
// component; normalising divides an error by |sum| (√3 for three components, 2 for the second
// order, valid while the result is below 1/2). The shift: t's components are sums of two products
// of the centre by |α|, |β| <= 1, so |Δt| <= 2·|Δc| + 2u; m·t/|t| moves by at most
// 2·√3·|Δt|·m/|t| (m <= 1), plus its own division and sqrt; never more than 2 (|s| <= 1 on both
// sides).
MotionBounds motion_bounds(const gt::PlanetParams& params, const std::vector<float>& positions,
                           const gt::PlatePartition& partition, const gt::PlateMotion<float>& reference) {
  const auto plates = static_cast<std::size_t>(params.plates);
  std::vector<std::array<double, 3>> sums(plates, {0, 0, 0}), absolute_sums(plates, {0, 0, 0});
  std::vector<double> members(plates, 0.0);
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    if (params.centre == gt::PlateCentre::edge_sum && !partition.is_edge[region]) continue;
    const auto plate = static_cast<std::size_t>(partition.plate[region]);
    members[plate] += 1.0;
    for (int axis = 0; axis < 3; ++axis) {
      sums[plate][axis] += positions[3 * region + axis];
      absolute_sums[plate][axis] += std::abs(positions[3 * region + axis]);
    }
  }
  const double fixed_point_error = params.region_count() * 0x1p-40 + 0x1p-33;
  MotionBounds bounds;
  for (std::size_t k = 0; k < plates; ++k) {
    const double sum_length = std::hypot(sums[k][0], sums[k][1], sums[k][2]);
    double sum_error = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      sum_error = std::max(sum_error, members[k] * u * absolute_sums[k][axis] + fixed_point_error + 2.0 * u * sum_length);
    }
    const double centre = sum_length > 0.0 ? std::min(2.0, 2.0 * 1.7321 * sum_error / sum_length + unit_vector_licence) : 2.0;
    const auto& c = reference.centre[k];
    const double alpha = 2.0 * gt::uniform01(gt::random_u32(params.seed, std::uint32_t(k), 1, gt::planet_stream_shift)) - 1.0;
    const double beta = 2.0 * gt::uniform01(gt::random_u32(params.seed, std::uint32_t(k), 2, gt::planet_stream_shift)) - 1.0;
    const double tangent_length = std::hypot(beta * c[2], alpha * c[2], beta * c[0] - alpha * c[1]);
    const double tangent_error = 2.0 * centre + 2.0 * u;
    const double shift = tangent_length > tangent_error
                             ? std::min(2.0, 2.0 * 1.7321 * tangent_error / (tangent_length - tangent_error) + unit_vector_licence)
                             : 2.0;
    bounds.centre.push_back(centre);
    bounds.shift.push_back(shift);
  }
  return bounds;
}

void expect_vectors_within(const std::vector<gt::Vector3<float>>& gpu, const std::vector<gt::Vector3<float>>& reference,
                           const std::vector<double>& bounds, const char* what) {
  ASSERT_EQ(gpu.size(), reference.size());
  for (std::size_t k = 0; k < gpu.size(); ++k) {
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_LE(std::abs(double(gpu[k][axis]) - double(reference[k][axis])), bounds[k]) << what << " of plate " << k;
    }
  }
}

void expect_within(const std::vector<float>& gpu, const std::vector<float>& reference, const std::vector<double>& bounds,
                   const char* what) {
  ASSERT_EQ(gpu.size(), reference.size());
  std::size_t outside = 0;
  for (std::size_t i = 0; i < gpu.size(); ++i) {
    if (!(std::abs(double(gpu[i]) - double(reference[i])) <= bounds[i])) ++outside;
  }
  EXPECT_EQ(outside, 0u) << what << ": regions outside the bound (max |difference| "
                         << max_abs_difference(gpu, reference) << ")";
}

// What the GPU computed for `params` from (positions, partition) against planet_elevation<float>.
void expect_elevation_matches(const gt::CubeSphere& sphere, const gt::PlanetParams& params,
                              const std::vector<float>& positions, const gt::PlatePartition& partition,
                              const gt::PlanetElevation<float>& on_gpu) {
  const auto reference = gt::reference::planet_elevation<float>(sphere, params, positions, partition);
  const auto motion = motion_bounds(params, positions, partition, reference.motion);
  expect_vectors_within(on_gpu.motion.centre, reference.motion.centre, motion.centre, "centre");
  expect_vectors_within(on_gpu.motion.shift, reference.motion.shift, motion.shift, "shift");
  EXPECT_EQ(on_gpu.motion.base, reference.motion.base) << "e_r·(2U − 1): the same bits";
  EXPECT_EQ(on_gpu.noisy, reference.noisy) << "base + S·fbm: no division, the same bits";
  // E1 and E2: the driver's error model (compare/checks/planet_error_model.hpp) for the GPU fed
  // the same state as ref<float>: no position error, 4u per operation; evaluated on the double
  // reference of the same positions.
  const std::vector<double> wide_positions(positions.begin(), positions.end());
  const auto truth = gt::reference::planet_elevation<double>(sphere, params, wide_positions, partition);
  const auto bounds = gt::elevation_bounds(sphere, params, wide_positions, partition, truth, {0.0, 4.0 * u});
  expect_within(on_gpu.collided, reference.collided, bounds.collided, "collided");
  expect_within(on_gpu.smoothed, reference.smoothed, bounds.smoothed, "smoothed");
}

struct ElevationCase {
  gt::PressureFormula pressure;
  gt::Smoothing smoothing;
  bool noise;
  gt::PlateCentre centre;
};

void PrintTo(const ElevationCase& elevation_case, std::ostream* out) {
  *out << (elevation_case.pressure == gt::PressureFormula::code ? "code" : "thesis") << "_"
       << gt::smoothing_name(elevation_case.smoothing) << (elevation_case.noise ? "_noise" : "_quiet")
       << (elevation_case.centre == gt::PlateCentre::mean ? "_mean" : "_edge_sum");
}

std::vector<ElevationCase> every_elevation_case() {
  std::vector<ElevationCase> cases;
  for (const auto pressure : {gt::PressureFormula::code, gt::PressureFormula::thesis}) {
    for (const auto smoothing : {gt::Smoothing::jacobi, gt::Smoothing::off}) {
      for (const bool noise : {true, false}) {
        for (const auto centre : {gt::PlateCentre::mean, gt::PlateCentre::edge_sum}) {
          cases.push_back({pressure, smoothing, noise, centre});
        }
      }
    }
  }
  return cases;
}

class PlanetElevationGpu : public gt::testing::GlTestWithParam<ElevationCase> {};

TEST_P(PlanetElevationGpu, StagesAndMotionWithinTheModelOfTheFloatReference) {
  auto params = planet_params(10, 12, 0.5, 23);
  params.pressure = GetParam().pressure;
  params.smoothing = GetParam().smoothing;
  params.noise = GetParam().noise;
  params.centre = GetParam().centre;
  params.perlin_octaves = 3;
  const gt::CubeSphere sphere(params.resolution);
  const auto positions = gt::reference::jitter_regions<float>(sphere, params).positions;
  const auto partition = gt::reference::grow_plates(sphere, params);
  gt::gpu::PlanetGenerator gpu(sphere, params);
  expect_elevation_matches(sphere, params, positions, partition, gpu.elevation(positions, partition));
}

INSTANTIATE_TEST_SUITE_P(Variants, PlanetElevationGpu, ::testing::ValuesIn(every_elevation_case()));

class PlanetChainGpu : public gt::testing::GlTest {};

TEST_F(PlanetChainGpu, WithoutCollisionsTheCodesRuleSkipsSmoothing) {
  auto params = planet_params(8, 9, 0.5, 4);
  params.collisions = false;
  params.smooth_only_with_collisions = true;
  const gt::CubeSphere sphere(params.resolution);
  const auto positions = gt::reference::jitter_regions<float>(sphere, params).positions;
  const auto partition = gt::reference::grow_plates(sphere, params);
  gt::gpu::PlanetGenerator gpu(sphere, params);
  const auto on_gpu = gpu.elevation(positions, partition);
  EXPECT_EQ(on_gpu.collided, on_gpu.noisy);
  EXPECT_EQ(on_gpu.smoothed, on_gpu.noisy);
  expect_elevation_matches(sphere, params, positions, partition, on_gpu);
}

// run(): the whole chain on the GPU, no download between steps; the same partition as the
// reference, the same elevation model against the reference fed the GPU's positions (identical to
// jitter()'s: the same pass), and two runs give the same bits (the centre sums are order-free).
TEST_F(PlanetChainGpu, RunGivesTheStepwiseResultsAndRepeatsBitForBit) {
  auto params = planet_params(12, 20, 0.5, 8);
  params.pressure = gt::PressureFormula::thesis;
  const gt::CubeSphere sphere(params.resolution);
  gt::gpu::PlanetGenerator gpu(sphere, params);
  const auto positions = gpu.jitter().positions;
  gpu.run();
  const auto partition = gpu.partition_result();
  const auto elevation = gpu.elevation_result();
  const auto reference_partition = gt::reference::grow_plates(sphere, params);
  EXPECT_EQ(partition.plate, reference_partition.plate);
  EXPECT_EQ(partition.cycles, reference_partition.cycles);
  EXPECT_EQ(partition.is_edge, reference_partition.is_edge);
  expect_elevation_matches(sphere, params, positions, reference_partition, elevation);
  gpu.run();
  EXPECT_EQ(gpu.elevation_result().smoothed, elevation.smoothed);
}

// The cell-grid search (5×5 through the neighbour table) against the exact nearest centroid, both
// on ref<float>'s positions: a label may differ only on a near-tie, where the GPU's float squared
// chords cannot tell the two apart. Each squared chord takes 3 subtractions, 3 products and 2 sums,
// each rounded by at most 2^-24 of a magnitude <= 4 (2^-22): 8·2^-22 = 2^-19 per distance, so a
// label may be farther than the nearest by 2^-18 in squared chord, no more.
TEST_F(PlanetChainGpu, VoronoiLabelsAreTheNearestCentroidsUpToTies) {
  for (const int resolution : {3, 10, 25}) {
    const gt::CubeSphere sphere(resolution);
    const auto positions = gt::reference::jitter_regions<float>(sphere, planet_params(resolution, 5, 0.5, 21)).positions;
    std::vector<gt::Vector3<double>> directions;
    std::vector<gt::Vector3<float>> queries;
    for (std::uint32_t index = 0; index < 20000; ++index) {
      std::array<double, 3> direction{};
      double squared = 0.0;
      for (std::uint32_t axis = 0; axis < 3; ++axis) {
        direction[axis] = 2.0 * gt::uniform01(gt::random_u32(5, index, axis, 1)) - 1.0;
        squared += direction[axis] * direction[axis];
      }
      if (squared < 1e-6 || squared > 1.0) continue;
      const auto single = gt::Vector3<float>{float(direction[0] / std::sqrt(squared)), float(direction[1] / std::sqrt(squared)),
                                             float(direction[2] / std::sqrt(squared))};
      queries.push_back(single);
      directions.push_back({single[0], single[1], single[2]});
    }
    const std::vector<double> wide(positions.begin(), positions.end());
    const auto nearest = gt::reference::nearest_sites(wide, directions);
    for (const int rings : {1, 2}) {
      const auto labels = gt::gpu::PlanetVoronoi(sphere, rings).labels(positions, queries);
      std::size_t misses = 0;
      for (std::size_t index = 0; index < labels.size(); ++index) {
        const auto label = static_cast<std::size_t>(labels[index]);
        const double distance = std::hypot(wide[3 * label] - directions[index][0], wide[3 * label + 1] - directions[index][1],
                                           wide[3 * label + 2] - directions[index][2]);
        misses += distance * distance > nearest[index].distance * nearest[index].distance + 0x1p-18 ? 1 : 0;
      }
      if (rings == 2) {
        EXPECT_EQ(misses, 0u) << "R = " << resolution << ": the 5×5 block holds the nearest centroid";
      }
      EXPECT_LE(misses, labels.size() / 100) << "R = " << resolution << ", " << rings << " ring(s)";
    }
  }
}

// The planet drawn by both twins from the same centroids and elevations (float on the GPU, their
// exact widening on the CPU) through the same P·V. Coverage: both follow GL's rules at 8 subpixel
// bits, the GPU from float clip coordinates, so they may differ only on pixels whose centre lies
// within float rounding of the silhouette: fewer than its perimeter, 2πr pixels. Labels: the GPU's
// fragment direction is within float interpolation error (~2^-20) of the reference's, so a label
// may differ only where two centroids are that close to a tie; with cells ~0.1 wide that is far
// below 1 pixel in 1000. Colour: a pixel whose label agrees shows the same palette bytes (the
// palette is exact in float up to round(255·c) on a half, which no elevation here hits).
TEST_F(PlanetChainGpu, RenderedPlanetMatchesTheReferencePixelForPixel) {
  const auto params = planet_params(12, 20, 0.5, 3);
  const gt::CubeSphere sphere(params.resolution);
  const auto positions = gt::reference::jitter_regions<float>(sphere, params).positions;
  std::vector<float> elevation(sphere.region_count());
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    elevation[region] = float(6.0 * gt::uniform01(gt::random_u32(3, std::uint32_t(region), 0, 0)) - 3.0);
  }
  const gt::Mesh mesh = gt::sphere_mesh(sphere);
  gt::reference::Camera camera;
  camera.eye = {1.2, 1.1, 2.3};
  camera.near = 1.0;
  camera.far = 5.0;
  camera.width = camera.height = 128;
  const auto cpu = gt::reference::render_planet(mesh, camera, std::vector<double>(positions.begin(), positions.end()),
                                                std::vector<double>(elevation.begin(), elevation.end()));
  const auto view_projection =
      gt::reference::multiply(gt::reference::projection_matrix(camera), gt::reference::view_matrix(camera));
  const gt::gpu::PlanetRenderer renderer(mesh, view_projection, sphere, gt::CubeWarp{}, positions, elevation, camera.width,
                                         camera.height);
  renderer.run();
  const gt::gpu::PlanetPixels gpu = renderer.image();
  ASSERT_EQ(gpu.regions.size(), cpu.regions.size());
  const double radius_px = std::sqrt(double(cpu.image.covered_pixels) / std::numbers::pi);
  std::size_t coverage_differs = 0, both = 0, labels_differ = 0, colours_differ = 0;
  for (std::size_t pixel = 0; pixel < cpu.regions.size(); ++pixel) {
    const bool cpu_drew = cpu.regions[pixel] >= 0, gpu_drew = gpu.regions[pixel] >= 0;
    coverage_differs += cpu_drew != gpu_drew ? 1 : 0;
    if (!cpu_drew || !gpu_drew) continue;
    ++both;
    if (cpu.regions[pixel] != gpu.regions[pixel]) {
      ++labels_differ;
      continue;
    }
    for (std::size_t channel = 0; channel < 3; ++channel) {
      colours_differ += cpu.image.rgb[3 * pixel + channel] == gpu.rgb[3 * pixel + channel] ? 0 : 1;
    }
  }
  EXPECT_GT(both, cpu.regions.size() / 4);
  EXPECT_LT(double(coverage_differs), 2.0 * std::numbers::pi * radius_px);
  EXPECT_LE(labels_differ, both / 1000);
  EXPECT_EQ(colours_differ, 0u);
}

TEST_F(PlanetChainGpu, RefusesTheCpuOnlyModes) {
  const gt::CubeSphere sphere(6);
  auto legacy_plates = planet_params(6, 10, 0.5, 1);
  legacy_plates.plate_rule = gt::PlateRule::legacy;
  EXPECT_NE(refusal([&] { gt::gpu::PlanetGenerator(sphere, legacy_plates); }).find("plate_rule 'legacy'"),
            std::string::npos);
  auto legacy_smoothing = planet_params(6, 10, 0.5, 1);
  legacy_smoothing.smoothing = gt::Smoothing::legacy;
  EXPECT_NE(refusal([&] { gt::gpu::PlanetGenerator(sphere, legacy_smoothing); }).find("smoothing 'legacy'"),
            std::string::npos);
  const auto too_many_plates = planet_params(6, 217, 0.5, 1);
  EXPECT_NE(refusal([&] { gt::gpu::PlanetGenerator(sphere, too_many_plates); }).find("outside 1..216"),
            std::string::npos);
}


// The fault-line planet on the GPU against ref<float>: the same float inputs and the same `precise`
// dot in the same order, every region's votes equal (R = 20, 300 faults).
class FaultLinesGpu : public gt::testing::GlTest {};

TEST_F(FaultLinesGpu, VotesEqualTheFloatReference) {
  const gt::FaultPlanetParams params{.resolution = 20, .faults = 300, .seed = 4};
  std::vector<float> normals;
  for (const auto& n : gt::fault_normals(params)) normals.insert(normals.end(), n.begin(), n.end());
  const auto positions_double = gt::fault_planet_positions(params.resolution);
  const std::vector<float> positions(positions_double.begin(), positions_double.end());
  const auto expected = gt::reference::fault_votes(positions, normals);
  gt::gpu::FaultLines gpu;
  EXPECT_EQ(gpu.votes(positions, normals), expected);
  EXPECT_NE(*std::max_element(expected.begin(), expected.end()), *std::min_element(expected.begin(), expected.end()));
}

}  // namespace
