// diff-image: read both files, compare, write the pictures, print, and map the tolerant verdict
// to the exit status. Outputs are checked against the inputs before anything is computed.
#include "compare/cli/diff_image.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "compare/checks/image.hpp"
#include "compare/output_folder.hpp"
#include "core/errors.hpp"

namespace gt {

namespace {

namespace fs = std::filesystem;

constexpr int exit_passes = 0;
constexpr int exit_fails = 1;
constexpr int exit_bad_input = 2;

struct Pictures {
  fs::path heat_map, mask;
  double heat_map_scale = 0.0;
};

fs::path mask_path(const fs::path& heat_map) {
  return heat_map.parent_path() / (heat_map.stem().string() + ".mask.png");
}

// The pictures go to an existing folder and overwrite neither input; the mask, which the user did
// not name, replaces only a mask groundtruth wrote.
void check_outputs(const DiffImageOptions& options) {
  const fs::path folder = options.out.parent_path().empty() ? fs::path(".") : options.out.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw InputError(fmt::format("--out {}: the folder {} does not exist", options.out.string(), folder.string()));
  }
  for (const fs::path& output : {options.out, mask_path(options.out)}) {
    for (const fs::path& input : {options.a, options.b}) {
      if (same_file(output, input)) {
        throw InputError(fmt::format("--out {}: writing {} would overwrite the input {}", options.out.string(),
                                     output.string(), input.string()));
      }
    }
  }
  const fs::path mask = mask_path(options.out);
  if (fs::exists(fs::symlink_status(mask, error)) && !written_by_groundtruth(mask)) {
    throw InputError(fmt::format("--out {}: the verdict mask would replace {}, which groundtruth did not write; move "
                                 "it or choose another --out",
                                 options.out.string(), mask.string()));
  }
}

// "0.0392157 (10/255)": the value, and in 8-bit levels when that is informative.
std::string with_levels(double value) {
  return std::isfinite(value) ? fmt::format("{:.6g} ({:.3g}/255)", value, value * 255.0) : fmt::format("{}", value);
}

std::string share_text(double share) { return fmt::format("{:.3g} %", 100.0 * share); }

void print_paragraph(const DiffImageOptions& options, const OIIO::ImageBuf& a, const ImageDifference& strict,
                     const NeighbourhoodComparison& tolerant, const Pictures& pictures) {
  const OIIO::ImageSpec& spec = a.spec();
  fmt::print("{} vs {}: {}x{}, {} channels, tolerance {}\n", options.a.string(), options.b.string(), spec.width,
             spec.height, spec.nchannels, with_levels(strict.tolerance));
  fmt::print("  max |a-b| {} at ({}, {}) channel {}; mean {:.6g}; RMS {:.6g}; PSNR {:.6g} dB\n",
             with_levels(strict.max_abs), strict.max_x, strict.max_y, spec.channel_name(strict.max_channel),
             strict.mean_abs, strict.rms, strict.psnr_db);
  fmt::print("  strict (same pixel): {} of {} pixels beyond the tolerance ({})\n", strict.pixels_beyond_tolerance,
             strict.pixels, share_text(strict.share_beyond_tolerance));
  fmt::print("  neighbourhood-tolerant (3x3, both ways): {} pixels fail ({}): {}\n", tolerant.failing_pixels,
             share_text(tolerant.failing_share), tolerant.failing_pixels == 0 ? "PASS" : "FAIL");
  if (pictures.heat_map.empty()) return;
  fmt::print("  heat map {} (black 0, red, yellow, white at {}); mask {} (grey identical, green within tolerance, "
             "blue matched by a neighbour, red fails)\n",
             pictures.heat_map.string(), with_levels(pictures.heat_map_scale), pictures.mask.string());
}

void print_json(const DiffImageOptions& options, const OIIO::ImageBuf& a, const ImageDifference& strict,
                const NeighbourhoodComparison& tolerant, const Pictures& pictures) {
  const OIIO::ImageSpec& spec = a.spec();
  nlohmann::json out = {
      {"a", options.a.string()},
      {"b", options.b.string()},
      {"width", spec.width},
      {"height", spec.height},
      {"channels", spec.nchannels},
      {"tolerance", strict.tolerance},
      {"max_abs", strict.max_abs},
      {"max_at", {{"x", strict.max_x}, {"y", strict.max_y}, {"channel", spec.channel_name(strict.max_channel)}}},
      {"mean_abs", strict.mean_abs},
      {"rms", strict.rms},
      {"psnr_db", std::isfinite(strict.psnr_db) ? nlohmann::json(strict.psnr_db) : nlohmann::json(nullptr)},
      {"pixels", strict.pixels},
      {"strict", {{"pixels_beyond_tolerance", strict.pixels_beyond_tolerance},
                  {"share", strict.share_beyond_tolerance}}},
      {"neighbourhood", {{"failing_pixels", tolerant.failing_pixels}, {"share", tolerant.failing_share}}},
      {"passes", tolerant.failing_pixels == 0},
  };
  if (!pictures.heat_map.empty()) {
    out["heat_map"] = {{"file", pictures.heat_map.string()}, {"scale", pictures.heat_map_scale}};
    out["mask"] = pictures.mask.string();
  }
  fmt::print("{}\n", out.dump(2));
}

int compare_files(const DiffImageOptions& options) {
  if (!options.out.empty()) check_outputs(options);
  const OIIO::ImageBuf a = read_image(options.a);
  const OIIO::ImageBuf b = read_image(options.b);
  const ImageDifference strict = compare_images(a, b, options.tolerance);
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(a, b, options.tolerance);
  Pictures pictures;
  if (!options.out.empty()) {
    pictures.heat_map = options.out;
    pictures.mask = mask_path(options.out);
    pictures.heat_map_scale = write_difference_heat_map(a, b, pictures.heat_map);
    write_verdict_mask(tolerant, pictures.mask);
  }
  if (options.as_json) {
    print_json(options, a, strict, tolerant, pictures);
  } else {
    print_paragraph(options, a, strict, tolerant, pictures);
  }
  return tolerant.failing_pixels == 0 ? exit_passes : exit_fails;
}

}  // namespace

int diff_image_command(const DiffImageOptions& options) {
  try {
    return compare_files(options);
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_bad_input;
  }
}

}  // namespace gt
