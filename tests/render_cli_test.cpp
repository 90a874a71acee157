// End-to-end tests of `groundtruth render` (compare/cli/render.hpp), run as a user runs it
// (tests/support/run_program.hpp: posix_spawn, no shell, a fresh folder): a mesh and a heightmap to
// PNG on both twins, and every refusal of the issue — unreadable or empty input, a camera inside a
// closed mesh, a camera that sees nothing, bad sizes, outputs that would overwrite the input or
// cannot be written, no GL context for --backend gpu — each exit 2 with a message and no file.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <fmt/format.h>
#include <OpenImageIO/imageio.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compare/checks/image.hpp"
#include "tests/support/run_program.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using gt::testing::ProgramRun;
using gt::testing::read_text;
using TempDir = gt::testing::TemporaryFolder;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const fs::path volcano = fs::path(GT_DATASET_DIR) / "real" / "volcano.json";

ProgramRun render(const TempDir& work, const std::vector<std::string>& args, const gt::testing::EnvChanges& env = {}) {
  std::vector<std::string> arguments = {"render"};
  arguments.insert(arguments.end(), args.begin(), args.end());
  return gt::testing::run_program(groundtruth, arguments, work.path(), env);
}

void write_text(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

// The cube [-1, 1]³, outward counter-clockwise triangles (or all reversed: a room seen from inside).
std::string cube_off(bool inward = false) {
  std::string text = "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) text += fmt::format("{} {} {}\n", (i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1);
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  for (const auto& f : faces) text += inward ? fmt::format("3 {} {} {}\n", f[0], f[2], f[1]) : fmt::format("3 {} {} {}\n", f[0], f[1], f[2]);
  return text;
}

struct Png {
  int width = 0, height = 0, channels = 0;
  std::vector<std::uint8_t> pixels;
  const std::uint8_t* at(int x, int y) const { return &pixels[(std::size_t(y) * width + x) * channels]; }
  bool black(int x, int y) const { return at(x, y)[0] == 0 && at(x, y)[1] == 0 && at(x, y)[2] == 0; }
};

Png read_png(const fs::path& file) {
  auto input = OIIO::ImageInput::open(file.string());
  if (!input) throw std::runtime_error("cannot open " + file.string());
  const OIIO::ImageSpec& spec = input->spec();
  Png png{spec.width, spec.height, spec.nchannels, {}};
  png.pixels.resize(std::size_t(spec.width) * spec.height * spec.nchannels);
  input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, png.pixels.data());
  return png;
}

std::vector<std::string> names_in(const TempDir& work) {
  std::vector<std::string> names;
  for (const auto& entry : work.entries()) names.push_back(entry.filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A refusal: exit 2, `reason` on stderr (after "groundtruth: " unless the command-line parser
// refused the option itself), and the folder unchanged.
void expect_refused(const ProgramRun& run, const std::string& reason, const TempDir& work,
                    const std::vector<std::string>& files_before, bool by_parser = false) {
  EXPECT_EQ(run.status, 2) << run;
  if (!by_parser) {
    EXPECT_THAT(run.err, HasSubstr("groundtruth: ")) << run;
  }
  EXPECT_THAT(run.err, HasSubstr(reason)) << run;
  EXPECT_EQ(names_in(work), files_before) << run;
}

// ---- pictures -------------------------------------------------------------------------------

TEST(RenderCli, MeshToPngOnTheCpu) {
  const TempDir work("gt_render_cli");
  write_text(work / "cube.off", cube_off());
  write_text(work / "cube.png", "an older picture, replaced");
  const ProgramRun run = render(work, {"cube.off", "--out", "cube.png", "--width", "96", "--height", "64"});
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_THAT(run.out, HasSubstr("96x64 pixels, CPU reference (double), look plain")) << run;
  EXPECT_EQ(names_in(work), (std::vector<std::string>{"cube.off", "cube.png"}));  // no temporary left
  const Png png = read_png(work / "cube.png");
  EXPECT_EQ(png.width, 96);
  EXPECT_EQ(png.height, 64);
  EXPECT_EQ(png.channels, 3);
  // The fitted orbit camera keeps the cube's bounding sphere inside the picture: the corners are
  // background, the centre is the cube (ambient alone gives it at least 0.1·0.6·255 > 0).
  EXPECT_TRUE(png.black(0, 0) && png.black(95, 0) && png.black(0, 63) && png.black(95, 63));
  EXPECT_FALSE(png.black(48, 32));
}

TEST(RenderCli, HeightmapOnBothBackendsAgrees) {
  const TempDir work("gt_render_cli");
  const std::vector<std::string> common = {volcano.string(), "--width", "160", "--height", "120", "--azimuth", "200"};
  std::vector<std::string> cpu_args = common, gpu_args = common;
  cpu_args.insert(cpu_args.end(), {"--out", "cpu.png"});
  gpu_args.insert(gpu_args.end(), {"--out", "gpu.png", "--backend", "gpu"});
  const ProgramRun cpu = render(work, cpu_args);
  ASSERT_EQ(cpu.status, 0) << cpu;
  EXPECT_THAT(cpu.out, HasSubstr("look terrain")) << cpu;
  EXPECT_THAT(cpu.out, HasSubstr("as a terrain solid of 21224 triangles")) << cpu;  // 86·60·4 + 2·2·(86 + 60)
  const ProgramRun gpu = render(work, gpu_args);
  ASSERT_EQ(gpu.status, 0) << gpu;
  EXPECT_THAT(gpu.out, HasSubstr("GPU: ")) << gpu;
  // The twins' acceptance of issue 6 (compare/render_case.hpp): PSNR >= 40 dB and at most 0.5 % of
  // pixels beyond 4/255 once one-pixel edge shifts are allowed.
  const OIIO::ImageBuf a = gt::read_image(work / "cpu.png"), b = gt::read_image(work / "gpu.png");
  EXPECT_GE(gt::compare_images(a, b, 4.0 / 255.0).psnr_db, 40.0);
  EXPECT_LE(gt::compare_neighbourhoods(a, b, 4.0 / 255.0).failing_share, 0.005);
  // Something was drawn, and not everything: the solid sits in the middle of a black background.
  const Png png = read_png(work / "cpu.png");
  EXPECT_TRUE(png.black(0, 0));
  EXPECT_FALSE(png.black(80, 60));
}

// ---- refusals -------------------------------------------------------------------------------

TEST(RenderCli, UnreadableAndEmptyInputsAreRefused) {
  const TempDir work("gt_render_cli");
  write_text(work / "garbage.off", "this is not an OFF file\n");
  write_text(work / "empty.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  write_text(work / "nodata.json", R"({"width": 3, "height": 2, "values": [null, null, null, null, null, null]})");
  write_text(work / "one_row.json", R"({"width": 4, "height": 1, "values": [1, 2, 3, 4]})");
  const auto before = names_in(work);
  expect_refused(render(work, {"missing.off", "--out", "a.png"}), "missing.off", work, before);
  expect_refused(render(work, {"garbage.off", "--out", "a.png"}), "garbage.off", work, before);
  expect_refused(render(work, {"empty.off", "--out", "a.png"}), "empty.off", work, before);
  expect_refused(render(work, {"missing.json", "--out", "a.png"}), "missing.json", work, before);
  const ProgramRun no_data = render(work, {"nodata.json", "--out", "a.png"});
  EXPECT_EQ(no_data.status, 2) << no_data;
  EXPECT_EQ(names_in(work), before);
  expect_refused(render(work, {"one_row.json", "--out", "a.png"}), "no 2x2 block of valid samples", work, before);
}

TEST(RenderCli, CameraInsideAClosedMeshIsRefusedButARoomIsDrawn) {
  const TempDir work("gt_render_cli");
  write_text(work / "cube.off", cube_off());
  write_text(work / "room.off", cube_off(true));
  const auto before = names_in(work);
  // --distance 0.1: the eye is 0.17 from the centre of the cube of half side 1.
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--distance", "0.1"}), "inside the closed mesh", work,
                 before);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--eye", "0.5,0.2,-0.3", "--target", "2,2,2"}),
                 "winding number 1", work, before);
  // The same box facing inward is a room: from inside it shows its walls on every pixel.
  const ProgramRun room = render(work, {"room.off", "--out", "room.png", "--distance", "0.1", "--width", "32",
                                        "--height", "24"});
  ASSERT_EQ(room.status, 0) << room;
  EXPECT_THAT(room.out, HasSubstr("100 % covered")) << room;
  // Just outside the cube is outside: drawn.
  const ProgramRun outside = render(work, {"cube.off", "--out", "near.png", "--distance", "1.2", "--width", "32",
                                           "--height", "24"});
  EXPECT_EQ(outside.status, 0) << outside;
}

TEST(RenderCli, CameraSeeingNothingIsRefusedOnBothBackends) {
  const TempDir work("gt_render_cli");
  write_text(work / "cube.off", cube_off());
  const auto before = names_in(work);
  for (const char* backend : {"cpu", "gpu"}) {
    // Looking away: from z = 5 towards z = 10, the cube is behind the camera.
    expect_refused(render(work, {"cube.off", "--out", "a.png", "--eye", "0,0,5", "--target", "0,0,10", "--backend",
                                 backend}),
                   "sees nothing", work, before);
    // Looking past it: a 2° field of view aimed beside the cube.
    expect_refused(render(work, {"cube.off", "--out", "a.png", "--eye", "0,0,5", "--target", "3,0,5", "--fov", "2",
                                 "--backend", backend}),
                   "sees nothing", work, before);
  }
}

TEST(RenderCli, BadSizesAndOutputsAreRefused) {
  const TempDir work("gt_render_cli");
  write_text(work / "cube.off", cube_off());
  // A 16-bit PNG heightmap, so that "--out" can name the input itself.
  {
    std::vector<std::uint16_t> ramp(8 * 8);
    for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = std::uint16_t(k * 1000);
    auto out = OIIO::ImageOutput::create((work / "heights.png").string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open((work / "heights.png").string(), OIIO::ImageSpec(8, 8, 1, OIIO::TypeDesc::UINT16)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT16, ramp.data()));
    out->close();
  }
  const std::string heights_before = read_text(work / "heights.png");
  const auto before = names_in(work);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--width", "0"}), "--width", work, before, true);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--height", "20000"}), "--height", work, before, true);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--fov", "180"}), "--fov", work, before, true);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--eye", "1,2"}), "--eye", work, before, true);
  expect_refused(render(work, {"cube.off", "--out", "a.jpg"}), "must name a .png file", work, before);
  expect_refused(render(work, {"cube.off", "--out", "no/such/folder/a.png"}), "does not exist", work, before);
  expect_refused(render(work, {"cube.off", "--out", "a.png", "--eye", "1,2,3"}), "both --eye and --target", work,
                 before);
  expect_refused(render(work, {"heights.png", "--out", "heights.png"}), "would overwrite the input", work, before);
  expect_refused(render(work, {"heights.png", "--out", "./heights.png"}), "would overwrite the input", work, before);
  EXPECT_EQ(read_text(work / "heights.png"), heights_before);
  // The same heightmap to another name is fine (an 8x8 grid of 16-bit heights, 1 m cells).
  const ProgramRun fine = render(work, {"heights.png", "--out", "view.png", "--width", "40", "--height", "30",
                                        "--vertical-scale", "5"});
  EXPECT_EQ(fine.status, 0) << fine;
}

TEST(RenderCli, GpuWithoutAContextIsBadInput) {
  const TempDir work("gt_render_cli");
  write_text(work / "cube.off", cube_off());
  const auto before = names_in(work);
  // libglvnd loads no EGL vendor, so no EGL display exists (as in cli_test's no-GPU run).
  const ProgramRun run = render(work, {"cube.off", "--out", "a.png", "--backend", "gpu"},
                                {{"__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json"}});
  expect_refused(run, "--backend gpu needs a GL context", work, before);
  // The CPU backend needs none.
  const ProgramRun cpu = render(work, {"cube.off", "--out", "a.png", "--width", "32", "--height", "32"},
                                {{"__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json"}});
  EXPECT_EQ(cpu.status, 0) << cpu;
}

}  // namespace
