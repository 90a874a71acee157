// Seed 004's cave look on the reference (formulas, decisions and the fix of the seed's texture
// frequency in cave_look.hpp) and the scene of a camera inside the seed's cave.
#include "reference/render/cave_look.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/noise/perlin_texture_table.hpp"
#include "core/vec3.hpp"
#include "reference/cave/density.hpp"
#include "reference/cave/marching_tetrahedra.hpp"
#include "reference/cave/normals.hpp"
#include "reference/noise/perlin.hpp"
#include "reference/noise/perlin_texture.hpp"
#include "reference/render/phong.hpp"

namespace gt::reference {
namespace {

// The permutation and the texture table of one noise seed, built once per seed (the table is
// 256 KiB; the fragment functions run once per pixel).
struct NoiseTables {
  Permutation permutation;
  std::vector<std::uint8_t> texture_rgba;
};

const NoiseTables& noise_tables(std::uint32_t seed) {
  static std::mutex mutex;
  static std::map<std::uint32_t, std::unique_ptr<const NoiseTables>> tables;
  const std::lock_guard lock(mutex);
  auto& entry = tables[seed];
  if (!entry) {
    const Permutation permutation = seeded_permutation(seed);
    entry = std::make_unique<const NoiseTables>(NoiseTables{permutation, perlin_texture_rgba(permutation)});
  }
  return *entry;
}

double texture_noise(const NoiseTables& tables, const Vec3& p, double frequency) {
  return perlin3_texture<double>(tables.texture_rgba, p[0] * frequency, p[1] * frequency, p[2] * frequency);
}

}  // namespace

std::vector<Vec3> sampled_strip(const std::vector<StripStop>& stops) {
  if (stops.size() < 2 || stops.front().position != 0.0 || stops.back().position != 1.0) {
    throw InputError("colour strip: need at least two stops, the first at 0 and the last at 1");
  }
  for (std::size_t k = 1; k < stops.size(); ++k) {
    if (!(stops[k].position > stops[k - 1].position)) throw InputError("colour strip: stop positions must increase");
  }
  std::vector<Vec3> strip(colour_strip_size);
  for (int i = 0; i < colour_strip_size; ++i) {
    const double s = (i + 0.5) / colour_strip_size;
    std::size_t k = 1;
    while (stops[k].position < s) ++k;  // stops[k - 1].position <= s <= stops[k].position
    const StripStop &a = stops[k - 1], &b = stops[k];
    const double f = (s - a.position) / (b.position - a.position);
    for (int c = 0; c < 3; ++c) {
      const double value = a.colour[c] + f * (b.colour[c] - a.colour[c]);
      strip[std::size_t(i)][c] = std::round(255.0 * std::clamp(value, 0.0, 1.0)) / 255.0;
    }
  }
  return strip;
}

std::vector<Vec3> seed_colour_strip() {
  return sampled_strip({{0.00, {0.20, 0.16, 0.13}},
                        {0.25, {0.42, 0.33, 0.25}},
                        {0.35, {0.62, 0.50, 0.36}},
                        {0.42, {0.74, 0.66, 0.54}},
                        {0.48, {0.60, 0.58, 0.55}},
                        {0.53, {0.78, 0.75, 0.68}},
                        {0.58, {0.56, 0.40, 0.30}},
                        {0.64, {0.70, 0.60, 0.46}},
                        {0.72, {0.50, 0.48, 0.46}},
                        {1.00, {0.85, 0.82, 0.76}}});
}

Vec3 strip_colour(const std::vector<Vec3>& strip, double s) {
  if (strip.empty()) throw InputError("colour strip: no entries");
  const int last = int(strip.size()) - 1;
  const double x = double(strip.size()) * std::clamp(s, 0.0, 1.0) - 0.5;
  const double lower = std::floor(x);
  const double f = x - lower;
  const Vec3& a = strip[std::size_t(std::clamp(int(lower), 0, last))];
  const Vec3& b = strip[std::size_t(std::clamp(int(lower) + 1, 0, last))];
  return {a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])};
}

double cave_shade(const CaveLook& look, const Vec3& p) {
  const NoiseTables& tables = noise_tables(look.noise_seed);
  const double octaves = std::clamp((look.colour_reference_height - p[1]) * look.colour_octaves_per_unit,
                                    -look.colour_octave_limit, look.colour_octave_limit);
  const double lower = std::floor(octaves);
  const double t = octaves - lower;
  const int k = int(lower);
  const double coarse = texture_noise(tables, p, std::ldexp(look.colour_frequency, k));
  const double fine = texture_noise(tables, p, std::ldexp(look.colour_frequency, k + 1));
  const double noise = ((1.0 - t) * coarse + t * fine) / std::sqrt((1.0 - t) * (1.0 - t) + t * t);
  return 0.5 + 0.5 * noise;
}

Vec3 cave_albedo(const CaveLook& look, const Vec3& p, const Vec3& facing_normal) {
  Vec3 albedo = strip_colour(look.colour_strip, cave_shade(look, p));
  if (facing_normal[1] > 0.0) albedo[1] = albedo[1] + look.moss * facing_normal[1];
  return albedo;
}

double cave_bump_height(const CaveLook& look, const Vec3& p) {
  const NoiseTables& tables = noise_tables(look.noise_seed);
  const double s = look.bump_frequency;
  return look.bump_amplitude * perlin3<double>(tables.permutation, p[0] * s, p[1] * s, p[2] * s);
}

Vec3 cave_bump_gradient(const CaveLook& look, const Vec3& p) {
  const NoiseTables& tables = noise_tables(look.noise_seed);
  const double s = look.bump_frequency, slope = look.bump_amplitude * look.bump_frequency;
  const auto gradient = perlin3_gradient<double>(tables.permutation, p[0] * s, p[1] * s, p[2] * s);
  return {slope * gradient[1], slope * gradient[2], slope * gradient[3]};
}

Vec3 cave_bumped_normal(const CaveLook& look, const Vec3& p, const Vec3& n) {
  if (look.bump_amplitude * look.bump_frequency == 0.0) return n;
  const Vec3 g = cave_bump_gradient(look, p);
  const Vec3 tangential = g - dot(g, n) * n;
  const Vec3 m = n - tangential;
  return (1.0 / std::sqrt(dot(m, m))) * m;
}

PhongScene cave_scene(const CaveParams& block, const Camera& camera, const CaveLook& look, double light_power,
                      CaveNormals normals) {
  if (!(light_power > 0.0) || !std::isfinite(light_power)) throw InputError("cave scene: the light power must be positive");
  for (int axis = 0; axis < 3; ++axis) {
    const double low = block.origin[axis], high = double(block.origin[axis]) + block.size[axis];
    if (!(camera.eye[axis] > low && camera.eye[axis] < high)) {
      throw InputError(fmt::format("cave scene: the eye ({}, {}, {}) lies outside the block [{}, {}] along axis {}",
                                   camera.eye[0], camera.eye[1], camera.eye[2], low, high, axis));
    }
  }
  const Permutation permutation = seeded_permutation(block.seed);
  const double density_at_eye =
      cave_density_at<double>(permutation, block, camera.eye[0], camera.eye[1], camera.eye[2]);
  if (!(density_at_eye >= block.threshold)) {
    throw InputError(fmt::format("cave scene: the eye ({}, {}, {}) lies in rock (density {:.4g} below the threshold {})",
                                 camera.eye[0], camera.eye[1], camera.eye[2], density_at_eye, block.threshold));
  }
  require_checkable_block(block);
  const Mesh mesh = marching_tetrahedra<double>(cave_density<double>(block), block.threshold, block.solid,
                                                {block.origin[0], block.origin[1], block.origin[2]});
  if (mesh.triangles.empty()) throw InputError("cave scene: the block has no cave surface");
  PhongScene scene = phong_scene(mesh, camera, Look::cave);
  scene.normals = normals == CaveNormals::analytic ? gradient_normals<double>(scene.mesh, block)
                                                   : central_difference_normals<double>(scene.mesh, block);
  scene.cave = look;
  scene.light_power = light_power;
  return scene;
}

}  // namespace gt::reference
