// What every Phong-rendered case shares (render.phong, render.terrain) and what `groundtruth
// render` draws with: one PhongScene (reference/render/phong.hpp) drawn by the reference
// rasterizer (double) and by the GL pipeline (gpu/render/phong.hpp), the images compared with
// compare/checks/image.hpp (channel values in [0, 1]).
//
// The GPU's view of a scene is compare/algorithms/render_phong.hpp's phong_draw (look included).
//
// run_phong_twins(scene, subpixel_bits, min_covered_share, input, options, result): runs one case.
//   result.input = "<input>, WxH pixels", result.width/height = the image's, a note with the camera.
//   Checks (issue 6's acceptance for rendered cases):
//     image.psnr.gpu_vs_cpu        value = -PSNR in dB (so "value <= bound" reads PSNR >= 40 dB),
//                                  bound -40; -inf when the images are identical
//     image.share_beyond_tolerance_outside_edges.gpu_vs_cpu
//                                  share of pixels failing the 3×3 neighbourhood-tolerant comparison
//                                  at 4/255 (a one-pixel shift of an edge passes), bound 0.005
//     image.max_abs.gpu_vs_cpu, image.rms.gpu_vs_cpu, image.share_beyond_tolerance.gpu_vs_cpu
//                                  informative: the plain pixel-by-pixel comparison
//     image.uncovered_share.cpu    share of the reference's pixels no triangle covers: bound
//                                  1 - min_covered_share when min_covered_share > 0, else informative
//     determinism.gpu              bytes differing between the first and the last GPU run, bound 0
//   spec (optional)              checks of each image against what is known of the scene without
//                                either twin (a probe's closed-form colours, compare/algorithms/
//                                render_probe.hpp): called with the reference's image ("cpu") and the
//                                GPU's ("gpu"), RGB8 rows top first
//   Without a GL context image.gpu_vs_cpu and determinism.gpu are `skip` and the reference still runs.
//   With options.candidate.image (run --candidate) the user's image stands where the GPU's does:
//   image.*.candidate_vs_cpu, the spec as "candidate", candidate.png and its heat map and mask;
//   determinism.candidate is not applicable (a file is read once) and the GPU does not run.
//   Timings: the reference's whole render (cpu_ms, median of cpu_reps, at least one run), the GPU's
//   clear and draw bracketed by glFinish (gpu_ms; upload and download excluded, median of gpu_reps).
//   Pictures (under options.report_dir / result.name, when set): cpu.png and gpu.png (the compared
//   images), gpu_vs_cpu_heat.png (heat map of max |gpu - cpu| over channels) and
//   gpu_vs_cpu_mask.png (verdicts: grey identical, green within 4/255, blue matched by a neighbour,
//   red failing). The report shows them side by side with the image.* metrics under them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "compare/field_twin.hpp"
#include "compare/result.hpp"
#include "reference/render/phong.hpp"

namespace gt {

inline constexpr double phong_tolerance = 4.0 / 255.0;
inline constexpr double phong_min_psnr_db = 40.0;
inline constexpr double phong_max_failing_share = 0.005;

// Spec checks of one backend's image (3 bytes per pixel, rows top first); backend "cpu" or "gpu".
using RenderedImageSpec =
    std::function<void(const std::vector<std::uint8_t>& rgb, const std::string& backend, CaseResult& result)>;

// The image.* checks (PSNR, the 3×3-tolerant share, the informative metrics) and the pictures (cpu.png,
// gpu.png, heat map, mask, the channels as fields) of any rendered pair: RGB8, rows top first, both
// width × height. Without a GPU image (nullptr), the reference's pictures alone: the caller adds
// the skipped checks.
void compare_rendered_images(int width, int height, const std::vector<std::uint8_t>& cpu_rgb,
                             const std::vector<std::uint8_t>* gpu_rgb, const RunOptions& options, CaseResult& result);

// The image.* checks compare_rendered_images makes of a GPU image (twin "gpu") or run_phong_twins of
// a candidate ("candidate"), by name: a caller without one adds them as `skip`.
std::vector<std::string> image_check_names(const std::string& twin = "gpu");

void run_phong_twins(const reference::PhongScene& scene, int subpixel_bits, double min_covered_share,
                     const std::string& input, const RunOptions& options, CaseResult& result,
                     const RenderedImageSpec& spec = {});

}  // namespace gt
