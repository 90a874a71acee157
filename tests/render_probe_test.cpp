// The render family's probes and spec checks (compare/algorithms/render_probe.hpp, issue 11): the
// closed forms themselves (the digest's numbers, the tent's corners and apex), each twin's output
// within the error model unmutated, and each both-twin mutant of compare/mutants/render.cpp moving
// the reference beyond the GPU's (wider) bound, so the spec check fails on both twins. Also the
// exact-coverage condition of render_heightmap.hpp and the reference-only edge mutant it exposes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "compare/algorithms/render_heightmap.hpp"
#include "compare/algorithms/render_phong.hpp"
#include "compare/algorithms/render_probe.hpp"
#include "compare/checks/error_model.hpp"
#include "core/mutant.hpp"
#include "gpu/render/heightmap_from_mesh.hpp"
#include "gpu/render/phong.hpp"
#include "reference/render/heightmap_from_mesh.hpp"
#include "reference/render/phong.hpp"
#include "tests/support/gl_test.hpp"

namespace {

using gt::Vec3;

// The framing of render.phong.mutant_probe.quad (datasets/cases/render.json).
gt::reference::Camera quad_camera() {
  return {.eye = {0.2, 0.1, 4.0}, .target = {0.0, 0.0, 0.0}, .up = {0.0, 1.0, 0.0}, .fov_y_deg = 40.0,
          .near = 1.0, .far = 10.0, .width = 64, .height = 64};
}

gt::ProbeCamera probe_camera(const gt::reference::Camera& camera) {
  return {.eye = camera.eye, .target = camera.target, .up = camera.up, .fov_y_deg = camera.fov_y_deg,
          .width = camera.width, .height = camera.height};
}

gt::reference::PhongScene quad_scene() {
  gt::reference::PhongScene scene =
      gt::reference::phong_scene(gt::phong_quad_mesh(gt::phong_quad_probe()), quad_camera());
  scene.light_power = 10.0;
  return scene;
}

gt::ProbeImageComparison compare_quad(const std::vector<std::uint8_t>& rgb) {
  const auto scene = quad_scene();
  return gt::compare_with_phong_quad(gt::phong_quad_probe(), probe_camera(scene.camera), scene.albedo,
                                     scene.light_power, rgb);
}

// Switches a mutant on for one scope.
class ActiveMutant {
 public:
  explicit ActiveMutant(const std::string& name) { gt::set_active_mutant(name); }
  ~ActiveMutant() { gt::set_active_mutant(""); }
  ActiveMutant(const ActiveMutant&) = delete;
  ActiveMutant& operator=(const ActiveMutant&) = delete;
};

TEST(PhongQuadSpec, ClosedFormHasTheDigestsNumbers) {
  // Head on (c = 1) at distance 2 with power 4: E = 1, colour = albedo·1.1 + 0.3, clamped.
  const Vec3 albedo{0.5, 0.25, 0.0};
  const Vec3 head_on = gt::seed_phong_closed_form({0, 0, 0}, {0, 0, 1}, {0, 0, 2}, albedo, 4.0);
  EXPECT_NEAR(head_on[0], 0.85, 1e-15);
  EXPECT_NEAR(head_on[1], 0.575, 1e-15);
  EXPECT_NEAR(head_on[2], 0.3, 1e-15);
  // c = 0.9: specular factor (2c² - 1)^5 = 0.0916 (the digest's 0.092); a normal facing away is flipped.
  const double s = std::sqrt(1.0 - 0.81);
  const Vec3 oblique = gt::seed_phong_closed_form({0, 0, 0}, {0, -s, -0.9}, {0, 0, 2}, {0, 0, 0}, 4.0);
  EXPECT_NEAR(oblique[0], 0.3 * std::pow(2 * 0.81 - 1, 5), 1e-15);
  EXPECT_NEAR(oblique[0] / 0.3, 0.0916, 5e-5);
}

TEST(PhongQuadSpec, ReferenceRenderIsTheClosedFormWithinHalfALevel) {
  const auto image = gt::reference::render_phong(quad_scene());
  const auto comparison = compare_quad(image.rgb);
  EXPECT_GT(comparison.quad_pixels, 64u * 64u / 4);  // the quad fills a good part of the picture
  EXPECT_GT(comparison.compared_pixels - comparison.quad_pixels, 64u * 64u / 8);  // and background is seen
  EXPECT_LE(comparison.max_abs, gt::phong_probe_bound_cpu);
}

class PhongQuadBothTwinMutants : public ::testing::TestWithParam<std::string> {};

TEST_P(PhongQuadBothTwinMutants, MoveTheReferenceBeyondTheGpuBound) {
  const ActiveMutant mutant(GetParam());
  const auto image = gt::reference::render_phong(quad_scene());
  EXPECT_GT(compare_quad(image.rgb).max_abs, gt::phong_probe_bound_gpu);
}

INSTANTIATE_TEST_SUITE_P(Render, PhongQuadBothTwinMutants,
                         ::testing::Values("render.phong.no_ambient", "render.phong.specular_exponent",
                                           "render.phong.facing_reversed", "render.phong.vertical_flip"),
                         [](const auto& info) {
                           std::string name = info.param.substr(info.param.rfind('.') + 1);
                           return name;
                         });

TEST(TentSpec, ClosedFormAtApexRimAndRoof) {
  EXPECT_EQ(gt::tent_height(0.25, 0.25), 1.0);  // apex
  EXPECT_EQ(gt::tent_height(0.0, 0.0), 0.25);   // rim corners
  EXPECT_EQ(gt::tent_height(1.0, 0.0), 0.25);
  EXPECT_EQ(gt::tent_height(0.0, 1.0), 0.25);
  EXPECT_EQ(gt::tent_height(0.125, 0.5), 0.625);  // on the roof face z = 1/4 + 3x
  EXPECT_EQ(gt::tent_height(0.5, 0.25), 0.625);   // on the roof face z = 1/4 + 3/2·(1 - x - y)
}

TEST(TentSpec, ReferenceHeightmapMatchesTheClosedForm) {
  const auto heightmap = gt::reference::heightmap_from_mesh(gt::tent_mesh(), 64, 64);
  const auto tent = gt::compare_with_tent(heightmap.heights, heightmap.covered, gt::unit_roundoff_double);
  EXPECT_GT(tent.height_compared, 1000u);
  EXPECT_GT(tent.coverage_compared, 64u * 64u - 2 * 64u);  // only texels on the hypotenuse are left out
  EXPECT_EQ(tent.coverage_mismatches, 0u);
  EXPECT_LE(tent.height_max_abs, tent.height_bound);
}

TEST(TentSpec, BothTwinMutantsFailIt) {
  for (const std::string name : {"render.heightmap_from_mesh.lowest_surface", "render.heightmap_from_mesh.rows_flipped"}) {
    const ActiveMutant mutant(name);
    const auto heightmap = gt::reference::heightmap_from_mesh(gt::tent_mesh(), 64, 64);
    const auto tent = gt::compare_with_tent(heightmap.heights, heightmap.covered, gt::unit_roundoff_float);
    EXPECT_GT(tent.height_max_abs, tent.height_bound) << name;
  }
}

TEST(ExactCoverage, HoldsForDyadicMeshesOnly) {
  EXPECT_TRUE(gt::exact_window_coordinates(gt::tent_mesh(), 64, 64, 8));
  EXPECT_TRUE(gt::exact_window_coordinates(gt::tent_mesh(), 96, 40, 8));
  gt::Mesh tenth = gt::tent_mesh();
  tenth.positions[3][0] = 0.1;  // not exact in float
  EXPECT_FALSE(gt::exact_window_coordinates(tenth, 64, 64, 8));
  gt::Mesh wide = gt::tent_mesh();
  wide.positions[1][0] = 3.0;  // scale 2/3: not a power of two
  EXPECT_FALSE(gt::exact_window_coordinates(wide, 64, 64, 8));
  // The apex's window x is 98/4 = 24.5 pixels: on the grid of 2^-8 pixel, off the grid of whole pixels.
  EXPECT_TRUE(gt::exact_window_coordinates(gt::tent_mesh(), 98, 64, 8));
  EXPECT_FALSE(gt::exact_window_coordinates(gt::tent_mesh(), 98, 64, 0));
}

TEST(ExactCoverage, MirroredEdgeRuleChangesTheTentsHypotenuse) {
  // The hypotenuse x + y = 1 passes through 64 texel centres; GL's left-edge rule leaves them out.
  const auto unmutated = gt::reference::heightmap_from_mesh(gt::tent_mesh(), 64, 64);
  const ActiveMutant mutant("render.heightmap_from_mesh.right_edges_owned");
  const auto mirrored = gt::reference::heightmap_from_mesh(gt::tent_mesh(), 64, 64);
  std::size_t changed = 0;
  for (std::size_t texel = 0; texel < unmutated.covered.size(); ++texel) {
    changed += unmutated.covered.values[texel] != mirrored.covered.values[texel];
  }
  EXPECT_EQ(changed, 64u);
}

class ProbeGpu : public gt::testing::GlTest {};

TEST_F(ProbeGpu, GlQuadIsTheClosedFormWithinOneLevel) {
  const auto scene = quad_scene();
  const gt::gpu::PhongRenderer renderer(gt::phong_draw(scene));
  renderer.run();
  EXPECT_LE(compare_quad(renderer.image().rgb).max_abs, gt::phong_probe_bound_gpu);
}

TEST_F(ProbeGpu, GlTentMatchesTheClosedFormAndTheReferenceCoverage) {
  const gt::gpu::HeightmapFromMesh renderer(gt::tent_mesh(), 64, 64);
  renderer.run();
  const auto gpu = renderer.result();
  const auto tent = gt::compare_with_tent(gpu.heights.cast<double>(), gpu.covered, gt::unit_roundoff_float);
  EXPECT_EQ(tent.coverage_mismatches, 0u);
  EXPECT_LE(tent.height_max_abs, tent.height_bound);
  const auto cpu = gt::reference::heightmap_from_mesh(gt::tent_mesh(), 64, 64);
  EXPECT_EQ(gt::compare_mesh_heightmaps(cpu.heights, cpu.covered, gpu.heights, gpu.covered).coverage_differences_beyond_bottom,
            0u);
}

}  // namespace
