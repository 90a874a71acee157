// The driver's view of the two thermal-erosion models: parameters to constants, the three
// versions (ref<double>, ref<float>, GPU) as steppable field twins, the error model's count of
// rounded additions, and each model's first iteration written on the host as a spec of the
// transfer (the ledger mass.moved_first_iteration.cpu of compare/field_twin.cpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/threshold.hpp"
#include "core/errors.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"

namespace gt {
namespace {

// The GPU object lives as long as the runner's closures.
GpuFieldRunner field_runner(std::shared_ptr<gpu::ThermalErosion> gpu) {
  return {[gpu](const Grid<float>& heights) { gpu->load(heights); }, [gpu] { gpu->run(); },
          [gpu] { return gpu->result(); }, [gpu](int first, int count) { gpu->step(first, count); }};
}

GpuFieldRunner field_runner(std::shared_ptr<gpu::ThermalJakoErosion> gpu) {
  return {[gpu](const Grid<float>& heights) { gpu->load(heights); }, [gpu] { gpu->run(); },
          [gpu] { return gpu->result(); }, [gpu](int, int count) { gpu->step(count); }};
}

// For the specs below, written here apart from either twin: a pipe's offset to its neighbour, and
// whether a cell takes part (inside the grid and not masked).
struct Offset {
  int dx;
  int dy;
};

bool takes_part(const Grid<double>& heights, int x, int y) { return heights.inside(x, y) && heights.is_valid(x, y); }

// Seed 000's first iteration (Algorithms 9-11) on the host in double, visiting each pair of
// neighbours once (the twins visit each cell's four pipes): requests by Algorithm 10, then across
// each pipe the smaller of two opposite requests moves (Algorithm 11). Iteration 0 uses the
// cardinal pipes unless the neighbourhood is diagonal.
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

// Jákó & Tóth's first iteration (eqs. 2.30-2.34 as decided in reference/erosion/thermal_jako.cpp)
// on the host in double, sending each outflow to its neighbour as it is computed: A = the lower
// neighbours beyond T·l, ΔS = rate·H/2 with H the largest drop in A, shared by the drops.
Grid<double> jako_first_iteration(const Grid<double>& heights, const ThermalConstants& constants) {
  const std::array<Offset, 8> offsets{{{-1, 0}, {0, 1}, {1, 0}, {0, -1}, {-1, -1}, {-1, 1}, {1, 1}, {1, -1}}};
  Grid<double> after = heights;
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      if (!heights.is_valid(x, y)) continue;
      std::array<double, 8> drop{};
      for (int k = 0; k < 8; ++k) {
        const int nx = x + offsets[k].dx, ny = y + offsets[k].dy;
        if (!takes_part(heights, nx, ny)) continue;
        const double length = k >= 4 ? constants.length_diagonal : (k % 2 == 0 ? constants.length_x : constants.length_y);
        const double fall = heights.at(x, y) - heights.at(nx, ny);
        if (fall > constants.talus_slope * length) drop[k] = fall;
      }
      const double drop_sum = drop[0] + drop[1] + drop[2] + drop[3] + drop[4] + drop[5] + drop[6] + drop[7];
      if (drop_sum <= 0.0) continue;
      const double sent = constants.request_factor * *std::max_element(drop.begin(), drop.end()) / 2.0;
      for (int k = 0; k < 8; ++k) {
        const double share = sent * drop[k] / drop_sum;
        after.at(x, y) -= share;
        if (drop[k] > 0.0) after.at(x + offsets[k].dx, y + offsets[k].dy) += share;
      }
    }
  }
  return after;
}

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

PreparedTwin prepare_thermal(const nlohmann::json& resolved, const Heightmap& input) {
  require_heightmap(input, "erosion.thermal");
  const ThermalParams params = thermal_params_from_json(resolved);
  PreparedTwin prepared;
  prepared.input = params.normalised ? normalise_heights(input) : input;
  const ThermalConstants constants = thermal_constants(params, input);
  FieldTwin& twin = prepared.twin;
  twin.reference_double = [=](const Grid<double>& field) {
    return reference::thermal_erosion(field, constants, params.iterations, params.neighbourhood);
  };
  twin.reference_float = [=](const Grid<float>& field) {
    return reference::thermal_erosion(field, constants, params.iterations, params.neighbourhood);
  };
  twin.make_gpu = [=, width = input.width, height = input.height] {
    return field_runner(std::make_shared<gpu::ThermalErosion>(width, height, constants, params.neighbourhood,
                                                              params.iterations));
  };
  constexpr double additions_per_iteration = 4.0;  // one per pipe (Algorithm 11)
  twin.additions_per_cell = additions_per_iteration * params.iterations;
  twin.stepping = FieldTwin::Stepping{
      .iterations = params.iterations,
      .additions_per_iteration = additions_per_iteration,
      .reference_double = [=](const Grid<double>& state, int first, int count) {
        return reference::thermal_erosion(state, constants, count, params.neighbourhood, first);
      },
      .reference_float = [=](const Grid<float>& state, int first, int count) {
        return reference::thermal_erosion(state, constants, count, params.neighbourhood, first);
      },
      .first_iteration_spec = [=](const Grid<double>& heights) {
        return hydra_first_iteration(heights, constants, params.neighbourhood);
      }};
  prepared.extra_checks = add_talus_spec;
  return prepared;
}

PreparedTwin prepare_thermal_jako(const nlohmann::json& resolved, const Heightmap& input) {
  require_heightmap(input, "erosion.thermal_jako");
  const ThermalJakoParams params = thermal_jako_params_from_json(resolved);
  const ThermalConstants constants = thermal_jako_constants(params, input);
  PreparedTwin prepared;
  prepared.input = input;
  FieldTwin& twin = prepared.twin;
  twin.reference_double = [=](const Grid<double>& field) {
    return reference::thermal_jako_erosion(field, constants, params.iterations);
  };
  twin.reference_float = [=](const Grid<float>& field) {
    return reference::thermal_jako_erosion(field, constants, params.iterations);
  };
  twin.make_gpu = [=, width = input.width, height = input.height] {
    return field_runner(std::make_shared<gpu::ThermalJakoErosion>(width, height, constants, params.iterations));
  };
  constexpr double additions_per_iteration = 16.0;  // 8 outflows subtracted, 8 inflows added
  twin.additions_per_cell = additions_per_iteration * params.iterations;
  twin.stepping = FieldTwin::Stepping{
      .iterations = params.iterations,
      .additions_per_iteration = additions_per_iteration,
      .reference_double = [=](const Grid<double>& state, int, int count) {
        return reference::thermal_jako_erosion(state, constants, count);
      },
      .reference_float = [=](const Grid<float>& state, int, int count) {
        return reference::thermal_jako_erosion(state, constants, count);
      },
      .first_iteration_spec = [=](const Grid<double>& heights) { return jako_first_iteration(heights, constants); }};
  return prepared;
}

// The field's spec vectors plus add_talus_spec's eq. 4.10 vector.
nlohmann::json talus_spec_shape() {
  nlohmann::json shape = field_spec_shape();
  shape["talus_eq_4_10"] = {{"angle", nullptr}, {"width", nullptr}, {"vertical_aspect", nullptr}, {"value", nullptr}};
  return shape;
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
          // Counted in reference/erosion/thermal.cpp and gpu/erosion/thermal.cpp.
          .traffic = {.cpu = 88.0, .gpu = 52.0},
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
            return prepare_thermal_jako(resolved, input.heights);
          },
          // Counted in reference/erosion/thermal_jako.cpp and gpu/erosion/thermal_jako.cpp.
          .traffic = {.cpu = 152.0, .gpu = 84.0},
          .expect_shape = field_spec_shape(),
          // Measured 438 B a cell (1024² vs 256², 64 iterations, both backends, 8 shadow checkpoints).
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 500 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
