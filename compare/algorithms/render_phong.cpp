// `render.phong`: seed 004's Phong look (digest 004_cave.md §2.9) on a mesh seen through a
// perspective camera, by the reference rasterizer (double; reference/render/phong.hpp documents
// camera, normals, the shading formula and the looks) and by the GL pipeline
// (gpu/render/phong.hpp). Both draw the same PhongScene: normals and P·V are computed once in
// double, the GPU gets them rounded to float. Images are RGB8 (what GL writes to RGBA8).
//
// Inputs and cameras:
//   {"mesh": path}   a mesh file; camera = orbit (around the bounding-box centre: azimuth_deg,
//                    elevation_deg) or fixed (eye_*, target_*, near, far)
//   {} (no input), generated = quad
//                    the probe quad of compare/algorithms/render_probe.hpp (any look, either camera):
//                    with look = plain its colours are known in closed form, and the case gets the
//                    spec checks spec.phong_quad.{cpu,gpu} (issue 11; error model there)
//   {} (no input), generated = cave (default)
//                    with look = cave only: the seed's cave, a block of block_size_* cells at
//                    block_origin_* of its density (scale 10, threshold 0, kernel 0.6, Perlin's
//                    table, capped with air) meshed by the reference marching tetrahedra, normals from
//                    the analytic noise gradient or, normals = central, the seed's central differences
//                    (reference/render/cave_look.hpp cave_scene), seen by
//                    the fixed camera from inside (an eye in rock or outside the block is refused)
//   look             plain (one albedo: the seed's Phong), cave (seed 004's full look: colour strip
//                    by solid noise, moss, bump), terrain (height ramp and rock by slope, up_axis up)
//   light_power      the seed's LIGHTPOWER (irradiance = power/d²). 0: |eye - box centre|² for a mesh
//                    file (the bounding box of the mesh), 25 for the generated cave (opengl-tutorial's
//                    default 50 clamps cave walls nearer than about 5 units to white); > 0: as given
//
// Checks, timings and pictures: compare/render_case.hpp (run_phong_twins, shared with
// render.terrain): image.psnr.gpu_vs_cpu (PSNR >= 40 dB), image.share_beyond_tolerance_outside_edges
// (at most 0.5 % of pixels beyond 4/255 after the 3×3 edge tolerance), image.uncovered_share.cpu
// (bound 1 - min_covered_share when that is > 0: a camera inside the cave must see walls, not the
// void), determinism.gpu, informative pixel-wise metrics; cpu.png, gpu.png, heat map and mask.
// Meshing the generated cave happens once in prepare, outside the timings.
#include "compare/algorithms/render_phong.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/algorithms/render_probe.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/render_case.hpp"
#include "core/errors.hpp"
#include "core/params/cave.hpp"
#include "reference/render/cave_look.hpp"

namespace gt {
namespace {

constexpr Choice<bool> camera_choices[] = {{"orbit", false}, {"fixed", true}};
constexpr Choice<reference::Look> look_choices[] = {
    {"plain", reference::Look::plain}, {"cave", reference::Look::cave}, {"terrain", reference::Look::terrain}};
constexpr Choice<reference::Vec3> up_axis_choices[] = {
    {"x", {1.0, 0.0, 0.0}}, {"y", {0.0, 1.0, 0.0}}, {"z", {0.0, 0.0, 1.0}}};
constexpr Choice<bool> generated_choices[] = {{"cave", false}, {"quad", true}};
constexpr Choice<reference::CaveNormals> normal_choices[] = {{"analytic", reference::CaveNormals::analytic},
                                                             {"central", reference::CaveNormals::central_difference}};

const ParamSpecs& phong_specs() {
  static const ParamSpecs specs = param_specs(phong_render_param_table());
  return specs;
}

struct PhongCase {
  reference::PhongScene scene;
  int subpixel_bits = 8;
  double min_covered_share = 0.0;
  bool quad_spec = false;  // the probe quad in the plain look: its closed-form colours are checked
};

reference::Camera fixed_camera(const PhongRenderParams& params) {
  return {.eye = params.eye,
          .target = params.target,
          .up = {0.0, 1.0, 0.0},
          .fov_y_deg = params.fov_deg,
          .near = params.near,
          .far = params.far,
          .width = params.width,
          .height = params.height};
}

// The seed's cave block of the case (core/params/cave.hpp defaults: scale 10, threshold 0,
// kernel 0.6, Perlin's table), capped with air.
CaveParams cave_block(const PhongRenderParams& params) {
  CaveParams block;
  block.origin = params.block_origin;
  block.size = params.block_size;
  block.solid = true;
  return block;
}

}  // namespace

gpu::PhongDraw phong_draw(const reference::PhongScene& scene) {
  gpu::PhongDraw draw{.mesh = scene.mesh,
                      .normals = scene.normals,
                      .view_projection = scene.view_projection,
                      .eye = scene.camera.eye,
                      .albedo = scene.albedo,
                      .light_power = scene.light_power,
                      .width = scene.camera.width,
                      .height = scene.camera.height};
  switch (scene.look) {
    case reference::Look::plain: draw.look = gpu::PhongLook::plain; break;
    case reference::Look::cave: draw.look = gpu::PhongLook::cave; break;
    case reference::Look::terrain: draw.look = gpu::PhongLook::terrain; break;
  }
  const reference::CaveLook& cave = scene.cave;
  draw.cave = {.colour_strip = cave.colour_strip,
               .colour_frequency = cave.colour_frequency,
               .colour_reference_height = cave.colour_reference_height,
               .colour_octaves_per_unit = cave.colour_octaves_per_unit,
               .colour_octave_limit = cave.colour_octave_limit,
               .bump_amplitude = cave.bump_amplitude,
               .bump_frequency = cave.bump_frequency,
               .moss = cave.moss,
               .noise_seed = cave.noise_seed};
  const reference::TerrainLook& terrain = scene.terrain;
  draw.terrain = {.ramp = terrain.ramp,
                  .up = terrain.up,
                  .height_low = terrain.height_low,
                  .height_high = terrain.height_high,
                  .rock = terrain.rock,
                  .rock_start_deg = terrain.rock_start_deg,
                  .rock_full_deg = terrain.rock_full_deg,
                  .drape = {}};
  if (terrain.drape) {
    const reference::TerrainDrape& drape = *terrain.drape;
    draw.terrain.drape = gpu::PhongTerrainDrape{.width = drape.width, .height = drape.height, .rgb = drape.rgb,
                                                .x_west = drape.x_west, .x_east = drape.x_east,
                                                .z_north = drape.z_north, .z_south = drape.z_south};
  }
  return draw;
}

namespace {

// The mesh of the case: the input's, or the generated probe quad.
std::optional<Mesh> case_mesh(const PhongRenderParams& params, const LoadedInput& input, std::string& description) {
  if (input.mesh) return input.mesh;
  if (!params.quad) return std::nullopt;
  description = "the probe quad (render_probe.hpp)";
  return phong_quad_mesh(phong_quad_probe());
}

PhongCase prepared_case(const nlohmann::json& resolved, const LoadedInput& input, std::string& description) {
  const auto params = params_from_json(phong_render_param_table(), resolved);
  const reference::Look look = params.look;
  const bool fixed = params.fixed_camera;
  const double light_power = params.light_power;
  reference::PhongScene scene;
  if (const std::optional<Mesh> mesh = case_mesh(params, input, description)) {
    const reference::Camera camera =
        fixed ? fixed_camera(params)
              : reference::orbit_camera(*mesh, params.azimuth_deg, params.elevation_deg, params.fov_deg, params.width,
                                        params.height);
    scene = reference::phong_scene(*mesh, camera, look);
    if (look == reference::Look::terrain) scene.terrain = reference::terrain_look(*mesh, params.up);
    if (light_power > 0.0) scene.light_power = light_power;
  } else {
    if (look == reference::Look::terrain || !fixed) {
      throw InputError("render.phong needs a mesh input ({\"mesh\": \"path.off\"}), generated = quad, or look = cave "
                       "(or plain: seed 004 Fig. 3.8's first stage) with camera = fixed to mesh a block of the seed's "
                       "cave");
    }
    const CaveParams block = cave_block(params);
    scene = reference::cave_scene(block, fixed_camera(params), {}, light_power > 0.0 ? light_power : 25.0,
                                  params.normals);
    scene.look = look;  // plain: the block in one diffuse hue
    description = fmt::format("the seed's cave, block of {}x{}x{} cells at ({}, {}, {})", block.size[0], block.size[1],
                              block.size[2], block.origin[0], block.origin[1], block.origin[2]);
  }
  if (look == reference::Look::cave) {
    const auto strip = scene.cave.colour_strip;
    scene.cave = params.cave;
    scene.cave.colour_strip = strip;
  }
  if (look == reference::Look::terrain) {
    scene.terrain.rock_start_deg = params.terrain.rock_start_deg;
    scene.terrain.rock_full_deg = params.terrain.rock_full_deg;
  }
  const bool quad_spec = !input.mesh && params.quad && look == reference::Look::plain;
  return {std::move(scene), params.subpixel_bits, params.min_covered_share, quad_spec};
}

// spec.phong_quad.<backend>: the image against the probe quad's closed-form colours (render_probe.hpp).
RenderedImageSpec quad_spec(const reference::PhongScene& scene) {
  const reference::Camera& camera = scene.camera;
  const ProbeCamera probe_camera{.eye = camera.eye, .target = camera.target, .up = camera.up,
                                 .fov_y_deg = camera.fov_y_deg, .width = camera.width, .height = camera.height};
  return [probe_camera, albedo = scene.albedo, light_power = scene.light_power](
             const std::vector<std::uint8_t>& rgb, const std::string& backend, CaseResult& result) {
    const ProbeImageComparison comparison = compare_with_phong_quad(phong_quad_probe(), probe_camera, albedo, light_power, rgb);
    const bool reference = backend == "cpu";  // the GPU's and a candidate's bound: a float renderer's
    result.checks.push_back(bounded_check(
        "spec.phong_quad." + backend, comparison.max_abs, reference ? phong_probe_bound_cpu : phong_probe_bound_gpu,
        std::nullopt,
        fmt::format("largest |image - closed form| over channel values of {} pixels at least 1 pixel from the quad's "
                    "outline ({} on the quad: seed 004 §2.9 with K_a 0.1, specular 0.3, exponent 5, light at the eye, "
                    "1/d²; the rest background 0), at pixel ({}, {}); bound: {}",
                    comparison.compared_pixels, comparison.quad_pixels, comparison.max_x, comparison.max_y,
                    reference ? "half an 8-bit level + 1e-9 of double error"
                              : "one 8-bit level (either rounding) + 2^-12 of float error")));
  };
}

PreparedTwin prepare_phong(const nlohmann::json& resolved, const LoadedInput& input) {
  std::string description = input.description;
  PhongCase phong = prepared_case(resolved, input, description);
  PreparedTwin prepared;
  prepared.kind = CaseRun([phong = std::move(phong), file = std::move(description)](const nlohmann::json&,
                                                                            const RunOptions& options,
                                                                            CaseResult& result) {
    run_phong_twins(phong.scene, phong.subpixel_bits, phong.min_covered_share, file, options, result,
                    phong.quad_spec ? quad_spec(phong.scene) : RenderedImageSpec{});
  });
  return prepared;
}

}  // namespace

const ParamTable<PhongRenderParams>& phong_render_param_table() {
  using P = PhongRenderParams;
  using L = reference::CaveLook;
  using T = reference::TerrainLook;
  static const ParamTable<P> table = {
      integer_param("width", &P::width, 1, 4096, "pixel", "image columns"),
      integer_param("height", &P::height, 1, 4096, "pixel", "image rows"),
      real_param("fov_deg", &P::fov_deg, 1.0, 150.0, "degree", "vertical field of view"),
      choice_param("camera", &P::fixed_camera, camera_choices, "1",
                   "orbit: around the mesh's box centre (azimuth_deg, elevation_deg); "
                   "fixed: eye_* looking at target_*"),
      real_param("azimuth_deg", &P::azimuth_deg, -360.0, 360.0, "degree",
                 "orbit camera direction around +y from the box centre, from +z towards +x"),
      real_param("elevation_deg", &P::elevation_deg, -89.0, 89.0, "degree",
                 "orbit camera direction above the xz plane"),
      real_param("eye_x", element(&P::eye, 0), -1e6, 1e6, "mesh", "fixed camera: eye position x"),
      real_param("eye_y", element(&P::eye, 1), -1e6, 1e6, "mesh", "fixed camera: eye position y"),
      real_param("eye_z", element(&P::eye, 2), -1e6, 1e6, "mesh", "fixed camera: eye position z"),
      real_param("target_x", element(&P::target, 0), -1e6, 1e6, "mesh", "fixed camera: point looked at, x"),
      real_param("target_y", element(&P::target, 1), -1e6, 1e6, "mesh", "fixed camera: point looked at, y"),
      real_param("target_z", element(&P::target, 2), -1e6, 1e6, "mesh", "fixed camera: point looked at, z"),
      real_param("near", &P::near, 1e-6, 1e6, "mesh", "fixed camera: near plane distance"),
      real_param("far", &P::far, 1e-6, 1e7, "mesh", "fixed camera: far plane distance"),
      integer_param("subpixel_bits", &P::subpixel_bits, 0, 16, "bit",
                    "GL_SUBPIXEL_BITS the reference snaps vertices to (8: llvmpipe and NVIDIA)"),
      choice_param("look", &P::look, look_choices, "1",
                   "plain: one albedo (seed 004's Phong); cave: seed 004's colour strip, moss and bump; "
                   "terrain: height ramp and rock by slope"),
      real_param("light_power", &P::light_power, 0.0, 1e12, "mesh²",
                 "point light power (irradiance = power/d²); 0: |eye - box centre|² (mesh file) or 25 (generated "
                 "cave)"),
      real_param("min_covered_share", &P::min_covered_share, 0.0, 1.0, "1",
                 "least share of pixels the mesh must cover in the reference image (0: not checked)"),
      nested(&P::cave, real_param("colour_frequency", &L::colour_frequency, 1e-6, 1e4, "1/mesh",
                                  "cave look: noise cells per unit of the colour texture at colour_reference_height "
                                  "(seed: 2)")),
      nested(&P::cave, real_param("colour_reference_height", &L::colour_reference_height, -1e6, 1e6, "mesh",
                                  "cave look: height y0 where the colour texture has colour_frequency")),
      nested(&P::cave, real_param("colour_octaves_per_unit", &L::colour_octaves_per_unit, -1.0, 1.0, "1/mesh",
                                  "cave look: octaves the colour texture gets finer per unit of depth (1/(200 ln 2) "
                                  "matches the seed's slope 1/100 at y0; 0: one frequency)")),
      nested(&P::cave, real_param("colour_octave_limit", &L::colour_octave_limit, 0.0, 60.0, "1",
                                  "cave look: the colour frequency stays within f0·2^±limit (the seed's y is "
                                  "unbounded)")),
      nested(&P::cave, real_param("bump_amplitude", &L::bump_amplitude, 0.0, 100.0, "mesh",
                                  "cave look: height of the bump field (0: no bump)")),
      nested(&P::cave, real_param("bump_frequency", &L::bump_frequency, 0.0, 1e4, "1/mesh",
                                  "cave look: noise cells per unit of the bump field")),
      nested(&P::cave, real_param("moss", &L::moss, 0.0, 10.0, "1",
                                  "cave look: green added per unit of n_y on upward normals (seed: 1/40)")),
      nested(&P::cave, integer_param("noise_seed", &L::noise_seed, 0, 4294967295.0, "1",
                                     "cave look: permutation of the colour and bump noises (0: Perlin's table, the "
                                     "seed's)")),
      choice_param("up_axis", &P::up, up_axis_choices, "1", "terrain look: the height axis"),
      nested(&P::terrain, real_param("rock_start_deg", &T::rock_start_deg, 0.0, 180.0, "degree",
                                     "terrain look: slope where the rock colour starts")),
      nested(&P::terrain, real_param("rock_full_deg", &T::rock_full_deg, 0.0, 180.0, "degree",
                                     "terrain look: slope from which the surface is all rock")),
      choice_param("generated", &P::quad, generated_choices, "1",
                   "without an input: cave (the seed's cave, look = cave or plain and camera = fixed) or quad (the probe quad "
                   "of render_probe.hpp, whose plain look has closed-form colours)"),
      integer_param("block_origin_x", element(&P::block_origin, 0), -100000, 100000, "lattice",
                    "generated cave: block origin x"),
      integer_param("block_origin_y", element(&P::block_origin, 1), -100000, 100000, "lattice",
                    "generated cave: block origin y"),
      integer_param("block_origin_z", element(&P::block_origin, 2), -100000, 100000, "lattice",
                    "generated cave: block origin z"),
      integer_param("block_size_x", element(&P::block_size, 0), 1, 160, "lattice", "generated cave: cells along x"),
      integer_param("block_size_y", element(&P::block_size, 1), 1, 160, "lattice", "generated cave: cells along y"),
      integer_param("block_size_z", element(&P::block_size, 2), 1, 160, "lattice", "generated cave: cells along z"),
      choice_param("normals", &P::normals, normal_choices, "1",
                   "generated cave: the vertices' normals, analytic (the simplex gradient, exact) or central (the "
                   "seed's central differences of Listing 3.3, ND = 1), both in double"),

  };
  return table;
}

Algorithm render_phong_algorithm() {
  return {.name = "render.phong",
          .summary = "Phong-shaded mesh through a perspective camera (looks: plain, cave, terrain): reference "
                     "rasterizer vs the GL pipeline",
          .source = "seed 004 §2.9 (digest 004_cave.md): ambient 0.1, specular 0.3, exponent 5, light at the eye; "
                    "colour strip by solid Perlin noise, moss, bump mapping; issue 6",
          .params = &phong_specs(),
          .prepare = prepare_phong,
          .kind = CaseKind::custom,
          .ad_hoc_input = AdHocInput::mesh,
          .candidate = CandidateOutput::image,
          // Measured 79 B a pixel (bunny00, 1024² vs 256²) and 330 B a triangle (bunny00 vs cow);
          // the generated cave is meshed first: as cave.marching_tetrahedra, 6000 B a lattice sample.
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const auto params = params_from_json(phong_render_param_table(), resolved);
            const double pixels = double(params.width) * params.height;
            MemoryEstimate estimate = memory_for(pixels, "pixels", 120);
            if (input.mesh) return estimate + memory_for(static_cast<double>(input.mesh->triangles.size()), "triangles", 500);
            if (params.quad) return estimate;
            double samples = 1.0;
            for (const int cells : params.block_size) samples *= cells + 3.0;  // cells + 1 samples, + 2 of capping air
            return estimate + memory_for(samples, "lattice samples", 6000);
          }};
}

}  // namespace gt
