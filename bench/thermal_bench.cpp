// Google Benchmark of the thermal-erosion twins: the references in double and float and the GPU
// versions, on generated square grids (a noisy cone, so every iteration moves material).
// GPU runs use manual time: glFinish before and after the dispatches, a steady clock between
// (llvmpipe's timer queries read 0 for compute). Counters: Mcell-iterations per second; GPU rows
// are labelled with the GL renderer.
//   ./build/release/bench/thermal_bench --benchmark_filter=gpu
// The report's performance table (`groundtruth bench`) measures the same with medians; this
// binary is for profiling one kernel at a time.
#include <memory>

#include <benchmark/benchmark.h>

#include "compare/inputs.hpp"
#include "core/errors.hpp"
#include "core/params/thermal.hpp"
#include "gpu/context/context.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/erosion/thermal_jako.hpp"
#include "gpu/timing.hpp"
#include "reference/erosion/thermal.hpp"
#include "reference/erosion/thermal_jako.hpp"

namespace {

constexpr int iterations_per_run = 10;

gt::Heightmap cone(int size) {
  const nlohmann::json input = {{"generator", "cone"}, {"width", size}, {"height", size},
                                {"peak", 0.8 * size},  {"noise", 2.0},  {"seed", 7}};
  return gt::load_input(input, nullptr, {}).heights;
}

gt::ThermalConstants hydra_constants(const gt::Heightmap& field) {
  gt::ThermalParams params;
  params.talus_angle_deg = 30.0;
  return gt::thermal_constants(params, field);
}

gt::ThermalConstants jako_constants(const gt::Heightmap& field) {
  gt::ThermalJakoParams params;
  params.talus_angle_deg = 30.0;
  return gt::thermal_jako_constants(params, field);
}

void count_cells(benchmark::State& state, int size) {
  state.counters["Mcell-it/s"] = benchmark::Counter(static_cast<double>(size) * size * iterations_per_run / 1e6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

template <class Real>
void reference_thermal(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const auto field = cone(size);
  const auto input = field.cast<Real>();
  const auto constants = hydra_constants(field);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        gt::reference::thermal_erosion(input, constants, iterations_per_run, gt::Neighbourhood::alternating));
  }
  count_cells(state, size);
}

template <class Real>
void reference_thermal_jako(benchmark::State& state) {
  const int size = static_cast<int>(state.range(0));
  const auto field = cone(size);
  const auto input = field.cast<Real>();
  const auto constants = jako_constants(field);
  for (auto _ : state) {
    benchmark::DoNotOptimize(gt::reference::thermal_jako_erosion(input, constants, iterations_per_run));
  }
  count_cells(state, size);
}

// One context for the whole binary; GPU benchmarks skip with the reason when there is none.
gt::GlContext* shared_context(benchmark::State& state) {
  static std::unique_ptr<gt::GlContext> context;
  static std::string failure;
  if (!context && failure.empty()) {
    try {
      context = gt::GlContext::create(gt::GlBackend::egl);
    } catch (const gt::GpuUnavailable& error) {
      failure = error.what();
    }
  }
  if (!context) state.SkipWithError(failure.c_str());
  return context.get();
}

template <class Gpu, class... Extra>
void time_gpu(benchmark::State& state, const gt::Heightmap& field, const gt::ThermalConstants& constants,
              Extra... extra) {
  const gt::GlContext* context = shared_context(state);
  if (context == nullptr) return;
  state.SetLabel(context->info().renderer);
  const auto input = field.cast<float>();
  Gpu gpu(field.width, field.height, constants, extra..., iterations_per_run);
  for (auto _ : state) {
    gpu.load(input);
    state.SetIterationTime(gt::gpu_wall_ms([&] { gpu.run(); }) * 1e-3);
  }
  count_cells(state, field.width);
}

void gpu_thermal(benchmark::State& state) {
  const auto field = cone(static_cast<int>(state.range(0)));
  time_gpu<gt::gpu::ThermalErosion>(state, field, hydra_constants(field), gt::Neighbourhood::alternating);
}

void gpu_thermal_jako(benchmark::State& state) {
  const auto field = cone(static_cast<int>(state.range(0)));
  time_gpu<gt::gpu::ThermalJakoErosion>(state, field, jako_constants(field));
}

BENCHMARK(reference_thermal<double>)->RangeMultiplier(2)->Range(256, 2048)->Unit(benchmark::kMillisecond);
BENCHMARK(reference_thermal<float>)->RangeMultiplier(2)->Range(256, 2048)->Unit(benchmark::kMillisecond);
BENCHMARK(reference_thermal_jako<double>)->RangeMultiplier(2)->Range(256, 2048)->Unit(benchmark::kMillisecond);
BENCHMARK(gpu_thermal)->RangeMultiplier(2)->Range(256, 2048)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(gpu_thermal_jako)->RangeMultiplier(2)->Range(256, 2048)->UseManualTime()->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
