// `planet.fault_lines`: the fault-line planet seed 002 compares its plates against (§2.5, after Hugo
// Elias and Paul Bourke, "Modelling fake planets", 2000): N random planes through the centre, each
// raising one side by Δ and lowering the other, on the cube sphere's regions. Spec and decisions:
// core/params/fault_planet.hpp; the twins: reference/planet/fault_lines.hpp, gpu/planet/fault_lines.hpp.
//
// Each twin counts integer votes, so a float twin differs from ref<double> only where a dot's sign
// flips, and only a plane that passes within the float dot's error of a region can flip it: the
// error model is per region and fixed from the double dots before any float vote is read.
// Checks (backend cpu = ref<double>, float = ref<float>, gpu = the GPU twin):
//   spec.antipodal.cpu                 regions r whose votes do not cancel their antipode's, v(r) +
//                                      v(-r) = 0 (every plane through the centre raises one and
//                                      lowers the other), beyond the planes within the double dot's
//                                      error of either (must be 0)
//   parity.votes_beyond_flips.{float,gpu}_vs_double   regions whose |Δvotes| exceeds twice the
//                                      planes within the float dot's error, 6u·Σ|n_c·p_c| (must be 0)
//   parity.votes.gpu_vs_float          regions whose votes differ (must be 0: the same float inputs,
//                                      the same `precise` dot in the same order)
//   votes.uncertain_planes.float       informative: the (region, plane) pairs within the float error
//   determinism.gpu                    regions whose votes differ between the first and the last of
//                                      the timed GPU runs
//   fidelity.*                         the relief beside the Earth (compare/planet_relief.hpp)
// Pictures: the elevation (equirectangular and cube map, §4.3 palette), the hypsometry and spectrum
// plots beside the Earth's.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/planet_relief.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/params/fault_planet.hpp"
#include "core/planet/cube_sphere.hpp"
#include "gpu/planet/fault_lines.hpp"
#include "reference/planet/fault_lines.hpp"
#include "reference/planet/voronoi.hpp"

namespace gt {
namespace {

std::vector<double> flat(const std::vector<std::array<double, 3>>& normals) {
  std::vector<double> values;
  for (const auto& normal : normals) values.insert(values.end(), normal.begin(), normal.end());
  return values;
}

std::vector<float> rounded(const std::vector<double>& values) { return {values.begin(), values.end()}; }

// Per region, the planes whose exact dot lies within a Real dot's error of 0 (so that its sign may
// differ from the double one's), for Real = double and float, from one pass over the double dots.
struct UncertainPlanes {
  std::vector<int> in_double;
  std::vector<int> in_float;
};

UncertainPlanes uncertain_planes(const std::vector<double>& positions, const std::vector<std::array<double, 3>>& normals) {
  const std::size_t regions = positions.size() / 3;
  UncertainPlanes counts{std::vector<int>(regions, 0), std::vector<int>(regions, 0)};
  for (std::size_t region = 0; region < regions; ++region) {
    const double* p = &positions[3 * region];
    for (const auto& n : normals) {
      const double dot = std::abs((n[0] * p[0] + n[1] * p[1]) + n[2] * p[2]);
      const double double_error = reference::dot_error_bound(n, p, unit_roundoff_double);
      counts.in_double[region] += dot <= 2.0 * double_error ? 1 : 0;
      counts.in_float[region] += dot <= reference::dot_error_bound(n, p, unit_roundoff_float) + double_error ? 1 : 0;
    }
  }
  return counts;
}

// The region whose centre is -p_r (the cube sphere is centrally symmetric), for every region.
std::vector<std::size_t> antipodes(const CubeSphere& sphere, const std::vector<double>& positions) {
  std::vector<std::size_t> opposite(sphere.region_count());
  for (std::size_t region = 0; region < opposite.size(); ++region) {
    const Vec3 direction{-positions[3 * region], -positions[3 * region + 1], -positions[3 * region + 2]};
    const auto found = sphere.region_at(local_position_of(direction));
    if (!found) throw std::logic_error("planet.fault_lines: a region centre's antipode lies over a cube corner");
    opposite[region] = *found;
  }
  return opposite;
}

void add_antipodal_check(const CubeSphere& sphere, const std::vector<double>& positions,
                         const std::vector<std::int32_t>& votes, const std::vector<int>& uncertain, CaseResult& result) {
  const auto opposite = antipodes(sphere, positions);
  std::size_t broken = 0;
  std::int64_t largest = 0;
  for (std::size_t region = 0; region < votes.size(); ++region) {
    const std::int64_t sum = std::int64_t(votes[region]) + votes[opposite[region]];
    largest = std::max(largest, std::abs(sum));
    broken += std::abs(sum) > 2 * (uncertain[region] + uncertain[opposite[region]]) ? 1 : 0;
  }
  result.checks.push_back(bounded_check(
      "spec.antipodal.cpu", double(broken), 0.0, std::nullopt,
      fmt::format("regions r whose votes do not cancel their antipode's (v(r) + v(-r) = 0 for planes through the "
                  "centre), beyond 2 per plane within the double dot's error of either; largest |v(r) + v(-r)| {}",
                  largest)));
}

// Regions whose votes differ from the truth's by more than two per plane that may flip there.
void add_flip_check(const std::string& name, const std::vector<std::int32_t>& twin,
                    const std::vector<std::int32_t>& truth, const std::vector<int>& uncertain, CaseResult& result) {
  std::size_t beyond = 0, differing = 0;
  for (std::size_t region = 0; region < truth.size(); ++region) {
    const std::int64_t difference = std::abs(std::int64_t(twin[region]) - truth[region]);
    differing += difference != 0 ? 1 : 0;
    beyond += difference > 2 * uncertain[region] ? 1 : 0;
  }
  result.checks.push_back(bounded_check(
      name, double(beyond), 0.0, std::nullopt,
      fmt::format("regions whose |Δvotes| exceeds 2 per plane within the float dot's error 6u·Σ|n_c·p_c| of the "
                  "region (fixed from the double dots); {} regions differ at all",
                  differing)));
}

std::size_t regions_differing(const std::vector<std::int32_t>& a, const std::vector<std::int32_t>& b) {
  std::size_t count = 0;
  for (std::size_t region = 0; region < a.size(); ++region) count += a[region] != b[region] ? 1 : 0;
  return count;
}

const std::vector<std::string> gpu_checks = {"parity.votes_beyond_flips.gpu_vs_double", "parity.votes.gpu_vs_float",
                                             "determinism.gpu"};

void add_gpu_checks(const std::vector<float>& positions, const std::vector<float>& normals,
                    const std::vector<std::int32_t>& truth, const std::vector<std::int32_t>& single,
                    const std::vector<int>& uncertain, const RunOptions& options, CaseResult& result) {
  gpu::FaultLines gpu;
  const auto votes = gpu.votes(positions, normals);
  add_flip_check("parity.votes_beyond_flips.gpu_vs_double", votes, truth, uncertain, result);
  result.checks.push_back(bounded_check("parity.votes.gpu_vs_float", double(regions_differing(votes, single)), 0.0,
                                        std::nullopt,
                                        "regions whose votes differ from ref<float>'s: the same float inputs and the "
                                        "same `precise` dot in the same order"));
  time_gpu(options.gpu_reps, [&] { gpu.run(); }, result.timings);
  const auto last = gpu.votes(positions, normals);
  result.checks.push_back(bounded_check("determinism.gpu", double(regions_differing(votes, last)), 0.0, std::nullopt,
                                        fmt::format("regions whose votes differ between the first and the last of {} "
                                                    "GPU runs",
                                                    options.gpu_reps + 2)));
}

std::vector<double> elevation_of(const std::vector<std::int32_t>& votes, double step) {
  std::vector<double> elevation(votes.size());
  for (std::size_t region = 0; region < votes.size(); ++region) elevation[region] = step * double(votes[region]);
  return elevation;
}

void run_fault_lines(const FaultPlanetParams& params, const std::optional<ReferenceRelief>& given,
                     const RunOptions& options, CaseResult& result) {
  const CubeSphere sphere(params.resolution);
  result.input = fmt::format("cube sphere R = {} ({} regions), {} faults of {} each, seed {}", params.resolution,
                             sphere.region_count(), params.faults, params.step, params.seed);
  result.width = 6 * params.resolution;
  result.height = params.resolution;
  result.notes.push_back(
      "the thesis gives no Δ and no schedule: a constant step per fault; regions at their cells' centres on the warped "
      "cube sphere; the normals uniform on the sphere from the counter RNG (core/params/fault_planet.hpp)");
  const std::vector<double> positions = fault_planet_positions(params.resolution);
  const auto normals = fault_normals(params);
  const std::vector<double> flat_normals = flat(normals);
  std::vector<std::int32_t> truth;
  time_cpu(std::max(options.cpu_reps, 1), [&] { truth = reference::fault_votes(positions, flat_normals); },
           result.timings);
  const UncertainPlanes uncertain = uncertain_planes(positions, normals);
  add_antipodal_check(sphere, positions, truth, uncertain.in_double, result);
  const std::vector<float> float_positions = rounded(positions), float_normals = rounded(flat_normals);
  const auto single = reference::fault_votes(float_positions, float_normals);
  add_flip_check("parity.votes_beyond_flips.float_vs_double", single, truth, uncertain.in_float, result);
  double pairs = 0.0;
  for (const int count : uncertain.in_float) pairs += count;
  result.checks.push_back(informative_check(
      "votes.uncertain_planes.float", pairs,
      "(region, plane) pairs whose dot lies within the float dot's error of 0: where a float twin may vote otherwise"));
  const std::vector<double> elevation = elevation_of(truth, params.step);
  // Votes change by 2 with every plane, so Δ·votes lies on the lattice 2Δ·k + Δ·(faults mod 2).
  add_fidelity_checks({sphere, positions, elevation, 2.0 * params.step, params.step * double(params.faults % 2)}, false,
                      given, options, result);
  write_elevation_maps({sphere, positions, elevation},
                       reference::nearest_sites(positions, planet_map_directions()), options, result);
  if (!options.gpu_available) {
    for (const auto& name : gpu_checks) result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    return;
  }
  add_gpu_checks(float_positions, float_normals, truth, single, uncertain.in_float, options, result);
}

PreparedTwin prepare_fault_lines(const nlohmann::json& resolved, const LoadedInput& input) {
  if (input.heights.size() != 0 || input.mesh || input.volume) {
    throw InputError("planet.fault_lines makes its own surface: give it no input, or a global elevation grid to be "
                     "set beside");
  }
  const FaultPlanetParams params = fault_planet_params_from_json(resolved);
  std::optional<ReferenceRelief> given;
  if (input.global_grid) given = reference_relief(*input.global_grid, input.description);
  return {.kind = CaseRun([params, given](const nlohmann::json&, const RunOptions& options, CaseResult& result) {
    run_fault_lines(params, given, options, result);
  })};
}

// Positions, normals and votes in double and float, the maps and the spectrum's samples: about 300 B
// a region beside the planet's reporting (the earth-like planet's 1000 B a region covers it).
MemoryEstimate fault_lines_memory(const nlohmann::json& resolved, const LoadedInput&) {
  const FaultPlanetParams params = fault_planet_params_from_json(resolved);
  return memory_for(6.0 * params.resolution * params.resolution, "regions", 1000);
}

}  // namespace

Algorithm fault_lines_algorithm() {
  return {.name = "planet.fault_lines",
          .summary = "the fault-line planet (random planes through the centre raise one side, lower the other), the "
                     "baseline seed 002 compares its plates against",
          .source = "seed 002 §2.5 (Fig. 2.8), after H. Elias and P. Bourke 2000",
          .params = &fault_planet_param_specs(),
          .prepare = prepare_fault_lines,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::optional_global_grid,
          .memory = fault_lines_memory};
}

}  // namespace gt
