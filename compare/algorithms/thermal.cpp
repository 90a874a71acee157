// The driver's view of the two thermal-erosion models: parameters to constants, the three
// versions (ref<double>, ref<float>, GPU) as stepped twins of one field, terrain (compare/
// stepped_case.hpp runs them), the error model's count of rounded additions, and each model's
// first iteration written on the host as a spec of the transfer (mass.moved_first_iteration.cpu for
// the material moved, spec.first_iteration_cells.cpu cell by cell).
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/algorithms/thermal_specs.hpp"
#include "core/rounding_interval.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/field.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/steppers/height.hpp"
#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"

namespace gt {
namespace {

// For the specs below, written here apart from either twin: a pipe's offset to its neighbour, and
// whether a cell takes part (inside the grid and not masked).
struct Offset {
  int dx;
  int dy;
};

bool takes_part(const Grid<double>& heights, int x, int y) { return heights.inside(x, y) && heights.is_valid(x, y); }

}  // namespace

Grid<double> hydra_first_iteration(const Grid<double>& heights, const ThermalConstants& constants,
                                   Neighbourhood neighbourhood) {
  const bool cardinal = neighbourhood != Neighbourhood::diagonal;
  const std::array<Offset, 4> offsets = cardinal ? std::array<Offset, 4>{{{-1, 0}, {0, 1}, {1, 0}, {0, -1}}}
                                                 : std::array<Offset, 4>{{{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}};
  const auto length = [&](int k) {
    return cardinal ? (k % 2 == 0 ? constants.length_x : constants.length_y) : constants.length_diagonal;
  };
  std::vector<std::array<double, 4>> request(heights.size(), std::array<double, 4>{});
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!heights.is_valid(x, y)) continue;
      std::array<double, 4> demand{}, supply{};
      for (int k = 0; k < 4; ++k) {
        if (!takes_part(heights, x + offsets[k].dx, y + offsets[k].dy)) continue;
        const double rise = heights.at(x + offsets[k].dx, y + offsets[k].dy) - heights.at(x, y);
        const double limit = constants.talus_slope * length(k);
        if (rise > limit) demand[k] = rise - limit;
        if (rise < -limit) supply[k] = rise + limit;
      }
      const double demand_sum = demand[0] + demand[1] + demand[2] + demand[3];
      const double supply_sum = supply[0] + supply[1] + supply[2] + supply[3];
      const double c_d = demand_sum > 0.0
                             ? std::clamp(constants.request_factor * *std::max_element(demand.begin(), demand.end()) /
                                              demand_sum, 0.0, 1.0)
                             : 0.0;
      const double c_s = supply_sum < 0.0
                             ? std::clamp(constants.request_factor * *std::min_element(supply.begin(), supply.end()) /
                                              supply_sum, 0.0, 1.0)
                             : 0.0;
      for (int k = 0; k < 4; ++k) request[heights.index(x, y)][k] = demand[k] * c_d + supply[k] * c_s;
    }
  }
  Grid<double> after = heights;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      for (int k = 0; k < 2; ++k) {  // pipes k and k + 2 are the two ends of one pair
        const int nx = x + offsets[k].dx, ny = y + offsets[k].dy;
        if (!heights.is_valid(x, y) || !takes_part(heights, nx, ny)) continue;
        const double mine = request[heights.index(x, y)][k];
        const double theirs = request[heights.index(nx, ny)][k + 2];
        if (!((mine > 0.0 && theirs < 0.0) || (mine < 0.0 && theirs > 0.0))) continue;  // one asks, one offers
        const double amount = std::min(std::abs(mine), std::abs(theirs));
        const double to_me = mine > 0.0 ? amount : -amount;
        after.at(x, y) += to_me;
        after.at(nx, ny) -= to_me;
      }
    }
  }
  if (constants.clamp_unit) {
    for (double& height : after.values) height = std::clamp(height, 0.0, 1.0);
  }
  return after;
}

namespace {

// R(x, y) of the hardness map, 1 without one.
template <class Real>
double hardness_at(const ThermalConstants& constants, const Grid<Real>& heights, int x, int y) {
  return constants.hardness.empty() ? 1.0 : constants.hardness[heights.index(x, y)];
}

}  // namespace

template <class Real>
Grid<Real> jako_first_iteration(const Grid<Real>& heights, const ThermalConstants& constants) {
  using std::max;  // unqualified: RoundingInterval brings its own
  const auto& offsets = moore_offsets;  // core/grid.hpp, the pipes of both twins
  Grid<Real> after = heights;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!heights.is_valid(x, y)) continue;
      std::array<Real, 8> drop{};
      for (int k = 0; k < 8; ++k) {
        const int nx = x + offsets[k].dx, ny = y + offsets[k].dy;
        if (!heights.inside(nx, ny) || !heights.is_valid(nx, ny)) continue;
        const double length = k >= 4 ? constants.length_diagonal : (k % 2 == 0 ? constants.length_x : constants.length_y);
        const Real fall = heights.at(x, y) - heights.at(nx, ny);
        // Eq. 2.33: the talus slope toward n is C_a·R(n) + C_i.
        const double slope = constants.hardness_talus * hardness_at(constants, heights, nx, ny) + constants.talus_slope;
        if (fall > Real(slope * length)) drop[k] = fall;
      }
      const Real drop_sum = ((drop[0] + drop[1]) + (drop[2] + drop[3])) + ((drop[4] + drop[5]) + (drop[6] + drop[7]));
      if (!(drop_sum > Real(0))) continue;
      Real largest = drop[0];
      for (int k = 1; k < 8; ++k) largest = max(largest, drop[k]);
      const Real sent = Real(constants.request_factor * hardness_at(constants, heights, x, y)) * largest / Real(2);
      for (int k = 0; k < 8; ++k) {
        const Real share = sent * drop[k] / drop_sum;
        after.at(x, y) = after.at(x, y) - share;
        if (drop[k] > Real(0)) after.at(x + offsets[k].dx, y + offsets[k].dy) = after.at(x + offsets[k].dx, y + offsets[k].dy) + share;
      }
    }
  }
  return after;
}

template Grid<double> jako_first_iteration(const Grid<double>&, const ThermalConstants&);
template Grid<RoundingInterval> jako_first_iteration(const Grid<RoundingInterval>&, const ThermalConstants&);

namespace {


// Spec vector of eq. 4.10 when a case asks for it: {"talus_eq_4_10": {"angle", "width",
// "vertical_aspect", "value"}}; exact in double up to the rounding of tan (a few ulp).
void add_talus_spec(const nlohmann::json& expect, const RunOptions&, CaseResult& result) {
  if (!expect.is_object() || !expect.contains("talus_eq_4_10")) return;
  const auto& vector = expect["talus_eq_4_10"];
  const double value = talus_threshold_eq_4_10(vector.at("angle"), vector.at("width"), vector.at("vertical_aspect"));
  const double expected = vector.at("value");
  result.checks.push_back(bounded_check("spec.talus_eq_4_10", std::abs(value - expected), 4e-16 * std::abs(expected),
                                        std::nullopt, "T_α = tan(α)/(width·d_z); tolerance: a few ulp of tan in double"));
}

void require_heightmap(const Heightmap& input, const char* algorithm) {
  if (input.size() == 0) throw InputError(fmt::format("{} erodes a heightmap: the case needs an input", algorithm));
}

// What the two thermal models share as stepped twins: the state {terrain}, the shadow bound of the
// same float arithmetic and the mass ledger, both from `additions_per_iteration` rounded additions
// into a height an iteration (compare/checks/error_model.hpp).
SteppedTwin thermal_twin(const std::string& algorithm, const Heightmap& input, int iterations,
                         double additions_per_iteration) {
  SteppedTwin twin{.algorithm = algorithm,
                   .fields = {terrain_field(input.vertical_unit)},
                   .initial = height_state(input),
                   .iterations = iterations};
  const FieldTotals totals = field_totals(input);
  const double range = totals.high > totals.low ? totals.high - totals.low : 1.0;
  const double magnitude = std::max(std::abs(totals.low), std::abs(totals.high)) / range;
  twin.shadow_bounds = [=](const State&, int count) {
    const Bounds bounds = parity_bounds_same_arithmetic(additions_per_iteration * count, magnitude);
    // Relative to the input's height range: a bug that moves under 1 % of it in one iteration must
    // still show, so a bound wider than that cannot tell (inconclusive).
    return std::vector<ShadowBound>{
        {.strict = bounds.strict * range,
         .loose = bounds.loose * range,
         .scale = range,
         .tellable_share = 0.01,
         .model = fmt::format("{}; {} additions per cell", bounds.model, additions_per_iteration * count)}};
  };
  const double additions = additions_per_iteration * iterations;
  twin.ledger.push_back({"mass.relative_drift", [=](const LedgerRun& run) {
    // The float twins round the input to float first: one rounding more.
    const bool in_double = run.backend == "cpu";
    const auto bounds = mass_drift_bounds(unit_roundoff_of(run.backend),
                                          in_double ? additions : additions + 1.0, totals);
    return bounded_check("", relative_mass_drift(heights_of<double>(run.initial), heights_of<double>(run.final)),
                         bounds.strict, bounds.loose, bounds.model);
  }});
  return twin;
}

// The material the double reference moves in its first iteration from the input, against the
// model's spec of that iteration written on the host (both ½Σ|h1 - h0|). Catches a transfer
// misapplied in both twins (talus, rate, a side of the exchange), which the twins' agreement cannot.
// Then the same first iteration cell by cell: a transfer sent the wrong way moves as much material
// (½Σ|Δh| alike on a symmetric input) but not to the same cells.
CaseRun moved_ledger(const Heightmap& input, int iterations, double additions_per_iteration,
                     std::function<Grid<double>(const Grid<double>&)> reference_first,
                     std::function<Grid<double>(const Grid<double>&)> spec_first) {
  return [=](const nlohmann::json&, const RunOptions&, CaseResult& result) {
    if (iterations < 1) return;
    const Grid<double> spec = spec_first(input);
    const Grid<double> twin = reference_first(input);
    const FieldTotals totals = field_totals(input);
    const Bounds cell_bounds = first_iteration_cell_bounds(additions_per_iteration, totals);
    result.checks.push_back(bounded_check("spec.first_iteration_cells.cpu", field_difference(spec, twin).max_abs,
                                          cell_bounds.strict, std::nullopt,
                                          "the largest |ref<double> − spec| over the cells after one iteration; " +
                                              cell_bounds.model));
    const double moved_spec = moved_material(input, spec);
    const double moved_twin = moved_material(input, twin);
    const std::string measured = fmt::format("moved {:.9g} where the spec (host, double) moves {:.9g}", moved_twin, moved_spec);
    if (moved_spec == 0.0) {
      result.checks.push_back(bounded_check("mass.moved_first_iteration.cpu", moved_twin, 0.0, std::nullopt,
                                            measured + "; the spec moves nothing, so the twin must not"));
      return;
    }
    const auto bounds = moved_ledger_bounds(additions_per_iteration, totals, moved_spec);
    result.checks.push_back(bounded_check("mass.moved_first_iteration.cpu", std::abs(moved_twin - moved_spec) / moved_spec,
                                          bounds.strict, std::nullopt,
                                          fmt::format("relative to the spec's: {}; {}", measured, bounds.model)));
  };
}

PreparedTwin prepare_thermal(const nlohmann::json& resolved, const Heightmap& given) {
  require_heightmap(given, "erosion.thermal");
  const ThermalParams params = thermal_params_from_json(resolved);
  const Heightmap input = params.normalised ? normalise_heights(given) : given;
  const ThermalConstants constants = thermal_constants(params, given);
  const Neighbourhood neighbourhood = params.neighbourhood;
  constexpr double additions_per_iteration = 4.0;  // one per pipe (Algorithm 11)
  SteppedTwin twin = thermal_twin("erosion.thermal", input, params.iterations, additions_per_iteration);
  twin.reference_double = [=] {
    return std::make_unique<HeightStepper<double>>([=](const Grid<double>& heights, int first, int count) {
      return reference::thermal_erosion(heights, constants, count, neighbourhood, first);
    });
  };
  twin.reference_float = [=] {
    return std::make_unique<HeightStepper<float>>([=](const Grid<float>& heights, int first, int count) {
      return reference::thermal_erosion(heights, constants, count, neighbourhood, first);
    });
  };
  twin.make_gpu = [=, width = input.width, height = input.height]() -> std::unique_ptr<Stepper> {
    auto gpu = std::make_shared<gpu::ThermalErosion>(width, height, constants, neighbourhood, params.iterations);
    return std::make_unique<GpuHeightStepper>([gpu](const Grid<float>& heights) { gpu->load(heights); },
                                              [gpu](int first, int count) { gpu->step(first, count); },
                                              [gpu] { return gpu->result(); });
  };
  const CaseRun moved = moved_ledger(
      input, params.iterations, additions_per_iteration,
      [=](const Grid<double>& heights) { return reference::thermal_erosion(heights, constants, 1, neighbourhood, 0); },
      [=](const Grid<double>& heights) { return hydra_first_iteration(heights, constants, neighbourhood); });
  return {.kind = std::move(twin), .extra_checks = in_turn(moved, add_talus_spec)};
}

// The "hardness" input field as the state's R per cell (1 everywhere without one), and what was
// decided, said.
std::vector<double> hardness_map(const LoadedInput& loaded, double rate, std::vector<std::string>& notes) {
  const Heightmap& input = loaded.heights;
  const auto field = loaded.fields.find("hardness");
  if (field == loaded.fields.end()) {
    notes.push_back("no hardness field: R = 1 in every cell (eq. 2.32's rate and eq. 2.33's talus C_a + C_i)");
    return std::vector<double>(input.size(), 1.0);
  }
  std::vector<double> hardness = jako_hardness(field->second.values, input.valid, input.width, rate, "erosion.thermal_jako");
  const auto [least, most] = std::minmax_element(hardness.begin(), hardness.end());
  notes.push_back(fmt::format("hardness R from the input field 'hardness', {:.6g} .. {:.6g}", *least, *most));
  return hardness;
}

// The state's second field: R, read by both twins on every load and handed back unchanged.
FieldDecl hardness_field() {
  return {.name = "hardness",
          .unit = "1",
          .meaning = "R(x, y) of eqs. 2.32-2.33, an input: the cell's rate × R, the talus toward it C_a·R + C_i",
          .read_only = true};
}

// The R a state loads, checked (an outside caller may load any map).
std::vector<double> loaded_hardness(const State& loaded, double rate) {
  return jako_hardness(loaded.fields.at(1), loaded.grid.valid, loaded.grid.width, rate,
                       "erosion.thermal_jako's loaded hardness");
}

template <class Real>
std::unique_ptr<Stepper> jako_reference_stepper(const ThermalConstants& prepared, double rate) {
  auto constants = std::make_shared<ThermalConstants>(prepared);
  return std::make_unique<HeightStepper<Real>>(
      [constants](const Grid<Real>& heights, int, int count) {
        return reference::thermal_jako_erosion(heights, *constants, count);
      },
      [constants, rate](State& loaded) { constants->hardness = loaded_hardness(loaded, rate); });
}

PreparedTwin prepare_thermal_jako(const nlohmann::json& resolved, const LoadedInput& loaded) {
  const Heightmap& input = loaded.heights;
  require_heightmap(input, "erosion.thermal_jako");
  const ThermalJakoParams params = thermal_jako_params_from_json(resolved);
  std::vector<std::string> notes;
  ThermalConstants constants = thermal_jako_constants(params, input);
  constants.hardness = hardness_map(loaded, params.rate, notes);
  constexpr double additions_per_iteration = 16.0;  // 8 outflows subtracted, 8 inflows added
  SteppedTwin twin = thermal_twin("erosion.thermal_jako", input, params.iterations, additions_per_iteration);
  twin.fields.push_back(hardness_field());
  twin.initial.fields.push_back(constants.hardness);
  twin.reference_double = [=] { return jako_reference_stepper<double>(constants, params.rate); };
  twin.reference_float = [=] { return jako_reference_stepper<float>(constants, params.rate); };
  twin.make_gpu = [=, width = input.width, height = input.height]() -> std::unique_ptr<Stepper> {
    auto gpu = std::make_shared<gpu::ThermalJakoErosion>(width, height, constants, params.iterations);
    const ReadInputs set_hardness = [gpu, rate = params.rate](State& loaded) {
      // Mutant erosion.thermal_jako.gpu_rate_folded_into_hardness (GPU): the adapter folds the rate
      // into the map it holds (R <- rate·R), which it then steps with and hands back.
      if (mutant_active("erosion.thermal_jako.gpu_rate_folded_into_hardness")) {
        for (double& hardness : loaded.fields.at(1)) hardness *= rate;
      }
      gpu->set_hardness(loaded_hardness(loaded, rate));
    };
    return std::make_unique<GpuHeightStepper>([gpu](const Grid<float>& heights) { gpu->load(heights); },
                                              [gpu](int, int count) { gpu->step(count); },
                                              [gpu] { return gpu->result(); }, set_hardness);
  };
  const CaseRun moved = moved_ledger(
      input, params.iterations, additions_per_iteration,
      [=](const Grid<double>& heights) { return reference::thermal_jako_erosion(heights, constants, 1); },
      [=](const Grid<double>& heights) { return jako_first_iteration(heights, constants); });
  const CaseRun say_hardness = [notes](const nlohmann::json&, const RunOptions&, CaseResult& result) {
    result.notes.insert(result.notes.end(), notes.begin(), notes.end());
  };
  return {.kind = std::move(twin), .extra_checks = in_turn(moved, say_hardness)};
}

// The field's spec vectors plus add_talus_spec's eq. 4.10 vector.
nlohmann::json talus_spec_shape() {
  nlohmann::json shape = field_spec_shape();
  shape["talus_eq_4_10"] = {{"angle", "number"}, {"width", "number"}, {"vertical_aspect", "number"}, {"value", "number"}};
  return shape;
}

// Hydra's Table 5.6 (digest 000 §6.6): thermal erosion, total time of 50 iterations (ms) by texture side.
std::vector<BenchmarkRow> hydra_thermal_rows() {
  const std::pair<const char*, std::array<double, 5>> table_5_6[] = {{"NVIDIA RTX 3080 12GB", {1.80, 5.75, 19, 79, 318}},
                                                                     {"NVIDIA GTX 745 4GB", {22, 85, 427, 1708, 11054}}};
  const int sides[] = {128, 256, 512, 1024, 2048};
  std::vector<BenchmarkRow> rows;
  for (const auto& [device, totals] : table_5_6) {
    for (std::size_t column = 0; column < totals.size(); ++column) {
      rows.push_back(published_row("erosion.thermal", fmt::format("{} (Hydra, thesis Table 5.6)", device),
                                   sides[column], 50, totals[column],
                                   "Hydra's two-pass thermal erosion in fragment shaders, total of 50 iterations, as "
                                   "published"));
    }
  }
  return rows;
}

}  // namespace

Algorithm thermal_algorithm() {
  return {.name = "erosion.thermal",
          .summary = "two-pass thermal erosion with requests and transfers (Hydra)",
          .source = "seed 000 §4.4.3, Algorithms 9-11, eq. 4.10 (digest 000 §4.6)",
          .params = &thermal_param_specs(),
          .prepare = [](const nlohmann::json& resolved, const LoadedInput& input) {
            return prepare_thermal(resolved, input.heights);
          },
          .kind = CaseKind::stepped,
          // Counted in reference/erosion/thermal.cpp and gpu/erosion/thermal.cpp.
          .traffic = {.cpu = 88.0, .gpu = 52.0},
          .published = hydra_thermal_rows(),
          .expect_shape = talus_spec_shape(),
          // Measured 395 B a cell (1024² vs 256², 64 iterations, both backends, 8 shadow checkpoints).
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 450 + descriptor_bytes_per_cell);
          }};
}

Algorithm thermal_jako_algorithm() {
  return {.name = "erosion.thermal_jako",
          .summary = "8-neighbour thermal erosion with proportional outflow (Jákó & Tóth 2011)",
          .source = "seed 000 §2.6, eqs. 2.30-2.34 (digest 000 §3.6)",
          .params = &thermal_jako_param_specs(),
          .prepare = [](const nlohmann::json& resolved, const LoadedInput& input) {
            return prepare_thermal_jako(resolved, input);
          },
          .kind = CaseKind::stepped,
          .input_fields = {{"hardness", "1",
                            "R(x, y) of eqs. 2.32-2.33, >= 0: the cell's rate × R, and the talus toward it C_a·R + C_i"}},
          // Counted in reference/erosion/thermal_jako.cpp and gpu/erosion/thermal_jako.cpp.
          .traffic = {.cpu = 224.0, .gpu = 120.0},
          .expect_shape = field_spec_shape(),
          // Measured 438 B a cell (1024² vs 256², 64 iterations, both backends, 8 shadow checkpoints),
          // before the per-cell constants: 9 doubles on the host, rounded copies in the float and
          // interval runs (9 floats, 9 pairs of doubles) and on the GPU (9 floats): 288 B more; R in
          // the state (a double in each of about 20 states the runner keeps or steps): 160 B more.
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 950 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
