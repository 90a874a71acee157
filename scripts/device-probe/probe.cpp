// The device probe: what scripts/device-check.sh runs on a GPU machine that lacks the Debian
// packages the harness links (CGAL, OpenImageIO, OpenMesh, netCDF, ...; the lent NVIDIA machines
// run Ubuntu 24.04 with CUDA and reach no package registry). Built from the project's own GL
// context, shader loader, thermal GPU twin and thermal reference (scripts/device-probe/build.sh),
// it checks the EGL device path and takes the GPU timings the harness would:
//   1. a GL 4.5 core context through EGL (a hardware device first), its renderer and platform;
//   2. erosion.thermal on a noisy cone of N² cells, I iterations, cardinal: the GPU twin against
//      ref<float> (the twins' contract: bit for bit, so the count of differing cells must be 0), and
//      the material total's drift from the input's, shown (info: the harness grades it);
//   3. the GPU's median wall time of R runs (glFinish and a steady clock, after one warm-up) beside
//      ref<double>'s one run, in Mcell·iterations/s.
// Usage: probe [N=1024] [I=100] [R=5]. Exit 0 when the GPU matches ref<float>, 1 when it does not,
// 2 when no GL context could be made.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/grid.hpp"
#include "core/params/thermal.hpp"
#include "gpu/context/context.hpp"
#include "gpu/erosion/thermal.hpp"
#include "gpu/timing.hpp"
#include "reference/erosion/thermal.hpp"

namespace gt::detail {
// This build links no OSMesa: EGL only.
std::unique_ptr<GlContext> create_osmesa_context() { throw GpuUnavailable("the device probe is built without OSMesa"); }
}  // namespace gt::detail

namespace {

// A cone of peak 0.2·N m on 1 m cells with a deterministic ripple, so every cell moves material.
gt::Heightmap noisy_cone(int side) {
  gt::Heightmap heights(side, side);
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const double distance = std::hypot(x + 0.5 - side / 2.0, y + 0.5 - side / 2.0) / (0.4 * side);
      heights.at(x, y) = std::max(0.0, 0.2 * side * (1.0 - distance)) + 0.5 * std::sin(0.7 * x) * std::cos(1.3 * y);
    }
  }
  return heights;
}

double seconds_of(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int argument(int argc, char** argv, int index, int fallback) {
  return argc > index ? std::max(1, std::atoi(argv[index])) : fallback;
}

}  // namespace

int main(int argc, char** argv) {
  const int side = argument(argc, argv, 1, 1024);
  const int iterations = argument(argc, argv, 2, 100);
  const int reps = argument(argc, argv, 3, 5);
  std::unique_ptr<gt::GlContext> context;
  try {
    context = gt::GlContext::create(gt::GlBackend::egl);
  } catch (const gt::GpuUnavailable& error) {
    fmt::print(stderr, "probe: no GL context: {}\n", error.what());
    return 2;
  }
  fmt::print("GL: {} | {} | {}\n", context->info().renderer, context->info().version, context->info().platform);
  for (const auto& attempt : context->info().passed_over) fmt::print("   passed over: {}\n", attempt);

  const gt::Heightmap heights = noisy_cone(side);
  gt::ThermalParams params;
  params.talus_angle_deg = 30.0;
  const gt::ThermalConstants constants = gt::thermal_constants(params, heights);
  const auto neighbourhood = gt::Neighbourhood::cardinal;

  gt::gpu::ThermalErosion gpu(side, side, constants, neighbourhood, iterations);
  gpu.load(heights.cast<float>());
  gpu.run();  // the warm-up run is also the one compared
  const gt::Grid<float> gpu_result = gpu.result();
  std::vector<double> times;
  for (int rep = 0; rep < reps; ++rep) {
    gpu.load(heights.cast<float>());
    times.push_back(gt::gpu_wall_ms([&] { gpu.run(); }));
  }
  std::sort(times.begin(), times.end());
  const double gpu_ms = times[times.size() / 2];

  const auto float_result = gt::reference::thermal_erosion<float>(heights.cast<float>(), constants, iterations, neighbourhood);
  const double double_ms = 1000.0 * seconds_of([&] { gt::reference::thermal_erosion<double>(heights, constants, iterations, neighbourhood); });

  std::size_t differing = 0;
  double before = 0.0, after = 0.0;
  for (std::size_t i = 0; i < gpu_result.values.size(); ++i) {
    if (gpu_result.values[i] != float_result.values[i]) ++differing;
    before += heights.values[i];
    after += gpu_result.values[i];
  }
  const double drift = std::abs(after - before) / before;
  const double cells = double(side) * side * iterations;
  fmt::print("erosion.thermal {}x{}, {} iterations, cardinal:\n", side, side, iterations);
  fmt::print("  gpu            median {:10.2f} ms of {} runs  {:10.1f} Mcell·it/s  ({})\n", gpu_ms, reps,
             cells / (gpu_ms * 1e3), context->info().renderer);
  fmt::print("  ref<double>    {:10.2f} ms, one run         {:10.1f} Mcell·it/s\n", double_ms, cells / (double_ms * 1e3));
  fmt::print("  parity.gpu_vs_float  cells differing {} (bound 0)   {}\n", differing, differing == 0 ? "pass" : "FAIL");
  fmt::print("  mass.relative_drift.gpu  {:.3g}   info\n", drift);
  return differing == 0 ? 0 : 1;
}
