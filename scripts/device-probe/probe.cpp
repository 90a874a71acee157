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
//      ref<double>'s one run, in Mcell·iterations/s;
//   4. one iteration from the input (the shadow step), GPU against ref<float>: the cells that
//      differ, the largest difference in metres and in floats of that cell's height, and the worst
//      cell's neighbourhood, so that a difference seen after I iterations can be told from a
//      per-step rounding difference (GLSL lets a division be off by 2.5 ULP: on an NVIDIA H200 one
//      step moves 1 in ~1,000-4,000 cells by one float, docs/fast-feedback.md).
// Usage: probe [N=1024] [I=100] [R=5]. Exit 0 when the GPU matches ref<float> (the run and the
// step), 1 when it does not, 2 when no GL context could be made.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
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

// How many floats lie between a and b (0: equal), for finite floats of either sign.
long long ulp_distance(float a, float b) {
  const auto ordered = [](float value) {
    std::int32_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    return bits < 0 ? static_cast<long long>(std::numeric_limits<std::int32_t>::min()) - bits : static_cast<long long>(bits);
  };
  return std::llabs(ordered(a) - ordered(b));
}

struct Agreement {
  std::size_t differing = 0;
  double largest_metres = 0.0;
  long long worst_ulps = 0;  // floats between the twins' heights at `worst`
  double largest_share_of_change = 0.0;  // |GPU − ref<float>| / |ref<float>'s change of that cell|
  std::size_t worst = 0;                 // the cell of largest_metres
};

// Where the GPU and ref<float> differ after a run from `start`, and by how much.
Agreement agreement(const gt::Grid<float>& gpu, const gt::Grid<float>& reference, const gt::Heightmap& start) {
  Agreement out;
  for (std::size_t i = 0; i < gpu.values.size(); ++i) {
    if (gpu.values[i] == reference.values[i]) continue;
    ++out.differing;
    const double difference = std::abs(double(gpu.values[i]) - double(reference.values[i]));
    const double change = std::abs(double(reference.values[i]) - double(static_cast<float>(start.values[i])));
    if (difference > out.largest_metres) {
      out.worst = i;
      out.worst_ulps = ulp_distance(gpu.values[i], reference.values[i]);
    }
    out.largest_metres = std::max(out.largest_metres, difference);
    if (change > 0.0) out.largest_share_of_change = std::max(out.largest_share_of_change, difference / change);
  }
  return out;
}

std::string described(const Agreement& agreement) {
  return fmt::format("cells differing {}, largest {:.3g} m ({} ULP of that cell's height), {:.3g} of a cell's change",
                     agreement.differing, agreement.largest_metres, agreement.worst_ulps,
                     agreement.largest_share_of_change);
}

// The worst cell of a step: its input height and its four neighbours' (float, hexadecimal), and
// what each twin made of it, for telling a rounding difference from another formula.
void print_worst_cell(const Agreement& step, const gt::Heightmap& start, const gt::Grid<float>& gpu,
                      const gt::Grid<float>& reference) {
  if (step.differing == 0) return;
  const int x = static_cast<int>(step.worst % start.width);
  const int y = static_cast<int>(step.worst / start.width);
  const auto height = [&](int cx, int cy) {
    return cx < 0 || cy < 0 || cx >= start.width || cy >= start.height ? std::string("-")
                                                                        : fmt::format("{:a}", static_cast<float>(start.at(cx, cy)));
  };
  fmt::print("    worst cell ({}, {}): input {} | x-1 {} x+1 {} y-1 {} y+1 {}\n", x, y, height(x, y), height(x - 1, y),
             height(x + 1, y), height(x, y - 1), height(x, y + 1));
  fmt::print("    ref<float> {:a}  gpu {:a}\n", reference.values[step.worst], gpu.values[step.worst]);
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

  gt::gpu::ThermalErosion shadow(side, side, constants, neighbourhood, 1);
  shadow.load(heights.cast<float>());
  shadow.run();
  const gt::Grid<float> reference_step =
      gt::reference::thermal_erosion<float>(heights.cast<float>(), constants, 1, neighbourhood);
  const Agreement step = agreement(shadow.result(), reference_step, heights);
  const Agreement run = agreement(gpu_result, float_result, heights);
  const std::size_t differing = run.differing;
  double before = 0.0, after = 0.0;
  for (std::size_t i = 0; i < gpu_result.values.size(); ++i) {
    before += heights.values[i];
    after += gpu_result.values[i];
  }
  const double drift = std::abs(after - before) / before;
  const double cells = double(side) * side * iterations;
  fmt::print("erosion.thermal {}x{}, {} iterations, cardinal:\n", side, side, iterations);
  fmt::print("  gpu            median {:10.2f} ms of {} runs  {:10.1f} Mcell·it/s  ({})\n", gpu_ms, reps,
             cells / (gpu_ms * 1e3), context->info().renderer);
  fmt::print("  ref<double>    {:10.2f} ms, one run         {:10.1f} Mcell·it/s\n", double_ms, cells / (double_ms * 1e3));
  fmt::print("  parity.gpu_vs_float (bound 0)  {}   {}\n", described(run), differing == 0 ? "pass" : "FAIL");
  fmt::print("  one step from the input         {}   {}\n", described(step), step.differing == 0 ? "pass" : "FAIL");
  print_worst_cell(step, heights, shadow.result(), reference_step);
  fmt::print("  constants: talus_slope {} length_x {} request_factor {} clamp_unit {}\n", constants.talus_slope,
             constants.length_x, constants.request_factor, constants.clamp_unit);
  fmt::print("  mass.relative_drift.gpu  {:.3g}   info\n", drift);
  return differing == 0 && step.differing == 0 ? 0 : 1;
}
