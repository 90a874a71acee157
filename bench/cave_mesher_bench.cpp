// Google Benchmark of the CPU cave meshers (reference/cave/): marching tetrahedra and marching
// cubes in double on seed 004's density for solid blocks of side 32 to 256, the density sampled
// once beforehand (as the performance table times it). Counter: M voxels per second.
//   ./build/release/bench/cave_mesher_bench --benchmark_filter=tetrahedra/128
#include <benchmark/benchmark.h>

#include "core/params/cave.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_cubes.hpp"
#include "reference/cave/marching_tetrahedra.hpp"

namespace {

gt::CaveParams block(int side) {
  gt::CaveParams params;
  params.size = {side, side, side};
  return params;
}

template <class Mesh>
void run_mesher(benchmark::State& state, Mesh mesh) {
  const gt::CaveParams params = block(static_cast<int>(state.range(0)));
  const auto density = gt::reference::cave_density<double>(params);
  const std::array<std::int64_t, 3> origin = {params.origin[0], params.origin[1], params.origin[2]};
  std::size_t triangles = 0;
  for (auto _ : state) {
    triangles = mesh(density, params.threshold, params.solid, origin).triangles.size();
    benchmark::DoNotOptimize(triangles);
  }
  const double voxels = double(state.range(0)) * state.range(0) * state.range(0);
  state.counters["Mvoxel/s"] = benchmark::Counter(voxels * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["triangles"] = double(triangles);
}

void tetrahedra(benchmark::State& state) {
  run_mesher(state, [](const auto& density, double threshold, bool solid, const auto& origin) {
    return gt::reference::marching_tetrahedra(density, threshold, solid, origin);
  });
}

void cubes(benchmark::State& state) {
  run_mesher(state, [](const auto& density, double threshold, bool solid, const auto& origin) {
    return gt::reference::marching_cubes(density, threshold, solid, origin);
  });
}

}  // namespace

BENCHMARK(tetrahedra)->RangeMultiplier(2)->Range(32, 256)->Unit(benchmark::kMillisecond);
BENCHMARK(cubes)->RangeMultiplier(2)->Range(32, 256)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
