// `render.heightmap_from_mesh`: seed 000's heightmap from a mesh (digest §4.3, eqs. 4.1–4.4) by the
// reference rasterizer (double) and by the GL pipeline, on a mesh file ({"mesh": path}) or, with
// generated = tent and no input, the probe tent of render_probe.hpp, with the parity checks of
// issue 6 (texel classes and error model in render_heightmap.hpp):
//   parity.interior_max_abs.gpu_vs_cpu     max |gpu - cpu| over interior texels, bound max B(t)
//   parity.interior_model.gpu_vs_cpu       max |gpu - cpu| / B(t) over interior texels, bound 1
//   parity.silhouette_texels.gpu_vs_cpu    coverage differences that are not silhouette texels
//                                          (bound 0); the detail gives all coverage differences
//   parity.silhouette_shift.gpu_vs_cpu     silhouette texels covered on both sides whose GPU height
//                                          is no reference height of its 3×3 neighbourhood (bound 0)
//   parity.coverage_exact.gpu_vs_cpu       only where every window coordinate is exact in float
//                                          (exact_window_coordinates) and GL snaps to the case's
//                                          subpixel bits: coverage differences beyond the box's
//                                          bottom (bound 0; issue 11)
//   spec.tent_coverage.{cpu,gpu}, spec.tent_heights.{cpu,gpu}
//                                          the tent only: each twin against the closed form
//                                          (render_probe.hpp; issue 11)
//   parity.coverage_share.{cpu,gpu}        share of covered texels (informative)
//   determinism.gpu                        texels differing between two GPU runs (bound 0)
// Timings: the reference's whole render (cpu_ms, median of cpu_reps), the GPU's clear and draw
// bracketed by glFinish (gpu_ms; upload and download excluded, median of gpu_reps).
// Pictures: cpu.png and gpu.png on the colour scale [0, 1] with the reference's hillshade, and
// gpu_vs_cpu.png, the difference (uncovered texels are height 0 on both sides, as in the seed).
#include "compare/algorithms/render_heightmap.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <numeric>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/algorithms/render_probe.hpp"
#include "compare/checks/error_model.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "gpu/render/heightmap_from_mesh.hpp"
#include "gpu/timing.hpp"
#include "reference/render/heightmap_from_mesh.hpp"

namespace gt {
namespace {

bool covered_at(const Grid<std::uint8_t>& covered, int x, int y) {
  return covered.inside(x, y) && covered.at(x, y) != 0;
}

// Whether every texel of the 3×3 neighbourhood of (x, y), (x, y) included, is covered.
bool neighbourhood_covered(const Grid<std::uint8_t>& covered, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (!covered_at(covered, x + dx, y + dy)) return false;
    }
  }
  return true;
}

bool has_uncovered_neighbour(const Grid<std::uint8_t>& covered, int x, int y) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if ((dx != 0 || dy != 0) && !covered_at(covered, x + dx, y + dy)) return true;
    }
  }
  return false;
}

// s(t) of the error model: along x and along y, the larger difference to a covered neighbour
// (covered in the reference, where the heights come from; the GPU's own for a texel only it covers).
template <class T>
double local_slope(const Grid<T>& heights, const Grid<std::uint8_t>& covered, int x, int y) {
  const double h = heights.at(x, y);
  const auto step = [&](int dx, int dy) {
    return covered_at(covered, x + dx, y + dy) ? std::abs(double(heights.at(x + dx, y + dy)) - h) : 0.0;
  };
  return std::max(step(1, 0), step(-1, 0)) + std::max(step(0, 1), step(0, -1));
}

double texel_bound(double slope, int width, int height) {
  return 16.0 * unit_roundoff_float * (1.0 + slope * double(width + height));
}

// Whether `value` lies within the covered reference heights of the 3×3 neighbourhood, ± bound.
bool within_neighbourhood(const Heightmap& cpu, const Grid<std::uint8_t>& cpu_covered, int x, int y, double value,
                          double bound) {
  double low = INFINITY, high = -INFINITY;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (!covered_at(cpu_covered, x + dx, y + dy)) continue;
      low = std::min(low, cpu.at(x + dx, y + dy));
      high = std::max(high, cpu.at(x + dx, y + dy));
    }
  }
  return value >= low - bound && value <= high + bound;
}

}  // namespace

HeightmapParity compare_mesh_heightmaps(const Heightmap& cpu, const Grid<std::uint8_t>& cpu_covered,
                                        const Grid<float>& gpu, const Grid<std::uint8_t>& gpu_covered) {
  HeightmapParity parity;
  for (int y = 0; y < cpu.height; ++y) {
    for (int x = 0; x < cpu.width; ++x) {
      const bool on_cpu = covered_at(cpu_covered, x, y), on_gpu = covered_at(gpu_covered, x, y);
      parity.covered_cpu += on_cpu;
      parity.covered_gpu += on_gpu;
      const bool silhouette = has_uncovered_neighbour(cpu_covered, x, y) || has_uncovered_neighbour(gpu_covered, x, y);
      const double difference = std::abs(double(gpu.at(x, y)) - cpu.at(x, y));
      const double bound = on_cpu ? texel_bound(local_slope(cpu, cpu_covered, x, y), cpu.width, cpu.height) : 0.0;
      if (on_cpu != on_gpu) {
        ++parity.coverage_differences;
        parity.coverage_differences_off_silhouette += !silhouette;
        const double covered_height = on_cpu ? cpu.at(x, y) : double(gpu.at(x, y));
        const double covered_bound =
            on_cpu ? bound : texel_bound(local_slope(gpu, gpu_covered, x, y), cpu.width, cpu.height);
        parity.coverage_differences_beyond_bottom += covered_height > covered_bound;
      } else if (on_cpu && silhouette) {
        ++parity.silhouette_texels_both_covered;
        parity.silhouette_beyond_one_texel +=
            !within_neighbourhood(cpu, cpu_covered, x, y, gpu.at(x, y), bound);
      } else if (neighbourhood_covered(cpu_covered, x, y) && neighbourhood_covered(gpu_covered, x, y)) {
        ++parity.interior_texels;
        parity.interior_max_abs = std::max(parity.interior_max_abs, difference);
        parity.interior_bound = std::max(parity.interior_bound, bound);
        parity.interior_model_ratio = std::max(parity.interior_model_ratio, difference / bound);
      }
    }
  }
  return parity;
}

bool exact_window_coordinates(const Mesh& mesh, int width, int height, int subpixel_bits) {
  const auto [low, high] = bounding_box(mesh);
  const auto exact_in_float = [](double value) { return double(float(value)) == value; };
  const auto power_of_two = [](double value) {
    int exponent = 0;
    return value > 0.0 && std::frexp(value, &exponent) == 0.5;
  };
  const double grid = std::ldexp(1.0, subpixel_bits), limit = std::ldexp(1.0, 23 - subpixel_bits);
  for (int axis = 0; axis < 2; ++axis) {
    const double scale = 2.0 / (high[axis] - low[axis]), centre = 0.5 * (low[axis] + high[axis]);
    const double pixels = axis == 0 ? width : height;
    if (!power_of_two(scale)) return false;
    for (const auto& p : mesh.positions) {
      const double offset = p[axis] - centre, ndc_plus_one = scale * offset + 1.0;
      const double window = 0.5 * ndc_plus_one * pixels;
      if (!exact_in_float(offset) || !exact_in_float(ndc_plus_one) || std::abs(window) >= limit ||
          window * grid != std::round(window * grid)) {
        return false;
      }
    }
  }
  return true;
}

namespace {

// A case: its parameters and the mesh it renders.
struct RenderCase : HeightmapRenderParams {
  Mesh mesh;
};

constexpr Choice<bool> generated_choices[] = {{"none", false}, {"tent", true}};

const ParamSpecs& render_specs() {
  static const ParamSpecs specs = param_specs(heightmap_render_param_table());
  return specs;
}

// spec.tent_coverage.<backend> and spec.tent_heights.<backend> (render_probe.hpp).
void add_tent_checks(const Heightmap& heights, const Grid<std::uint8_t>& covered, const std::string& backend,
                     CaseResult& result) {
  const double unit_roundoff = backend == "gpu" ? unit_roundoff_float : unit_roundoff_double;
  const TentComparison tent = compare_with_tent(heights, covered, unit_roundoff);
  result.checks.push_back(bounded_check(
      "spec.tent_coverage." + backend, double(tent.coverage_mismatches), 0.0, std::nullopt,
      fmt::format("texels whose coverage differs from the tent's footprint, of {} whose centre lies more than 2^-8 "
                  "texel from its outline",
                  tent.coverage_compared)));
  result.checks.push_back(bounded_check(
      "spec.tent_heights." + backend, tent.height_max_abs, tent.height_bound, std::nullopt,
      fmt::format("max |h - min(4x, 4y, 2(1 - x - y))| over {} texels at least one texel inside the footprint; bound "
                  "B = 16u·(1 + s·(W + H)), u = {}",
                  tent.height_compared, backend == "gpu" ? "2^-24" : "2^-53")));
}

reference::MeshHeightmap run_reference(const RenderCase& render, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("CPU reference (double)");
  reference::MeshHeightmap heightmap;
  time_cpu(std::max(options.cpu_reps, 1), [&] {
    heightmap = reference::heightmap_from_mesh(render.mesh, render.width, render.height, render.subpixel_bits);
  }, result.timings);
  return heightmap;
}

gpu::MeshHeightmap run_gpu(const RenderCase& render, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("GPU");
  const gpu::HeightmapFromMesh renderer(render.mesh, render.width, render.height);
  result.notes.push_back(fmt::format("GL_SUBPIXEL_BITS of the GL implementation: {} (the reference snaps to {})",
                                     gpu::HeightmapFromMesh::subpixel_bits(), render.subpixel_bits));
  renderer.run();
  const gpu::MeshHeightmap first = renderer.result();
  time_gpu(options.gpu_reps, [&] { renderer.run(); }, result.timings);
  const gpu::MeshHeightmap last = renderer.result();
  const auto changed = std::inner_product(first.heights.values.begin(), first.heights.values.end(),
                                          last.heights.values.begin(), std::size_t{0}, std::plus<>(),
                                          [](float a, float b) { return std::size_t(std::memcmp(&a, &b, sizeof a) != 0); });
  result.checks.push_back(bounded_check("determinism.gpu", double(changed), 0.0, std::nullopt,
                                        "texels whose height differs in any bit between the first and the last GPU run"));
  return first;
}

void add_parity_checks(const HeightmapParity& parity, const RenderCase& render, CaseResult& result) {
  const double texels = double(render.width) * render.height;
  result.checks.push_back(informative_check("parity.coverage_share.cpu", double(parity.covered_cpu) / texels,
                                            "share of texels a surface covers, reference"));
  result.checks.push_back(informative_check("parity.coverage_share.gpu", double(parity.covered_gpu) / texels,
                                            "share of texels a surface covers, GPU"));
  result.checks.push_back(bounded_check(
      "parity.interior_max_abs.gpu_vs_cpu", parity.interior_max_abs, parity.interior_bound, std::nullopt,
      fmt::format("max |gpu - cpu| over {} interior texels (3×3 covered on both sides), heights in [0, 1]; bound: the "
                  "largest B(t) = 16u·(1 + s(t)·(W + H)), u = 2^-24, s the reference's local slope per texel",
                  parity.interior_texels)));
  result.checks.push_back(bounded_check(
      "parity.interior_model.gpu_vs_cpu", parity.interior_model_ratio, 1.0, std::nullopt,
      "max over interior texels of |gpu - cpu| / B(t): the float error model texel by texel"));
  result.checks.push_back(bounded_check(
      "parity.silhouette_texels.gpu_vs_cpu", double(parity.coverage_differences_off_silhouette), 0.0, std::nullopt,
      fmt::format("coverage differences on texels without an uncovered neighbour on either side; {} texels are "
                  "covered on one side only, all allowed on silhouettes (edges within one texel)",
                  parity.coverage_differences)));
  result.checks.push_back(bounded_check(
      "parity.silhouette_shift.gpu_vs_cpu", double(parity.silhouette_beyond_one_texel), 0.0, std::nullopt,
      fmt::format("of {} silhouette texels covered on both sides, those whose GPU height lies outside the reference "
                  "heights of its 3×3 neighbourhood (± B(t)): more than a one-texel shift",
                  parity.silhouette_texels_both_covered)));
  if (exact_window_coordinates(render.mesh, render.width, render.height, render.subpixel_bits) &&
      gpu::HeightmapFromMesh::subpixel_bits() == render.subpixel_bits) {
    result.checks.push_back(bounded_check(
        "parity.coverage_exact.gpu_vs_cpu", double(parity.coverage_differences_beyond_bottom), 0.0, std::nullopt,
        fmt::format("every window coordinate is exact in float, so both twins apply GL's coverage rules to the same "
                    "snapped vertices: texels covered on one side only ({} in all; those whose height there is at "
                    "most B(t), a surface at the box's bottom, are not counted)",
                    parity.coverage_differences)));
  }
}

void write_pictures(const reference::MeshHeightmap& cpu, const gpu::MeshHeightmap* gpu_heightmap,
                    const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  const ColourScale heights = height_scale(0.0, 1.0, "1");
  const double exaggeration = write_height_image(cpu.heights, 0.0, 1.0, folder / "cpu.png");
  add_picture(result, "cpu.png", "CPU reference (double): 1 - z', top of the box 1, uncovered 0", heights);
  const std::string height_meaning = "1 - z' (seed 000 §4.3): top of the mesh's box 1, uncovered texels 0";
  write_field_files(cpu.heights, {"height_cpu", "height", "cpu", "1", height_meaning + ", CPU reference (double)"},
                    options, result);
  if (!gpu_heightmap) return;
  const Heightmap gpu_heights = gpu_heightmap->heights.cast<double>();
  write_field_files(gpu_heights, {"height_gpu", "height", "gpu", "1", height_meaning + ", GPU (GL pipeline, R32F)"},
                    options, result);
  write_height_image(gpu_heights, 0.0, 1.0, folder / "gpu.png", exaggeration);
  add_picture(result, "gpu.png", "GPU (GL pipeline, R32F)", heights);
  const auto difference = write_difference_image(cpu.heights, gpu_heights, folder / "gpu_vs_cpu.png");
  add_picture(result, "gpu_vs_cpu.png", "GPU - reference (silhouette texels dominate)", difference_scale(difference, "1"));
}

void run_render(const RenderCase& render, const std::string& file, const RunOptions& options, CaseResult& result) {
  result.input = fmt::format("{}, {}x{} texels", file, render.width, render.height);
  result.width = render.width;
  result.height = render.height;
  const reference::MeshHeightmap cpu = run_reference(render, options, result);
  result.notes.push_back(fmt::format("aspect ratios (eq. 4.3): d_xy = {:.6g}, d_z = {:.6g}", cpu.d_xy, cpu.d_z));
  if (render.tent) add_tent_checks(cpu.heights, cpu.covered, "cpu", result);
  if (!options.gpu_available) {
    for (const char* name : {"parity.coverage_share.cpu", "parity.coverage_share.gpu", "parity.interior_max_abs.gpu_vs_cpu",
                             "parity.interior_model.gpu_vs_cpu", "parity.silhouette_shift.gpu_vs_cpu",
                             "parity.silhouette_texels.gpu_vs_cpu", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
    write_pictures(cpu, nullptr, options, result);
    return;
  }
  const gpu::MeshHeightmap gpu_heightmap = run_gpu(render, options, result);
  if (render.tent) add_tent_checks(gpu_heightmap.heights.cast<double>(), gpu_heightmap.covered, "gpu", result);
  add_parity_checks(compare_mesh_heightmaps(cpu.heights, cpu.covered, gpu_heightmap.heights, gpu_heightmap.covered),
                    render, result);
  write_pictures(cpu, &gpu_heightmap, options, result);
}

PreparedTwin prepare_render(const nlohmann::json& resolved, const LoadedInput& input) {
  const auto given = params_from_json(heightmap_render_param_table(), resolved);
  const bool tent = given.tent;
  if (input.mesh && tent) throw InputError("render.heightmap_from_mesh: generated = tent replaces the mesh input; give one");
  if (!input.mesh && !tent) {
    throw InputError("render.heightmap_from_mesh needs a mesh input ({\"mesh\": \"path.off\"}) or generated = tent");
  }
  const Mesh mesh = tent ? tent_mesh() : *input.mesh;
  reference::require_visible_from_above(mesh);
  RenderCase render{given, mesh};
  PreparedTwin prepared;
  prepared.kind = CaseRun([render = std::move(render), file = tent ? std::string("the probe tent (render_probe.hpp)")
                                                          : input.description](const nlohmann::json&,
                                                                               const RunOptions& options,
                                                                               CaseResult& result) {
    run_render(render, file, options, result);
  });
  return prepared;
}

}  // namespace

const ParamTable<HeightmapRenderParams>& heightmap_render_param_table() {
  using P = HeightmapRenderParams;
  static const ParamTable<P> table = {
      integer_param("width", &P::width, 1, 4096, "texel", "heightmap columns (along the mesh's x)"),
      integer_param("height", &P::height, 1, 4096, "texel", "heightmap rows (along the mesh's y)"),
      integer_param("subpixel_bits", &P::subpixel_bits, 0, 16, "bit",
                    "GL_SUBPIXEL_BITS the reference snaps vertices to (8: llvmpipe and NVIDIA)"),
      choice_param("generated", &P::tent, generated_choices, "1",
                   "without a mesh input: tent, the probe tetrahedron of render_probe.hpp whose heightmap is known in "
                   "closed form (spec.tent_* checks)"),
  };
  return table;
}

Algorithm render_heightmap_algorithm() {
  return {.name = "render.heightmap_from_mesh",
          .summary = "heightmap of a mesh seen from above: reference rasterizer vs the GL pipeline",
          .source = "seed 000 §4.3 (digest 000_water_erosion.md), eqs. 4.1–4.4; issue 6",
          .params = &render_specs(),
          .prepare = prepare_render,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::mesh,
          // Measured 54 B a texel (cow, 2048² vs 512²); triangles as render.phong's.
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const auto given = params_from_json(heightmap_render_param_table(), resolved);
            const double texels = double(given.width) * given.height;
            const double triangles = input.mesh ? static_cast<double>(input.mesh->triangles.size()) : 0.0;
            return memory_for(texels, "texels", 80) + memory_for(triangles, "triangles", 500);
          }};
}

}  // namespace gt
