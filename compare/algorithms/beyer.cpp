// The driver's view of Beyer 2015's droplet erosion (seed 000 §2.7): parameters to constants and
// the twins (reference/erosion/beyer.hpp, gpu/erosion/beyer.hpp) as a droplet twin
// (compare/droplet_twin.hpp: ledger, orderings, race statistics, pictures, performance rows). The
// brush weights of eq. 2.42 (Fig. 2.10) and a hand-derived step are the spec vectors of
// tests/beyer_test.cpp.
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/droplet_twin.hpp"
#include "core/errors.hpp"
#include "core/params/beyer.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/beyer.hpp"
#include "reference/erosion/beyer.hpp"

namespace gt {
namespace {

// The GPU object lives as long as the runner's closures.
GpuFieldRunner beyer_runner(std::shared_ptr<gpu::BeyerErosion> gpu) {
  return {[gpu](const Grid<float>& heights) { gpu->load(heights); }, [gpu] { gpu->run(); },
          [gpu] { return gpu->result(); }, [gpu](int, int count) { gpu->step(count); }};
}

BeyerConstants with_setup(BeyerConstants constants, DropletSetup setup) {
  constants.spacing = setup.spacing;
  constants.ordering = setup.ordering;
  return constants;
}

// The brush's samples within the radius: at most (2·ceil(r) + 1)².
double brush_samples(const BeyerConstants& constants) {
  const double side = 2.0 * std::ceil(constants.radius) + 1.0;
  return side * side;
}

DropletTwin beyer_twin(const Heightmap& input, const BeyerConstants& constants) {
  DropletTwin twin;
  twin.algorithm = "erosion.beyer";
  twin.input = input;
  twin.setup = {constants.spacing, constants.ordering};
  twin.iterations = constants.iterations;
  twin.lifetime = constants.lifetime;
  // A step erodes with the brush (a store and a sediment update per sample) or deposits on 4
  // samples (a store each, one sediment update): each sample, a distinct cell, written once.
  twin.roundings_per_step = 2.0 * brush_samples(constants);
  twin.writes_per_cell_per_step = 1.0;
  twin.reference_double = [constants](const Grid<double>& heights, int iterations, DropletSetup setup) {
    return reference::beyer_erosion(heights, with_setup(constants, setup), iterations,
                                    reference_ordering(setup.ordering));
  };
  twin.reference_float = [constants](const Grid<float>& heights, int iterations, DropletSetup setup) {
    return reference::beyer_erosion(heights, with_setup(constants, setup), iterations,
                                    reference_ordering(setup.ordering));
  };
  twin.make_gpu = [constants, width = input.width, height = input.height](DropletSetup setup) {
    return beyer_runner(std::make_shared<gpu::BeyerErosion>(width, height, with_setup(constants, setup)));
  };
  return twin;
}

DropletTwin make_twin(const nlohmann::json& resolved, const Heightmap& given) {
  if (given.size() == 0) throw InputError("erosion.beyer erodes a heightmap: the case needs an input");
  check_finite(given, "erosion.beyer input");
  check_fits_float(given, "erosion.beyer input");
  const bool normalised = resolved.at("normalised").get<bool>();
  const Heightmap input = normalised ? normalise_heights(given) : given;
  const BeyerConstants c = beyer_constants(resolved, input);
  DropletTwin twin = beyer_twin(input, c);
  set_droplet_input(twin, given, normalised);
  if (given.has_mask()) {
    twin.notes.push_back("a droplet whose cell touches a no-data sample has left the map: it ends and its sediment "
                         "leaves with it; the brush skips no-data samples");
  }
  twin.notes.push_back(fmt::format(
      "ordering {}: {} droplets per pass, {} passes per iteration, lifetime {}, brush radius {}, speed rule {}; "
      "batch quantum {:.6g}",
      droplet_ordering_name(c.ordering),
      static_cast<long long>((given.width + c.spacing - 1) / c.spacing) * ((given.height + c.spacing - 1) / c.spacing),
      c.spacing * c.spacing, c.lifetime, c.radius, beyer_speed_rule_name(c.speed_rule), c.quantum));
  if (c.speed_rule == BeyerSpeedRule::physical) {
    twin.notes.push_back("speed rule physical: without friction a droplet speeds up on every downhill step and its "
                         "capacity with it; expect the terrain to run away over several iterations");
  }
  return twin;
}

PreparedTwin prepare_beyer(const nlohmann::json& resolved, const LoadedInput& input) {
  PreparedTwin prepared;
  prepared.kind = CaseRun([twin = make_twin(resolved, input.heights)](const nlohmann::json& expect, const RunOptions& options,
                                                            CaseResult& result) {
    run_droplet_case(twin, expect, options, result);
  });
  return prepared;
}

// A noisy cone normalised to [0, 1] with the defaults at spacing 4, up to 1024² (as Hydra's rows).
std::vector<BenchmarkRow> benchmark_beyer(const BenchmarkOptions& options, bool gpu_available,
                                          const Environment& environment) {
  constexpr int largest_side = 1024;
  std::vector<BenchmarkRow> rows;
  for (const int size : options.sizes) {
    if (size > largest_side) continue;
    const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                  {"peak", 30.0}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap field = normalise_heights(load_input(input, nullptr, {}).heights);
    const auto resolved = resolve_params("erosion.beyer", beyer_param_specs(), {{"iterations", 1}});
    for (auto& row : droplet_benchmark_rows(beyer_twin(field, beyer_constants(resolved, field)), options.reps,
                                            gpu_available, environment)) {
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace

Algorithm beyer_algorithm() {
  return {.name = "erosion.beyer",
          .summary = "droplet erosion with inertia, capacity, a radius brush and evaporation (Beyer 2015)",
          .source = "seed 000 §2.7, eqs. 2.35-2.45 (digest 000 §3.7, Appendix B item 6)",
          .params = &beyer_param_specs(),
          .prepare = prepare_beyer,
          .kind = CaseKind::custom,
          .benchmark = benchmark_beyer,
          .expect_shape = descriptor_expect_shape(),
          // As erosion.particle's without colour and flow map: the same grids are kept; measured within
          // this by tests/memory_estimates_test.cpp at 768².
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 300 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
