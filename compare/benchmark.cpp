#include "compare/benchmark.hpp"

#include <algorithm>
#include <chrono>
#include <fnmatch.h>
#include <memory>
#include <variant>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/benchmark_table.hpp"
#include "compare/inputs.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "gpu/memory/copy_bandwidth.hpp"
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

// A peer timed on the grid the twin's parameters lay out (noise: one sample per cell), on the
// thread that times our CPU reference; a peer that cannot take the parameters gets a note.
BenchmarkRow peer_row(const Peer& peer, const std::string& algorithm, const nlohmann::json& params, int size, int reps,
                      const Environment& environment) {
  std::function<void()> work;
  try {
    work = peer.prepare(params, size, size);
  } catch (const std::exception& error) {
    return {.algorithm = algorithm, .backend = "peer", .size = size, .iterations = 1, .device = environment.cpu,
            .note = error.what(), .peer = peer.name};
  }
  work();
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) times.push_back(cpu_wall_ms(work));
  BenchmarkRow result = row(algorithm, "peer", size, 1, reps, times, environment.cpu);
  result.peer = peer.name;
  return result;
}

// The bandwidth probe: 4096² floats copied between buffers far larger than any cache (64 MiB
// each), on the CPU (std::copy, one thread) and through GL (gpu/memory/copy_bandwidth.hpp, a vec4
// per invocation). Its bytes per cell (float) are the 4 read and 4 written.
constexpr int probe_side = 4096;

BenchmarkRow probe_row(const std::string& backend, const std::vector<double>& times, int reps, const std::string& device) {
  BenchmarkRow result = row(bandwidth_probe_name, backend, probe_side, 1, reps, times, device);
  result.bytes_per_cell = 8.0;
  result.detail = fmt::format("copy bandwidth {:.3g} GB/s (one float read and written per cell): the floor of this "
                              "device's rows",
                              8.0 * benchmark_work(result) / (result.median_ms * 1e-3) / 1e9);
  return result;
}

void benchmark_bandwidth(const BenchmarkOptions& options, bool gpu_available, const Environment& environment,
                         std::vector<BenchmarkRow>& rows) {
  const std::size_t elements = std::size_t{probe_side} * probe_side;
  require_memory(memory_for(static_cast<double>(elements), "floats", 2 * sizeof(float)), "the bandwidth probe");
  {
    const std::vector<float> source(elements, 1.0f);
    std::vector<float> target(elements);
    std::copy(source.begin(), source.end(), target.begin());
    std::vector<double> times;
    for (int rep = 0; rep < options.reps; ++rep) {
      times.push_back(cpu_wall_ms([&] { std::copy(source.begin(), source.end(), target.begin()); }));
    }
    rows.push_back(probe_row("cpu", times, options.reps, environment.cpu));
  }
  if (!gpu_available) return;
  const gpu::CopyKernel kernel(elements);
  kernel.run();
  std::vector<double> times;
  for (int rep = 0; rep < options.reps; ++rep) times.push_back(gpu_wall_ms([&] { kernel.run(); }));
  rows.push_back(probe_row("gpu", times, options.reps, environment.gl_renderer));
}

// The algorithm's declared bytes per cell on its CPU and GPU rows that did not set their own.
void add_traffic(const Algorithm& algorithm, std::vector<BenchmarkRow>::iterator first,
                 std::vector<BenchmarkRow>::iterator last) {
  for (auto row = first; row != last; ++row) {
    if (row->bytes_per_cell || !row->peer.empty()) continue;
    if (row->backend == "cpu") row->bytes_per_cell = algorithm.traffic.cpu;
    if (row->backend == "gpu") row->bytes_per_cell = algorithm.traffic.gpu;
  }
}

// A cone steep enough everywhere on its flank that every iteration moves material, with noise
// so that flat ground is active too.
Heightmap benchmark_input(int size) {
  const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                {"peak", 0.8 * size}, {"noise", 2.0}, {"seed", 7}};
  return load_input(input, nullptr, {}).heights;
}

// One backend's work for the generic rows: reset (not timed) before each timed run.
struct Work {
  std::function<void()> reset;
  std::function<void()> run;
};

// A generated field's whole grid; a stepped twin's iterations from its start state (upload and
// download excluded).
Work stepped_work(const SteppedTwin& twin, std::shared_ptr<Stepper> stepper) {
  return {[stepper, &twin] { stepper->set_state(twin.initial, 0); },
          [stepper, &twin] { stepper->update(twin.iterations); }};
}

Work cpu_work(const PreparedTwin& prepared) {
  if (const auto* generated = std::get_if<GeneratedCase>(&prepared.kind)) {
    return {[] {}, [generated] { generated->twin.reference_double(generated->grid); }};
  }
  const auto& twin = std::get<SteppedTwin>(prepared.kind);
  return stepped_work(twin, twin.reference_double());
}

Work gpu_work(const PreparedTwin& prepared) {
  if (const auto* generated = std::get_if<GeneratedCase>(&prepared.kind)) {
    auto runner = std::make_shared<GpuFieldRunner>(generated->twin.make_gpu());
    auto grid = std::make_shared<Grid<float>>(generated->grid.cast<float>());
    return {[runner, grid] { runner->load(*grid); }, [runner] { runner->run(); }};
  }
  const auto& twin = std::get<SteppedTwin>(prepared.kind);
  return stepped_work(twin, twin.make_gpu());
}

// The median of `reps` timed runs after one warm-up.
std::vector<double> timed_runs(const Work& work, int reps, double (*clock)(const std::function<void()>&)) {
  work.reset();
  work.run();
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) {
    work.reset();
    times.push_back(clock(work.run));
  }
  return times;
}

}  // namespace

std::vector<double> time_stepped_cpu(const SteppedTwin& twin, int reps) {
  return timed_runs(stepped_work(twin, twin.reference_double()), reps, cpu_wall_ms);
}

bool within_table_sizes(double cells, const BenchmarkOptions& options) {
  const int largest = options.sizes.empty() ? 0 : *std::max_element(options.sizes.begin(), options.sizes.end());
  return cells <= 4.0 * static_cast<double>(largest) * static_cast<double>(largest);
}

std::vector<double> time_stepped_gpu(const SteppedTwin& twin, int reps) {
  return timed_runs(stepped_work(twin, twin.make_gpu()), reps, gpu_wall_ms);
}

namespace {

// Generated fields and stepped twins: the double reference and the GPU on generated square grids.
void benchmark_field_twin(const Algorithm& algorithm, const BenchmarkOptions& options, bool gpu_available,
                          const Environment& environment, Progress& progress, std::vector<BenchmarkRow>& rows) {
  const bool stepped = algorithm.kind == CaseKind::stepped;
  const int iterations = stepped ? options.iterations : 1;
  const nlohmann::json given = stepped ? nlohmann::json{{"iterations", iterations}} : nlohmann::json::object();
  const auto params = resolve_params(algorithm.name, *algorithm.params, given);
  for (int size : options.sizes) {
    const auto started = std::chrono::steady_clock::now();
    const std::string step = fmt::format("benchmark {} {}x{}", algorithm.name, size, size);
    progress.start_case(step);
    LoadedInput input_grid;
    input_grid.heights = benchmark_input(size);
    require_memory(algorithm.memory(params, input_grid), fmt::format("benchmark {} {}x{}", algorithm.name, size, size));
    const PreparedTwin prepared = algorithm.prepare(params, input_grid);
    progress.stage("cpu");
    const auto cpu_times = timed_runs(cpu_work(prepared), options.reps, cpu_wall_ms);
    rows.push_back(row(algorithm.name, "cpu", size, iterations, options.reps, cpu_times, environment.cpu));
    for (const Peer& peer : algorithm.peers) {
      progress.stage("peer");
      rows.push_back(peer_row(peer, algorithm.name, params, size, options.reps, environment));
    }
    if (gpu_available) {
      progress.stage("gpu");
      const auto gpu_times = timed_runs(gpu_work(prepared), options.reps, gpu_wall_ms);
      rows.push_back(row(algorithm.name, "gpu", size, iterations, options.reps, gpu_times, environment.gl_renderer));
    }
    progress.end_case(step, std::nullopt, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  }
}

bool has_rows(const Algorithm& algorithm) { return algorithm.benchmark || algorithm.kind != CaseKind::custom; }

// The algorithms of the table that match the options' patterns, in the table's order.
std::vector<const Algorithm*> selected_algorithms(const BenchmarkOptions& options) {
  const auto matches = [](const std::string& pattern, const Algorithm& algorithm) {
    return has_rows(algorithm) && fnmatch(pattern.c_str(), algorithm.name.c_str(), 0) == 0;
  };
  for (const std::string& pattern : options.patterns) {
    if (std::none_of(algorithms().begin(), algorithms().end(), [&](const Algorithm& a) { return matches(pattern, a); })) {
      throw InputError(fmt::format("no algorithm of the performance table matches '{}' (`groundtruth list` names them)",
                                   pattern));
    }
  }
  std::vector<const Algorithm*> selected;
  for (const Algorithm& algorithm : algorithms()) {
    const bool wanted = options.patterns.empty() ? has_rows(algorithm)
                                                 : std::any_of(options.patterns.begin(), options.patterns.end(),
                                                               [&](const std::string& p) { return matches(p, algorithm); });
    if (wanted) selected.push_back(&algorithm);
  }
  return selected;
}

}  // namespace

BenchmarkRow published_row(const std::string& algorithm, const std::string& device, int size, int iterations,
                           double total_ms, const std::string& detail) {
  BenchmarkRow row{.algorithm = algorithm, .backend = "published", .size = size, .iterations = iterations, .reps = 0,
                   .median_ms = total_ms, .device = device};
  row.mcell_iterations_per_s = double(size) * size * iterations / (total_ms * 1e-3) / 1e6;
  row.detail = detail;
  return row;
}

std::vector<BenchmarkRow> run_benchmarks(const BenchmarkOptions& options, bool gpu_available,
                                         const Environment& environment) {
  const auto selected = selected_algorithms(options);
  std::vector<BenchmarkRow> rows;
  std::size_t steps = 1;  // the probe, then each algorithm's own table or each of its sizes
  for (const Algorithm* algorithm : selected) steps += algorithm->benchmark ? 1 : options.sizes.size();
  Progress progress(static_cast<int>(steps), options.quiet);
  const auto timed_step = [&](const std::string& step, const auto& work) {
    const auto started = std::chrono::steady_clock::now();
    progress.start_case(step);
    work();
    progress.end_case(step, std::nullopt, std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
  };
  timed_step("benchmark memory.copy (the bandwidth floor)", [&] { benchmark_bandwidth(options, gpu_available, environment, rows); });
  for (const Algorithm* selected_algorithm : selected) {
    const Algorithm& algorithm = *selected_algorithm;
    const std::size_t first_row = rows.size();
    if (algorithm.benchmark) {
      timed_step("benchmark " + algorithm.name, [&] {
        const auto own_rows = algorithm.benchmark(options, gpu_available, environment);
        rows.insert(rows.end(), own_rows.begin(), own_rows.end());
      });
    } else if (algorithm.kind != CaseKind::custom) {
      benchmark_field_twin(algorithm, options, gpu_available, environment, progress, rows);
    }
    add_traffic(algorithm, rows.begin() + static_cast<std::ptrdiff_t>(first_row), rows.end());
    for (const BenchmarkRow& published : algorithm.published) {
      if (std::find(options.sizes.begin(), options.sizes.end(), published.size) != options.sizes.end()) {
        rows.push_back(published);
      }
    }
  }
  progress.finish();
  annotate_benchmarks(rows);
  return rows;
}

}  // namespace gt
