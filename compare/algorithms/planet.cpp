// `planet.earth_like`: seed 002's Earth-like generator (digest 002 §4.4, §9): jitter, tectonic
// plates, elevation, on the CPU (ref<double>, ref<float>) and the GPU, beside the real Earth.
// Spec of every step: core/params/planet.hpp; error model: compare/checks/planet_error_model.hpp.
//
// The twins: the GPU runs the synchronous plate rule and Jacobi (or no) smoothing. A case that asks
// for the seed code's legacy rules gets them on the CPU (its pictures, its relief, its fidelity),
// and its twins are compared in the parallel configuration: the same parameters with the
// synchronous rule and Jacobi smoothing in place of the legacy ones (said in the case's notes).
//
// Checks (backend cpu = ref<double>, float = ref<float>, gpu = the GPU twin):
//   topology.*                the cube sphere's neighbour table: asymmetric pairs, regions whose
//                             neighbour count is not 7 (corner cells) or 8, the largest round-trip
//                             error (face, a, b) -> direction -> (face, a, b) (§9.5)
//   mesh.*.planet, topology.mesh_genus, topology.mesh_vertices   the planet as a closed mesh
//                             (core/planet/sphere_mesh.hpp) through the mesh checks: closed,
//                             manifold, oriented, free of self-intersections, genus 0, 6R² + 2 vertices
//   parity.voronoi.gpu_vs_cpu map directions whose GPU label (Algorithm 1's 5×5 cell-grid search) is
//                             farther than the exact nearest centroid (CGAL k-d tree) beyond the
//                             positions' error (must be 0); voronoi.misses_3x3.gpu, informative: the
//                             seed shader's 3×3 search
//   partition.*.{cpu,gpu}     regions without a plate, empty plates, plates not 8-connected,
//                             regions whose is_edge is not the definition (all must be 0)
//   spec.expansion_rate.cpu   Algorithm 3 as intended: rings per cycle average to the rate (6σ)
//   spec.rate_bounds.cpu      every plate's rate within the asked formula's interval (the code's
//                             or the thesis's, rate_formula), written here from the parameters
//   spec.smoothing_constant.cpu   the Jacobi mean keeps a constant field
//   spec.pressure_symmetry.cpu    pressure(i, n) = pressure(n, i) bit for bit (§9.5)
//   legacy.*                  informative: the share of regions whose plate the seed code's
//                             sequential fill gives differently, and the largest change of the
//                             elevation that its sequential smoothing makes, against the parallel
//                             rules on the same seeds
//   parity.positions.*        largest position difference (float vs double; GPU vs float, strict
//                             4 ulp per operation, warn up to the Vulkan environment's 2^-11 tan)
//   parity.offsets.gpu_vs_float     offsets that differ in any bit (must be 0: the same draws and
//                             operations, every intermediate `precise`)
//   parity.plates.gpu_vs_cpu, parity.plate_cycles.gpu_vs_cpu, parity.edges.gpu_vs_cpu   regions
//                             whose plate or is_edge differ, and the difference in cycles (all 0)
//   parity.{noise,collision,elevation}.{float_vs_double,gpu_vs_float}   the largest ratio of a
//                             region's difference to its bound (strict 1): the GPU fed ref<float>'s
//                             positions and partition (shadow parity), ref<float> on its own
//                             positions; `inconclusive` when the largest bound exceeds a tenth of
//                             the elevation's range
//   determinism.gpu           regions whose plate or elevation differ in any bit between the first
//                             and the last of the GPU's timed runs
//   image.*.gpu_vs_cpu        the planet drawn by both twins (reference rasterizer and GL, mesh,
//                             per-pixel Voronoi, palette): PSNR >= 40 dB and at most 0.5 % of pixels
//                             beyond 4/255 after the 3×3 edge tolerance (compare/render_case.hpp);
//                             image.region_agreement informative
//   fidelity.land_fraction, fidelity.bimodality   for cases whose expect says earth_like: the
//                             land share within 0.1 of the Earth's 0.290 (ETOPO 1°, data-sources.md),
//                             Sarle's bimodality coefficient above 5/9; `warn` when not met
//   fidelity.spectral_exponent  |β − the Earth's β| of the spherical power spectrum C_l ∝ l^-β over
//                             l = 2..R, within 0.5 for earth_like cases (`warn` when not)
//   fidelity.*                informative otherwise, with the mean and range
// Pictures (equirectangular, 512 x 256, each pixel the region of the exact nearest centroid): the
// elevation palette (§4.3), the plates (edges in the plate's colour, interiors mixed with white), the
// Voronoi cells with their borders; the elevation as a cube map; the hypsometric curves and
// histograms of the planet and the Earth; their spherical power spectra; both elevation maps as
// EXR/NPY fields; the planet drawn by both twins (cpu.png, gpu.png, their difference).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <deque>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/checks/mesh.hpp"
#include "compare/checks/planet_error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/planet_relief.hpp"
#include "compare/report/images.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/planet.hpp"
#include "core/planet/sphere_mesh.hpp"
#include "core/rng.hpp"
#include "compare/render_case.hpp"
#include "gpu/planet/generator.hpp"
#include "gpu/planet/render.hpp"
#include "gpu/planet/voronoi.hpp"
#include "reference/planet/elevation.hpp"
#include "reference/planet/jitter.hpp"
#include "reference/planet/plates.hpp"
#include "reference/planet/render.hpp"
#include "reference/planet/voronoi.hpp"

namespace gt {
namespace {

constexpr double tellable_share = 0.1;           // a parity bound wider than this share of the range tells nothing
constexpr int map_width = planet_map_width;
constexpr int map_height = planet_map_height;

template <class Real>
struct Planet {
  JitteredRegions<Real> regions;
  PlatePartition partition;
  PlanetElevation<Real> elevation;
};

template <class Real>
Planet<Real> generate(const CubeSphere& sphere, const PlanetParams& params) {
  Planet<Real> planet;
  planet.regions = reference::jitter_regions<Real>(sphere, params);
  planet.partition = reference::grow_plates(sphere, params);
  planet.elevation = reference::planet_elevation<Real>(sphere, params, planet.regions.positions, planet.partition);
  return planet;
}

// The configuration both twins run: legacy rules replaced by the parallel ones.
PlanetParams twin_params(PlanetParams params) {
  params.plate_rule = PlateRule::synchronous;
  if (params.smoothing == Smoothing::legacy) params.smoothing = Smoothing::jacobi;
  return params;
}

bool uses_legacy(const PlanetParams& params) {
  return params.plate_rule != PlateRule::synchronous || params.smoothing == Smoothing::legacy;
}

// ---- topology and partition invariants -----------------------------------------------------

void add_topology_checks(const CubeSphere& sphere, CubeWarp cube_warp, CaseResult& result) {
  std::size_t asymmetric = 0, wrong_count = 0;
  double round_trip = 0.0;
  const int resolution = sphere.resolution();
  for (std::size_t region = 0; region < sphere.region_count(); ++region) {
    int valid = 0;
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region) continue;
      ++valid;
      const auto& back = sphere.neighbours(static_cast<std::size_t>(neighbour));
      asymmetric += std::count(back.begin(), back.end(), static_cast<std::int32_t>(region)) == 1 ? 0 : 1;
    }
    const int x = static_cast<int>(region % resolution), y = static_cast<int>(region / resolution % resolution);
    const bool corner = (x == 0 || x == resolution - 1) && (y == 0 || y == resolution - 1);
    wrong_count += valid == (corner ? 7 : 8) ? 0 : 1;
    const LocalPosition local = sphere.local_position(region, 0.3, 0.8);
    const LocalPosition back = local_position_of(sphere_position(local, cube_warp), cube_warp);
    round_trip = std::max({round_trip, back.face == local.face ? 0.0 : 1.0, std::abs(back.a - local.a), std::abs(back.b - local.b)});
  }
  result.checks.push_back(bounded_check("topology.asymmetric_neighbours", double(asymmetric), 0.0, std::nullopt,
                                        "directed neighbour pairs whose reverse is missing or repeated"));
  result.checks.push_back(bounded_check("topology.neighbour_count", double(wrong_count), 0.0, std::nullopt,
                                        "regions with other than 7 valid neighbours (the 24 corner cells) or 8"));
  // tan, atan, the normalisation and the division by the largest component, each within an ulp or
  // two of double, amplified at most by the inverse warp's slope tan θ/θ (1.36 for the optimised
  // warp, 4/π for eq. 3.4's, 1 for none): 1e-13, some 450 ulp (tests/cube_sphere_test.cpp).
  result.checks.push_back(bounded_check("topology.round_trip", round_trip, 1e-13, std::nullopt,
                                        "largest |Δa|, |Δb| of (face, a, b) -> direction -> (face, a, b) at offset "
                                        "(0.3, 0.8) in every cell; a changed face counts 1"));
}

// The largest over the smallest value of the warp's area element on a face, f'(u)·f'(v)/(1 + f(u)² +
// f(v)²)^(3/2) (the solid angle of d(face space) through f, normalised), on a 2001² grid of
// [-1, 1]², written from the seed's formulas here (θ transcribed from eq. 3.4 and 3.5, not taken
// from the cube sphere the cells come from): the limit of the cells' area ratio as R grows. f(t) =
// tan(θt)/tan θ, f'(t) = θ/(tan θ·cos²(θt)); f(t) = t for none.
double area_element_ratio(PlanetWarp warp) {
  const double angle = warp == PlanetWarp::none      ? 0.0
                       : warp == PlanetWarp::tangent ? std::numbers::pi / 4.0  // eq. 3.4
                                                     : 0.868734829276;         // eq. 3.5, Zucker and Higashi's θ
  // f and f' at the grid's coordinates, once per axis value.
  constexpr int steps = 2000;
  std::array<double, steps + 1> value{}, slope{};
  for (int i = 0; i <= steps; ++i) {
    const double t = -1.0 + 2.0 * i / steps;
    value[i] = angle == 0.0 ? t : std::tan(angle * t) / std::tan(angle);
    slope[i] = angle == 0.0 ? 1.0 : angle / (std::tan(angle) * std::cos(angle * t) * std::cos(angle * t));
  }
  double largest = 0.0, smallest = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= steps; ++i) {
    for (int j = 0; j <= steps; ++j) {
      const double density = slope[i] * slope[j] / std::pow(1.0 + value[i] * value[i] + value[j] * value[j], 1.5);
      largest = std::max(largest, density);
      smallest = std::min(smallest, density);
    }
  }
  return largest / smallest;
}

// spec.cell_area_ratio.cpu: the largest cell's solid angle over the smallest's (the seed's reason for
// the optimised warp, §2.7: more equal cells) against the warp's own limit. A cell is an equal
// square of face space, so its solid angle is that square times the mean of the area element over
// it, and the ratio of two such means lies below the element's largest over its smallest value,
// whatever R. The grid's extremes miss the element's by at most an eighth of its second derivative
// times the squared spacing (10⁻⁶; the element's second derivatives stay below 10 and its values
// above 0.19 on a face): 10⁻⁴ relative covers it.
void add_cell_area_check(const CubeSphere& sphere, PlanetWarp warp, CaseResult& result) {
  const auto areas = cell_solid_angles(sphere, cube_warp(warp));
  const auto [smallest, largest] = std::minmax_element(areas.begin(), areas.end());
  double total = 0.0, squares = 0.0;
  for (double area : areas) {
    total += area;
    squares += area * area;
  }
  const double mean = total / double(areas.size());
  const double variation = std::sqrt(std::max(0.0, squares / double(areas.size()) - mean * mean)) / mean;
  const double limit = area_element_ratio(warp);
  result.checks.push_back(bounded_check(
      "spec.cell_area_ratio.cpu", *largest / *smallest, limit * (1.0 + 1e-4), std::nullopt,
      fmt::format("largest over smallest cell solid angle through the {} warp (their coefficient of variation {:.3f}); "
                  "bound: the warp's area element, largest over smallest value, {:.4f} (none 3^1.5, eq. 3.4's √2, eq. "
                  "3.5's about 1.305)",
                  planet_warp_name(warp), variation, limit)));
}

// The planet as a closed mesh (core/planet/sphere_mesh.hpp) through the mesh checks of
// compare/checks/mesh.hpp, with its genus (0) and its vertex count (6R² + 2: the cube's corners
// and edges welded) held to what a sphere must have.
void add_mesh_checks(const CubeSphere& sphere, CubeWarp cube_warp, CaseResult& result) {
  const Mesh mesh = sphere_mesh(sphere, cube_warp);
  const MeshReport report = check_mesh(mesh);
  for (auto& check : mesh_checks(report, "planet", true)) result.checks.push_back(std::move(check));
  result.checks.push_back(bounded_check("topology.mesh_genus", std::abs(report.openmesh.genus), 0.0, std::nullopt,
                                        "genus of the planet mesh (OpenMesh: (2C − χ − b)/2); a sphere has 0"));
  const double expected_vertices = 6.0 * sphere.resolution() * sphere.resolution() + 2.0;
  result.checks.push_back(bounded_check("topology.mesh_vertices", std::abs(double(mesh.positions.size()) - expected_vertices),
                                        0.0, std::nullopt,
                                        fmt::format("|vertices − (6R² + 2)|: {} vertices, {} triangles",
                                                    mesh.positions.size(), mesh.triangles.size())));
}

// Members of each plate reachable from its first member over its own 8-neighbours.
std::size_t disconnected_plates(const CubeSphere& sphere, const PlanetParams& params, const PlatePartition& partition) {
  std::vector<std::size_t> members(static_cast<std::size_t>(params.plates), 0), reached(members.size(), 0);
  std::vector<std::int32_t> first(members.size(), invalid_region);
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    const std::int32_t plate = partition.plate[region];
    if (plate < 0 || plate >= params.plates) continue;
    ++members[plate];
    if (first[plate] == invalid_region) first[plate] = static_cast<std::int32_t>(region);
  }
  std::vector<bool> seen(partition.plate.size(), false);
  std::size_t disconnected = 0;
  for (int plate = 0; plate < params.plates; ++plate) {
    if (first[plate] == invalid_region) continue;
    std::deque<std::int32_t> queue{first[plate]};
    seen[first[plate]] = true;
    while (!queue.empty()) {
      const std::int32_t region = queue.front();
      queue.pop_front();
      ++reached[plate];
      for (const std::int32_t neighbour : sphere.neighbours(region)) {
        if (neighbour == invalid_region || seen[neighbour] || partition.plate[neighbour] != plate) continue;
        seen[neighbour] = true;
        queue.push_back(neighbour);
      }
    }
    disconnected += reached[plate] == members[plate] ? 0 : 1;
  }
  return disconnected;
}

void add_partition_checks(const CubeSphere& sphere, const PlanetParams& params, const PlatePartition& partition,
                          const std::string& backend, CaseResult& result) {
  std::size_t unassigned = 0;
  std::vector<std::size_t> members(static_cast<std::size_t>(params.plates), 0);
  for (const std::int32_t plate : partition.plate) {
    if (plate < 0 || plate >= params.plates) {
      ++unassigned;
    } else {
      ++members[plate];
    }
  }
  // The definition written out here, apart from reference::edge_regions, so that the CPU's flags are
  // checked too.
  std::size_t wrong_edges = 0;
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    const auto& around = sphere.neighbours(region);
    const bool bordered = std::any_of(around.begin(), around.end(), [&](std::int32_t neighbour) {
      return neighbour != invalid_region && partition.plate[neighbour] != partition.plate[region];
    });
    wrong_edges += bordered == (partition.is_edge[region] != 0) ? 0 : 1;
  }
  const auto empty = static_cast<std::size_t>(std::count(members.begin(), members.end(), std::size_t{0}));
  result.checks.push_back(bounded_check("partition.unassigned." + backend, double(unassigned), 0.0, std::nullopt,
                                        fmt::format("regions without a plate in 0..{} (of {})", params.plates - 1,
                                                    partition.plate.size())));
  result.checks.push_back(bounded_check("partition.empty_plates." + backend, double(empty), 0.0, std::nullopt,
                                        "plates without a region (seeds are distinct, §9.2)"));
  result.checks.push_back(bounded_check("partition.disconnected_plates." + backend,
                                        double(disconnected_plates(sphere, params, partition)), 0.0, std::nullopt,
                                        "plates not 8-connected"));
  result.checks.push_back(bounded_check("partition.edge_definition." + backend, double(wrong_edges), 0.0, std::nullopt,
                                        "regions whose is_edge is not 'a valid neighbour has another plate'"));
}

// ---- spec checks of the parallel rules, against what was asked -----------------------------

// Algorithm 3 as intended (erratum 10): a plate grows `rate` rings a cycle on average. Over 4000
// cycles the mean of floor(rate) + Bernoulli(rate − floor(rate)) has a standard deviation of at
// most 0.5/sqrt(4000) = 0.0079; the bound is 6 of them (the draws are fixed by the seed: no flake).
void add_expansion_rate_check(const PlanetParams& params, CaseResult& result) {
  constexpr int cycles = 4000;
  const auto rates = reference::plate_rates(params);
  double worst = 0.0;
  for (int plate = 0; plate < params.plates; ++plate) {
    double total = 0.0;
    for (int cycle = 0; cycle < cycles; ++cycle) total += reference::plate_expansions(params, rates, plate, cycle);
    worst = std::max(worst, std::abs(total / cycles - rates[plate]));
  }
  result.checks.push_back(bounded_check("spec.expansion_rate.cpu", worst, 6.0 * 0.5 / std::sqrt(double(cycles)),
                                        std::nullopt,
                                        "largest |mean rings per cycle − rate| over the plates, 4000 cycles each; "
                                        "bound 6σ of a Bernoulli mean"));
}

// Step 2's rates against the formula asked, written here from the parameters (not from the twins'
// plate_rate_bounds): every plate's rate in [lo, hi] of the code's U[max(0, 1 − e), 1 + e] or the
// thesis's (U[1 − e, 1 + e] for e < 1, U[0, e] for e > 1), up to the floor of 1/256 and the float
// rounding of lo + (hi − lo)·U (2u of hi).
void add_rate_bounds_check(const PlanetParams& params, CaseResult& result) {
  const double e = params.expansion_range;
  const bool thesis = params.rate_formula == RateFormula::thesis;
  const double low = thesis && e > 1.0 ? 0.0 : std::max(0.0, 1.0 - e);
  const double high = thesis && e > 1.0 ? e : 1.0 + e;
  const double slack = 2.0 * 0x1p-24 * high;
  double outside = 0.0;
  for (const float rate : reference::plate_rates(params)) {
    const double floor_low = std::max(low, double(minimum_plate_rate));
    outside = std::max({outside, floor_low - slack - rate, rate - (high + slack)});
  }
  result.checks.push_back(bounded_check(
      "spec.rate_bounds.cpu", std::max(outside, 0.0), 0.0, std::nullopt,
      fmt::format("largest distance of a plate's rate outside [{:.6g}, {:.6g}], the {} formula's interval for e = {:g} "
                  "(with the floor 1/256), beyond 2u of float rounding",
                  low, high, thesis ? "thesis's" : "code's", e)));
}

// The thesis' smoothing is a mean: a constant field stays that constant, up to the rounding of nine
// additions and a division in double (10·2^-53 relative).
void add_smoothing_check(const CubeSphere& sphere, CaseResult& result) {
  constexpr double level = 0.37;
  const auto smoothed = reference::smoothed_elevation(sphere, Smoothing::jacobi, std::vector<double>(sphere.region_count(), level));
  double worst = 0.0;
  for (const double value : smoothed) worst = std::max(worst, std::abs(value - level));
  result.checks.push_back(bounded_check("spec.smoothing_constant.cpu", worst, 10.0 * 0x1p-53 * level, std::nullopt,
                                        "largest |Jacobi mean of a constant 0.37 − 0.37|"));
}

// Both pressure formulas are symmetric bit for bit: normalise(−x) = −normalise(x) and the two terms
// swap places in a commutative addition (core/params/planet.hpp). Every pair of neighbouring regions
// on different plates, once, both ways.
void add_pressure_symmetry_check(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& planet,
                                 CaseResult& result) {
  const auto& positions = planet.regions.positions;
  const auto& shift = planet.elevation.motion.shift;
  const auto& plate = planet.partition.plate;
  const auto position = [&](std::size_t region) {
    return Vector3<double>{positions[3 * region], positions[3 * region + 1], positions[3 * region + 2]};
  };
  std::size_t asymmetric = 0, pairs = 0;
  for (std::size_t region = 0; region < plate.size(); ++region) {
    for (const std::int32_t neighbour : sphere.neighbours(region)) {
      if (neighbour == invalid_region || std::size_t(neighbour) < region || plate[neighbour] == plate[region]) continue;
      ++pairs;
      const double forward = reference::pressure(params.pressure, position(region), shift[plate[region]],
                                                 position(neighbour), shift[plate[neighbour]]);
      const double backward = reference::pressure(params.pressure, position(neighbour), shift[plate[neighbour]],
                                                  position(region), shift[plate[region]]);
      asymmetric += forward == backward ? 0 : 1;
    }
  }
  result.checks.push_back(bounded_check("spec.pressure_symmetry.cpu", double(asymmetric), 0.0, std::nullopt,
                                        fmt::format("pairs of neighbours on different plates (of {}) whose pressure "
                                                    "differs from the reverse pair's in any bit",
                                                    pairs)));
}

// ---- legacy modes --------------------------------------------------------------------------

void add_legacy_checks(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& parallel,
                       CaseResult& result) {
  const struct {
    PlateRule rule;
    const char* name;
    const char* what;
  } rules[] = {{PlateRule::legacy, "legacy.plate_difference",
                "the seed code's sequential fill (ceil(rate) + 1 rings a cycle, plates in index order)"},
               {PlateRule::legacy_random, "legacy.random_plate_difference",
                "the seed code's random-driven fill (one random plate per pick)"}};
  for (const auto& [rule, name, what] : rules) {
    PlanetParams legacy = params;
    legacy.plate_rule = rule;
    const auto legacy_partition = reference::grow_plates(sphere, legacy);
    std::size_t differing = 0;
    for (std::size_t region = 0; region < legacy_partition.plate.size(); ++region) {
      differing += legacy_partition.plate[region] == parallel.partition.plate[region] ? 0 : 1;
    }
    result.checks.push_back(informative_check(
        name, double(differing) / double(legacy_partition.plate.size()),
        fmt::format("share of regions {} gives another plate than the synchronous rule; {} cycles (picks) against {}",
                    what, legacy_partition.cycles, parallel.partition.cycles)));
  }
  const auto sequential = reference::smoothed_elevation(sphere, Smoothing::legacy, parallel.elevation.collided);
  const auto jacobi = reference::smoothed_elevation(sphere, Smoothing::jacobi, parallel.elevation.collided);
  double largest = 0.0;
  for (std::size_t region = 0; region < jacobi.size(); ++region) largest = std::max(largest, std::abs(sequential[region] - jacobi[region]));
  result.checks.push_back(informative_check("legacy.smoothing_difference", largest,
                                            "largest |E_sequential − E_jacobi| of the two smoothings of the same "
                                            "collided elevation (the code's halving blend against the thesis' mean)"));
}

// ---- parity ---------------------------------------------------------------------------------

template <class Real>
double largest_difference(const std::vector<Real>& values, const std::vector<double>& truth) {
  double largest = 0.0;
  for (std::size_t index = 0; index < truth.size(); ++index) {
    largest = std::max(largest, std::abs(double(values[index]) - truth[index]));
    if (std::isnan(double(values[index]))) return std::numeric_limits<double>::infinity();
  }
  return largest;
}

double elevation_range(const std::vector<double>& elevation) {
  const auto [low, high] = std::minmax_element(elevation.begin(), elevation.end());
  return *high - *low;
}

// The largest ratio of a region's |difference| to its bound: strict 1.
template <class Real>
Check ratio_check(const std::string& name, const std::vector<Real>& values, const std::vector<double>& truth,
                  const std::vector<double>& bounds, double range) {
  double worst = 0.0, widest = 0.0;
  std::size_t worst_region = 0;
  for (std::size_t region = 0; region < truth.size(); ++region) {
    widest = std::max(widest, bounds[region]);
    const double difference = std::abs(double(values[region]) - truth[region]);
    const double ratio = std::isnan(double(values[region])) ? std::numeric_limits<double>::infinity()
                         : bounds[region] > 0.0           ? difference / bounds[region]
                         : difference > 0.0               ? std::numeric_limits<double>::infinity()
                                                          : 0.0;
    if (ratio > worst || region == 0) {
      worst = std::max(worst, ratio);
      worst_region = region;
    }
  }
  const std::string detail = fmt::format(
      "largest |difference| / bound over the regions: region {} differs by {:.3g} against its bound {:.3g} "
      "(compare/checks/planet_error_model.hpp); widest bound {:.3g}",
      worst_region, std::abs(double(values[worst_region]) - truth[worst_region]), bounds[worst_region], widest);
  Check check = bounded_check(name, worst, 1.0, std::nullopt, detail);
  if ((check.status == Outcome::pass) && widest > tellable_share * range) {
    check.status = Outcome::inconclusive;
    check.detail += fmt::format(" — inconclusive: the widest bound exceeds {} of the elevation's range {:.3g}",
                                tellable_share, range);
  }
  return check;
}

void add_elevation_parity(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& truth,
                          const PlanetElevation<double>& compared_to, const PlanetElevation<float>& compared,
                          const PlanetErrorModel& model, const std::string& suffix, CaseResult& result) {
  const auto bounds = elevation_bounds(sphere, params, truth.regions.positions, truth.partition, truth.elevation, model);
  const double range = elevation_range(truth.elevation.smoothed);
  result.checks.push_back(ratio_check("parity.noise." + suffix, compared.noisy, compared_to.noisy, bounds.noisy, range));
  result.checks.push_back(
      ratio_check("parity.collision." + suffix, compared.collided, compared_to.collided, bounds.collided, range));
  result.checks.push_back(
      ratio_check("parity.elevation." + suffix, compared.smoothed, compared_to.smoothed, bounds.smoothed, range));
}

std::vector<double> widened(const std::vector<float>& values) { return {values.begin(), values.end()}; }

PlanetElevation<double> widened(const PlanetElevation<float>& elevation) {
  PlanetElevation<double> wide;
  wide.noisy = widened(elevation.noisy);
  wide.collided = widened(elevation.collided);
  wide.smoothed = widened(elevation.smoothed);
  return wide;
}

void add_float_parity(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& truth,
                      const Planet<float>& single, CaseResult& result) {
  const double position_difference = largest_difference(single.regions.positions, truth.regions.positions);
  result.checks.push_back(bounded_check("parity.positions.float_vs_double", position_difference,
                                        float_position_error(), std::nullopt,
                                        "largest |Δ| of a position component; bound 32u (planet_error_model.hpp)"));
  add_elevation_parity(sphere, params, truth, truth.elevation, single.elevation,
                       {float_position_error(), 0x1p-24}, "float_vs_double", result);
}

// The whole pipeline once, then the timed runs: the last one's plates and elevations must equal the
// first's in every bit (integer claims, fixed-point sums, one thread per output: nothing may race or
// be left over from the run before).
void add_determinism_check(gpu::PlanetGenerator& generator, const RunOptions& options, CaseResult& result) {
  generator.run();
  const PlatePartition first_partition = generator.partition_result();
  const std::vector<float> first_elevation = generator.elevation_result().smoothed;
  time_gpu(options.gpu_reps, [&] { generator.run(); }, result.timings);
  const PlatePartition last_partition = generator.partition_result();
  const std::vector<float> last_elevation = generator.elevation_result().smoothed;
  std::size_t changed = 0;
  for (std::size_t region = 0; region < first_elevation.size(); ++region) {
    const bool same = first_partition.plate[region] == last_partition.plate[region] &&
                      std::bit_cast<std::uint32_t>(first_elevation[region]) == std::bit_cast<std::uint32_t>(last_elevation[region]);
    changed += same ? 0 : 1;
  }
  result.checks.push_back(bounded_check("determinism.gpu", double(changed), 0.0, std::nullopt,
                                        fmt::format("regions whose plate or elevation differ in any bit between the first "
                                                    "and the last of {} GPU runs",
                                                    options.gpu_reps + 1)));
}

// Returns the GPU's own centroids (3 per region), which the Voronoi search runs on.
// The checks add_gpu_checks and add_voronoi_checks make, by name: a CPU-only run has them as `skip`.
std::vector<std::string> gpu_check_names() {
  std::vector<std::string> names = {"parity.offsets.gpu_vs_float", "parity.positions.gpu_vs_float",
                                    "parity.plates.gpu_vs_cpu",    "parity.plate_cycles.gpu_vs_cpu",
                                    "parity.edges.gpu_vs_cpu"};
  for (const char* check : {"unassigned", "empty_plates", "disconnected_plates", "edge_definition"}) {
    names.push_back(fmt::format("partition.{}.gpu", check));
  }
  for (const char* field : {"noise", "collision", "elevation"}) names.push_back(fmt::format("parity.{}.gpu_vs_float", field));
  names.insert(names.end(), {"determinism.gpu", "parity.voronoi.gpu_vs_cpu", "voronoi.misses_3x3.gpu"});
  return names;
}

std::vector<float> add_gpu_checks(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& truth,
                                  const Planet<float>& single, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("GPU");
  gpu::PlanetGenerator generator(sphere, params);
  const auto regions = generator.jitter();
  std::size_t differing_offsets = 0;
  for (std::size_t index = 0; index < regions.offsets.size(); ++index) {
    differing_offsets += regions.offsets[index] == single.regions.offsets[index] ? 0 : 1;
  }
  result.checks.push_back(bounded_check("parity.offsets.gpu_vs_float", double(differing_offsets), 0.0, std::nullopt,
                                        "jitter offsets that differ in any bit from ref<float>'s"));
  // Loose: the Vulkan environment's 2^-11 absolute error of sin and cos, through tan's quotient
  // (≤ 2.2·2^-11 over the warp's range) and the warp's slope 1.77: 4·2^-11.
  result.checks.push_back(bounded_check(
      "parity.positions.gpu_vs_float", largest_difference(regions.positions, widened(single.regions.positions)),
      gpu_position_error(), 4.0 * 0x1p-11,
      "largest |Δ| of a position component; strict: each float operation within 4 ulp (tan, division, sqrt)"));
  const auto partition = generator.grow_plates();
  std::size_t differing_plates = 0, differing_edges = 0;
  for (std::size_t region = 0; region < partition.plate.size(); ++region) {
    differing_plates += partition.plate[region] == truth.partition.plate[region] ? 0 : 1;
    differing_edges += partition.is_edge[region] == truth.partition.is_edge[region] ? 0 : 1;
  }
  result.checks.push_back(bounded_check("parity.plates.gpu_vs_cpu", double(differing_plates), 0.0, std::nullopt,
                                        "regions whose plate differs (the synchronous rule: integers, exact)"));
  result.checks.push_back(bounded_check("parity.plate_cycles.gpu_vs_cpu",
                                        std::abs(double(partition.cycles - truth.partition.cycles)), 0.0, std::nullopt,
                                        fmt::format("flood-fill cycles: GPU {}, CPU {}", partition.cycles,
                                                    truth.partition.cycles)));
  result.checks.push_back(bounded_check("parity.edges.gpu_vs_cpu", double(differing_edges), 0.0, std::nullopt,
                                        "regions whose is_edge differs"));
  add_partition_checks(sphere, params, partition, "gpu", result);
  // Shadow parity: the GPU fed ref<float>'s positions and partition.
  const auto shadow = generator.elevation(single.regions.positions, single.partition);
  add_elevation_parity(sphere, params, truth, widened(single.elevation), shadow, {0.0, 4.0 * 0x1p-24}, "gpu_vs_float",
                       result);
  add_determinism_check(generator, options, result);
  return regions.positions;
}

// The GPU's cell-grid search (Algorithm 1) on its own positions against the exact nearest centroid
// (the jitter, hence the positions, do not depend on the plate rules: `nearest` holds for both).
// A GPU label counts as a miss when its centroid's squared chord exceeds the nearest's by more than
// the GPU can tell apart: its own float rounding, 2^-19 per squared chord (8 operations, each within
// 2^-24 of a magnitude <= 4), twice, plus the positions' error e (the GPU's and ref<float>'s from
// ref<double>, per component) moving each squared chord by at most 2·|p − w|·√3·e <= 4√3·e.
void add_voronoi_checks(const CubeSphere& sphere, CubeWarp cube_warp, const Planet<double>& truth,
                        const std::vector<float>& positions,
                        const std::vector<Vector3<double>>& directions,
                        const std::vector<reference::NearestSite>& nearest, CaseResult& result) {
  std::vector<Vector3<float>> queries;
  for (const auto& direction : directions) {
    queries.push_back({static_cast<float>(direction[0]), static_cast<float>(direction[1]), static_cast<float>(direction[2])});
  }
  const double margin = 0x1p-18 + 8.0 * std::sqrt(3.0) * (gpu_position_error() + float_position_error());
  const auto& position = truth.regions.positions;
  const auto misses = [&](const std::vector<std::int32_t>& labels, std::size_t& agreeing) {
    std::size_t missed = 0;
    agreeing = 0;
    for (std::size_t index = 0; index < labels.size(); ++index) {
      const std::size_t label = static_cast<std::size_t>(labels[index]);
      const double distance = std::hypot(position[3 * label] - directions[index][0], position[3 * label + 1] - directions[index][1],
                                         position[3 * label + 2] - directions[index][2]);
      missed += distance * distance > nearest[index].distance * nearest[index].distance + margin ? 1 : 0;
      agreeing += labels[index] == nearest[index].region ? 1 : 0;
    }
    return missed;
  };
  std::size_t agreeing = 0, agreeing_3x3 = 0;
  const std::size_t missed = misses(gpu::PlanetVoronoi(sphere, 2, cube_warp).labels(positions, queries), agreeing);
  const std::size_t missed_3x3 = misses(gpu::PlanetVoronoi(sphere, 1, cube_warp).labels(positions, queries), agreeing_3x3);
  result.checks.push_back(bounded_check(
      "parity.voronoi.gpu_vs_cpu", double(missed), 0.0, std::nullopt,
      fmt::format("of {} map directions, those whose 5×5 cell-grid label (Algorithm 1) is farther than the exact "
                  "nearest centroid (CGAL k-d tree) by more than {:.2g} in squared chord; {:.4f} % agree label for "
                  "label (the rest are near-ties)",
                  directions.size(), margin, 100.0 * double(agreeing) / double(directions.size()))));
  result.checks.push_back(informative_check(
      "voronoi.misses_3x3.gpu", double(missed_3x3) / double(directions.size()),
      fmt::format("share of map directions the seed shader's 3×3 search gives a farther centroid than the nearest "
                  "({} of {}); {:.4f} % agree label for label",
                  missed_3x3, directions.size(), 100.0 * double(agreeing_3x3) / double(directions.size()))));
}

// The planet drawn by both twins as the seed's demo draws it: the mesh, the per-pixel Voronoi and
// the palette, from ref<float>'s centroids and elevations on the GPU and ref<double>'s on the CPU.
// A camera 2.8 radii from the centre at azimuth 35° and elevation 25°, 45° field of view, 384².
void add_render_checks(const CubeSphere& sphere, CubeWarp cube_warp, const Planet<double>& truth, const Planet<float>& single,
                       const RunOptions& options, CaseResult& result) {
  constexpr double azimuth = 35.0 * std::numbers::pi / 180.0, elevation = 25.0 * std::numbers::pi / 180.0;
  reference::Camera camera;
  camera.eye = {2.8 * std::cos(elevation) * std::sin(azimuth), 2.8 * std::sin(elevation),
                2.8 * std::cos(elevation) * std::cos(azimuth)};
  camera.near = 1.0;
  camera.far = 5.0;
  camera.width = camera.height = 384;
  const Mesh mesh = sphere_mesh(sphere, cube_warp);
  const auto cpu = reference::render_planet(mesh, camera, truth.regions.positions, truth.elevation.smoothed);
  if (!options.gpu_available) {
    compare_rendered_images(camera.width, camera.height, cpu.image.rgb, nullptr, options, result);
    for (const auto& name : image_check_names()) result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    result.checks.push_back(skipped_check("image.region_agreement.gpu_vs_cpu", options.gpu_unavailable_reason));
    return;
  }
  const reference::Matrix4 view_projection =
      reference::multiply(reference::projection_matrix(camera), reference::view_matrix(camera));
  const gpu::PlanetRenderer renderer(mesh, view_projection, sphere, cube_warp, single.regions.positions,
                                     single.elevation.smoothed,
                                     camera.width, camera.height);
  renderer.run();
  const gpu::PlanetPixels image = renderer.image();
  compare_rendered_images(camera.width, camera.height, cpu.image.rgb, &image.rgb, options, result);
  std::size_t both = 0, agreeing = 0;
  for (std::size_t pixel = 0; pixel < cpu.regions.size(); ++pixel) {
    if (cpu.regions[pixel] < 0 || image.regions[pixel] < 0) continue;
    ++both;
    agreeing += cpu.regions[pixel] == image.regions[pixel] ? 1 : 0;
  }
  result.checks.push_back(informative_check(
      "image.region_agreement.gpu_vs_cpu", both > 0 ? double(agreeing) / double(both) : 1.0,
      fmt::format("share of the {} pixels both twins drew whose region is the same (the rest: Voronoi near-ties, "
                  "and the float centroids' and elevations' rounding)",
                  both)));
}


// ---- pictures -------------------------------------------------------------------------------

// with white (pale).
std::array<float, 3> index_colour(const PlanetParams& params, std::int32_t index, bool full) {
  std::array<float, 3> colour{};
  for (std::uint32_t channel = 0; channel < 3; ++channel) {
    const float value = 0.15f + 0.7f * uniform01(random_u32(params.seed, static_cast<std::uint32_t>(index), channel, 0x706c0010u));
    colour[channel] = full ? value : 0.5f * (value + 1.0f);
  }
  return colour;
}

// The Voronoi cells: each region a pale colour of its own, a pixel whose right or lower neighbour
// (wrapping in longitude) lies in another cell dark.
void write_region_borders(const PlanetParams& params, const std::vector<reference::NearestSite>& nearest,
                          const std::filesystem::path& png) {
  std::vector<std::array<float, 3>> pixels;
  for (int row = 0; row < map_height; ++row) {
    for (int column = 0; column < map_width; ++column) {
      const auto label = [&](int y, int x) { return nearest[std::size_t(y) * map_width + std::size_t(x)].region; };
      const std::int32_t own = label(row, column);
      const bool border = own != label(row, (column + 1) % map_width) || (row + 1 < map_height && own != label(row + 1, column));
      pixels.push_back(border ? std::array<float, 3>{0.15f, 0.15f, 0.15f} : index_colour(params, own, false));
    }
  }
  write_colour_image(map_width, map_height, pixels, png);
}

// Pictures of the spherical Voronoi cells (the exact reference's nearest centroid per pixel): the
// elevation maps (compare/planet_relief.hpp), the plates and the regions.
void write_maps(const CubeSphere& sphere, const PlanetParams& params, const Planet<double>& planet,
                const std::vector<reference::NearestSite>& nearest, const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  write_elevation_maps({sphere, planet.regions.positions, planet.elevation.smoothed}, nearest, options, result);
  const auto folder = options.report_dir / result.name;
  std::vector<std::array<float, 3>> plate_pixels;
  for (const auto& site : nearest) {
    const auto region = static_cast<std::size_t>(site.region);
    plate_pixels.push_back(index_colour(params, planet.partition.plate[region], planet.partition.is_edge[region] != 0));
  }
  write_colour_image(map_width, map_height, plate_pixels, folder / "plates.png");
  add_picture(result, "plates.png",
              fmt::format("the {} plates ({} rule), edge regions in full colour", params.plates,
                          plate_rule_name(params.plate_rule)));
  write_region_borders(params, nearest, folder / "regions.png");
  add_picture(result, "regions.png",
              "the spherical Voronoi cells of the region centroids (exact nearest centroid per pixel), "
              "their borders dark");
}

// ---- the case -------------------------------------------------------------------------------

void run_planet(const PlanetParams& params, const std::optional<ReferenceRelief>& given, const nlohmann::json& expect,
                const RunOptions& options, CaseResult& result) {
  const CubeSphere sphere(params.resolution);
  const CubeWarp warp = cube_warp(params.warp);
  result.input = fmt::format("cube sphere R = {} ({} regions, {} warp), {} plates, seed {}", params.resolution,
                             sphere.region_count(), planet_warp_name(params.warp), params.plates, params.seed);
  result.width = 6 * params.resolution;
  result.height = params.resolution;
  const PlanetParams twins = twin_params(params);
  if (uses_legacy(params)) {
    result.notes.push_back(fmt::format("the legacy rules ({} plates, {} smoothing) run on the CPU; the twins are compared "
                                       "with the synchronous rule and Jacobi smoothing on the same draws",
                                       plate_rule_name(params.plate_rule), smoothing_name(params.smoothing)));
  }
  add_topology_checks(sphere, warp, result);
  add_mesh_checks(sphere, warp, result);
  add_cell_area_check(sphere, params.warp, result);
  if (options.progress) options.progress->stage("CPU reference (double)");
  Planet<double> planet;
  try {
    time_cpu(std::max(options.cpu_reps, 1), [&] { planet = generate<double>(sphere, params); }, result.timings);
  } catch (const std::invalid_argument&) {
    // The elevation refuses a partition that is not whole: its checks say why before the case errs.
    add_partition_checks(sphere, params, reference::grow_plates(sphere, params), "cpu", result);
    throw;
  }
  add_partition_checks(sphere, params, planet.partition, "cpu", result);
  add_expansion_rate_check(twins, result);
  add_rate_bounds_check(twins, result);
  add_smoothing_check(sphere, result);
  add_pressure_symmetry_check(sphere, params, planet, result);
  const Planet<double> truth = uses_legacy(params) ? generate<double>(sphere, twins) : planet;
  add_legacy_checks(sphere, twins, truth, result);
  if (options.progress) options.progress->stage("CPU reference (float)");
  const Planet<float> single = generate<float>(sphere, twins);
  add_float_parity(sphere, twins, truth, single, result);
  add_fidelity_checks({.sphere = sphere, .positions = planet.regions.positions, .elevation = planet.elevation.smoothed,
                       .warp = warp},
                      expect.is_object() && expect.value("earth_like", false), given, options, result);
  const auto directions = planet_map_directions();
  const auto nearest = reference::nearest_sites(planet.regions.positions, directions);
  write_maps(sphere, params, planet, nearest, options, result);
  add_render_checks(sphere, warp, truth, single, options, result);
  if (!options.gpu_available) {
    for (const auto& name : gpu_check_names()) result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    return;
  }
  const auto gpu_positions = add_gpu_checks(sphere, twins, truth, single, options, result);
  add_voronoi_checks(sphere, warp, truth, gpu_positions, directions, nearest, result);
}

PreparedTwin prepare_planet(const nlohmann::json& resolved, const LoadedInput& input) {
  if (input.heights.size() != 0 || input.mesh || input.volume) {
    throw InputError("the planet makes its own surface: give it no input, or a global elevation grid to be set beside");
  }
  const PlanetParams params = planet_params_from_json(resolved);
  std::optional<ReferenceRelief> given;
  if (input.global_grid) given = reference_relief(*input.global_grid, input.description);
  PreparedTwin prepared;
  prepared.kind = CaseRun([params, given](const nlohmann::json& expect, const RunOptions& options, CaseResult& result) {
    run_planet(params, given, expect, options, result);
  });
  return prepared;
}

// Measured 700 B a region: peak RSS of `groundtruth run` on both backends, report included, 271 MB at
// R = 120 and 588 MB at R = 300 (the mesh checks of 12R² triangles, the two CPU twins, the legacy
// fills, the GPU's downloads, the Voronoi maps); rounded up to 1000 B.
// A global grid the case gives is read (its own estimate, core/io/global_grid.cpp) before this.
MemoryEstimate planet_memory(const nlohmann::json& resolved, const LoadedInput&) {
  const PlanetParams params = params_from_json(planet_param_table(), resolved);
  return memory_for(params.region_count(), "regions", 1000);
}

// ---- performance ----------------------------------------------------------------------------

constexpr int benchmark_resolutions[] = {25, 50, 120, 300};

BenchmarkRow planet_row(const std::string& algorithm, const std::string& backend, int resolution, int reps,
                        const std::vector<double>& times, const std::string& device, const std::string& detail) {
  BenchmarkRow row{.algorithm = algorithm, .backend = backend, .size = resolution, .iterations = 1, .reps = reps,
                   .median_ms = median(times), .device = device, .dimensions = 2};
  const double regions = 6.0 * resolution * resolution;
  row.mcell_iterations_per_s = regions / (row.median_ms * 1e-3) / 1e6;
  row.detail = fmt::format("R = {}: {:.0f} regions (the size column shows R×R, a face), 50 plates; {}", resolution,
                           regions, detail);
  return row;
}

// PlanetaryCreation's published figures (issue 13): its oceanic stage at 163,842 vertices on an
// RTX 3080, GPU 10.9 ms and CPU 19.4 ms: other work, named beside ours for scale. 6·165² = 163,350.
std::vector<BenchmarkRow> published_planet_rows() {
  std::vector<BenchmarkRow> rows;
  for (const auto& [backend_device, ms] : {std::pair{std::string("GPU, RTX 3080"), 10.9}, {std::string("CPU"), 19.4}}) {
    BenchmarkRow row{.algorithm = "planet.earth_like", .backend = "published", .size = 165, .iterations = 1, .reps = 1,
                     .median_ms = ms, .device = "PlanetaryCreation (" + backend_device + ")", .dimensions = 2};
    row.mcell_iterations_per_s = 163842.0 / (ms * 1e-3) / 1e6;
    row.detail = "its oceanic stage at 163,842 vertices, as published: other work than ours, named for scale";
    rows.push_back(row);
  }
  return rows;
}

void add_cpu_planet_rows(const PlanetParams& params, int reps, const Environment& environment,
                         std::vector<BenchmarkRow>& rows) {
  const CubeSphere sphere(params.resolution);
  JitteredRegions<double> regions;
  PlatePartition partition;
  std::vector<double> jitter_times, plate_times, elevation_times;
  for (int rep = 0; rep < reps; ++rep) {
    jitter_times.push_back(cpu_wall_ms([&] { regions = reference::jitter_regions<double>(sphere, params); }));
    plate_times.push_back(cpu_wall_ms([&] { partition = reference::grow_plates(sphere, params); }));
    elevation_times.push_back(cpu_wall_ms([&] { reference::planet_elevation<double>(sphere, params, regions.positions, partition); }));
  }
  std::vector<double> totals;
  for (int rep = 0; rep < reps; ++rep) totals.push_back(jitter_times[rep] + plate_times[rep] + elevation_times[rep]);
  const int resolution = params.resolution;
  rows.push_back(planet_row("planet.jitter", "cpu", resolution, reps, jitter_times, environment.cpu, "step 1, ref<double>"));
  rows.push_back(planet_row("planet.plates", "cpu", resolution, reps, plate_times, environment.cpu,
                            fmt::format("steps 2–3, synchronous rule, {} cycles", partition.cycles)));
  rows.push_back(planet_row("planet.elevation", "cpu", resolution, reps, elevation_times, environment.cpu, "steps 4–9"));
  rows.push_back(planet_row("planet.earth_like", "cpu", resolution, reps, totals, environment.cpu, "steps 1–9"));
}

void add_gpu_planet_rows(const PlanetParams& params, int reps, const Environment& environment,
                         std::vector<BenchmarkRow>& rows) {
  gpu::PlanetGenerator generator(CubeSphere(params.resolution), params);
  generator.run();
  std::vector<double> jitter_times, plate_times, elevation_times, totals;
  for (int rep = 0; rep < reps; ++rep) {
    jitter_times.push_back(gpu_wall_ms([&] { generator.run_jitter(); }));
    plate_times.push_back(gpu_wall_ms([&] { generator.run_plate_growth(); }));
    elevation_times.push_back(gpu_wall_ms([&] { generator.run_elevation(); }));
    totals.push_back(gpu_wall_ms([&] { generator.run(); }));
  }
  const int resolution = params.resolution;
  const std::string& device = environment.gl_renderer;
  rows.push_back(planet_row("planet.jitter", "gpu", resolution, reps, jitter_times, device, "step 1"));
  rows.push_back(planet_row("planet.plates", "gpu", resolution, reps, plate_times, device,
                            "steps 2–3: one dispatch per sub-step and a 4-byte counter read per cycle"));
  rows.push_back(planet_row("planet.elevation", "gpu", resolution, reps, elevation_times, device, "steps 4–9"));
  rows.push_back(planet_row("planet.earth_like", "gpu", resolution, reps, totals, device, "steps 1–9, run()"));
}

std::vector<BenchmarkRow> benchmark_planet(const BenchmarkOptions& options, bool gpu_available,
                                           const Environment& environment) {
  std::vector<BenchmarkRow> rows = published_planet_rows();
  for (const int resolution : benchmark_resolutions) {
    if (!within_table_sizes(6.0 * resolution * resolution, options)) continue;  // the cube sphere's samples
    PlanetParams params;
    params.resolution = resolution;
    add_cpu_planet_rows(params, options.reps, environment, rows);
    if (gpu_available) add_gpu_planet_rows(params, options.reps, environment, rows);
  }
  return rows;
}

}  // namespace

Algorithm planet_algorithm() {
  return {.name = "planet.earth_like",
          .summary = "seed 002's Earth-like planet: jitter, tectonic plates, elevation on a cube sphere, beside the Earth",
          .source = "seed 002 digest §4.4, §9 (eq. 5.1–5.3, Algorithm 3)",
          .params = &planet_param_specs(),
          .prepare = prepare_planet,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::optional_global_grid,
          .benchmark = benchmark_planet,
          .expect_shape = {{"earth_like", "boolean"}},
          .memory = planet_memory};
}

}  // namespace gt
