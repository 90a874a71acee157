// spec.step.*.cpu: ref<double>'s step against the host spec (see pipe_spec_check.hpp).
#include "compare/checks/pipe_spec_check.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "compare/algorithms/pipe_spec.hpp"
#include "compare/checks/threshold.hpp"
#include "core/rounding_interval.hpp"
#include "reference/erosion/pipes.hpp"

namespace gt {

namespace {

constexpr double double_per_float_unit = 0x1p-29;

// The value farthest beyond its bound (or nearest to it) so far.
struct SpecWorst {
  double distance = 0.0;
  double bound = 0.0;
  double ratio = -1.0;
  double truth = 0.0;
  double spec = 0.0;
  std::size_t value = 0;  // the value's index: cell, or cell·pipes + pipe
};

void keep_worst(SpecWorst& worst, std::size_t value, double truth, const RoundingInterval& spec,
                const RoundingInterval& truth_interval) {
  const double distance = std::abs(truth - spec.value);
  const double bound = double_per_float_unit * (spec.width() + truth_interval.width());
  const double ratio =
      distance == 0.0 ? 0.0 : (distance <= bound ? distance / bound : std::numeric_limits<double>::infinity());
  if (ratio > worst.ratio || (ratio == worst.ratio && distance > worst.distance)) {
    worst = {distance, bound, ratio, truth, spec.value, value};
  }
}

Check spec_step_field(const std::string& field, const SpecWorst& worst, int width, int components, int step) {
  const std::size_t cell = worst.value / static_cast<std::size_t>(components);
  const std::size_t columns = static_cast<std::size_t>(width);
  const std::string where =
      components == 1 ? fmt::format("cell (x={}, y={})", cell % columns, cell / columns)
                      : fmt::format("cell (x={}, y={}) pipe {}", cell % columns, cell / columns,
                                    pipe_name(static_cast<int>(worst.value % static_cast<std::size_t>(components))));
  return bounded_check(
      fmt::format("spec.step.{}.cpu", field), worst.distance, worst.bound, std::nullopt,
      fmt::format("ref<double>'s step {} against the host spec of one step (compare/algorithms/pipe_spec.hpp), "
                  "worst at {}: {:.17g} where the spec gives {:.17g}; bound there: both steps' rounding-interval "
                  "widths at double's unit (2^-29 of float's)",
                  step, where, worst.truth, worst.spec));
}

}  // namespace

std::vector<Check> pipe_spec_checks(const PipeState<double>& start, const PipeConstants& constants,
                                    const HydraulicParams& params, const HydraulicForcing& forcing, int step) {
  reference::PipeErosion<double> truth(start, constants, forcing);
  truth.step();
  const auto exact = [](double value) { return RoundingInterval::exact(value); };
  const PipeState<RoundingInterval> exact_start = map_pipe_state<RoundingInterval>(start, exact);
  reference::PipeErosion<RoundingInterval> truth_interval(exact_start, constants, forcing);
  truth_interval.step();
  const PipeState<RoundingInterval> spec = pipe_spec_step(exact_start, params, forcing);

  std::vector<Check> checks;
  const auto& terrain = truth.state().terrain;
  const auto grade_grid = [&](const std::string& field, auto grid_of) {
    SpecWorst worst;
    for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
      if (!terrain.is_valid(cell)) continue;
      keep_worst(worst, cell, grid_of(truth.state()).values[cell], grid_of(spec).values[cell],
                 grid_of(truth_interval.state()).values[cell]);
    }
    checks.push_back(spec_step_field(field, worst, terrain.width, 1, step));
  };
  grade_grid("terrain", [](const auto& state) -> const auto& { return state.terrain; });
  grade_grid("water", [](const auto& state) -> const auto& { return state.water; });
  grade_grid("sediment", [](const auto& state) -> const auto& { return state.sediment; });
  if (params.regolith_depth > 0.0) grade_grid("regolith", [](const auto& state) -> const auto& { return state.regolith; });
  for (std::size_t k = 0; k < static_cast<std::size_t>(params.layers); ++k) {
    grade_grid(fmt::format("layer_{}", k + 1), [k](const auto& state) -> const auto& { return state.layers[k]; });
  }
  grade_grid("velocity_x", [](const auto& state) -> const auto& { return state.velocity_x; });
  grade_grid("velocity_y", [](const auto& state) -> const auto& { return state.velocity_y; });
  SpecWorst outflow;
  const auto pipes = static_cast<std::size_t>(params.pipe_count);
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    if (!terrain.is_valid(cell)) continue;
    for (std::size_t k = 0; k < pipes; ++k) {
      keep_worst(outflow, cell * pipes + k, truth.state().outflow[cell][k], spec.outflow[cell][k],
                 truth_interval.state().outflow[cell][k]);
    }
  }
  checks.push_back(spec_step_field("outflow", outflow, terrain.width, params.pipe_count, step));
  return checks;
}

}  // namespace gt
