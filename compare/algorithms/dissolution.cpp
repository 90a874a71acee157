// The driver's view of Beneš's dissolution erosion (erosion.dissolution; reference/erosion/
// dissolution.cpp): the declared state {terrain, water, dissolved, evaporated}, the three versions
// (ref<double>, ref<float>, GPU) as stepped twins, the shadow step's per-cell bounds, the two ledgers
// and a spec of one iteration written on the host from the thesis's equations.
//
// Checks beyond the runner's (compare/stepped_case.hpp):
//   mass.material_drift.<backend>   |Σ(b + s)_end − Σ(b + s)_0| over an a-priori bound of Σ(|b| + s)
//                                   during the run; material only moves between terrain and water
//   mass.water_balance.<backend>    |Σ(d + evaporated)_end − Σ(d + evaporated)_0 − N·K_r·cells| over the
//                                   water handled; rain is known before the run, evaporation is booked
//   spec.step.<field>.cpu           ref<double>'s iteration k + 1 from its own state after k against
//                                   the host's spec of that iteration, cell by cell (k = min(N − 1, 10))
// Error models, all fixed before the run from the parameters and the start state:
//   shadow step: the step in rounding-interval arithmetic from ref<float>'s state (core/
//   rounding_interval.hpp), 2·width per value; every branch of the model is continuous (the
//   evaporation threshold, s < S, Δh > 0, the minima), so a branch taken otherwise by an ulp moves
//   nothing the interval misses. Over several steps not graded (the runner's multi-step shadow).
//   ledgers: worst case of the additions' rounding, each at most u times the partial sum it forms,
//   which over the cells is at most twice the total (a cell's own plus what it receives).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/steppers/height.hpp"
#include "core/errors.hpp"
#include "core/params/dissolution.hpp"
#include "core/rounding_interval.hpp"
#include "core/sum.hpp"
#include "gpu/erosion/dissolution.hpp"
#include "reference/erosion/dissolution.hpp"

namespace gt {
namespace {

StateDecl dissolution_fields(const std::string& unit) {
  return {terrain_field(unit),
          {.name = "water", .unit = unit, .meaning = "water depth d", .conserved = true,
           .standard_name = "surface_water__depth"},
          {.name = "dissolved", .unit = unit, .meaning = "material carried by the water s, as a height of terrain",
           .conserved = true},
          {.name = "evaporated", .unit = unit, .meaning = "water evaporated from the cell since the start, a depth"}};
}

template <class Real>
auto grids_of(DissolutionState<Real>& state) {
  return std::array<Grid<Real>*, 4>{&state.terrain, &state.water, &state.dissolved, &state.evaporated};
}

// The runner's state as the model's, each value converted by `convert`.
template <class Real, class Convert>
DissolutionState<Real> model_state(const State& state, const std::string& unit, Convert convert) {
  DissolutionState<Real> model;
  const auto grids = grids_of(model);
  for (std::size_t field = 0; field < grids.size(); ++field) {
    Grid<Real>& grid = *grids[field];
    grid = state.grid.blank<Real>(Real(0), unit);
    for (std::size_t cell = 0; cell < grid.size(); ++cell) grid.values[cell] = convert(state.fields[field][cell]);
  }
  return model;
}

// The model's state as the runner's, each value converted by `convert`.
template <class Real, class Convert>
State runner_state(DissolutionState<Real> model, Convert convert) {
  State state{StateGrid::of(model.terrain), {}};
  for (const Grid<Real>* grid : grids_of(model)) {
    std::vector<double> values(grid->size());
    std::transform(grid->values.begin(), grid->values.end(), values.begin(), convert);
    state.fields.push_back(std::move(values));
  }
  return state;
}

template <class Real>
DissolutionState<Real> model_state(const State& state, const std::string& unit) {
  return model_state<Real>(state, unit, [](double value) { return static_cast<Real>(value); });
}

template <class Real>
State runner_state(const DissolutionState<Real>& model) {
  return runner_state(model, [](Real value) { return static_cast<double>(value); });
}

// ref<Real> as a stepper.
template <class Real>
class DissolutionReferenceStepper : public Stepper {
 public:
  DissolutionReferenceStepper(const DissolutionConstants& constants, std::string unit)
      : constants_(constants), unit_(std::move(unit)) {}
  void set_state(const State& state, int) override { state_ = model_state<Real>(state, unit_); }
  void update(int count) override { state_ = reference::dissolution_erosion(state_, constants_, count); }
  State get_state() override { return runner_state(state_); }

 private:
  DissolutionConstants constants_;
  std::string unit_;
  DissolutionState<Real> state_;
};

class DissolutionGpuStepper : public Stepper {
 public:
  DissolutionGpuStepper(const StateGrid& grid, const DissolutionConstants& constants, std::string unit)
      : erosion_(grid.width, grid.height, constants), unit_(std::move(unit)) {}
  void set_state(const State& state, int) override { erosion_.load(model_state<float>(state, unit_)); }
  void update(int count) override { erosion_.step(count); }
  State get_state() override { return runner_state(erosion_.result()); }

 private:
  gpu::DissolutionErosion erosion_;
  std::string unit_;
};

// What the bounds and ledgers need to know of the run before it starts, in double.
struct RunScales {
  double water_handled = 0.0;  // Σ(d_0 + evaporated_0) + N·K_r·cells: the most water the run holds
  double material = 0.0;       // Σ(|b_0| + s_0) + 2·N·K_s·water_handled: Σ(|b| + s) never exceeds it
  double rain_total = 0.0;     // N·K_r·cells, asked
};

RunScales run_scales(const State& initial, const DissolutionParams& params) {
  RunScales scales;
  CompensatedSum water, material;
  std::size_t cells = 0;  // valid
  for (std::size_t cell = 0; cell < initial.grid.cells(); ++cell) {
    if (!initial.grid.is_valid(cell)) continue;
    ++cells;
    water.add(initial.fields[1][cell] + initial.fields[3][cell]);
    material.add(std::abs(initial.fields[0][cell]) + initial.fields[2][cell]);
  }
  scales.rain_total = params.iterations * params.rain * static_cast<double>(cells);
  scales.water_handled = water.value() + scales.rain_total;
  scales.material = material.value() + 2.0 * params.iterations * params.saturation * scales.water_handled;
  return scales;
}

// Σ over valid cells of the sum of two fields.
double total_of(const State& state, std::size_t first, std::size_t second) {
  CompensatedSum sum;
  for (std::size_t cell = 0; cell < state.grid.cells(); ++cell) {
    if (state.grid.is_valid(cell)) sum.add(state.fields[first][cell] + state.fields[second][cell]);
  }
  return sum.value();
}

// Roundings a cell's totals take per iteration (see the top of this file): material, the terrain's
// b ± c and the dissolved's s ± c and 16 exchanges (on partial sums at most twice the total);
// water, the rain's addition, the evaporated's two and 16 exchanges (again twice).
constexpr double material_roundings = 1.0 + 2.0 * (1.0 + 16.0);
constexpr double water_roundings = 1.0 + 2.0 + 2.0 * 16.0;
// The host's compensated sums of the totals.
constexpr double ledger_slack = 4.0 * unit_roundoff_double;

std::vector<LedgerTerm> dissolution_ledger(const RunScales& scales, const DissolutionParams& params) {
  const int iterations = params.iterations;
  return {
      {"mass.material_drift",
       [=](const LedgerRun& run) {
         const double drift = std::abs(total_of(run.final, 0, 2) - total_of(run.initial, 0, 2));
         const double bound = material_roundings * iterations * unit_roundoff_of(run.backend) + ledger_slack;
         return bounded_check(
             "", scales.material > 0.0 ? drift / scales.material : drift, bound, std::nullopt,
             fmt::format("|Σ(terrain + dissolved)_end − Σ(…)_0| / {:.6g} (Σ(|b_0| + s_0) + 2·N·K_s·water handled, a "
                         "bound of Σ(|b| + s) during the run); worst case of {} roundings a cell and iteration, u·{} "
                         "iterations",
                         scales.material, material_roundings, iterations));
       }},
      {"mass.water_balance",
       [=](const LedgerRun& run) {
         const double balance = total_of(run.final, 1, 3) - total_of(run.initial, 1, 3) - scales.rain_total;
         // The float twins add K_r rounded to float: at most u·K_r a cell and iteration, u of the rain.
         const double rain_rounding = run.backend == "cpu" ? 0.0 : 1.0;
         const double bound =
             (water_roundings * iterations + rain_rounding) * unit_roundoff_of(run.backend) + ledger_slack;
         return bounded_check(
             "", scales.water_handled > 0.0 ? std::abs(balance) / scales.water_handled : std::abs(balance), bound,
             std::nullopt,
             fmt::format("|Σ(water + evaporated)_end − Σ(…)_0 − rain asked| / water handled ({:.6g}; rain asked "
                         "N·K_r·cells = {:.6g}); worst case of {} roundings a cell and iteration, u·{} iterations",
                         scales.water_handled, scales.rain_total, water_roundings, iterations));
       }},
  };
}

// The shadow step's bounds: 2·width of each value of the step in rounding-interval arithmetic.
// Scales for tellability: the terrain's range, the largest water, dissolved and evaporated amounts
// one step can hold.
std::vector<ShadowBound> dissolution_bounds(const State& from, int count, const DissolutionConstants& constants,
                                            const std::string& unit) {
  double low = 0.0, high = 0.0, water = 0.0, dissolved = 0.0, evaporated = 0.0;
  bool first = true;
  for (std::size_t cell = 0; cell < from.grid.cells(); ++cell) {
    if (!from.grid.is_valid(cell)) continue;
    const double height = from.fields[0][cell];
    low = first ? height : std::min(low, height);
    high = first ? height : std::max(high, height);
    first = false;
    water = std::max(water, from.fields[1][cell]);
    dissolved = std::max(dissolved, from.fields[2][cell]);
    evaporated = std::max(evaporated, from.fields[3][cell]);
  }
  const double wettest = water + constants.rain;
  const std::array<double, 4> scales{high - low, wettest, dissolved + constants.saturation * wettest,
                                     evaporated + wettest};
  std::vector<ShadowBound> bounds;
  if (count > 1) {
    for (double scale : scales) {
      bounds.push_back({.scale = scale, .graded = false,
                        .why_not_graded = "over several steps a neighbour that changes side of level (Δh > 0) by an "
                                          "ulp in one twin reroutes its share; the one-step shadow is graded"});
    }
    return bounds;
  }
  const auto interval = [](double value) { return RoundingInterval::exact(value); };
  const auto stepped =
      reference::dissolution_erosion(model_state<RoundingInterval>(from, unit, interval), constants, count);
  // The interval holds the exact step and ref<float>'s; a candidate no less accurate lies within
  // its width too, so the two lie within twice the width.
  const State widths = runner_state(stepped, [](const RoundingInterval& value) { return 2.0 * value.width(); });
  for (std::size_t field = 0; field < widths.fields.size(); ++field) {
    bounds.push_back({.per_value = widths.fields[field], .scale = scales[field],
                      .model = "the step in rounding-interval arithmetic from that state, 2·width per value "
                               "(core/rounding_interval.hpp)"});
  }
  return bounds;
}

// One iteration of Beneš's model from `state`, written on the host from the thesis's equations
// apart from both twins: eq. 2.5 as one signed change (s − S), evaporation and eq. 2.9's levelled
// water ŵ as printed (or the mean surface of the cell and its lower neighbours, mean_level), the
// exchange scattered from each giver to its receivers.
DissolutionState<double> spec_iteration(const DissolutionState<double>& state, const DissolutionParams& params) {
  DissolutionState<double> local = state;
  const double retained = std::exp(-params.evaporation);
  for (std::size_t cell = 0; cell < state.terrain.size(); ++cell) {
    if (!state.terrain.is_valid(cell)) continue;
    const double rained = state.water.values[cell] + params.rain;                              // eq. 2.1
    const double decayed = rained * retained;                                                  // eq. 2.2
    const double left = decayed < params.evaporation_threshold ? 0.0 : decayed - params.evaporation_threshold;  // 2.3
    local.water.values[cell] = left;
    local.evaporated.values[cell] = state.evaporated.values[cell] + (rained - left);
    const double excess = state.dissolved.values[cell] - params.saturation * left;  // s − S, eqs. 2.4-2.5
    const double rate = excess < 0.0 ? params.dissolution_rate : params.deposition_rate;
    local.terrain.values[cell] = state.terrain.values[cell] + rate * excess;
    local.dissolved.values[cell] = state.dissolved.values[cell] - rate * excess;
  }
  DissolutionState<double> after = local;
  const Grid<double>& terrain = local.terrain;
  for (int y = 0; y < terrain.height; ++y) {
    for (int x = 0; x < terrain.width; ++x) {
      const std::size_t cell = terrain.index(x, y);
      const double b = terrain.values[cell], w = local.water.values[cell];
      if (!terrain.is_valid(cell) || !(w > 0.0)) continue;
      std::vector<std::pair<std::size_t, double>> lower;  // receivers and their Δh (eq. 2.7)
      double fall_sum = 0.0, levelled_sum = 0.0, surfaces = b + w;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx == 0 && dy == 0) || !terrain.inside(x + dx, y + dy) || !terrain.is_valid(x + dx, y + dy)) continue;
          const std::size_t other = terrain.index(x + dx, y + dy);
          const double b_other = terrain.values[other], w_other = local.water.values[other];
          const double fall = (b + w) - (b_other + w_other);  // Δh = h − h' with h = b + d (eq. 2.6)
          if (!(fall > 0.0)) continue;
          const double level = (b + w + b_other + w_other) / 2.0 - b;  // ŵ, eq. 2.9
          lower.emplace_back(other, fall);
          fall_sum += fall;
          levelled_sum += level < 0.0 ? w : w - level;
          surfaces += b_other + w_other;
        }
      }
      // pairwise: eq. 2.9's moves summed; mean_level: down to the mean surface h̄ of the cell and
      // its lower neighbours.
      const double mean_surface = surfaces / static_cast<double>(lower.size() + 1);
      const double wanted = params.water_share == DissolutionShare::pairwise ? levelled_sum : (b + w) - mean_surface;
      const double given = std::min(w, wanted);
      for (const auto& [other, fall] : lower) {
        const double sent = given * fall / fall_sum;  // eq. 2.8
        const double material = local.dissolved.values[cell] * sent / w;
        after.water.values[cell] -= sent;
        after.water.values[other] += sent;
        after.dissolved.values[cell] -= material;
        after.dissolved.values[other] += material;
      }
    }
  }
  return after;
}

// The spec's tolerance against ref<double>, per value: each side forms a cell's value from its own
// state with at most 16 exchanges, each a handful of operations on numbers no larger than the
// largest |terrain| plus nine cells' water and dissolved material (eq. 2.9's ŵ subtracts the
// terrain), rounded by u each: 2 sides · 16 · 32 operations · u · that magnitude.
double spec_tolerance(const DissolutionState<double>& state, const DissolutionParams& params) {
  double terrain = 0.0, water = 0.0, dissolved = 0.0, evaporated = 0.0;
  for (std::size_t cell = 0; cell < state.terrain.size(); ++cell) {
    if (!state.terrain.is_valid(cell)) continue;
    terrain = std::max(terrain, std::abs(state.terrain.values[cell]));
    water = std::max(water, state.water.values[cell] + params.rain);
    dissolved = std::max(dissolved, state.dissolved.values[cell] + params.saturation * water);
    evaporated = std::max(evaporated, state.evaporated.values[cell]);
  }
  const double magnitude = terrain + evaporated + 9.0 * (water + dissolved);
  return 2.0 * 16.0 * 32.0 * unit_roundoff_double * magnitude;
}

constexpr int spec_start = 10;

CaseRun spec_step_check(std::shared_ptr<const State> initial, DissolutionParams params, DissolutionConstants constants,
                        std::string unit) {
  return [=](const nlohmann::json&, const RunOptions&, CaseResult& result) {
    if (params.iterations < 1) return;
    const int from = std::min(params.iterations - 1, spec_start);
    const auto start = reference::dissolution_erosion(model_state<double>(*initial, unit), constants, from);
    const State spec = runner_state(spec_iteration(start, params));
    const State twin = runner_state(reference::dissolution_erosion(start, constants, 1));
    const double tolerance = spec_tolerance(start, params);
    const StateDecl fields = dissolution_fields(unit);
    for (std::size_t field = 0; field < fields.size(); ++field) {
      double worst = 0.0;
      for (std::size_t cell = 0; cell < spec.grid.cells(); ++cell) {
        if (spec.grid.is_valid(cell)) worst = std::max(worst, std::abs(spec.fields[field][cell] - twin.fields[field][cell]));
      }
      result.checks.push_back(bounded_check(
          fmt::format("spec.step.{}.cpu", fields[field].name), worst, tolerance, std::nullopt,
          fmt::format("largest |ref<double> − spec| over the cells, iteration {} from ref<double>'s own state (the spec: "
                      "eqs. 2.1-2.9 on the host, ŵ as printed, scattered); 2·16·32·u·(max|b| + max evaporated + "
                      "9·(max d + max s))",
                      from + 1)));
    }
  };
}

PreparedTwin prepare_dissolution(const nlohmann::json& resolved, const Heightmap& input) {
  if (input.size() == 0) throw InputError("erosion.dissolution erodes a heightmap: the case needs an input");
  const DissolutionParams params = dissolution_params_from_json(resolved);
  const DissolutionConstants constants = dissolution_constants(params);
  const std::string unit = input.vertical_unit;
  Grid<double> zero = input;
  std::fill(zero.values.begin(), zero.values.end(), 0.0);
  auto initial = std::make_shared<const State>(
      State{StateGrid::of(input), {input.values, zero.values, zero.values, zero.values}});
  SteppedTwin twin{.algorithm = "erosion.dissolution",
                   .fields = dissolution_fields(unit),
                   .initial = *initial,
                   .iterations = params.iterations};
  twin.reference_double = [=] { return std::make_unique<DissolutionReferenceStepper<double>>(constants, unit); };
  twin.reference_float = [=] { return std::make_unique<DissolutionReferenceStepper<float>>(constants, unit); };
  twin.make_gpu = [=, grid = initial->grid]() -> std::unique_ptr<Stepper> {
    return std::make_unique<DissolutionGpuStepper>(grid, constants, unit);
  };
  twin.shadow_bounds = [=](const State& from, int count) { return dissolution_bounds(from, count, constants, unit); };
  twin.ledger = dissolution_ledger(run_scales(*initial, params), params);
  return {.kind = std::move(twin), .extra_checks = spec_step_check(initial, params, constants, unit)};
}

}  // namespace

Algorithm dissolution_algorithm() {
  return {.name = "erosion.dissolution",
          .summary = "dissolution erosion: rain dissolves the ground, slow water carries it to rest (Beneš 2002)",
          .source = "seed 000 §2.3, eqs. 2.1-2.9 (digest 000 §3.3)",
          .params = &dissolution_param_specs(),
          .prepare = [](const nlohmann::json& resolved, const LoadedInput& input) {
            return prepare_dissolution(resolved, input.heights);
          },
          .kind = CaseKind::stepped,
          // Counted in reference/erosion/dissolution.cpp and gpu/erosion/dissolution.cpp.
          .traffic = {.cpu = 240.0, .gpu = 132.0},
          .expect_shape = stepped_spec_shape(),
          // Measured 1406 B a cell (1024² vs 256², 64 iterations, both backends, 8 shadow checkpoints).
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 1450 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
