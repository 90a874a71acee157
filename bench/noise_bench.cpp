// Google Benchmark of the CPU noise references (reference/noise/) in double: one 512² slice of
// each function at the twins' default sampling (step 0.05), as the performance table samples it.
// Counter: M samples per second.
//   ./build/release/bench/noise_bench --benchmark_filter=simplex3
#include <benchmark/benchmark.h>

#include "core/params/noise.hpp"
#include "reference/noise/noise_field.hpp"

namespace {

void sample_field(benchmark::State& state, gt::NoiseBasis basis, gt::Fractal fractal) {
  gt::NoiseParams params;
  params.basis = basis;
  params.fractal = fractal;
  params.sampling = {.width = 512, .height = 512, .origin = {0.3, 0.7, 0.5, 0.25}, .step = 0.05};
  for (auto _ : state) {
    auto field = gt::reference::noise_field<double>(params, params.sampling.origin);
    benchmark::DoNotOptimize(field.at(0, 0));
  }
  state.counters["Msample/s"] = benchmark::Counter(512.0 * 512.0 * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK_CAPTURE(sample_field, simplex2, gt::NoiseBasis::simplex2, gt::Fractal::none)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(sample_field, simplex3, gt::NoiseBasis::simplex3, gt::Fractal::none)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(sample_field, simplex4, gt::NoiseBasis::simplex4, gt::Fractal::none)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(sample_field, perlin3, gt::NoiseBasis::perlin3, gt::Fractal::none)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(sample_field, fbm, gt::NoiseBasis::perlin3, gt::Fractal::fbm)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
