#include "compare/benchmark.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/inputs.hpp"
#include "compare/timing.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

BenchmarkRow row(const std::string& algorithm, const std::string& backend, int size, int iterations, int reps,
                 const std::vector<double>& times, const std::string& device) {
  BenchmarkRow result{.algorithm = algorithm, .backend = backend, .size = size, .iterations = iterations, .reps = reps,
                      .median_ms = median(times), .device = device};
  result.mcell_iterations_per_s = static_cast<double>(size) * size * iterations / (result.median_ms * 1e-3) / 1e6;
  return result;
}

// A cone steep enough everywhere on its flank that every iteration moves material, with noise
// so that flat ground is active too.
Heightmap benchmark_input(int size) {
  const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                {"peak", 0.8 * size}, {"noise", 2.0}, {"seed", 7}};
  return load_input(input, nullptr, {}).heights;
}

// Field twins: the double reference and the GPU on generated square grids.
void benchmark_field_twin(const Algorithm& algorithm, const BenchmarkOptions& options, bool gpu_available,
                          const Environment& environment, Progress& progress, std::vector<BenchmarkRow>& rows) {
  const int iterations = algorithm.iterates ? options.iterations : 1;
  const nlohmann::json given = algorithm.iterates ? nlohmann::json{{"iterations", iterations}} : nlohmann::json::object();
  const auto params = resolve_params(algorithm.name, *algorithm.params, given);
  for (int size : options.sizes) {
    progress.start_case(static_cast<int>(rows.size()) + 1, fmt::format("benchmark {} {}x{}", algorithm.name, size, size));
    LoadedInput input_grid;
    input_grid.heights = benchmark_input(size);
    require_memory(algorithm.memory(params, input_grid), fmt::format("benchmark {} {}x{}", algorithm.name, size, size));
    const PreparedTwin prepared = algorithm.prepare(params, input_grid);
    std::vector<double> cpu_times;
    progress.stage("cpu");
    prepared.twin.reference_double(prepared.input);
    for (int rep = 0; rep < options.reps; ++rep) {
      cpu_times.push_back(cpu_wall_ms([&] { prepared.twin.reference_double(prepared.input); }));
    }
    rows.push_back(row(algorithm.name, "cpu", size, iterations, options.reps, cpu_times, environment.cpu));
    if (!gpu_available) continue;
    progress.stage("gpu");
    const auto input = prepared.input.cast<float>();
    GpuFieldRunner runner = prepared.twin.make_gpu();
    runner.load(input);
    runner.run();
    std::vector<double> gpu_times;
    for (int rep = 0; rep < options.reps; ++rep) {
      runner.load(input);
      gpu_times.push_back(gpu_wall_ms(runner.run));
    }
    rows.push_back(row(algorithm.name, "gpu", size, iterations, options.reps, gpu_times, environment.gl_renderer));
  }
}

}  // namespace

std::vector<BenchmarkRow> run_benchmarks(const BenchmarkOptions& options, bool gpu_available,
                                         const Environment& environment) {
  std::vector<BenchmarkRow> rows;
  Progress progress(static_cast<int>(2 * algorithms().size() * options.sizes.size()), options.quiet);
  for (const auto& algorithm : algorithms()) {
    if (algorithm.benchmark) {
      progress.start_case(static_cast<int>(rows.size()) + 1, "benchmark " + algorithm.name);
      const auto own_rows = algorithm.benchmark(options, gpu_available, environment);
      rows.insert(rows.end(), own_rows.begin(), own_rows.end());
    } else if (algorithm.has_field_twin) {
      benchmark_field_twin(algorithm, options, gpu_available, environment, progress, rows);
    }
  }
  progress.finish();
  return rows;
}

}  // namespace gt
