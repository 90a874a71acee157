// Tests of the image differences (compare/checks/image.hpp) and of `groundtruth diff-image`
// (compare/cli/diff_image.hpp), on 8-bit images built here whose answers are known:
//   - one pixel off by 10 levels: max, mean, RMS and PSNR by formula, one pixel beyond 4/255;
//   - differences of exactly 4 levels at every base level stay within 4/255 (the tie slack);
//   - the same numbers as OpenImageIO's idiff prints for a pair of PNGs (skipped without idiff);
//   - a scene shifted by one pixel: the strict count equals the pixels whose left neighbour has
//     another colour, the neighbourhood-tolerant count is 0; a brightened patch on top of the
//     shift fails the tolerant comparison on exactly the patch; the mask's colours say so;
//   - the heat map's colour scale; refusals of mismatched, missing and non-image files;
//   - the executable's exit codes (0 pass, 1 tolerant failures, 2 bad input), its JSON and its
//     output files, run with posix_spawn as a user runs it.
//
// 8-bit levels read by OpenImageIO are the floats k * (1/255f). Each carries a rounding error of
// at most 2^-24 (the error of 1/255f, 2^-24 relative, plus the product's, 2^-25 relative, for a
// value below 1), so a difference of two levels is off by at most 2^-23 from (j - k)/255; the
// bounds below start from this `level_rounding` and say how it propagates.

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <numbers>
#include <optional>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/checks/image.hpp"
#include "core/errors.hpp"
#include "tests/support/refusal.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using testing::ProgramRun;
using testing::read_text;
using testing::refusal;
using testing::run_program;
using testing::TemporaryFolder;

constexpr double level = 1.0 / 255.0;
constexpr double level_rounding = 0x1p-23;  // |float difference of two levels - exact difference|
constexpr double default_tolerance = 4.0 * level;
const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const fs::path idiff = "/usr/bin/idiff";

// ---- images built here ---------------------------------------------------------------------

using Rgb = std::array<int, 3>;

// An 8-bit image as levels 0..255, row-major, channels interleaved.
struct Levels {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> values;

  Levels(int width_, int height_, int channels_, int fill)
      : width(width_), height(height_), channels(channels_),
        values(static_cast<std::size_t>(width_) * height_ * channels_, static_cast<std::uint8_t>(fill)) {}

  std::uint8_t& at(int x, int y, int c) { return values[(static_cast<std::size_t>(y) * width + x) * channels + c]; }
  std::uint8_t at(int x, int y, int c) const {
    return values[(static_cast<std::size_t>(y) * width + x) * channels + c];
  }
  void set(int x, int y, const Rgb& colour) {
    for (int c = 0; c < channels; ++c) at(x, y, c) = static_cast<std::uint8_t>(colour[c]);
  }

  OIIO::ImageBuf image() const {
    OIIO::ImageBuf buffer(OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::UINT8));
    buffer.set_pixels(buffer.roi(), OIIO::TypeDesc::UINT8, values.data());
    return buffer;
  }
  fs::path write_png(const fs::path& file) const {
    if (!image().write(file.string())) ADD_FAILURE() << "cannot write " << file;
    return file;
  }
};

// 40x32 RGB: a background, a rectangle and a disc, each of one colour, every colour at least 30
// levels from the others in some channel (so far beyond the 4-level tolerance), the shapes at
// least 5 pixels from the border and from `patch`.
constexpr Rgb background = {60, 90, 120};
constexpr Rgb rectangle_colour = {200, 40, 40};
constexpr Rgb disc_colour = {30, 180, 60};
constexpr int scene_width = 40, scene_height = 32;

struct Box {
  int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
  bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
  int area() const { return (x1 - x0) * (y1 - y0); }
};
constexpr Box rectangle = {8, 6, 20, 18};
constexpr Box patch = {29, 2, 34, 6};
constexpr int patch_brightening = 40;  // levels added to the background: 100, 130, 160 matches no colour

Levels scene() {
  Levels levels(scene_width, scene_height, 3, 0);
  for (int y = 0; y < scene_height; ++y) {
    for (int x = 0; x < scene_width; ++x) {
      const bool in_disc = (x - 28) * (x - 28) + (y - 20) * (y - 20) <= 36;
      levels.set(x, y, rectangle.contains(x, y) ? rectangle_colour : in_disc ? disc_colour : background);
    }
  }
  return levels;
}

// Everything moved one pixel to the right; column 0 keeps its (background) colour.
Levels shifted_right(const Levels& original) {
  Levels shifted = original;
  for (int y = 0; y < original.height; ++y) {
    for (int x = 1; x < original.width; ++x) {
      for (int c = 0; c < original.channels; ++c) shifted.at(x, y, c) = original.at(x - 1, y, c);
    }
  }
  return shifted;
}

Levels with_brightened_patch(Levels levels) {
  for (int y = patch.y0; y < patch.y1; ++y) {
    for (int x = patch.x0; x < patch.x1; ++x) {
      levels.set(x, y, {background[0] + patch_brightening, background[1] + patch_brightening,
                        background[2] + patch_brightening});
    }
  }
  return levels;
}

// Pixels whose left neighbour has another colour: those a one-pixel shift to the right changes.
std::size_t horizontal_colour_changes(const Levels& levels) {
  std::size_t changes = 0;
  for (int y = 0; y < levels.height; ++y) {
    for (int x = 1; x < levels.width; ++x) {
      bool differs = false;
      for (int c = 0; c < levels.channels; ++c) differs = differs || levels.at(x, y, c) != levels.at(x - 1, y, c);
      changes += differs ? 1 : 0;
    }
  }
  return changes;
}

// 64x48 RGB of pseudo-random levels, and a copy where every seventh channel value moves by up
// to 12 levels either way (clamped): a pair with differences of many sizes for idiff.
std::pair<Levels, Levels> noisy_pair() {
  Levels a(64, 48, 3, 0);
  std::uint32_t state = 12345;
  const auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  for (auto& value : a.values) value = static_cast<std::uint8_t>(next() >> 24);
  Levels b = a;
  for (std::size_t i = 0; i < b.values.size(); i += 7) {
    const int moved = static_cast<int>(b.values[i]) + static_cast<int>(next() >> 27) - 12;
    b.values[i] = static_cast<std::uint8_t>(std::clamp(moved, 0, 255));
  }
  return {a, b};
}

std::vector<std::uint8_t> read_png_levels(const fs::path& file) {
  OIIO::ImageBuf image = read_image(file);
  std::vector<std::uint8_t> levels(image.spec().image_pixels() * image.spec().nchannels);
  image.get_pixels(image.roi(), OIIO::TypeDesc::UINT8, levels.data());
  return levels;
}

Rgb png_pixel(const std::vector<std::uint8_t>& rgb, int width, int x, int y) {
  const std::size_t at = (static_cast<std::size_t>(y) * width + x) * 3;
  return {rgb[at], rgb[at + 1], rgb[at + 2]};
}

// ---- running programs --------------------------------------------------------------------------

ProgramRun diff_image(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"diff-image"};
  all.insert(all.end(), args.begin(), args.end());
  return run_program(groundtruth, all);
}

// ---- idiff ---------------------------------------------------------------------------------

// idiff prints with 6 significant digits: the printed value is within half a unit of the 6th.
double printed_rounding(double value) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(std::abs(value))) - 5.0);
}

// The number after `label` in idiff's report.
std::optional<double> idiff_number(const std::string& report, const std::string& label) {
  std::smatch match;
  if (!std::regex_search(report, match, std::regex(label + R"(\s*=\s*([-+0-9.eE]+|inf))"))) return std::nullopt;
  return std::stod(match[1]);
}

// ---- metrics with known answers ----------------------------------------------------------------

TEST(ImageMetrics, OnePixelOffByTenLevelsGivesTheFormulaValues) {
  Levels a(4, 4, 3, 100);
  Levels b = a;
  b.at(2, 1, 0) = 110;
  const ImageDifference difference = compare_images(a.image(), b.image(), default_tolerance);

  // One of 48 channel values differs, by d = 10/255 (within level_rounding): mean d/48,
  // RMS d/sqrt(48), PSNR 20 log10(1/RMS); their errors scale the same way, and PSNR's error is
  // 20/ln(10) times RMS's relative error.
  const double d = 10.0 * level, values = 48.0;
  EXPECT_NEAR(difference.max_abs, d, level_rounding);
  EXPECT_EQ(difference.max_x, 2);
  EXPECT_EQ(difference.max_y, 1);
  EXPECT_EQ(difference.max_channel, 0);
  EXPECT_NEAR(difference.mean_abs, d / values, level_rounding / values);
  const double rms = d / std::sqrt(values), rms_error = level_rounding / std::sqrt(values);
  EXPECT_NEAR(difference.rms, rms, rms_error);
  EXPECT_NEAR(difference.psnr_db, 20.0 * std::log10(1.0 / rms), 20.0 / std::numbers::ln10 * rms_error / rms);
  EXPECT_EQ(difference.pixels, 16u);
  EXPECT_EQ(difference.pixels_beyond_tolerance, 1u);
  EXPECT_DOUBLE_EQ(difference.share_beyond_tolerance, 1.0 / 16.0);

  // a(2,1) = 110 has no neighbour of 110 in b; b's 100 everywhere has one in a.
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(a.image(), b.image(), default_tolerance);
  EXPECT_EQ(tolerant.failing_pixels, 1u);
  EXPECT_DOUBLE_EQ(tolerant.failing_share, 1.0 / 16.0);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      EXPECT_EQ(tolerant.verdicts[y * 4 + x], x == 2 && y == 1 ? PixelVerdict::fails : PixelVerdict::identical);
    }
  }
}

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnrAndNoFailures) {
  const Levels a = scene();
  const ImageDifference difference = compare_images(a.image(), a.image(), default_tolerance);
  EXPECT_EQ(difference.max_abs, 0.0);
  EXPECT_EQ(difference.rms, 0.0);
  EXPECT_EQ(difference.psnr_db, std::numeric_limits<double>::infinity());
  EXPECT_EQ(difference.pixels_beyond_tolerance, 0u);
}

// The float difference of two levels 4 apart lands up to 6e-8 on either side of the float 4/255
// (21 of the 252 pairs above it); every one of them must count as within a 4/255 tolerance, and
// every 5-level difference as beyond it.
TEST(ImageMetrics, ADifferenceOfExactlyTheToleranceIsWithinItAtEveryLevel) {
  Levels base(252, 1, 1, 0);
  for (int x = 0; x < 252; ++x) base.at(x, 0, 0) = static_cast<std::uint8_t>(x);
  Levels four_up = base, five_up = base;
  for (int x = 0; x < 252; ++x) {
    four_up.at(x, 0, 0) = static_cast<std::uint8_t>(x + 4);
    five_up.at(x, 0, 0) = static_cast<std::uint8_t>(x + 5 > 255 ? 255 : x + 5);
  }
  EXPECT_EQ(compare_images(base.image(), four_up.image(), default_tolerance).pixels_beyond_tolerance, 0u);
  // x = 251 clamps to 255, 4 levels up: 251 of the 252 pixels are beyond.
  EXPECT_EQ(compare_images(base.image(), five_up.image(), default_tolerance).pixels_beyond_tolerance, 251u);
}

TEST(ImageMetrics, AgreeWithIdiff) {
  if (!fs::exists(idiff)) GTEST_SKIP() << idiff << " is missing (package openimageio-tools, scripts/install-deps.sh)";
  const TemporaryFolder folder("gt_image_diff_idiff");
  const auto [a, b] = noisy_pair();
  const fs::path a_png = a.write_png(folder.path() / "a.png"), b_png = b.write_png(folder.path() / "b.png");
  // Between levels 4 and 5, so that idiff's count (no tie slack) and ours must agree.
  const double tolerance = 4.5 * level;
  const std::string threshold = fmt::format("{:.9g}", tolerance);
  const ProgramRun run =
      run_program(idiff.string(), {"-fail", threshold, "-warn", threshold, a_png.string(), b_png.string()});
  ASSERT_NE(run.status, -1) << run;

  const ImageDifference ours = compare_images(read_image(a_png), read_image(b_png), tolerance);
  for (const auto& [label, value] : {std::pair{"Mean error", ours.mean_abs}, std::pair{"RMS error", ours.rms},
                                     std::pair{"Peak SNR", ours.psnr_db}, std::pair{"Max error", ours.max_abs}}) {
    const auto printed = idiff_number(run.out, label);
    ASSERT_TRUE(printed.has_value()) << label << " missing in\n" << run;
    EXPECT_NEAR(value, *printed, printed_rounding(*printed)) << label << "\n" << run;
  }
  std::smatch count;
  ASSERT_TRUE(std::regex_search(run.out, count, std::regex(R"((\d+) pixels \([^)]*\) over)"))) << run;
  EXPECT_EQ(ours.pixels_beyond_tolerance, std::stoul(count[1])) << run;
  EXPECT_GT(ours.pixels_beyond_tolerance, 0u);
}

// ---- neighbourhood tolerance ---------------------------------------------------------------

TEST(NeighbourhoodComparison, AOnePixelShiftFailsStrictlyButPassesTolerantly) {
  const Levels a = scene(), b = shifted_right(a);
  const ImageDifference strict = compare_images(a.image(), b.image(), default_tolerance);
  // Two colour changes per row: 12 rows of the rectangle, 13 of the disc (|y - 20| <= 6).
  EXPECT_EQ(horizontal_colour_changes(a), 2u * (12u + 13u));
  EXPECT_EQ(strict.pixels_beyond_tolerance, horizontal_colour_changes(a));
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(a.image(), b.image(), default_tolerance);
  EXPECT_EQ(tolerant.failing_pixels, 0u);
  EXPECT_EQ(std::count(tolerant.verdicts.begin(), tolerant.verdicts.end(), PixelVerdict::matched_by_neighbour),
            static_cast<std::ptrdiff_t>(strict.pixels_beyond_tolerance));
}

TEST(NeighbourhoodComparison, AChangedShadingPatchFailsExactlyOnThePatch) {
  const Levels a = scene(), b = with_brightened_patch(shifted_right(a));
  const NeighbourhoodComparison tolerant = compare_neighbourhoods(a.image(), b.image(), default_tolerance);
  EXPECT_EQ(tolerant.failing_pixels, static_cast<std::size_t>(patch.area()));
  for (int y = 0; y < scene_height; ++y) {
    for (int x = 0; x < scene_width; ++x) {
      EXPECT_EQ(tolerant.verdicts[y * scene_width + x] == PixelVerdict::fails, patch.contains(x, y))
          << "at (" << x << ", " << y << ")";
    }
  }
}

TEST(NeighbourhoodComparison, TheMaskShowsEachVerdictInItsColour) {
  const TemporaryFolder folder("gt_image_diff_mask");
  const Levels a = scene(), b = with_brightened_patch(shifted_right(a));
  const fs::path mask = folder.path() / "mask.png";
  write_verdict_mask(compare_neighbourhoods(a.image(), b.image(), default_tolerance), mask);
  const auto rgb = read_png_levels(mask);
  EXPECT_EQ(png_pixel(rgb, scene_width, patch.x0, patch.y0), (Rgb{255, 0, 0}));   // fails: red
  EXPECT_EQ(png_pixel(rgb, scene_width, rectangle.x0, 10), (Rgb{38, 115, 255}));  // shifted edge: blue
  EXPECT_EQ(png_pixel(rgb, scene_width, 2, 28), (Rgb{128, 128, 128}));            // background: grey
  EXPECT_EQ(folder.entries().size(), 1u) << "a temporary file was left behind";
}

// ---- heat map ------------------------------------------------------------------------------

TEST(HeatMap, BlackRedYellowWhiteOverTheScale) {
  const TemporaryFolder folder("gt_image_diff_heat");
  Levels a(3, 1, 3, 100);
  Levels b = a;
  b.at(1, 0, 1) = 105;  // d = 5/255
  b.at(2, 0, 2) = 90;   // d = 10/255, the largest
  const fs::path automatic = folder.path() / "automatic.png", fixed = folder.path() / "fixed.png";

  // Automatic scale, the largest d: pixel 1 at half of it, 1.5 stops up, between red and
  // yellow (green 127.5, so 127 or 128 after the float ratio of two rounded differences).
  EXPECT_NEAR(write_difference_heat_map(a.image(), b.image(), automatic), 10.0 * level, level_rounding);
  const auto heat = read_png_levels(automatic);
  EXPECT_EQ(png_pixel(heat, 3, 0, 0), (Rgb{0, 0, 0}));
  EXPECT_THAT(png_pixel(heat, 3, 1, 0)[1], ::testing::AllOf(::testing::Ge(127), ::testing::Le(128)));
  EXPECT_EQ(png_pixel(heat, 3, 1, 0)[0], 255);
  EXPECT_EQ(png_pixel(heat, 3, 1, 0)[2], 0);
  EXPECT_EQ(png_pixel(heat, 3, 2, 0), (Rgb{255, 255, 255}));

  // Scale 20/255: pixel 2 at half (as pixel 1 above), pixel 1 at a quarter: 0.75 of the way
  // from black to red (191.25 -> 191).
  EXPECT_EQ(write_difference_heat_map(a.image(), b.image(), fixed, 20.0 * level), 20.0 * level);
  const auto scaled = read_png_levels(fixed);
  EXPECT_EQ(png_pixel(scaled, 3, 1, 0), (Rgb{191, 0, 0}));
  EXPECT_THAT(png_pixel(scaled, 3, 2, 0)[1], ::testing::AllOf(::testing::Ge(127), ::testing::Le(128)));
}

// ---- refusals ------------------------------------------------------------------------------

TEST(ImageRefusals, MismatchedSizesAndChannelsAndBadFilesAreInputErrors) {
  const TemporaryFolder folder("gt_image_diff_refusals");
  const fs::path wide = Levels(8, 4, 3, 0).write_png(folder.path() / "wide.png");
  const fs::path tall = Levels(4, 8, 3, 0).write_png(folder.path() / "tall.png");
  const fs::path grey = Levels(8, 4, 1, 0).write_png(folder.path() / "grey.png");
  const fs::path text = folder.path() / "text.png";
  std::ofstream(text) << "not an image\n";

  const std::string sizes = refusal([&] { compare_images(read_image(wide), read_image(tall), default_tolerance); });
  EXPECT_THAT(sizes, HasSubstr(wide.string()));
  EXPECT_THAT(sizes, HasSubstr(tall.string()));
  EXPECT_THAT(sizes, HasSubstr("8x4 against 4x8"));
  const std::string channels = refusal([&] { compare_neighbourhoods(read_image(wide), read_image(grey), 0.0); });
  EXPECT_THAT(channels, HasSubstr("differ in channels: 3 (R,G,B) against 1"));
  EXPECT_THAT(refusal([&] { read_image(folder.path() / "missing.png"); }), HasSubstr("no such file"));
  EXPECT_THAT(refusal([&] { read_image(text); }), HasSubstr(text.string()));
}

// ---- the executable ------------------------------------------------------------------------

class DiffImageCommand : public ::testing::Test {
 protected:
  TemporaryFolder folder{"gt_image_diff_cli"};
  fs::path path(const std::string& name) const { return folder.path() / name; }
};

TEST_F(DiffImageCommand, IdenticalImagesPass) {
  const std::string a = scene().write_png(path("a.png")).string();
  const ProgramRun run = diff_image({a, a});
  EXPECT_EQ(run.status, 0) << run;
  EXPECT_THAT(run.out, HasSubstr("PSNR inf dB"));
  EXPECT_THAT(run.out, HasSubstr("0 pixels fail"));
}

TEST_F(DiffImageCommand, AShiftPassesWithTheStrictCountInTheJson) {
  const Levels a = scene();
  const std::string a_png = a.write_png(path("a.png")).string();
  const std::string b_png = shifted_right(a).write_png(path("b.png")).string();
  const ProgramRun run = diff_image({a_png, b_png, "--json"});
  ASSERT_EQ(run.status, 0) << run;
  const auto report = nlohmann::json::parse(run.out);
  const ImageDifference library = compare_images(read_image(a_png), read_image(b_png), default_tolerance);
  EXPECT_EQ(report.at("rms").get<double>(), library.rms);
  EXPECT_EQ(report.at("psnr_db").get<double>(), library.psnr_db);
  EXPECT_EQ(report.at("max_abs").get<double>(), library.max_abs);
  EXPECT_EQ(report.at("strict").at("pixels_beyond_tolerance").get<std::size_t>(), horizontal_colour_changes(a));
  EXPECT_EQ(report.at("neighbourhood").at("failing_pixels"), 0);
  EXPECT_EQ(report.at("passes"), true);
  EXPECT_DOUBLE_EQ(report.at("tolerance").get<double>(), default_tolerance);
}

TEST_F(DiffImageCommand, APatchFailsAndWritesTheHeatMapAndTheMask) {
  const Levels a = scene();
  const std::string a_png = a.write_png(path("a.png")).string();
  const std::string b_png = with_brightened_patch(a).write_png(path("b.png")).string();
  const ProgramRun run = diff_image({a_png, b_png, "--out", path("diff.png").string()});
  EXPECT_EQ(run.status, 1) << run;
  EXPECT_THAT(run.out, HasSubstr(fmt::format("{} pixels fail", patch.area())));
  EXPECT_TRUE(fs::exists(path("diff.png")));
  EXPECT_TRUE(fs::exists(path("diff.mask.png")));
  EXPECT_EQ(folder.entries().size(), 4u) << "a temporary file was left behind";
  // A tolerance above the patch's 40 levels lets it pass.
  EXPECT_EQ(diff_image({a_png, b_png, "--tolerance", fmt::format("{}", 40.5 * level)}).status, 0);
}

TEST_F(DiffImageCommand, BadInputExitsTwoAndWritesNothing) {
  const std::string wide = Levels(8, 4, 3, 0).write_png(path("wide.png")).string();
  const std::string tall = Levels(4, 8, 3, 0).write_png(path("tall.png")).string();
  const ProgramRun sizes = diff_image({wide, tall, "--out", path("diff.png").string()});
  EXPECT_EQ(sizes.status, 2) << sizes;
  EXPECT_THAT(sizes.err, StartsWith("groundtruth: "));
  EXPECT_THAT(sizes.err, HasSubstr("8x4 against 4x8"));
  EXPECT_EQ(folder.entries().size(), 2u);

  const ProgramRun missing = diff_image({wide, path("missing.png").string()});
  EXPECT_EQ(missing.status, 2) << missing;
  EXPECT_THAT(missing.err, HasSubstr("missing.png"));

  const ProgramRun negative = diff_image({wide, wide, "--tolerance", "-1"});
  EXPECT_EQ(negative.status, 2) << negative;

  const ProgramRun no_folder = diff_image({wide, wide, "--out", path("missing/diff.png").string()});
  EXPECT_EQ(no_folder.status, 2) << no_folder;
  EXPECT_THAT(no_folder.err, HasSubstr("does not exist"));
  EXPECT_EQ(folder.entries().size(), 2u);
}

// The mask is a second file the user did not name: it replaces a mask diff-image wrote (a rerun
// into the same --out) but never a picture of the user's that has its name.
TEST_F(DiffImageCommand, TheMaskReplacesOnlyAMaskGroundtruthWrote) {
  const Levels a = scene();
  const std::string a_png = a.write_png(path("a.png")).string();
  const std::string b_png = with_brightened_patch(a).write_png(path("b.png")).string();
  const std::string users = shifted_right(a).write_png(path("d.mask.png")).string();
  const std::string before = read_text(users);
  const ProgramRun refused = diff_image({a_png, b_png, "--out", path("d.png").string()});
  EXPECT_EQ(refused.status, 2) << refused;
  EXPECT_THAT(refused.err, HasSubstr("which groundtruth did not write"));
  EXPECT_EQ(read_text(users), before);
  EXPECT_FALSE(fs::exists(path("d.png")));

  const std::string ours = path("e.png").string();
  ASSERT_EQ(diff_image({a_png, b_png, "--out", ours}).status, 1);
  EXPECT_TRUE(written_by_groundtruth(path("e.mask.png")));
  EXPECT_FALSE(written_by_groundtruth(users));
  EXPECT_EQ(diff_image({a_png, a_png, "--out", ours}).status, 0) << "a rerun replaces its own mask";
}

TEST_F(DiffImageCommand, AnOutputNamingAnInputIsRefused) {
  const Levels a = scene();
  const std::string a_png = a.write_png(path("a.png")).string();
  const std::string b_png = shifted_right(a).write_png(path("b.png")).string();
  const std::string before = read_text(b_png);
  const ProgramRun run = diff_image({a_png, b_png, "--out", b_png});
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("would overwrite the input"));
  EXPECT_EQ(read_text(b_png), before);
  // The mask's name, <stem>.mask.png, is checked too.
  const std::string mask_named = with_brightened_patch(a).write_png(path("c.mask.png")).string();
  EXPECT_EQ(diff_image({a_png, mask_named, "--out", path("c.png").string()}).status, 2);
}

}  // namespace
}  // namespace gt
