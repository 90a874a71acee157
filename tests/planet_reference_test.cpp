// The CPU reference of seed 002's Earth-like generator (reference/planet/) against the invariants
// of digest 002 §9.5 and properties that follow from the spec of core/params/planet.hpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <numbers>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/params.hpp"
#include "core/params/fault_planet.hpp"
#include "core/params/planet.hpp"
#include "core/rng.hpp"
#include "reference/planet/elevation.hpp"
#include "reference/planet/fault_lines.hpp"
#include "reference/planet/jitter.hpp"
#include "reference/planet/plates.hpp"
#include "reference/planet/render.hpp"
#include "reference/planet/voronoi.hpp"
#include "core/planet/sphere_mesh.hpp"
#include <map>

namespace gt {
namespace {

PlanetParams params_of(int resolution, int plates, double expansion_range = 0.5, std::uint32_t seed = 7) {
  PlanetParams params;
  params.resolution = resolution;
  params.plates = plates;
  params.expansion_range = expansion_range;
  params.seed = seed;
  return params;
}

// Hops from `source` to every region over valid 8-neighbours (the sphere is connected).
std::vector<int> hop_distances(const CubeSphere& sphere, std::int32_t source) {
  std::vector<int> distance(sphere.region_count(), -1);
  std::deque<std::int32_t> queue{source};
  distance[source] = 0;
  while (!queue.empty()) {
    const std::int32_t region = queue.front();
    queue.pop_front();
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region || distance[neighbour] >= 0) continue;
      distance[neighbour] = distance[region] + 1;
      queue.push_back(neighbour);
    }
  }
  return distance;
}

// Every region has a plate in [0, P); every plate is non-empty, holds its seed and is 8-connected.
void expect_valid_partition(const CubeSphere& sphere, const PlanetParams& params, const PlatePartition& partition) {
  ASSERT_EQ(partition.plate.size(), sphere.region_count());
  const auto seeds = reference::plate_seeds(params);
  std::vector<std::size_t> reached(static_cast<std::size_t>(params.plates), 0), members(reached.size(), 0);
  for (const std::int32_t plate : partition.plate) {
    ASSERT_GE(plate, 0);
    ASSERT_LT(plate, params.plates);
    ++members[plate];
  }
  for (int plate = 0; plate < params.plates; ++plate) {
    EXPECT_EQ(partition.plate[seeds[plate]], plate) << "a plate lost its seed region";
    std::vector<bool> seen(sphere.region_count(), false);
    std::deque<std::int32_t> queue{seeds[plate]};
    seen[seeds[plate]] = true;
    while (!queue.empty()) {
      const std::int32_t region = queue.front();
      queue.pop_front();
      ++reached[plate];
      for (const std::int32_t neighbour : sphere.neighbours(region)) {
        if (neighbour != invalid_region && !seen[neighbour] && partition.plate[neighbour] == plate) {
          seen[neighbour] = true;
          queue.push_back(neighbour);
        }
      }
    }
    EXPECT_EQ(reached[plate], members[plate]) << "plate " << plate << " is not 8-connected";
  }
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    bool bordered = false;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      bordered = bordered || (neighbour != invalid_region && partition.plate[neighbour] != partition.plate[region]);
    }
    EXPECT_EQ(partition.is_edge[region] != 0, bordered) << region;
  }
}

TEST(PlanetJitter, ZeroJitterPutsEveryCentroidAtItsCellCentre) {
  const CubeSphere sphere(7);
  PlanetParams params = params_of(7, 5);
  params.jitter = 0.0;
  const auto regions = reference::jitter_regions<double>(sphere, params);
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    EXPECT_EQ(regions.offsets[2 * region], 0.5);
    EXPECT_EQ(regions.offsets[2 * region + 1], 0.5);
    // core's sphere_position is computed independently (Vec3, its own matrix product): a few ulp.
    const Vec3 expected = sphere_position(sphere.local_position(region));
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(regions.positions[3 * region + axis], expected[axis], 1e-15);
  }
}

TEST(PlanetJitter, FullJitterKeepsEachCentroidInsideItsOwnCell) {
  const CubeSphere sphere(12);
  const PlanetParams params = params_of(12, 5);
  const auto regions = reference::jitter_regions<double>(sphere, params);
  double spread = 0.0;
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    const double a = regions.offsets[2 * region], b = regions.offsets[2 * region + 1];
    ASSERT_GE(a, 0.0);
    ASSERT_LT(a, 1.0);
    ASSERT_GE(b, 0.0);
    ASSERT_LT(b, 1.0);
    spread = std::max(spread, std::abs(a - 0.5));
    const Vec3 position{regions.positions[3 * region], regions.positions[3 * region + 1], regions.positions[3 * region + 2]};
    EXPECT_NEAR(length(position), 1.0, 1e-15);
    EXPECT_EQ(sphere.region_at(local_position_of(position)), region);
  }
  // 864 uniform draws: the largest |a − 0.5| is below 0.45 with probability 0.1^864.
  EXPECT_GT(spread, 0.45);
}

TEST(PlanetPlates, SeedsAreDistinctEvenWhenEveryRegionIsASeed) {
  const PlanetParams params = params_of(1, 6);
  auto seeds = reference::plate_seeds(params);
  std::sort(seeds.begin(), seeds.end());
  EXPECT_EQ(seeds, (std::vector<std::int32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(PlanetPlates, RatesLieInTheCodesRangeAndExpansionsAverageToThem) {
  const PlanetParams params = params_of(10, 40, 0.75);
  const auto rates = reference::plate_rates(params);
  for (int plate = 0; plate < params.plates; ++plate) {
    EXPECT_GE(rates[plate], 0.25f);
    EXPECT_LE(rates[plate], 1.75f);
    constexpr int cycles = 4000;
    double total = 0.0;
    for (int cycle = 0; cycle < cycles; ++cycle) total += reference::plate_expansions(params, rates, plate, cycle);
    // Bernoulli extra expansion: standard deviation of the mean <= 0.5/sqrt(4000) = 0.0079; 6σ.
    EXPECT_NEAR(total / cycles, rates[plate], 0.048) << plate;
  }
}

TEST(PlanetPlates, SynchronousFillIsAValidPartition) {
  for (const auto& [resolution, plates, range] : {std::tuple{1, 6, 0.5}, {10, 10, 0.5}, {25, 50, 2.5}, {20, 250, 0.5}}) {
    const CubeSphere sphere(resolution);
    const PlanetParams params = params_of(resolution, plates, range);
    expect_valid_partition(sphere, params, reference::grow_plates(sphere, params));
  }
}

// With e = 0 every plate grows one ring per cycle, so the synchronous rule is a multi-source BFS:
// each region belongs to a plate whose seed is fewest hops away, the lowest such plate on ties,
// and the fill takes as many cycles as the farthest region is from its seed.
TEST(PlanetPlates, EqualRatesGiveTheNearestSeedWithTheLowestIndexOnTies) {
  const CubeSphere sphere(15);
  const PlanetParams params = params_of(15, 30, 0.0);
  const auto partition = reference::grow_plates(sphere, params);
  const auto seeds = reference::plate_seeds(params);
  std::vector<std::vector<int>> distance;
  for (const std::int32_t seed : seeds) distance.push_back(hop_distances(sphere, seed));
  int farthest = 0;
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    int nearest = std::numeric_limits<int>::max(), owner = -1;
    for (int plate = 0; plate < params.plates; ++plate) {
      if (distance[plate][region] < nearest) {
        nearest = distance[plate][region];
        owner = plate;
      }
    }
    EXPECT_EQ(partition.plate[region], owner) << region;
    farthest = std::max(farthest, nearest);
  }
  EXPECT_EQ(partition.cycles, farthest);
}

TEST(PlanetPlates, LegacyFillIsAValidPartitionThatDiffersFromTheSynchronousOne) {
  const CubeSphere sphere(20);
  PlanetParams params = params_of(20, 50);
  params.plate_rule = PlateRule::legacy;
  const auto legacy = reference::grow_plates(sphere, params);
  expect_valid_partition(sphere, params, legacy);
  params.plate_rule = PlateRule::synchronous;
  const auto synchronous = reference::grow_plates(sphere, params);
  std::size_t differing = 0;
  for (std::size_t region = 0; region < sphere.region_count(); ++region) differing += legacy.plate[region] != synchronous.plate[region];
  // The legacy rule grows ceil(rate) + 1 rings a cycle where the synchronous one grows rate on
  // average, and serves plates in index order: the two must not coincide.
  EXPECT_GT(differing, 0u);
}

TEST(PlanetPlates, TheSameSeedGivesTheSamePlatesAndAnotherSeedOthers) {
  const CubeSphere sphere(12);
  const auto first = reference::grow_plates(sphere, params_of(12, 20, 0.5, 3));
  EXPECT_EQ(first.plate, reference::grow_plates(sphere, params_of(12, 20, 0.5, 3)).plate);
  EXPECT_NE(first.plate, reference::grow_plates(sphere, params_of(12, 20, 0.5, 4)).plate);
}

TEST(PlanetElevation, PressureIsSymmetricAndRaisesConvergingPlates) {
  const Vector3<double> west{std::cos(0.01), -std::sin(0.01), 0.0}, east{std::cos(0.01), std::sin(0.01), 0.0};
  const Vector3<double> eastward{0.0, 0.8, 0.0}, westward{0.0, -0.6, 0.0};
  for (const auto formula : {PressureFormula::code, PressureFormula::thesis}) {
    const double converging = reference::pressure(formula, west, eastward, east, westward);
    EXPECT_EQ(converging, reference::pressure(formula, east, westward, west, eastward));
    EXPECT_GT(converging, 0.0);
    EXPECT_LT(reference::pressure(formula, west, westward, east, eastward), 0.0);
  }
}

TEST(PlanetElevation, ShiftsAreTangentWithTheirMagnitudeAndBasesWithinTheirRange) {
  const CubeSphere sphere(16);
  const PlanetParams params = params_of(16, 40);
  const auto regions = reference::jitter_regions<double>(sphere, params);
  const auto motion = reference::plate_motion(params, regions.positions, reference::grow_plates(sphere, params));
  for (int plate = 0; plate < params.plates; ++plate) {
    const auto& centre = motion.centre[plate];
    const auto& shift = motion.shift[plate];
    EXPECT_NEAR(std::hypot(centre[0], centre[1], centre[2]), 1.0, 1e-14);
    EXPECT_NEAR(shift[0] * centre[0] + shift[1] * centre[1] + shift[2] * centre[2], 0.0, 1e-14);
    const double magnitude = std::hypot(shift[0], shift[1], shift[2]);
    EXPECT_GE(magnitude, 0.5 - 1e-15);
    EXPECT_LE(magnitude, 1.0 + 1e-15);
    EXPECT_LE(std::abs(motion.base[plate]), params.elevation_range);
  }
}

// Bimodal bases: oceanic plates in [−e_r, −e_r/2], continental ones in [0, e_r/4], and the oceanic
// share near ocean_share: 500 plates, binomial σ = sqrt(0.7·0.3/500) = 0.0205; bound 5σ.
TEST(PlanetElevation, BimodalBasesLieInTheirTwoRangesInTheirShares) {
  const CubeSphere sphere(20);
  PlanetParams params = params_of(20, 500);
  params.plate_bases = PlateBases::bimodal;
  const auto regions = reference::jitter_regions<double>(sphere, params);
  const auto motion = reference::plate_motion(params, regions.positions, reference::grow_plates(sphere, params));
  int oceanic = 0;
  for (const double base : motion.base) {
    if (base < 0.0) {
      ++oceanic;
      EXPECT_GE(base, -0.8);
      EXPECT_LE(base, -0.4);
    } else {
      EXPECT_LE(base, 0.2);
    }
  }
  EXPECT_NEAR(oceanic / 500.0, 0.7, 0.1025);
}

TEST(PlanetElevation, WithoutNoiseAndCollisionsEveryRegionHasItsPlatesBaseAndJacobiKeepsIt) {
  const CubeSphere sphere(10);
  PlanetParams params = params_of(10, 1);
  params.noise = false;
  params.collisions = false;
  const auto regions = reference::jitter_regions<double>(sphere, params);
  const auto elevation = reference::planet_elevation(sphere, params, regions.positions, reference::grow_plates(sphere, params));
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    EXPECT_EQ(elevation.noisy[region], elevation.motion.base[0]);
    // The mean of nine (or eight) equal numbers: within an ulp of each.
    EXPECT_NEAR(elevation.smoothed[region], elevation.motion.base[0], 1e-15);
  }
}

// A partition with a region left without a plate (or naming a plate that does not exist) is refused
// with the region named: the elevation indexes the plates by it.
TEST(PlanetElevation, APartitionThatIsNotWholeIsRefused) {
  const CubeSphere sphere(6);
  const PlanetParams params = params_of(6, 4);
  const auto regions = reference::jitter_regions<double>(sphere, params);
  for (const std::int32_t wrong : {std::int32_t{-1}, std::int32_t{4}}) {
    auto partition = reference::grow_plates(sphere, params);
    partition.plate[17] = wrong;
    try {
      reference::planet_elevation(sphere, params, regions.positions, partition);
      ADD_FAILURE() << "plate " << wrong << " was accepted";
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find("region 17 has plate " + std::to_string(wrong)), std::string::npos)
          << error.what();
    }
  }
}

// The code's blend (§4.4.3): in index order, e = E(i), then e = (e + E(n))/2 for up, upLeft, left,
// downLeft, down, downRight, right, upRight, so with 8 neighbours the weights are up 1/256, upLeft
// 1/128, left 1/64, downLeft 1/32, down 1/16, downRight 1/8, right 1/4, upRight 1/2 (self 1/256),
// and a neighbour of smaller index counts with its value already blended. Raise region 28 (front
// face, x 4, y 3) by 1 and follow it to region 27 (x 3, y 3) on an 8×8 face:
//   19 (3, 2) sees 28 as its downRight: 1/8;
//   20 (4, 2) sees 19 as its left and 28 as its down: 1/8·1/64 + 1/16 = 1/16 + 1/512;
//   26 (2, 3) sees 19 as its upRight: 1/8·1/2 = 1/16;
//   27 takes 19 as up (1/256), 26 as left (1/64), 28 as right (1/4), 20 as upRight (1/2):
//   1/2048 + 1/1024 + 1/4 + 1/32 + 1/1024, exactly. The thesis's mean gives 1/9.
TEST(PlanetElevation, LegacySmoothingIsTheCodesSequentialHalvingBlend) {
  const CubeSphere sphere(8);
  std::vector<double> field(sphere.region_count(), 0.0);
  field[28] = 1.0;
  ASSERT_EQ(sphere.neighbours(27)[6], 28);
  ASSERT_EQ(sphere.neighbours(27)[7], 20);
  ASSERT_EQ(sphere.neighbours(27)[0], 19);
  ASSERT_EQ(sphere.neighbours(27)[2], 26);
  EXPECT_EQ(reference::smoothed_elevation(sphere, Smoothing::legacy, field)[27], 1.0 / 2048 + 1.0 / 1024 + 0.25 + 1.0 / 32 + 1.0 / 1024);
  EXPECT_NEAR(reference::smoothed_elevation(sphere, Smoothing::jacobi, field)[27], 1.0 / 9.0, 1e-16);
  EXPECT_EQ(reference::smoothed_elevation(sphere, Smoothing::off, field), field);
}

// The k-d tree's nearest centroid against a brute-force scan of every centroid (the same double
// distances, so equal up to exact ties, which random directions do not meet).
TEST(PlanetVoronoi, NearestSiteIsTheBruteForceNearestCentroid) {
  const CubeSphere sphere(6);
  const auto regions = reference::jitter_regions<double>(sphere, params_of(6, 5));
  std::vector<Vector3<double>> directions;
  for (std::uint32_t index = 0; index < 2000; ++index) {
    Vec3 direction{};
    for (std::uint32_t axis = 0; axis < 3; ++axis) direction[axis] = 2.0 * uniform01(random_u32(9, index, axis, 0)) - 1.0;
    if (length(direction) < 1e-3) continue;
    direction = normalised(direction);
    directions.push_back({direction[0], direction[1], direction[2]});
  }
  const auto nearest = reference::nearest_sites(regions.positions, directions);
  for (std::size_t index = 0; index < directions.size(); ++index) {
    double best = std::numeric_limits<double>::infinity(), second = best;
    std::int32_t best_region = -1;
    for (std::size_t region = 0; region < sphere.region_count(); ++region) {
      const double distance = std::hypot(regions.positions[3 * region] - directions[index][0],
                                         regions.positions[3 * region + 1] - directions[index][1],
                                         regions.positions[3 * region + 2] - directions[index][2]);
      if (distance < best) {
        second = best;
        best = distance;
        best_region = static_cast<std::int32_t>(region);
      } else if (distance < second) {
        second = distance;
      }
    }
    EXPECT_EQ(nearest[index].region, best_region) << index;
    EXPECT_NEAR(nearest[index].distance, best, 1e-15);
    EXPECT_NEAR(nearest[index].second_distance, second, 1e-15);
  }
}

// A closed genus-0 surface: V − E + F = 2 with V = 6R² + 2 and F = 12R², every undirected edge used
// by exactly two triangles in opposite directions, and every vertex on the unit sphere.
TEST(PlanetMesh, TheCubeSphereMeshIsAClosedOrientedSphere) {
  for (const int resolution : {1, 2, 7}) {
    const Mesh mesh = sphere_mesh(CubeSphere(resolution));
    EXPECT_EQ(mesh.positions.size(), std::size_t(6 * resolution * resolution + 2));
    EXPECT_EQ(mesh.triangles.size(), std::size_t(12 * resolution * resolution));
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
    for (const auto& triangle : mesh.triangles) {
      for (int corner = 0; corner < 3; ++corner) ++directed[{triangle[corner], triangle[(corner + 1) % 3]}];
    }
    for (const auto& [edge, uses] : directed) {
      EXPECT_EQ(uses, 1) << "a directed edge used twice: misoriented";
      EXPECT_EQ(directed.count({edge.second, edge.first}), 1u) << "a border edge";
    }
    EXPECT_EQ(long(mesh.positions.size()) - long(directed.size() / 2) + long(mesh.triangles.size()), 2);
    for (const auto& position : mesh.positions) EXPECT_NEAR(length(position), 1.0, 1e-15);
    // Outward: the first triangle's normal points away from the centre.
    const auto& first = mesh.triangles.front();
    const Vec3 normal = cross(mesh.positions[first[1]] - mesh.positions[first[0]], mesh.positions[first[2]] - mesh.positions[first[0]]);
    EXPECT_GT(dot(normal, mesh.positions[first[0]]), 0.0);
  }
}

// §4.3's palette: the seed's two base colours at sea level, darkened linearly to black at |e| = 4.
TEST(PlanetRender, ThePaletteIsTheSeedsColoursDarkenedWithDepthAndHeight) {
  const Vec3 land = reference::elevation_colour(0.0), deep = reference::elevation_colour(-2.0);
  EXPECT_EQ(land, (Vec3{255.0 / 255.0, 189.0 / 255.0, 97.0 / 255.0}));
  EXPECT_EQ(deep, (Vec3{0.5 * 107.0 / 255.0, 0.5 * 193.0 / 255.0, 0.5 * 255.0 / 255.0}));
  const Vec3 shallow = reference::elevation_colour(-1e-12);
  EXPECT_GT(shallow[2], shallow[0]) << "just below sea level is ocean (blue over red)";
  for (const double beyond : {-4.0, 4.0, 7.5, -30.0}) EXPECT_EQ(reference::elevation_colour(beyond), (Vec3{0.0, 0.0, 0.0}));
}

// The planet seen from 2.8 radii: the mesh's silhouette lies between the sphere's and that of the
// sphere through the nearest face plane (the mesh is inscribed, its vertices on the unit sphere), so
// the covered pixel centres (GL's rule) lie between the two discs' pixel counts, each disc of
// radius r px holding between π(r − √2/2)² and π(r + √2/2)² centres. Every covered pixel shows its
// region's colour; the rest stay black.
TEST(PlanetRender, TheSphereCoversItsProjectedDiscAndEachPixelShowsItsRegionsColour) {
  const CubeSphere sphere(8);
  const auto positions = reference::jitter_regions<double>(sphere, params_of(8, 5)).positions;
  std::vector<double> elevation(sphere.region_count());
  for (std::size_t region = 0; region < elevation.size(); ++region) {
    elevation[region] = 6.0 * uniform01(random_u32(3, std::uint32_t(region), 0, 0)) - 3.0;
  }
  const Mesh mesh = sphere_mesh(sphere);
  reference::Camera camera;
  camera.eye = {0.0, 0.0, 2.8};
  camera.near = 1.0;
  camera.far = 5.0;
  camera.width = camera.height = 96;
  const auto drawn = reference::render_planet(mesh, camera, positions, elevation);
  double nearest_plane = 1.0;
  for (const auto& triangle : mesh.triangles) {
    const Vec3 normal = normalised(cross(mesh.positions[triangle[1]] - mesh.positions[triangle[0]],
                                         mesh.positions[triangle[2]] - mesh.positions[triangle[0]]));
    nearest_plane = std::min(nearest_plane, dot(normal, mesh.positions[triangle[0]]));
  }
  const double pixels_per_tangent = 0.5 * camera.height / std::tan(0.5 * camera.fov_y_deg * std::numbers::pi / 180.0);
  const auto disc_radius = [&](double radius) { return pixels_per_tangent * std::tan(std::asin(radius / 2.8)); };
  const double inner = disc_radius(nearest_plane) - std::sqrt(0.5), outer = disc_radius(1.0) + std::sqrt(0.5);
  EXPECT_GE(double(drawn.image.covered_pixels), std::numbers::pi * inner * inner);
  EXPECT_LE(double(drawn.image.covered_pixels), std::numbers::pi * outer * outer);
  for (std::size_t pixel = 0; pixel < drawn.regions.size(); ++pixel) {
    const std::int32_t region = drawn.regions[pixel];
    ASSERT_LT(region, std::int32_t(sphere.region_count()));
    const Vec3 colour = region < 0 ? Vec3{0.0, 0.0, 0.0} : reference::elevation_colour(elevation[std::size_t(region)]);
    for (std::size_t channel = 0; channel < 3; ++channel) {
      EXPECT_EQ(drawn.image.rgb[3 * pixel + channel], std::uint8_t(std::lround(255.0 * colour[channel]))) << pixel;
    }
  }
}

TEST(PlanetParams, PlatesBeyondTheRegionsAreRefused) {
  nlohmann::json given = {{"resolution", 2}, {"plates", 25}};
  EXPECT_THROW(planet_params_from_json(resolve_params("planet.earth_like", planet_param_specs(), given)), InputError);
  given["plates"] = 24;
  EXPECT_EQ(planet_params_from_json(resolve_params("planet.earth_like", planet_param_specs(), given)).plates, 24);
}


// ---- the fault-line planet (seed 002 §2.5) -------------------------------------------------------

// One plane by hand: n = +z raises the north pole, lowers the south pole, and lowers a point on the
// plane itself (dot 0: the loop's `else`).
TEST(FaultLines, OnePlaneRaisesItsSideAndLowersTheOther) {
  const std::vector<double> positions = {0, 0, 1, 0, 0, -1, 1, 0, 0};
  const std::vector<double> normal = {0, 0, 1};
  EXPECT_EQ(reference::fault_votes(positions, normal), (std::vector<std::int32_t>{1, -1, -1}));
}

// The spec's normals are unit vectors spread over the sphere: their mean within 6σ of 0 (each
// component's variance 1/3, σ = sqrt(1/(3N))); and on the cube sphere every region's votes cancel
// its antipode's (no region centre lies on one of 37 random planes).
TEST(FaultLines, NormalsAreUnitAndVotesCancelAtAntipodes) {
  const FaultPlanetParams params{.resolution = 6, .faults = 37, .seed = 9};
  const auto normals = fault_normals(params);
  ASSERT_EQ(normals.size(), 37u);
  std::array<double, 3> mean{};
  for (const auto& n : normals) {
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-15);
    for (int c = 0; c < 3; ++c) mean[c] += n[c] / 37.0;
  }
  for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(mean[c]), 6.0 * std::sqrt(1.0 / (3.0 * 37.0)));
  std::vector<double> flat;
  for (const auto& n : normals) flat.insert(flat.end(), n.begin(), n.end());
  const auto positions = fault_planet_positions(params.resolution);
  const auto votes = reference::fault_votes(positions, flat);
  const CubeSphere sphere(params.resolution);
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    const Vec3 opposite{-positions[3 * region], -positions[3 * region + 1], -positions[3 * region + 2]};
    const auto antipode = sphere.region_at(local_position_of(opposite));
    ASSERT_TRUE(antipode.has_value());
    EXPECT_EQ(votes[region] + votes[*antipode], 0) << region;
  }
}

TEST(FaultLines, ParametersRefuseMoreDotProductsThanACaseMayTake) {
  const auto resolved = resolve_params("planet.fault_lines", fault_planet_param_specs(),
                                       {{"resolution", 300}, {"faults", 10000}});
  EXPECT_THROW(fault_planet_params_from_json(resolved), InputError);
  EXPECT_THROW(resolve_params("planet.fault_lines", fault_planet_param_specs(), {{"step", 0.0}}), InputError);
}

}  // namespace
}  // namespace gt
