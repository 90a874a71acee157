// Seed 004's Phong look (reference/render/phong.hpp, gpu/render/phong.hpp): the camera matrices
// (the optical axis projects to the image centre, near and far to NDC depth -1 and +1), the
// shading formula (the digest's closed form with the light at the eye, and the analytic colour at
// the centre pixel of a facing quad), refusals of unusable cameras, and the GL twin against the
// reference on the bunny: PSNR >= 40 dB and at most 0.5 % of pixels failing the 3×3-tolerant
// comparison at 4/255 (issue 6's acceptance). The looks: plain is phong_colour itself; the cave
// look with every term neutral is the plain render bit for bit; the terrain look's height ramp and
// rock-by-slope blend, its range from the mesh, and its GL twin against the reference on a hill.
// (The cave look's own properties: tests/cave_look_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <filesystem>

#include <OpenImageIO/imagebuf.h>

#include "compare/algorithms/render_phong.hpp"
#include "compare/checks/image.hpp"
#include "core/errors.hpp"
#include "core/io/mesh_io.hpp"
#include "gpu/render/phong.hpp"
#include "reference/render/phong.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/phong_twins.hpp"

namespace {

using gt::reference::Camera;
using gt::reference::Vec3;

Camera oblique_camera() {
  return {.eye = {1.0, 2.0, 3.0}, .target = {-0.5, 0.25, 0.0}, .up = {0.0, 1.0, 0.0},
          .fov_y_deg = 50.0, .near = 0.5, .far = 20.0, .width = 320, .height = 200};
}

// NDC of a world point seen by `camera`.
std::array<double, 3> ndc(const Camera& camera, const Vec3& p) {
  using namespace gt::reference;
  const auto clip = transform_point(multiply(projection_matrix(camera), view_matrix(camera)), p);
  return {clip[0] / clip[3], clip[1] / clip[3], clip[2] / clip[3]};
}

// The point at distance `distance` from the eye along the optical axis.
Vec3 on_axis(const Camera& camera, double distance) {
  Vec3 forward{};
  for (int k = 0; k < 3; ++k) forward[k] = camera.target[k] - camera.eye[k];
  const double length = std::sqrt(forward[0] * forward[0] + forward[1] * forward[1] + forward[2] * forward[2]);
  Vec3 p{};
  for (int k = 0; k < 3; ++k) p[k] = camera.eye[k] + distance / length * forward[k];
  return p;
}

TEST(PhongCamera, OpticalAxisProjectsToTheImageCentre) {
  const Camera camera = oblique_camera();
  for (const double distance : {0.7, 3.0, 11.0}) {
    const auto p = ndc(camera, on_axis(camera, distance));
    EXPECT_NEAR(p[0], 0.0, 1e-14);
    EXPECT_NEAR(p[1], 0.0, 1e-14);
  }
}

TEST(PhongCamera, NearAndFarMapToMinusOneAndOne) {
  const Camera camera = oblique_camera();
  EXPECT_NEAR(ndc(camera, on_axis(camera, camera.near))[2], -1.0, 1e-13);
  EXPECT_NEAR(ndc(camera, on_axis(camera, camera.far))[2], 1.0, 1e-13);
}

TEST(PhongCamera, UpAndRightAreKeptInTheImage) {
  // A point above the target (along +y) lands in the upper half, one to the camera's right in the
  // right half: the picture is neither flipped nor mirrored.
  const Camera camera{.eye = {0.0, 0.0, 5.0}, .target = {0.0, 0.0, 0.0}};
  EXPECT_GT(ndc(camera, {0.0, 1.0, 0.0})[1], 0.0);
  EXPECT_GT(ndc(camera, {1.0, 0.0, 0.0})[0], 0.0);
}

TEST(PhongCamera, UnusableCamerasAreRefused) {
  Camera at_target = oblique_camera();
  at_target.target = at_target.eye;
  EXPECT_THROW(gt::reference::view_matrix(at_target), gt::InputError);
  Camera up_along_view{.eye = {0.0, 5.0, 0.0}, .target = {0.0, 0.0, 0.0}};
  EXPECT_THROW(gt::reference::view_matrix(up_along_view), gt::InputError);
  Camera reversed = oblique_camera();
  reversed.far = 0.1;
  EXPECT_THROW(gt::reference::projection_matrix(reversed), gt::InputError);
}

TEST(PhongShading, LightAtTheEyeGivesTheDigestsClosedForm) {
  // n·v = c: colour = albedo·(0.1 + E·c) + 0.3·E·max(0, 2c² - 1)^5 with E = power/d².
  const Vec3 eye = {0.0, 0.0, 2.0}, albedo = {0.5, 0.4, 0.3};
  const double c = 0.9, power = 2.0;  // d = 2, E = 0.5
  const Vec3 normal = {std::sqrt(1.0 - c * c), 0.0, c};
  const Vec3 colour = gt::reference::phong_colour({0.0, 0.0, 0.0}, normal, eye, albedo, power);
  const double specular = 0.3 * 0.5 * std::pow(2.0 * c * c - 1.0, 5.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(colour[k], albedo[k] * (0.1 + 0.5 * c) + specular, 1e-15);
  // Two-sided: the back face shades like the front.
  const Vec3 back = gt::reference::phong_colour({0.0, 0.0, 0.0}, {-normal[0], 0.0, -c}, eye, albedo, power);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], colour[k], 1e-15);
}

TEST(PhongShading, FacingQuadHasTheAnalyticColourAtTheCentrePixel) {
  // A quad z = 0, |x|, |y| <= 1 facing a camera at distance 4 on its axis; an odd image so that the
  // centre pixel's centre lies on the optical axis, where p = 0, n = l = v = r and d = 4.
  gt::Mesh quad;
  quad.positions = {{-1.0, -1.0, 0.0}, {1.0, -1.0, 0.0}, {1.0, 1.0, 0.0}, {-1.0, 1.0, 0.0}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Camera camera{.eye = {0.0, 0.0, 4.0}, .target = {0.0, 0.0, 0.0}, .fov_y_deg = 40.0, .near = 1.0,
                      .far = 10.0, .width = 33, .height = 33};
  auto scene = gt::reference::phong_scene(quad, camera);
  EXPECT_DOUBLE_EQ(scene.light_power, 16.0);  // |eye - box centre|²
  scene.light_power = 4.0;                    // E = 0.25: nothing clamps
  const auto image = gt::reference::render_phong(scene);
  const std::size_t centre = (16 * 33 + 16) * 3;
  for (int k = 0; k < 3; ++k) {
    const double expected = scene.albedo[k] * (0.1 + 0.25) + 0.3 * 0.25;
    EXPECT_EQ(image.rgb[centre + std::size_t(k)], std::lround(255.0 * expected)) << "channel " << k;
  }
  EXPECT_EQ(image.rgb[0], 0) << "the corner sees the background";
}

TEST(PhongNormals, AreaWeightedAverageOfFaceNormals) {
  // Vertex 0 is shared by a large face in z = 0 and a small one in x = 0: its normal leans towards
  // the large face's +z in proportion to the areas (2 and 0.5).
  gt::Mesh mesh;
  mesh.positions = {{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}};
  mesh.triangles = {{0, 1, 2}, {0, 4, 3}};
  const auto normals = gt::reference::vertex_normals(mesh);
  const double length = std::sqrt(2.0 * 2.0 + 0.5 * 0.5);
  EXPECT_NEAR(normals[0][0], 0.5 / length, 1e-15);
  EXPECT_NEAR(normals[0][1], 0.0, 1e-15);
  EXPECT_NEAR(normals[0][2], 2.0 / length, 1e-15);
}

// A smooth hill on a 33×33 grid, cell 1, y up: a Gaussian peak of height 12 plus a gentle tilt, so
// that the heights span the whole ramp and the flanks are steep enough for rock.
gt::Mesh hill_mesh() {
  gt::Mesh mesh;
  const int n = 33;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double x = i - 16.0, z = j - 16.0;
      mesh.positions.push_back({x, 12.0 * std::exp(-(x * x + z * z) / 60.0) + 0.05 * x, z});
    }
  }
  for (std::uint32_t j = 0; j + 1 < std::uint32_t(n); ++j) {
    for (std::uint32_t i = 0; i + 1 < std::uint32_t(n); ++i) {
      const std::uint32_t a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      mesh.triangles.push_back({a, c, d});  // counter-clockwise seen from +y
      mesh.triangles.push_back({a, d, b});
    }
  }
  return mesh;
}

TEST(PhongLooks, PlainLookIsPhongColour) {
  const gt::Mesh mesh = hill_mesh();
  const auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 35.0, 40.0, 64, 48));
  EXPECT_EQ(scene.look, gt::reference::Look::plain);
  for (const Vec3& p : {Vec3{0.5, 3.0, -2.0}, Vec3{-7.0, 1.0, 4.0}}) {
    for (const Vec3& normal : {Vec3{0.0, 2.0, 0.0}, Vec3{0.3, -0.2, 0.9}, Vec3{0.0, 0.0, 0.0}}) {
      EXPECT_EQ(gt::reference::shade_fragment(scene, p, normal),
                gt::reference::phong_colour(p, normal, scene.camera.eye, scene.albedo, scene.light_power));
    }
  }
}

TEST(PhongLooks, NeutralCaveLookRendersThePlainImageExactly) {
  // Strip = the albedo everywhere (a + f·(a - a) = a), moss 0 (g + 0 = g), bump amplitude 0 (n
  // untouched): the cave look must give the plain look's bytes, so its Phong terms are the same.
  const gt::Mesh mesh = hill_mesh();
  auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 35.0, 40.0, 80, 60));
  const auto plain = gt::reference::render_phong(scene);
  scene.look = gt::reference::Look::cave;
  scene.cave.colour_strip.assign(256, scene.albedo);
  scene.cave.moss = 0.0;
  scene.cave.bump_amplitude = 0.0;
  const auto cave = gt::reference::render_phong(scene);
  EXPECT_EQ(cave.rgb, plain.rgb);
  EXPECT_EQ(cave.covered_pixels, plain.covered_pixels);
  // And the look is not inert: the real strip, moss and bump change the picture.
  scene.cave = gt::reference::CaveLook{};
  EXPECT_NE(gt::reference::render_phong(scene).rgb, plain.rgb);
}

TEST(PhongLooks, TerrainRampFollowsHeightOnFlatGround) {
  // n = up: c = 1 >= cos 30°, no rock; the albedo is the ramp at the normalised height, exactly.
  gt::reference::TerrainLook look;
  look.height_low = 100.0;
  look.height_high = 300.0;
  for (const double height : {50.0, 100.0, 150.0, 237.5, 300.0, 420.0}) {
    const double h = std::clamp((height - 100.0) / 200.0, 0.0, 1.0);
    EXPECT_EQ(gt::reference::terrain_albedo(look, {3.0, height, -4.0}, {0.0, 1.0, 0.0}),
              gt::reference::strip_colour(look.ramp, h))
        << "height " << height;
  }
  // The ramp climbs from lowland green to snow.
  const auto low = gt::reference::terrain_albedo(look, {0.0, 100.0, 0.0}, {0.0, 1.0, 0.0});
  const auto high = gt::reference::terrain_albedo(look, {0.0, 300.0, 0.0}, {0.0, 1.0, 0.0});
  EXPECT_GT(low[1], low[0]);
  EXPECT_GT(high[0] + high[1] + high[2], 2.7);
}

TEST(PhongLooks, TerrainTurnsToRockWithSlope) {
  gt::reference::TerrainLook look;  // rock from 30° (no blend yet) to 45° (all rock)
  const Vec3 p = {0.0, 0.5, 0.0};
  const Vec3 ramp = gt::reference::strip_colour(look.ramp, 0.5);
  const auto at_slope = [&](double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return gt::reference::terrain_albedo(look, p, {std::sin(a), std::cos(a), 0.0});
  };
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(at_slope(20.0)[c], ramp[c], 1e-15) << "below rock_start: the ramp";
    EXPECT_NEAR(at_slope(50.0)[c], look.rock[c], 1e-15) << "beyond rock_full: rock";
    EXPECT_NEAR(at_slope(90.0)[c], look.rock[c], 1e-15) << "a wall: rock";
    EXPECT_NEAR(at_slope(150.0)[c], look.rock[c], 1e-15) << "seen from below: rock";
    // Halfway in cos between the two angles w = 0.5 and smoothstep keeps 0.5: the mean.
  }
  const double c_mid = 0.5 * (std::cos(std::numbers::pi / 6.0) + std::cos(std::numbers::pi / 4.0));
  const auto mid = gt::reference::terrain_albedo(look, p, {std::sqrt(1.0 - c_mid * c_mid), c_mid, 0.0});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(mid[c], 0.5 * (ramp[c] + look.rock[c]), 1e-15);
}

TEST(PhongLooks, TerrainRangeComesFromTheMeshAlongUp) {
  const gt::Mesh mesh = hill_mesh();
  const auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 35.0, 40.0, 64, 48),
                                                gt::reference::Look::terrain);
  EXPECT_EQ(scene.look, gt::reference::Look::terrain);
  double low = 1e300, high = -1e300;
  for (const auto& p : mesh.positions) {
    low = std::min(low, p[1]);
    high = std::max(high, p[1]);
  }
  EXPECT_EQ(scene.terrain.height_low, low);
  EXPECT_EQ(scene.terrain.height_high, high);
  const auto along_x = gt::reference::terrain_look(mesh, {1.0, 0.0, 0.0});
  EXPECT_EQ(along_x.height_low, -16.0);
  EXPECT_EQ(along_x.height_high, 16.0);
  EXPECT_THROW(gt::reference::terrain_look(mesh, {0.0, 2.0, 0.0}), gt::InputError) << "up must be a unit vector";
  auto bad = scene;
  bad.terrain.rock_full_deg = 10.0;  // before rock_start
  EXPECT_THROW(gt::reference::render_phong(bad), gt::InputError);
}

class PhongGpu : public gt::testing::GlTest {};


TEST_F(PhongGpu, BunnyMatchesTheReference) {
  const std::filesystem::path bunny = std::filesystem::path(GT_DATASET_DIR) / "real/meshes/bunny00.off";
  if (!std::filesystem::exists(bunny)) GTEST_SKIP() << bunny << " is missing (datasets/fetch.sh fetches it)";
  const gt::Mesh mesh = gt::read_mesh(bunny).mesh;
  const auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 20.0, 40.0, 160, 128));
  const auto cpu = gt::reference::render_phong(scene);
  const gt::gpu::PhongRenderer renderer({.mesh = scene.mesh, .normals = scene.normals,
                                         .view_projection = scene.view_projection, .eye = scene.camera.eye,
                                         .albedo = scene.albedo, .light_power = scene.light_power,
                                         .width = scene.camera.width, .height = scene.camera.height});
  renderer.run();
  const auto gpu = renderer.image();
  const auto a = gt::testing::rgb8(cpu.width, cpu.height, cpu.rgb), b = gt::testing::rgb8(gpu.width, gpu.height, gpu.rgb);
  const double tolerance = 4.0 / 255.0;
  EXPECT_GE(gt::compare_images(a, b, tolerance).psnr_db, 40.0);
  EXPECT_LE(gt::compare_neighbourhoods(a, b, tolerance).failing_share, 0.005);
  const auto lit = std::count_if(cpu.rgb.begin(), cpu.rgb.end(), [](std::uint8_t v) { return v > 0; });
  EXPECT_GT(lit, std::ptrdiff_t(cpu.rgb.size() / 10)) << "the bunny fills a good part of the picture";
}

TEST_F(PhongGpu, TerrainLookOnAHillMatchesTheReference) {
  // Error model as for the cave (tests/cave_look_test.cpp): the GPU's float height, slope and ramp
  // lookup are within ~1e-5 of the reference's, far below half an 8-bit step, so a channel differs
  // by at most one step except where another triangle is seen (silhouettes): the 3×3-tolerant
  // comparison at 1.5/255 passes on all but a few edge pixels, inside issue 6's acceptance.
  const gt::Mesh mesh = hill_mesh();
  const auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 35.0, 40.0, 160, 120),
                                                gt::reference::Look::terrain);
  const auto twins = gt::testing::render_twins(scene);
  gt::testing::expect_twins_agree(twins);
  const auto& cpu = twins.cpu;
  EXPECT_GT(cpu.covered_pixels, std::size_t(160 * 120 / 4)) << "the hill fills a good part of the picture";
}

TEST_F(PhongGpu, PlainDrawWithoutLookFieldsIsThePlainProgram) {
  // A PhongDraw built as before looks existed (designated initialisers without look) draws the
  // plain look, the same bytes as phong_draw of a plain scene.
  const gt::Mesh mesh = hill_mesh();
  const auto scene = gt::reference::phong_scene(mesh, gt::reference::orbit_camera(mesh, 30.0, 35.0, 40.0, 80, 60));
  const gt::gpu::PhongRenderer old_style({.mesh = scene.mesh, .normals = scene.normals,
                                          .view_projection = scene.view_projection, .eye = scene.camera.eye,
                                          .albedo = scene.albedo, .light_power = scene.light_power,
                                          .width = scene.camera.width, .height = scene.camera.height});
  old_style.run();
  const gt::gpu::PhongRenderer bridged(gt::phong_draw(scene));
  bridged.run();
  EXPECT_EQ(old_style.image().rgb, bridged.image().rgb);
}

}  // namespace
