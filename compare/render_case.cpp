// One Phong-rendered case: the reference and the GL pipeline on the same scene, the image checks
// and the pictures; see render_case.hpp.
#include "compare/render_case.hpp"
#include "compare/report/images.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <numeric>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <OpenImageIO/imagebuf.h>

#include "compare/algorithms/render_phong.hpp"
#include "compare/checks/image.hpp"
#include "compare/field_files.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "gpu/timing.hpp"

namespace gt {
namespace {

OIIO::ImageBuf rgb8_buffer(int width, int height, const std::vector<std::uint8_t>& rgb) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
  image.set_pixels(image.roi(), OIIO::TypeDesc::UINT8, rgb.data());
  return image;
}

OIIO::ImageBuf run_reference(const reference::PhongScene& scene, int subpixel_bits, double min_covered_share,
                             const RunOptions& options, CaseResult& result, const RenderedImageSpec& spec) {
  if (options.progress) options.progress->stage("CPU reference (double)");
  reference::Rgb8Image image;
  time_cpu(std::max(options.cpu_reps, 1), [&] { image = reference::render_phong(scene, subpixel_bits); },
           result.timings);
  const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
  const double uncovered = double(pixels - image.covered_pixels) / double(pixels);
  const std::string detail = fmt::format("share of pixels no triangle covers ({} of {})", pixels - image.covered_pixels, pixels);
  result.checks.push_back(min_covered_share > 0.0
                              ? bounded_check("image.uncovered_share.cpu", uncovered, 1.0 - min_covered_share,
                                              std::nullopt, detail + fmt::format("; the camera must see the mesh on at "
                                                                                 "least {:g} of the picture",
                                                                                 min_covered_share))
                              : informative_check("image.uncovered_share.cpu", uncovered, detail));
  if (spec) spec(image.rgb, "cpu", result);
  return rgb8_buffer(image.width, image.height, image.rgb);
}

OIIO::ImageBuf run_gpu(const reference::PhongScene& scene, const RunOptions& options, CaseResult& result,
                       const RenderedImageSpec& spec) {
  if (options.progress) options.progress->stage("GPU");
  const gpu::PhongRenderer renderer(phong_draw(scene));
  renderer.run();
  const gpu::Rgb8Pixels first = renderer.image();
  time_gpu(options.gpu_reps, [&] { renderer.run(); }, result.timings);
  const gpu::Rgb8Pixels last = renderer.image();
  const auto changed = std::inner_product(first.rgb.begin(), first.rgb.end(), last.rgb.begin(), std::size_t{0},
                                          std::plus<>(), std::not_equal_to<>());
  result.checks.push_back(bounded_check("determinism.gpu", double(changed), 0.0, std::nullopt,
                                        "channel bytes differing between the first and the last GPU run"));
  if (spec) spec(first.rgb, "gpu", result);
  return rgb8_buffer(first.width, first.height, first.rgb);
}

// The image being graded against the reference: the GPU twin's or a user's (run --candidate).
struct GradedImage {
  const OIIO::ImageBuf& image;
  std::string twin;     // "gpu" or "candidate": the checks' and pictures' names
  std::string made_by;  // for captions and field files
};

}  // namespace

std::vector<std::string> image_check_names(const std::string& twin) {
  std::vector<std::string> names;
  for (const char* metric : {"psnr", "share_beyond_tolerance_outside_edges", "max_abs", "rms", "share_beyond_tolerance"}) {
    names.push_back(fmt::format("image.{}.{}_vs_cpu", metric, twin));
  }
  return names;
}

namespace {

void add_image_checks(const ImageDifference& plain, const NeighbourhoodComparison& tolerant, const std::string& twin,
                      CaseResult& result) {
  const auto name = [&](const char* metric) { return fmt::format("image.{}.{}_vs_cpu", metric, twin); };
  result.checks.push_back(bounded_check(
      name("psnr"), -plain.psnr_db, -phong_min_psnr_db, std::nullopt,
      fmt::format("-PSNR in dB over the RGB channels (PSNR {:.2f} dB; passes when PSNR >= {} dB)", plain.psnr_db,
                  phong_min_psnr_db)));
  result.checks.push_back(bounded_check(
      name("share_beyond_tolerance_outside_edges"), tolerant.failing_share, phong_max_failing_share, std::nullopt,
      fmt::format("share of pixels with no match within 4/255 in the other image's 3×3 neighbourhood ({} of {})",
                  tolerant.failing_pixels, tolerant.verdicts.size())));
  result.checks.push_back(informative_check(name("max_abs"), plain.max_abs,
                                            fmt::format("largest |{} - cpu| over channel values, at pixel ({}, {})",
                                                        twin, plain.max_x, plain.max_y)));
  result.checks.push_back(
      informative_check(name("rms"), plain.rms, fmt::format("RMS of {} - cpu over channel values", twin)));
  result.checks.push_back(informative_check(name("share_beyond_tolerance"), plain.share_beyond_tolerance,
                                            "share of pixels beyond 4/255 at the same pixel (edges included)"));
}

void write_image(const OIIO::ImageBuf& image, const std::filesystem::path& file) {
  if (!image.write(file.string())) throw InputError(fmt::format("cannot write {}: {}", file.string(), image.geterror()));
}

// Fields as data (compare/field_files.hpp): each colour channel of a rendered image, 8-bit levels
// as OpenImageIO reads them (level / 255), row 0 at the top as in the picture.
void write_image_fields(const OIIO::ImageBuf& image, const std::string& backend, const std::string& made_by,
                        const RunOptions& options, CaseResult& result) {
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<float> pixels(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  image.get_pixels(image.roi(), OIIO::TypeDesc::FLOAT, pixels.data());
  const char* channels[] = {"red", "green", "blue"};
  for (int channel = 0; channel < 3 && channel < spec.nchannels; ++channel) {
    Grid<double> values(spec.width, spec.height);
    values.horizontal_unit = "pixel";
    for (std::size_t i = 0; i < values.size(); ++i) values.values[i] = pixels[i * spec.nchannels + channel];
    write_field_files(values,
                      {fmt::format("{}_{}", channels[channel], backend), channels[channel], backend, "1",
                       fmt::format("{} channel of the rendered image, {} (8-bit level / 255, row 0 at the top)",
                                   channels[channel], made_by)},
                      options, result);
  }
}

void write_pictures(const OIIO::ImageBuf& cpu, const GradedImage* graded, const NeighbourhoodComparison* tolerant,
                    const RunOptions& options, CaseResult& result) {
  if (options.report_dir.empty()) return;
  write_image_fields(cpu, "cpu", "CPU reference (double)", options, result);
  if (graded) write_image_fields(graded->image, graded->twin, graded->made_by, options, result);
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  write_image(cpu, folder / "cpu.png");
  add_picture(result, "cpu.png", "CPU reference (double), rounded to 8 bits");
  if (!graded) return;
  const std::string& twin = graded->twin;
  write_image(graded->image, folder / (twin + ".png"));
  add_picture(result, twin + ".png", graded->made_by);
  const double scale = write_difference_heat_map(cpu, graded->image, folder / (twin + "_vs_cpu_heat.png"));
  add_picture(result, twin + "_vs_cpu_heat.png", fmt::format("max |{} - cpu| over channels: black 0, white the largest", twin),
              sampled_scale("heat", 0.0, scale, "of full range", [scale](double difference) { return heat_colour(difference, scale); }));
  write_verdict_mask(*tolerant, folder / (twin + "_vs_cpu_mask.png"));
  add_picture(result, twin + "_vs_cpu_mask.png",
      "3×3-tolerant verdicts at 4/255: grey identical, green within, blue edge shift, red fails");
}

// The image checks and pictures of a pair, or the reference's pictures alone without a graded image.
void compare_images_and_picture(const OIIO::ImageBuf& cpu, const GradedImage* graded, const RunOptions& options,
                                CaseResult& result) {
  if (!graded) {
    write_pictures(cpu, nullptr, nullptr, options, result);
    return;
  }
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(cpu, graded->image, phong_tolerance);
  add_image_checks(compare_images(cpu, graded->image, phong_tolerance), tolerant, graded->twin, result);
  write_pictures(cpu, graded, &tolerant, options, result);
}

// A user's image (run --candidate) where the GPU's stands: the same image checks and the spec,
// named `candidate`; nothing to time and nothing to repeat.
void grade_candidate_image(const OIIO::ImageBuf& cpu, const CandidateImage& candidate, const RunOptions& options,
                           CaseResult& result, const RenderedImageSpec& spec) {
  result.notes.push_back(fmt::format("graded: {}, standing where the GPU twin stands{}", candidate.file.string(),
                                     candidate.notes.empty() ? "" : fmt::format(" ({})", fmt::join(candidate.notes, "; "))));
  result.checks.push_back(
      not_applicable_check("determinism.candidate", "a file is read once: run your renderer twice and compare the files"));
  if (spec) spec(candidate.rgb, "candidate", result);
  const OIIO::ImageBuf image = rgb8_buffer(candidate.width, candidate.height, candidate.rgb);
  const GradedImage graded{image, "candidate", "candidate " + candidate.file.filename().string()};
  compare_images_and_picture(cpu, &graded, options, result);
}

}  // namespace

void compare_rendered_images(int width, int height, const std::vector<std::uint8_t>& cpu_rgb,
                             const std::vector<std::uint8_t>* gpu_rgb, const RunOptions& options, CaseResult& result) {
  const OIIO::ImageBuf cpu = rgb8_buffer(width, height, cpu_rgb);
  if (!gpu_rgb) return compare_images_and_picture(cpu, nullptr, options, result);
  const OIIO::ImageBuf gpu_image = rgb8_buffer(width, height, *gpu_rgb);
  const GradedImage graded{gpu_image, "gpu", "GPU (GL pipeline, RGBA8 target)"};
  compare_images_and_picture(cpu, &graded, options, result);
}

void run_phong_twins(const reference::PhongScene& scene, int subpixel_bits, double min_covered_share,
                     const std::string& input, const RunOptions& options, CaseResult& result,
                     const RenderedImageSpec& spec) {
  const auto& camera = scene.camera;
  result.input = fmt::format("{}, {}x{} pixels", input, camera.width, camera.height);
  result.width = camera.width;
  result.height = camera.height;
  result.notes.push_back(fmt::format("eye ({:.4g}, {:.4g}, {:.4g}), target ({:.4g}, {:.4g}, {:.4g}), near {:.4g}, far "
                                     "{:.4g}, light power {:.4g}, {} triangles",
                                     camera.eye[0], camera.eye[1], camera.eye[2], camera.target[0], camera.target[1],
                                     camera.target[2], camera.near, camera.far, scene.light_power,
                                     scene.mesh.triangles.size()));
  const OIIO::ImageBuf cpu = run_reference(scene, subpixel_bits, min_covered_share, options, result, spec);
  if (options.candidate.image) return grade_candidate_image(cpu, *options.candidate.image, options, result, spec);
  if (!options.gpu_available) {
    for (const auto& name : image_check_names()) result.checks.push_back(skipped_check(name, options.gpu_unavailable_reason));
    result.checks.push_back(skipped_check("determinism.gpu", options.gpu_unavailable_reason));
    compare_images_and_picture(cpu, nullptr, options, result);
    return;
  }
  const OIIO::ImageBuf gpu_image = run_gpu(scene, options, result, spec);
  const GradedImage graded{gpu_image, "gpu", "GPU (GL pipeline, RGBA8 target)"};
  compare_images_and_picture(cpu, &graded, options, result);
}

}  // namespace gt
