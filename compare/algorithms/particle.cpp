// The driver's view of seed 000's particle (droplet) erosion: parameters to constants, the twins
// (reference/erosion/particle.hpp, gpu/erosion/particle.hpp) as a droplet twin
// (compare/droplet_twin.hpp: ledger, orderings, race statistics, pictures), the hand-derived
// droplets of a case (spec.droplet.*) and the performance rows beside the thesis's Table 5.1.
#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/case_descriptors.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/droplet_twin.hpp"
#include "core/errors.hpp"
#include "core/params/particle.hpp"
#include "core/params/thermal.hpp"
#include "gpu/erosion/particle.hpp"
#include "reference/erosion/particle.hpp"

namespace gt {
namespace {

// The GPU object lives as long as the runner's closures.
GpuFieldRunner particle_runner(std::shared_ptr<gpu::ParticleErosion> gpu) {
  return {[gpu](const Grid<float>& heights) { gpu->load(heights); }, [gpu] { gpu->run(); },
          [gpu] { return gpu->result(); }, [gpu](int, int count) { gpu->step(count); }};
}

ParticleConstants with_setup(ParticleConstants constants, DropletSetup setup) {
  constants.spacing = setup.spacing;
  constants.ordering = setup.ordering;
  return constants;
}

// The references' ordering: the sequential truth unless batch.
DropletOrdering reference_ordering(DropletOrdering ordering) {
  return ordering == DropletOrdering::batch ? DropletOrdering::batch : DropletOrdering::race;
}

DropletTwin particle_twin(const Heightmap& input, const ParticleConstants& constants) {
  DropletTwin twin;
  twin.algorithm = "erosion.particle";
  twin.input = input;
  twin.setup = {constants.spacing, constants.ordering};
  twin.iterations = constants.iterations;
  twin.lifetime = constants.lifetime;
  twin.roundings_per_step = 7.0;  // 4 corner stores + 1 deposit + 2 sediment updates
  twin.writes_per_step = 5.0;     // 4 corners + the deposit texel
  twin.reference_double = [constants](const Grid<double>& heights, int iterations, DropletSetup setup) {
    return reference::particle_erosion(heights, with_setup(constants, setup), iterations,
                                       reference_ordering(setup.ordering));
  };
  twin.reference_float = [constants](const Grid<float>& heights, int iterations, DropletSetup setup) {
    return reference::particle_erosion(heights, with_setup(constants, setup), iterations,
                                       reference_ordering(setup.ordering));
  };
  twin.make_gpu = [constants, width = input.width, height = input.height](DropletSetup setup) {
    return particle_runner(std::make_shared<gpu::ParticleErosion>(width, height, with_setup(constants, setup)));
  };
  return twin;
}

struct ParticleScenario {
  DropletTwin twin;
  ParticleConstants constants;
};

ParticleScenario make_scenario(const nlohmann::json& resolved, const Heightmap& given) {
  if (given.size() == 0) throw InputError("erosion.particle erodes a heightmap: the case needs an input");
  check_finite(given, "erosion.particle input");
  check_fits_float(given, "erosion.particle input");
  const bool normalised = resolved.at("normalised").get<bool>();
  const Heightmap input = normalised ? normalise_heights(given) : given;
  ParticleScenario scenario{{}, particle_constants(resolved, input)};
  const auto& c = scenario.constants;
  scenario.twin = particle_twin(input, c);
  set_droplet_input(scenario.twin, given, normalised);
  auto& notes = scenario.twin.notes;
  if (given.has_mask()) {
    notes.push_back("no-data cells behave as outside the grid: they read 0 and writes to them are lost (Hydra's "
                    "empty regions); the ledger counts what crosses them");
  }
  notes.push_back(fmt::format(
      "ordering {}: {} droplets per pass, {} passes per iteration, lifetime {}; batch quantum {:.6g}",
      droplet_ordering_name(c.ordering),
      static_cast<long long>((given.width + c.spacing - 1) / c.spacing) * ((given.height + c.spacing - 1) / c.spacing),
      c.spacing * c.spacing, c.lifetime, c.quantum));
  for (auto& warning : particle_warnings(c)) notes.push_back(std::move(warning));
  return scenario;
}

// A hand-derived trajectory in the case: {"droplet": {"start": [x, y], "positions": [[x, y], ...],
// "sediment": s, "cells": [[x, y, h], ...], "tolerance": t}} on the case's input, ref<double>.
void add_droplet_spec(const ParticleScenario& scenario, const nlohmann::json& expect, CaseResult& result) {
  if (!expect.is_object() || !expect.contains("droplet")) return;
  const auto& spec = expect["droplet"];
  Heightmap heights = scenario.twin.input;
  const auto path = reference::run_one_droplet(heights, scenario.constants, spec.at("start")[0].get<int>(),
                                               spec.at("start")[1].get<int>());
  const double tolerance = spec.at("tolerance");
  const auto& positions = spec.at("positions");
  double position_error = positions.size() == path.positions.size() ? 0.0 : INFINITY;
  for (std::size_t k = 0; k < std::min(positions.size(), path.positions.size()); ++k) {
    position_error = std::max({position_error, std::abs(path.positions[k].first - positions[k][0].get<double>()),
                               std::abs(path.positions[k].second - positions[k][1].get<double>())});
  }
  double cell_error = 0.0;
  for (const auto& cell : spec.at("cells")) {
    cell_error = std::max(cell_error, std::abs(heights.at(cell[0], cell[1]) - cell[2].get<double>()));
  }
  const std::string why = fmt::format("tolerance {:g}: the hand derivation's decimals against double roundings", tolerance);
  result.checks.push_back(bounded_check("spec.droplet.positions.cpu", position_error, tolerance, std::nullopt,
                                        "largest coordinate error over the droplet's positions (count must match); " + why));
  result.checks.push_back(bounded_check("spec.droplet.sediment.cpu",
                                        std::abs(path.sediment - spec.at("sediment").get<double>()), tolerance,
                                        std::nullopt, "sediment carried at the end of its life; " + why));
  result.checks.push_back(bounded_check("spec.droplet.cells.cpu", cell_error, tolerance, std::nullopt,
                                        "heights after its life at the listed texels; " + why));
}

// Hydra's Table 5.1 (digest 000 §6.2): total time of 50 iterations at spacing 4, lifetime 50.
struct PublishedTiming {
  const char* device;
  int size;
  double ms_for_50_iterations;
};
constexpr PublishedTiming hydra_table_5_1[] = {
    {"NVIDIA RTX 3080 12GB", 128, 3},     {"NVIDIA RTX 3080 12GB", 256, 9},   {"NVIDIA RTX 3080 12GB", 512, 20},
    {"NVIDIA RTX 3080 12GB", 1024, 72},   {"NVIDIA GTX 745 4GB", 128, 38},    {"NVIDIA GTX 745 4GB", 256, 172},
    {"NVIDIA GTX 745 4GB", 512, 804},     {"NVIDIA GTX 745 4GB", 1024, 3575}};
// The thesis measured up to 1024²; the sequential reference takes seconds an iteration there.
constexpr int largest_benchmark_side = 1024;

BenchmarkRow published_row(const PublishedTiming& published) {
  const double ms = published.ms_for_50_iterations / 50.0;
  const double steps = double(published.size) * published.size * 50;  // every droplet its whole life, as quoted
  BenchmarkRow row{.algorithm = "erosion.particle", .backend = "published", .size = published.size,
                   .iterations = 1, .reps = 0, .median_ms = ms,
                   .device = fmt::format("{} (Hydra, thesis Table 5.1)", published.device)};
  row.mcell_iterations_per_s = double(published.size) * published.size / (ms * 1e-3) / 1e6;
  row.detail = fmt::format("race droplets (Hydra's fragment shader), total of 50 iterations / 50; {:.3g} droplet "
                           "steps/s if every droplet lives 50 steps",
                           steps / (ms * 1e-3));
  return row;
}

// A noisy cone normalised to [0, 1] with Hydra's defaults at spacing 4.
std::vector<BenchmarkRow> benchmark_particle(const BenchmarkOptions& options, bool gpu_available,
                                             const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  for (const int size : options.sizes) {
    if (size > largest_benchmark_side) continue;
    const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                  {"peak", 30.0}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap field = normalise_heights(load_input(input, nullptr, {}).heights);
    const auto resolved = resolve_params("erosion.particle", particle_param_specs(), {{"iterations", 1}});
    for (auto& row : droplet_benchmark_rows(particle_twin(field, particle_constants(resolved, field)), options.reps,
                                            gpu_available, environment)) {
      rows.push_back(std::move(row));
    }
  }
  for (const auto& published : hydra_table_5_1) {
    if (std::find(options.sizes.begin(), options.sizes.end(), published.size) != options.sizes.end()) {
      rows.push_back(published_row(published));
    }
  }
  return rows;
}

PreparedTwin prepare_particle(const nlohmann::json& resolved, const LoadedInput& input) {
  PreparedTwin prepared;
  prepared.run = [scenario = make_scenario(resolved, input.heights)](const nlohmann::json& expect,
                                                                     const RunOptions& options, CaseResult& result) {
    run_droplet_case(scenario.twin, expect, options, result);
    add_droplet_spec(scenario, expect, result);
  };
  return prepared;
}

nlohmann::json particle_expect_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape["droplet"] = {{"start", nullptr}, {"positions", nullptr}, {"sediment", nullptr}, {"cells", nullptr},
                      {"tolerance", nullptr}};
  return shape;
}

}  // namespace

Algorithm particle_algorithm() {
  return {.name = "erosion.particle",
          .summary = "droplet water erosion (Hydra's kernel), sequential, racing, disjoint or batch droplets",
          .source = "seed 000 §4.4.1, Algorithms 4-7, eqs. 4.5-4.6, Appendix A (digest 000 §4.4)",
          .params = &particle_param_specs(),
          .prepare = prepare_particle,
          .iterates = false,
          .has_field_twin = false,
          .benchmark = benchmark_particle,
          .expect_shape = particle_expect_shape(),
          // Estimated, not yet measured: the input and ref<double> with its two side maps (5 doubles),
          // ref<float> with up to 16 checkpoint states and the GPU's copies (about 30 floats), the
          // difference and change maps of the checks (6 doubles), the descriptors.
          .memory = [](const nlohmann::json&, const LoadedInput& input) {
            return memory_for(static_cast<double>(input.heights.size()), "cells", 300 + descriptor_bytes_per_cell);
          }};
}

}  // namespace gt
