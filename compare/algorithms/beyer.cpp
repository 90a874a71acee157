// `erosion.beyer`: Beyer 2015's droplet erosion (seed 000 §2.7, eqs. 2.35-2.45; digest 000 §3.7,
// Appendix B item 6): droplets with inertia, a capacity, evaporation and a radius brush (eq. 2.42).
// Parameters to constants (core/params/beyer.hpp), the twins (reference/erosion/beyer.hpp,
// gpu/erosion/beyer.hpp) as a droplet twin that the stepped runner runs (compare/droplet_twin.hpp:
// state, orderings, shadow bounds, ledger, race statistics, pictures) and the performance rows.
//
// Inputs:  a heightmap, normalised to [0, 1] as seed 000 does unless `normalised` is off.
// Outputs: the state {terrain} of each twin in the input's own heights; Hydra-style depth and
//          sediment maps of ref<double>'s run.
// Units:   heights in the input's vertical unit (the twins' normalised heights are dimensionless);
//          positions, speeds and the brush radius in samples (the cell size does not enter).
// Decisions: the droplets of a pass are ordered as `ordering` says (core/params/droplets.hpp) and
//          ref<double> runs them one after the other (the truth). A droplet's random directions are
//          numbered by its iteration, pass and block, so a state resumed after `done` iterations
//          draws them on from there (the references' first_iteration, the GPU's load).
// Checks: the runner's and the droplet twin's; a case's hand-derived droplet (spec.droplet.*,
//          compare/droplet_twin.hpp); the brush weights of eq. 2.42 (Fig. 2.10) and more
//          hand-derived steps are the spec vectors of tests/beyer_test.cpp.
// Mutants: compare/mutants/beyer.cpp.
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

// The GPU object lives as long as the closures.
DropletGpu beyer_gpu(std::shared_ptr<gpu::BeyerErosion> gpu) {
  return {[gpu](const Grid<float>& heights, int done) { gpu->load(heights, done); },
          [gpu](int count) { gpu->step(count); }, [gpu] { return gpu->result(); }};
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

// The twins on `given` (normalised when asked); `constants` are those of the twins' heights.
DropletTwin beyer_twin(const Heightmap& given, bool normalised, const BeyerConstants& constants) {
  DropletTwin twin;
  twin.algorithm = "erosion.beyer";
  set_droplet_input(twin, given, normalised);
  twin.setup = {constants.spacing, constants.ordering};
  twin.iterations = constants.iterations;
  twin.lifetime = constants.lifetime;
  twin.apart_spacing = 2 * beyer_reach(constants) + 1;
  // A step erodes with the brush (a store and a sediment update per sample) or deposits on 4
  // samples (a store each, one sediment update): each sample, a distinct cell, written once.
  twin.roundings_per_step = 2.0 * brush_samples(constants);
  twin.writes_per_cell_per_step = 1.0;
  // Eq. 2.43's blend: 8 sums of exchanges and the final add at each cell (blur_blend.hpp).
  twin.cell_roundings_per_iteration = constants.blur_blend > 0.0 ? 9.0 : 0.0;
  twin.reference_double = [constants](const Grid<double>& heights, int first, int count, DropletSetup setup) {
    return reference::beyer_erosion(heights, with_setup(constants, setup), count, reference_ordering(setup.ordering),
                                    first);
  };
  twin.reference_float = [constants](const Grid<float>& heights, int first, int count, DropletSetup setup) {
    return reference::beyer_erosion(heights, with_setup(constants, setup), count, reference_ordering(setup.ordering),
                                    first);
  };
  twin.make_gpu = [constants, width = given.width, height = given.height](DropletSetup setup) {
    return beyer_gpu(std::make_shared<gpu::BeyerErosion>(width, height, with_setup(constants, setup)));
  };
  return twin;
}

// The twins of a case and the constants they were made with (the hand-derived droplet's too).
struct BeyerCase {
  DropletTwin twin;
  BeyerConstants constants;
};

BeyerCase make_case(const nlohmann::json& resolved, const Heightmap& given) {
  if (given.size() == 0) throw InputError("erosion.beyer erodes a heightmap: the case needs an input");
  check_finite(given, "erosion.beyer input");
  check_fits_float(given, "erosion.beyer input");
  const bool normalised = resolved.at("normalised").get<bool>();
  const Heightmap input = normalised ? normalise_heights(given) : given;
  const BeyerConstants c = beyer_constants(resolved, input);
  DropletTwin twin = beyer_twin(given, normalised, c);
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
  if (c.blur_blend > 0.0) {
    twin.notes.push_back(fmt::format(
        "blur blend c_b = {} (eq. 2.43) after each iteration: the 3x3 box blur as exchanges between neighbours (c_b/9 "
        "of each height difference), none across the border or with no-data cells, so the volume is kept{}",
        c.blur_blend, c.ordering == DropletOrdering::batch ? "; in batch ordering as quanta, applied as a pass's delta" : ""));
  }
  if (c.speed_rule == BeyerSpeedRule::physical) {
    twin.notes.push_back("speed rule physical: without friction a droplet speeds up on every downhill step and its "
                         "capacity with it; expect the terrain to run away over several iterations");
  }
  return {std::move(twin), c};
}

// A hand-derived droplet in the case (compare/droplet_twin.hpp droplet_spec_shape()): ref<double>
// traces it from the centre of its start texel on the twins' input, with the case's constants.
void add_droplet_spec(const DropletTwin& twin, const BeyerConstants& constants, const nlohmann::json& expect,
                      CaseResult& result) {
  if (!expect.is_object() || !expect.contains("droplet")) return;
  const auto& spec = expect["droplet"];
  DropletTrace trace{.heights_after = twin.input};
  const auto path = reference::beyer_one_droplet(trace.heights_after, constants, spec.at("start")[0].get<int>() + 0.5,
                                                 spec.at("start")[1].get<int>() + 0.5, 0);
  trace.positions.assign(path.positions.begin(), path.positions.end());
  trace.sediment = path.sediment;
  add_droplet_spec_checks(spec, trace, result);
}

PreparedTwin prepare_beyer(const nlohmann::json& resolved, const LoadedInput& input) {
  BeyerCase made = make_case(resolved, input.heights);
  const auto twin = std::make_shared<const DropletTwin>(std::move(made.twin));
  const BeyerConstants constants = made.constants;
  return {.kind = droplet_stepped_twin(twin),
          .extra_checks = [twin, constants](const nlohmann::json& expect, const RunOptions&, CaseResult& result) {
            add_droplet_spec(*twin, constants, expect, result);
          }};
}

nlohmann::json beyer_expect_shape() {
  nlohmann::json shape = descriptor_expect_shape();
  shape["droplet"] = droplet_spec_shape();
  return shape;
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
    for (auto& row : droplet_benchmark_rows(beyer_twin(field, false, beyer_constants(resolved, field)), options.reps,
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
          .kind = CaseKind::stepped,
          .benchmark = benchmark_beyer,
          .expect_shape = beyer_expect_shape(),
          // As erosion.particle's without colour and flow map: the same grids are kept; measured within
          // this by tests/memory_estimates_test.cpp at 768².
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const double cells = static_cast<double>(input.heights.size());
            return memory_for(cells, "cells", 300 + descriptor_bytes_per_cell) +
                   droplet_checkpoint_memory(cells, resolved.at("iterations").get<int>());
          }};
}

}  // namespace gt
