// `render.phong`: seed 004's Phong look (digest 004_cave.md §2.9) on a mesh file ({"mesh": path})
// seen through a perspective camera orbiting its bounding-box centre, by the reference rasterizer
// (double; reference/render/phong.hpp documents camera, normals and the shading formula) and by the
// GL pipeline (gpu/render/phong.hpp). Both draw the same PhongScene: normals and P·V are computed
// once in double, the GPU gets them rounded to float. Images are RGB8 (what GL writes to RGBA8).
//
// Checks (issue 6's acceptance for rendered cases; images compared with compare/checks/image.hpp,
// channel values in [0, 1]):
//   image.psnr.gpu_vs_cpu        value = -PSNR in dB (so the check's "value <= bound" reads
//                                PSNR >= 40 dB), bound -40; -inf when the images are identical.
//                                Decision: -PSNR rather than a shortfall max(0, 40 - PSNR), so the
//                                value keeps the measured PSNR.
//   image.share_beyond_tolerance_outside_edges.gpu_vs_cpu
//                                share of pixels failing the 3×3 neighbourhood-tolerant comparison at
//                                4/255 (a one-pixel shift of an edge passes), bound 0.005
//   image.max_abs.gpu_vs_cpu, image.rms.gpu_vs_cpu, image.share_beyond_tolerance.gpu_vs_cpu
//                                informative: the plain pixel-by-pixel comparison
//   determinism.gpu              bytes differing between the first and the last GPU run, bound 0
// Timings: the reference's whole render (cpu_ms, median of cpu_reps), the GPU's clear and draw
// bracketed by glFinish (gpu_ms; upload and download excluded, median of gpu_reps).
// Pictures: cpu.png and gpu.png (the compared images themselves), gpu_vs_cpu_heat.png (heat map of
// max |gpu - cpu| over channels) and gpu_vs_cpu_mask.png (verdicts: grey identical, green within
// 4/255, blue matched by a neighbour, red failing).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numeric>

#include <fmt/format.h>
#include <OpenImageIO/imagebuf.h>

#include "compare/algorithm.hpp"
#include "compare/checks/image.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "gpu/render/phong.hpp"
#include "gpu/timing.hpp"
#include "reference/render/phong.hpp"

namespace gt {
namespace {

constexpr double tolerance = 4.0 / 255.0;
constexpr double min_psnr_db = 40.0;
constexpr double max_failing_share = 0.005;

const ParamSpecs& phong_specs() {
  static const ParamSpecs specs = {
      {"width", ParamKind::integer, 256, 1, 4096, {}, "pixel", "image columns"},
      {"height", ParamKind::integer, 256, 1, 4096, {}, "pixel", "image rows"},
      {"fov_deg", ParamKind::real, 40.0, 1.0, 150.0, {}, "degree", "vertical field of view"},
      {"azimuth_deg", ParamKind::real, 30.0, -360.0, 360.0, {}, "degree",
       "camera direction around +y from the box centre, from +z towards +x"},
      {"elevation_deg", ParamKind::real, 20.0, -89.0, 89.0, {}, "degree", "camera direction above the xz plane"},
      {"subpixel_bits", ParamKind::integer, 8, 0, 16, {}, "bit",
       "GL_SUBPIXEL_BITS the reference snaps vertices to (8: llvmpipe and NVIDIA)"},
  };
  return specs;
}

struct PhongCase {
  reference::PhongScene scene;
  int subpixel_bits = 8;
};

OIIO::ImageBuf rgb8_buffer(int width, int height, const std::vector<std::uint8_t>& rgb) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
  image.set_pixels(image.roi(), OIIO::TypeDesc::UINT8, rgb.data());
  return image;
}

OIIO::ImageBuf run_reference(const PhongCase& phong, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("CPU reference (double)");
  reference::Rgb8Image image;
  time_cpu(std::max(options.cpu_reps, 1), [&] { image = reference::render_phong(phong.scene, phong.subpixel_bits); },
           result.timings);
  return rgb8_buffer(image.width, image.height, image.rgb);
}

gpu::PhongDraw gpu_draw(const reference::PhongScene& scene) {
  return {.mesh = scene.mesh,
          .normals = scene.normals,
          .view_projection = scene.view_projection,
          .eye = scene.camera.eye,
          .albedo = scene.albedo,
          .light_power = scene.light_power,
          .width = scene.camera.width,
          .height = scene.camera.height};
}

OIIO::ImageBuf run_gpu(const PhongCase& phong, const RunOptions& options, CaseResult& result) {
  if (options.progress) options.progress->stage("GPU");
  const gpu::PhongRenderer renderer(gpu_draw(phong.scene));
  renderer.run();
  const gpu::Rgb8Pixels first = renderer.image();
  time_gpu(options.gpu_reps, [&] { renderer.run(); }, result.timings);
  const gpu::Rgb8Pixels last = renderer.image();
  const auto changed = std::inner_product(first.rgb.begin(), first.rgb.end(), last.rgb.begin(), std::size_t{0},
                                          std::plus<>(), std::not_equal_to<>());
  result.checks.push_back(bounded_check("determinism.gpu", double(changed), 0.0, std::nullopt,
                                        "channel bytes differing between the first and the last GPU run"));
  return rgb8_buffer(first.width, first.height, first.rgb);
}

void add_image_checks(const ImageDifference& plain, const NeighbourhoodComparison& tolerant, CaseResult& result) {
  result.checks.push_back(bounded_check(
      "image.psnr.gpu_vs_cpu", -plain.psnr_db, -min_psnr_db, std::nullopt,
      fmt::format("-PSNR in dB over the RGB channels (PSNR {:.2f} dB; passes when PSNR >= {} dB)", plain.psnr_db,
                  min_psnr_db)));
  result.checks.push_back(bounded_check(
      "image.share_beyond_tolerance_outside_edges.gpu_vs_cpu", tolerant.failing_share, max_failing_share, std::nullopt,
      fmt::format("share of pixels with no match within 4/255 in the other image's 3×3 neighbourhood ({} of {})",
                  tolerant.failing_pixels, tolerant.verdicts.size())));
  result.checks.push_back(informative_check("image.max_abs.gpu_vs_cpu", plain.max_abs,
                                            fmt::format("largest |gpu - cpu| over channel values, at pixel ({}, {})",
                                                        plain.max_x, plain.max_y)));
  result.checks.push_back(informative_check("image.rms.gpu_vs_cpu", plain.rms, "RMS of gpu - cpu over channel values"));
  result.checks.push_back(informative_check("image.share_beyond_tolerance.gpu_vs_cpu", plain.share_beyond_tolerance,
                                            "share of pixels beyond 4/255 at the same pixel (edges included)"));
}

void write_image(const OIIO::ImageBuf& image, const std::filesystem::path& file) {
  if (!image.write(file.string())) throw InputError(fmt::format("cannot write {}: {}", file.string(), image.geterror()));
}

void write_pictures(const OIIO::ImageBuf& cpu, const OIIO::ImageBuf* gpu_image,
                    const NeighbourhoodComparison* tolerant, const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  const auto add = [&](const std::string& file, const std::string& caption) {
    result.artifacts.push_back({result.name + "/" + file, "image", caption});
  };
  write_image(cpu, folder / "cpu.png");
  add("cpu.png", "CPU reference (double), rounded to 8 bits");
  if (!gpu_image) return;
  write_image(*gpu_image, folder / "gpu.png");
  add("gpu.png", "GPU (GL pipeline, RGBA8 target)");
  const double scale = write_difference_heat_map(cpu, *gpu_image, folder / "gpu_vs_cpu_heat.png");
  add("gpu_vs_cpu_heat.png", fmt::format("max |gpu - cpu| over channels, white at {:.3g}", scale));
  write_verdict_mask(*tolerant, folder / "gpu_vs_cpu_mask.png");
  add("gpu_vs_cpu_mask.png", "3×3-tolerant verdicts at 4/255: grey identical, green within, blue edge shift, red fails");
}

void run_phong(const PhongCase& phong, const std::string& file, const RunOptions& options, CaseResult& result) {
  const auto& camera = phong.scene.camera;
  result.input = fmt::format("{}, {}x{} pixels", file, camera.width, camera.height);
  result.width = camera.width;
  result.height = camera.height;
  result.notes.push_back(fmt::format("eye ({:.4g}, {:.4g}, {:.4g}), near {:.4g}, far {:.4g}, light power {:.4g}",
                                     camera.eye[0], camera.eye[1], camera.eye[2], camera.near, camera.far,
                                     phong.scene.light_power));
  const OIIO::ImageBuf cpu = run_reference(phong, options, result);
  if (!options.gpu_available) {
    for (const char* name : {"image.gpu_vs_cpu", "determinism.gpu"}) {
      result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    }
    write_pictures(cpu, nullptr, nullptr, options, result);
    return;
  }
  const OIIO::ImageBuf gpu_image = run_gpu(phong, options, result);
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(cpu, gpu_image, tolerance);
  add_image_checks(compare_images(cpu, gpu_image, tolerance), tolerant, result);
  write_pictures(cpu, &gpu_image, &tolerant, options, result);
}

PreparedTwin prepare_phong(const nlohmann::json& resolved, const LoadedInput& input) {
  if (!input.mesh) throw InputError("render.phong needs a mesh input: {\"mesh\": \"path.off\"}");
  const reference::Camera camera =
      reference::orbit_camera(*input.mesh, resolved.at("azimuth_deg"), resolved.at("elevation_deg"),
                              resolved.at("fov_deg"), resolved.at("width"), resolved.at("height"));
  PhongCase phong{reference::phong_scene(*input.mesh, camera), resolved.at("subpixel_bits")};
  PreparedTwin prepared;
  prepared.run = [phong = std::move(phong), file = input.description](const nlohmann::json&, const RunOptions& options,
                                                                       CaseResult& result) {
    run_phong(phong, file, options, result);
  };
  return prepared;
}

}  // namespace

Algorithm render_phong_algorithm() {
  return {.name = "render.phong",
          .summary = "Phong-shaded mesh through a perspective camera: reference rasterizer vs the GL pipeline",
          .source = "seed 004 §2.9 (digest 004_cave.md): ambient 0.1, specular 0.3, exponent 5, light at the eye; issue 6",
          .params = &phong_specs(),
          .prepare = prepare_phong,
          .iterates = false,
          .has_field_twin = false,
          .ad_hoc_input = AdHocInput::mesh};
}

}  // namespace gt
