// Seed 004's Phong look on the reference rasterizer: camera matrices, vertex normals, the shading
// formula and the render; conventions and decisions in phong.hpp.
#include "reference/render/phong.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/mutant.hpp"
#include "core/vec3.hpp"
#include "reference/render/rasterizer.hpp"

namespace gt::reference {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Centre and half diagonal of the bounding box of all vertex positions.
struct Bounds {
  Vec3 centre{};
  double radius = 0.0;
};

Bounds bounds(const Mesh& mesh) {
  const auto [low, high] = bounding_box(mesh);
  const Vec3 diagonal = high - low;
  return {0.5 * (low + high), 0.5 * std::sqrt(dot(diagonal, diagonal))};
}

void require_drawable(const Mesh& mesh) {
  if (mesh.triangles.empty()) throw InputError("Phong render: the mesh has no triangles");
  if (!(bounds(mesh).radius > 0.0)) throw InputError("Phong render: the mesh has no extent (all vertices coincide)");
}

void require_valid(const Camera& camera) {
  const Vec3 forward = camera.target - camera.eye;
  if (!(dot(forward, forward) > 0.0)) throw InputError("Phong render: the camera's eye is at its target");
  const Vec3 side = cross(forward, camera.up);
  if (!(dot(side, side) > 0.0)) throw InputError("Phong render: the camera's up vector is along its view direction");
  if (!(camera.fov_y_deg > 0.0 && camera.fov_y_deg < 180.0)) {
    throw InputError("Phong render: the vertical field of view must lie in (0, 180) degrees");
  }
  if (!(camera.near > 0.0 && camera.far > camera.near)) throw InputError("Phong render: need 0 < near < far");
  if (camera.width < 1 || camera.height < 1 || camera.width > 16384 || camera.height > 16384) {
    throw InputError("Phong render: image sides must lie in [1, 16384] pixels");
  }
}

// The unit normal facing the viewer: the normalised interpolated normal, flipped when it points away
// from the eye (two-sided), v when it is exactly zero. Mutant render.phong.facing_reversed (in
// both twins): flipped when it points towards the eye instead.
Vec3 facing_normal(const Vec3& position, const Vec3& normal, const Vec3& eye) {
  const Vec3 v = normalised(eye - position);
  Vec3 n = dot(normal, normal) > 0.0 ? normalised(normal) : v;
  const bool faces_away = dot(n, v) < 0.0;
  if (faces_away != mutant_active("render.phong.facing_reversed")) n = -1.0 * n;
  return n;
}

// The seed's constants (digest §2.9): K_a = 0.1 and exponent 5, or the mutants' (in both
// twins): render.phong.no_ambient drops the ambient term, render.phong.specular_exponent uses 10.
double ambient() { return mutant_active("render.phong.no_ambient") ? 0.0 : 0.1; }
double specular_exponent() { return mutant_active("render.phong.specular_exponent") ? 10.0 : 5.0; }

double terrain_height(const Vec3& up, const Vec3& p) { return (p[0] * up[0] + p[1] * up[1]) + p[2] * up[2]; }

void require_strip(const std::vector<Vec3>& strip, const char* what) {
  if (strip.empty()) throw InputError(fmt::format("Phong render: the {} has no entries", what));
  for (const auto& entry : strip) {
    for (const double channel : entry) {
      if (!(channel >= 0.0 && channel <= 1.0)) throw InputError(fmt::format("Phong render: {} entries must lie in [0, 1]", what));
    }
  }
}

void require_finite(double value, const char* what) {
  if (!std::isfinite(value)) throw InputError(fmt::format("Phong render: {} must be finite", what));
}

void require_drape(const TerrainDrape& drape) {
  if (drape.width < 1 || drape.height < 1 || drape.width > 16384 || drape.height > 16384) {
    throw InputError("terrain look: the drape's sides must lie in [1, 16384] texels");
  }
  if (drape.rgb.size() != 3 * std::size_t(drape.width) * std::size_t(drape.height)) {
    throw InputError(fmt::format("terrain look: a {}x{} drape needs {} bytes, it has {}", drape.width, drape.height,
                                 3 * std::size_t(drape.width) * std::size_t(drape.height), drape.rgb.size()));
  }
  if (!(drape.x_east > drape.x_west) || !(drape.z_south > drape.z_north) ||
      !std::isfinite(drape.x_east - drape.x_west) || !std::isfinite(drape.z_south - drape.z_north)) {
    throw InputError("terrain look: the drape needs x_west < x_east and z_north < z_south");
  }
}

// Texel (column, row) of the drape, channels byte/255.
Vec3 drape_texel(const TerrainDrape& drape, int column, int row) {
  const std::size_t first = 3 * (std::size_t(row) * std::size_t(drape.width) + std::size_t(column));
  return {drape.rgb[first] / 255.0, drape.rgb[first + 1] / 255.0, drape.rgb[first + 2] / 255.0};
}

// Texel coordinate t in [0, 1] over `size` texels: the two clamped neighbours and the weight of the second.
struct TexelPair {
  int first, second;
  double weight;
};

TexelPair texel_pair(double t, int size) {
  const double x = double(size) * std::clamp(t, 0.0, 1.0) - 0.5;
  const double lower = std::floor(x);
  return {std::clamp(int(lower), 0, size - 1), std::clamp(int(lower) + 1, 0, size - 1), x - lower};
}

Vec3 mix(const Vec3& a, const Vec3& b, double weight) { return a + weight * (b - a); }

void require_look(const PhongScene& scene) {
  if (scene.look == Look::cave) {
    const CaveLook& cave = scene.cave;
    require_strip(cave.colour_strip, "cave colour strip");
    if (!(cave.colour_frequency > 0.0) || !std::isfinite(cave.colour_frequency)) {
      throw InputError("Phong render: the cave colour frequency must be positive");
    }
    require_finite(cave.colour_reference_height, "the cave colour reference height");
    require_finite(cave.colour_octaves_per_unit, "the cave colour octave rate");
    if (!(cave.colour_octave_limit >= 0.0 && cave.colour_octave_limit <= 60.0)) {
      throw InputError("Phong render: the cave colour octave limit must lie in [0, 60]");
    }
    if (!(cave.bump_amplitude >= 0.0 && cave.bump_frequency >= 0.0) || !std::isfinite(cave.bump_amplitude * cave.bump_frequency)) {
      throw InputError("Phong render: the cave bump amplitude and frequency must be finite and >= 0");
    }
    require_finite(cave.moss, "the cave moss strength");
  } else if (scene.look == Look::terrain) {
    const TerrainLook& terrain = scene.terrain;
    require_strip(terrain.ramp, "terrain height ramp");
    require_strip({terrain.rock}, "terrain rock colour");
    if (!(std::abs(dot(terrain.up, terrain.up) - 1.0) <= 1e-9)) throw InputError("terrain look: `up` must be a unit vector");
    if (!(terrain.height_high > terrain.height_low) || !std::isfinite(terrain.height_high - terrain.height_low)) {
      throw InputError("terrain look: need height_low < height_high");
    }
    if (!(terrain.rock_start_deg >= 0.0 && terrain.rock_start_deg < terrain.rock_full_deg && terrain.rock_full_deg <= 180.0)) {
      throw InputError("terrain look: need 0 <= rock_start_deg < rock_full_deg <= 180");
    }
    if (terrain.drape) require_drape(*terrain.drape);
  }
}

// Perspective-correct attributes: world position (3) then vertex normal (3).
RasterInput clip_input(const PhongScene& scene) {
  RasterInput input;
  input.attribute_count = 6;
  input.triangles = scene.mesh.triangles;
  for (std::size_t k = 0; k < scene.mesh.positions.size(); ++k) {
    const Vec3& p = scene.mesh.positions[k];
    input.clip_positions.push_back(transform_point(scene.view_projection, p));
    input.attributes.insert(input.attributes.end(), p.begin(), p.end());
    input.attributes.insert(input.attributes.end(), scene.normals[k].begin(), scene.normals[k].end());
  }
  return input;
}

// GL's bottom-first colour buffer to top-first RGB8. Mutant render.phong.vertical_flip (in
// both twins): rows read bottom first, the picture upside down.
}  // namespace

Matrix4 view_matrix(const Camera& camera) {
  require_valid(camera);
  // Mutant render.phong.camera_faces_away (both twins: they draw with this matrix): the forward
  // direction taken from the target to the eye, so the camera looks away from what it was aimed at.
  const Vec3 forward = mutant_active("render.phong.camera_faces_away") ? normalised(camera.eye - camera.target)
                                                                       : normalised(camera.target - camera.eye);
  const Vec3 right = normalised(cross(forward, camera.up));
  const Vec3 up = cross(right, forward);
  return {right[0],    right[1],    right[2],    -dot(right, camera.eye),   //
          up[0],       up[1],       up[2],       -dot(up, camera.eye),      //
          -forward[0], -forward[1], -forward[2], dot(forward, camera.eye),  //
          0.0,         0.0,         0.0,         1.0};
}

Matrix4 projection_matrix(const Camera& camera) {
  require_valid(camera);
  const double f = 1.0 / std::tan(0.5 * radians(camera.fov_y_deg));
  const double aspect = double(camera.width) / double(camera.height);
  const double n = camera.near, far = camera.far;
  return {f / aspect, 0.0, 0.0,                     0.0,                         //
          0.0,        f,   0.0,                     0.0,                         //
          0.0,        0.0, (far + n) / (n - far),   2.0 * far * n / (n - far),   //
          0.0,        0.0, -1.0,                    0.0};
}

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 product{};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) {
      for (int k = 0; k < 4; ++k) product[4 * r + c] += a[4 * r + k] * b[4 * k + c];
    }
  }
  return product;
}

std::array<double, 4> transform_point(const Matrix4& m, const Vec3& p) {
  std::array<double, 4> out{};
  for (int r = 0; r < 4; ++r) out[r] = m[4 * r] * p[0] + m[4 * r + 1] * p[1] + m[4 * r + 2] * p[2] + m[4 * r + 3];
  return out;
}

Camera orbit_camera(const Mesh& mesh, double azimuth_deg, double elevation_deg, double fov_y_deg, int width,
                    int height) {
  require_drawable(mesh);
  const Bounds box = bounds(mesh);
  const double distance = 2.5 * box.radius;
  const double a = radians(azimuth_deg), e = radians(elevation_deg);
  const Vec3 direction = {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
  Camera camera{.eye = box.centre + distance * direction,
                .target = box.centre,
                .up = {0.0, 1.0, 0.0},
                .fov_y_deg = fov_y_deg,
                .near = 0.5 * (distance - box.radius),
                .far = 2.0 * (distance + box.radius),
                .width = width,
                .height = height};
  require_valid(camera);
  return camera;
}

std::vector<Vec3> vertex_normals(const Mesh& mesh) {
  std::vector<Vec3> sums(mesh.positions.size(), Vec3{});
  for (const auto& t : mesh.triangles) {
    const Vec3& a = mesh.positions.at(t[0]);
    const Vec3 face = cross(mesh.positions.at(t[1]) - a, mesh.positions.at(t[2]) - a);  // 2·area·unit normal
    for (const auto vertex : t) sums[vertex] = sums[vertex] + face;
  }
  for (auto& n : sums) {
    if (dot(n, n) > 0.0) n = normalised(n);
  }
  return sums;
}

PhongScene phong_scene(const Mesh& mesh, const Camera& camera, Look look) {
  PhongScene scene = phong_scene(mesh, camera);
  scene.look = look;
  if (look == Look::terrain) scene.terrain = terrain_look(mesh);
  return scene;
}

PhongScene phong_scene(const Mesh& mesh, const Camera& camera) {
  require_drawable(mesh);
  const Vec3 to_centre = bounds(mesh).centre - camera.eye;
  return {.mesh = mesh,
          .normals = vertex_normals(mesh),
          .camera = camera,
          .view_projection = multiply(projection_matrix(camera), view_matrix(camera)),
          .light_power = dot(to_centre, to_centre)};
}

Vec3 phong_colour(const Vec3& position, const Vec3& normal, const Vec3& eye, const Vec3& albedo, double light_power) {
  return phong_lit(position, facing_normal(position, normal, eye), eye, albedo, light_power);
}

Vec3 phong_lit(const Vec3& position, const Vec3& unit_normal, const Vec3& eye, const Vec3& albedo, double light_power) {
  const Vec3 to_eye = eye - position;
  const double irradiance = light_power / dot(to_eye, to_eye);
  const Vec3 v = normalised(to_eye), l = v;
  const Vec3& n = unit_normal;
  const double n_dot_l = dot(n, l);
  const Vec3 r = 2.0 * n_dot_l * n - l;
  const double diffuse = std::max(0.0, n_dot_l), specular = std::pow(std::max(0.0, dot(r, v)), specular_exponent());
  const double ambient_term = ambient();
  Vec3 colour{};
  for (int c = 0; c < 3; ++c) {
    colour[c] = std::clamp(albedo[c] * (ambient_term + irradiance * diffuse) + 0.3 * irradiance * specular, 0.0, 1.0);
  }
  return colour;
}

std::vector<Vec3> terrain_height_ramp() {
  return sampled_strip({{0.00, {0.16, 0.32, 0.14}},
                        {0.30, {0.36, 0.52, 0.20}},
                        {0.55, {0.62, 0.56, 0.36}},
                        {0.78, {0.50, 0.42, 0.34}},
                        {0.90, {0.60, 0.58, 0.56}},
                        {1.00, {0.96, 0.96, 0.98}}});
}

TerrainLook terrain_look(const Mesh& mesh, const Vec3& up) {
  require_drawable(mesh);
  if (!(std::abs(dot(up, up) - 1.0) <= 1e-9)) throw InputError("terrain look: `up` must be a unit vector");
  TerrainLook look;
  look.up = up;
  look.height_low = std::numeric_limits<double>::infinity();
  look.height_high = -std::numeric_limits<double>::infinity();
  for (const auto& p : mesh.positions) {
    const double height = terrain_height(up, p);
    look.height_low = std::min(look.height_low, height);
    look.height_high = std::max(look.height_high, height);
  }
  if (!(look.height_high > look.height_low)) throw InputError("terrain look: the mesh has no extent along `up`");
  return look;
}

Vec3 drape_colour(const TerrainDrape& drape, double u, double v) {
  const TexelPair column = texel_pair(u, drape.width), row = texel_pair(v, drape.height);
  const Vec3 top = mix(drape_texel(drape, column.first, row.first), drape_texel(drape, column.second, row.first),
                       column.weight);
  const Vec3 bottom = mix(drape_texel(drape, column.first, row.second), drape_texel(drape, column.second, row.second),
                          column.weight);
  return mix(top, bottom, row.weight);
}

// The colour the rock blend starts from: the drape's at p when there is one, else the height ramp's.
Vec3 ground_colour(const TerrainLook& look, const Vec3& p) {
  if (look.drape) {
    const TerrainDrape& drape = *look.drape;
    return drape_colour(drape, (p[0] - drape.x_west) / (drape.x_east - drape.x_west),
                        (p[2] - drape.z_north) / (drape.z_south - drape.z_north));
  }
  const double h = std::clamp((terrain_height(look.up, p) - look.height_low) / (look.height_high - look.height_low),
                              0.0, 1.0);
  return strip_colour(look.ramp, h);
}

Vec3 terrain_albedo(const TerrainLook& look, const Vec3& p, const Vec3& n) {
  const Vec3 ground = ground_colour(look, p);
  const double cos_start = std::cos(radians(look.rock_start_deg)), cos_full = std::cos(radians(look.rock_full_deg));
  const double c = terrain_height(look.up, n);
  double w = std::clamp((cos_start - c) / (cos_start - cos_full), 0.0, 1.0);
  w = w * w * (3.0 - 2.0 * w);
  return ground + w * (look.rock - ground);
}

Vec3 shade_fragment(const PhongScene& scene, const Vec3& position, const Vec3& normal) {
  const Vec3& eye = scene.camera.eye;
  switch (scene.look) {
    case Look::plain: break;
    case Look::cave: {
      const Vec3 n = facing_normal(position, normal, eye);
      return phong_lit(position, cave_bumped_normal(scene.cave, position, n), eye, cave_albedo(scene.cave, position, n),
                       scene.light_power);
    }
    case Look::terrain: {
      const Vec3 n = facing_normal(position, normal, eye);
      return phong_lit(position, n, eye, terrain_albedo(scene.terrain, position, n), scene.light_power);
    }
  }
  return phong_colour(position, normal, eye, scene.albedo, scene.light_power);
}

std::uint8_t quantise_unorm8(double channel) { return std::uint8_t(std::lround(255.0 * channel)); }

Rgb8Image quantised_top_first(const RasterTarget& target) {
  Rgb8Image image{target.width, target.height, {}};
  image.rgb.reserve(std::size_t(target.width) * std::size_t(target.height) * 3);
  const bool flipped = mutant_active("render.phong.vertical_flip");
  for (int row = 0; row < target.height; ++row) {
    const int gl_row = flipped ? row : target.height - 1 - row;
    for (int x = 0; x < target.width; ++x) {
      for (int channel = 0; channel < 3; ++channel) {
        image.rgb.push_back(quantise_unorm8(target.colour_at(x, gl_row, channel)));
      }
    }
  }
  return image;
}

Rgb8Image render_phong(const PhongScene& scene, int subpixel_bits) {
  require_look(scene);
  RasterTarget target(scene.camera.width, scene.camera.height, 3, 0.0, 1.0);
  const FragmentShader shade = [&scene](std::span<const double> a, std::span<double> colour) {
    const Vec3 rgb = shade_fragment(scene, {a[0], a[1], a[2]}, {a[3], a[4], a[5]});
    std::copy(rgb.begin(), rgb.end(), colour.begin());
  };
  rasterize(clip_input(scene), shade, target, {.subpixel_bits = subpixel_bits});
  Rgb8Image image = quantised_top_first(target);
  image.covered_pixels = std::size_t(std::count_if(target.depth.begin(), target.depth.end(), [](double d) { return d < 1.0; }));
  return image;
}

}  // namespace gt::reference
