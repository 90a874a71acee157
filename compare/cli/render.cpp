// render: read a mesh or a heightmap (meshed as a terrain solid), place the camera, refuse what
// cannot give a picture (camera inside, nothing seen), render on the chosen twin and write the PNG
// atomically. See render.hpp for the conventions.
#include "compare/cli/render.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <system_error>

#include <fmt/format.h>
#include <OpenImageIO/imageio.h>

#include "compare/algorithms/render_phong.hpp"
#include "compare/output_folder.hpp"
#include "core/errors.hpp"
#include "core/io/atomic_file.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/io/mesh_io.hpp"
#include "core/memory.hpp"
#include "core/vec3.hpp"
#include "gpu/context/context.hpp"
#include "gpu/render/phong.hpp"
#include "reference/render/phong.hpp"
#include "reference/render/rasterizer.hpp"
#include "reference/render/terrain_solid.hpp"

namespace gt {

namespace {

namespace fs = std::filesystem;

constexpr int exit_written = 0;
constexpr int exit_bad_input = 2;
constexpr int max_side = 16384;
// Peak memory per pixel of the picture: measured as the peak RSS of `render` of the volcano at
// 1024² and 4096², 35 B a pixel more on the CPU backend (depth and colour targets in double, the
// 8-bit copy) and 15 B on llvmpipe, rounded up. The input's own estimate is the reader's.
constexpr double render_bytes_per_pixel = 40.0;
// A heightmap drawn as a terrain solid, per cell: its mesh (a vertex and two triangles), the
// rasterizer's or GL's copies of it and the heightmap read. Measured as peak RSS at 1000² and
// 2000² cells (a 64² picture): 448 B a cell on the CPU backend, 330 on llvmpipe; rounded up.
constexpr double render_bytes_per_cell = 500.0;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

bool is_mesh_file(const fs::path& file) {
  const std::string extension = lower(file.extension().string());
  return extension == ".off" || extension == ".obj" || extension == ".ply" || extension == ".stl";
}

void check_request(const RenderOptions& options) {
  if (options.out.empty()) throw InputError("render: name the picture with --out FILE.png");
  if (lower(options.out.extension().string()) != ".png") {
    throw InputError(fmt::format("render: --out {} must name a .png file", options.out.string()));
  }
  const fs::path folder = options.out.parent_path().empty() ? fs::path(".") : options.out.parent_path();
  std::error_code error;
  if (!fs::is_directory(folder, error)) {
    throw InputError(fmt::format("render: --out {}: the folder {} does not exist", options.out.string(), folder.string()));
  }
  if (same_file(options.out, options.input)) {
    throw InputError(fmt::format("render: --out {} would overwrite the input {}", options.out.string(),
                                 options.input.string()));
  }
  if (options.width < 1 || options.height < 1 || options.width > max_side || options.height > max_side) {
    throw InputError(fmt::format("render: image sides must lie in [1, {}] pixels, not {}x{}", max_side, options.width,
                                 options.height));
  }
  if (options.backend != "cpu" && options.backend != "gpu") {
    throw InputError(fmt::format("render: --backend {}: expected cpu or gpu", options.backend));
  }
  require_memory(memory_for(double(options.width) * double(options.height), "pixels", render_bytes_per_pixel),
                 fmt::format("render: a {}x{} picture", options.width, options.height));
  if (options.look != "auto" && options.look != "plain" && options.look != "terrain" && options.look != "cave") {
    throw InputError(fmt::format("render: --look {}: expected auto, plain, terrain or cave", options.look));
  }
  if (options.eye.empty() != options.target.empty()) {
    throw InputError("render: a free camera needs both --eye and --target");
  }
  for (const auto* point : {&options.eye, &options.target}) {
    if (!point->empty() && point->size() != 3) throw InputError("render: --eye and --target take three numbers, X,Y,Z");
    for (const double value : *point) {
      if (!std::isfinite(value)) throw InputError("render: --eye and --target must be finite");
    }
  }
  if (!(options.fov_deg > 0.0 && options.fov_deg < 180.0)) {
    throw InputError(fmt::format("render: --fov {} must lie in (0, 180) degrees", options.fov_deg));
  }
  if (!(options.distance >= 0.0 && std::isfinite(options.distance))) {
    throw InputError(fmt::format("render: --distance {} must be positive (or 0: fit)", options.distance));
  }
}

// What is drawn: the mesh, what it came from, and for a terrain solid the lowest surface height.
struct Subject {
  Mesh mesh;
  bool terrain = false;
  double surface_low = 0.0;  // terrain: lowest surface height (the base lies below)
  std::string description;
};

Subject read_subject(const RenderOptions& options) {
  Subject subject;
  if (is_mesh_file(options.input)) {
    MeshFile file = read_mesh(options.input);
    subject.mesh = std::move(file.mesh);
    subject.description = fmt::format("{} ({} vertices, {} triangles)", options.input.string(),
                                      subject.mesh.positions.size(), subject.mesh.triangles.size());
    return subject;
  }
  HeightmapReadOptions read_options;
  read_options.cell_size = options.cell_size;
  read_options.image_vertical_scale = options.image_vertical_scale;
  const HeightmapFile file = read_heightmap(options.input, read_options);
  require_memory(memory_for(double(file.heights.width) * double(file.heights.height), "cells", render_bytes_per_cell),
                 fmt::format("render: a terrain solid of {}x{} cells", file.heights.width, file.heights.height));
  reference::TerrainSolid solid;
  try {
    solid = reference::terrain_solid(file.heights, {.vertical_scale = options.vertical_scale});
  } catch (const InputError& error) {
    throw InputError(fmt::format("{}: {}", options.input.string(), error.what()));
  }
  subject.terrain = true;
  subject.surface_low = solid.base_y + solid.base_depth;
  subject.description = fmt::format("{} ({}x{} samples of {:.4g}x{:.4g} {}) as a terrain solid of {} triangles",
                                    options.input.string(), file.heights.width, file.heights.height,
                                    file.heights.cell_size_x, file.heights.cell_size_y, file.heights.horizontal_unit,
                                    solid.mesh.triangles.size());
  subject.mesh = std::move(solid.mesh);
  return subject;
}

struct Sphere {
  Vec3 centre{};
  double radius = 0.0;
};

Sphere bounding_sphere(const Mesh& mesh) {
  const auto [low, high] = bounding_box(mesh);
  return {0.5 * (low + high), 0.5 * length(high - low)};
}

// --distance, or when it is 0 the distance at which the bounding sphere just fits the narrower of
// the two fields of view: 1 / sin(half of it).
double orbit_distance(const RenderOptions& options) {
  if (options.distance > 0.0) return options.distance;
  const double half_y = 0.5 * options.fov_deg * std::numbers::pi / 180.0;
  const double half_x = std::atan(std::tan(half_y) * double(options.width) / double(options.height));
  return 1.0 / std::sin(std::min(half_x, half_y));
}

reference::Camera place_camera(const RenderOptions& options, const Mesh& mesh) {
  const Sphere sphere = bounding_sphere(mesh);
  if (!(sphere.radius > 0.0)) throw InputError("render: the mesh has no extent (all vertices coincide)");
  reference::Camera camera;
  if (options.eye.empty()) {
    const double a = options.azimuth_deg * std::numbers::pi / 180.0, e = options.elevation_deg * std::numbers::pi / 180.0;
    const Vec3 direction = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
    camera.eye = sphere.centre + (orbit_distance(options) * sphere.radius) * direction;
    camera.target = sphere.centre;
  } else {
    camera.eye = {options.eye[0], options.eye[1], options.eye[2]};
    camera.target = {options.target[0], options.target[1], options.target[2]};
  }
  const Vec3 forward = camera.target - camera.eye;
  if (!(length(forward) > 0.0)) throw InputError("render: the camera's eye is at its target");
  const Vec3 side = cross(forward, {0.0, 1.0, 0.0});
  camera.up = length(side) > 1e-9 * length(forward) ? Vec3{0.0, 1.0, 0.0} : Vec3{0.0, 0.0, -1.0};
  const double d = length(camera.eye - sphere.centre);
  camera.far = 2.0 * (d + sphere.radius);
  camera.near = std::max(0.5 * (d - sphere.radius), camera.far / 1000.0);
  camera.fov_y_deg = options.fov_deg;
  camera.width = options.width;
  camera.height = options.height;
  return camera;
}

// Generalised winding number at p (Jacobson et al. 2013): Σ signed solid angles / 4π, each by
// Van Oosterom and Strackee's formula. +1 inside a closed outward-facing mesh, 0 outside, -1 inside
// an inward-facing one; fractional near holes.
double winding_number(const Mesh& mesh, const Vec3& p) {
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.positions[t[0]] - p, b = mesh.positions[t[1]] - p, c = mesh.positions[t[2]] - p;
    const double la = length(a), lb = length(b), lc = length(c);
    const double numerator = dot(a, cross(b, c));
    const double denominator = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    total += 2.0 * std::atan2(numerator, denominator);
  }
  return total / (4.0 * std::numbers::pi);
}

// Pixels whose centre some triangle covers, by the reference rasterizer (what both twins cover,
// up to edge pixels).
std::size_t covered_pixels(const reference::PhongScene& scene) {
  reference::RasterInput input;
  input.attribute_count = 0;
  input.triangles = scene.mesh.triangles;
  input.clip_positions.reserve(scene.mesh.positions.size());
  for (const auto& p : scene.mesh.positions) input.clip_positions.push_back(reference::transform_point(scene.view_projection, p));
  reference::RasterTarget target(scene.camera.width, scene.camera.height, 1, 0.0, 1.0);
  reference::rasterize(input, [](std::span<const double>, std::span<double> colour) { colour[0] = 1.0; }, target);
  return std::size_t(std::count(target.colour.begin(), target.colour.end(), 1.0));
}

reference::Look look_for(const RenderOptions& options, const Subject& subject) {
  if (options.look == "terrain" || (options.look == "auto" && subject.terrain)) return reference::Look::terrain;
  if (options.look == "cave") return reference::Look::cave;
  return reference::Look::plain;
}

const char* look_name(reference::Look look) {
  switch (look) {
    case reference::Look::plain: return "plain";
    case reference::Look::cave: return "cave";
    case reference::Look::terrain: return "terrain";
  }
  return "?";
}

struct Picture {
  std::vector<std::uint8_t> rgb;  // rows top first
  std::size_t covered = 0;
  std::string renderer;           // "CPU reference (double)" or the GL renderer
};

void refuse_empty_view(std::size_t covered, const reference::Camera& camera) {
  if (covered > 0) return;
  throw InputError(fmt::format("render: the camera at ({:.6g}, {:.6g}, {:.6g}) looking at ({:.6g}, {:.6g}, {:.6g}) sees "
                               "nothing: no pixel is covered by the mesh; aim it at the mesh (orbit camera: drop --eye "
                               "and --target)",
                               camera.eye[0], camera.eye[1], camera.eye[2], camera.target[0], camera.target[1],
                               camera.target[2]));
}

Picture render_cpu(const reference::PhongScene& scene) {
  const reference::Rgb8Image image = reference::render_phong(scene);
  refuse_empty_view(image.covered_pixels, scene.camera);
  return {image.rgb, image.covered_pixels, "CPU reference (double)"};
}

Picture render_gpu(const reference::PhongScene& scene, const std::string& gl) {
  const std::size_t covered = covered_pixels(scene);
  refuse_empty_view(covered, scene.camera);
  std::unique_ptr<GlContext> context;
  try {
    context = GlContext::create(parse_gl_backend(gl));
  } catch (const GpuUnavailable& error) {
    throw InputError(fmt::format("render: --backend gpu needs a GL context and none could be made: {} (use --backend "
                                 "cpu)",
                                 error.what()));
  }
  const gpu::PhongRenderer renderer(phong_draw(scene));
  renderer.run();
  gpu::Rgb8Pixels image = renderer.image();
  return {std::move(image.rgb), covered, "GPU: " + context->info().renderer};
}

void write_png(const Picture& picture, int width, int height, const fs::path& out) {
  write_image_atomically(out, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), OIIO::TypeDesc::UINT8,
                         picture.rgb.data());
}

int render(const RenderOptions& options) {
  check_request(options);
  const Subject subject = read_subject(options);
  const reference::Camera camera = place_camera(options, subject.mesh);
  const double winding = winding_number(subject.mesh, camera.eye);
  if (winding >= 0.5) {
    throw InputError(fmt::format("render: the camera at ({:.6g}, {:.6g}, {:.6g}) is inside the closed mesh (winding "
                                 "number {:.3g}): it would see only back faces; move it out (--distance > 1, or an "
                                 "--eye outside)",
                                 camera.eye[0], camera.eye[1], camera.eye[2], winding));
  }
  const reference::Look look = look_for(options, subject);
  reference::PhongScene scene = reference::phong_scene(subject.mesh, camera, look);
  if (look == reference::Look::terrain && subject.terrain) scene.terrain.height_low = subject.surface_low;
  const Picture picture = options.backend == "gpu" ? render_gpu(scene, options.gl) : render_cpu(scene);
  write_png(picture, options.width, options.height, options.out);
  const double pixels = double(options.width) * double(options.height);
  fmt::print("{}: {}x{} pixels, {}, look {}, {:.3g} % covered; {}; eye ({:.6g}, {:.6g}, {:.6g}) looking at ({:.6g}, "
             "{:.6g}, {:.6g}), vertical field of view {:g}°\n",
             options.out.string(), options.width, options.height, picture.renderer, look_name(look),
             100.0 * double(picture.covered) / pixels, subject.description, camera.eye[0], camera.eye[1],
             camera.eye[2], camera.target[0], camera.target[1], camera.target[2], camera.fov_y_deg);
  return exit_written;
}

}  // namespace

int render_command(const RenderOptions& options) {
  try {
    return render(options);
  } catch (const InputError& error) {
    fmt::print(stderr, "groundtruth: {}\n", error.what());
    return exit_bad_input;
  }
}

}  // namespace gt
