// Seed 004's Phong look (digest 004_cave.md §2.9) on a mesh through a perspective camera, CPU reference in double.
//
// view_matrix(camera), projection_matrix(camera), multiply(a, b), transform_point(m, p) -> the camera's
//   matrices (conventions below); orbit_camera(mesh, azimuth, elevation, fov_y, width, height) -> Camera.
// vertex_normals(mesh) -> the area-weighted vertex normals (see Decisions).
// phong_scene(mesh, camera[, look]) -> PhongScene, everything both twins draw, computed once on the CPU;
//   with `look` selected; for terrain, terrain = terrain_look(mesh) (+y up).
// terrain_look(mesh, up), terrain_height_ramp(), drape_colour(drape, u, v), terrain_albedo(look, p, n):
//   the terrain look and its colour drape (below).
// phong_colour(p, n, eye, albedo, power), phong_lit(...), shade_fragment(scene, p, n): one fragment
//   (the shading formula below, clamped to [0, 1]; phong_lit for a unit normal used as it is).
// render_phong(scene, subpixel_bits = 8) -> Rgb8Image; quantised_top_first(target), quantise_unorm8(c):
//   a target as 8-bit levels, rows top first.
// Drawn by the reference rasterizer (rasterizer.hpp) in double. Slow by design.
//
// Camera conventions (right-handed world, OpenGL clip space):
//   view_matrix        gluLookAt: the camera sits at `eye`, looks along -z_eye towards `target`,
//                      +y_eye is `up` made orthogonal to the view direction, +x_eye to the right.
//   projection_matrix  gluPerspective: f = 1/tan(fov_y/2), a = width/height,
//                        [f/a 0 0 0; 0 f 0 0; 0 0 (F+N)/(N-F) 2FN/(N-F); 0 0 -1 0]
//                      so z_eye = -near goes to z_ndc = -1 and z_eye = -far to +1; the optical axis
//                      goes to x_ndc = y_ndc = 0, the image centre.
//   Matrices are row-major: element (row r, column c) at [4r + c]; clip = P·V·(x, y, z, 1).
//   orbit_camera       looks at the bounding-box centre c from the distance D = 2.5·r (r = half the box
//                      diagonal, so the mesh lies within r of c and is never clipped by near): eye =
//                      c + D·(cos e·sin a, sin e, cos e·cos a) for azimuth a (from +z towards +x) and
//                      elevation e (towards +y), up = +y, near = (D - r)/2, far = 2(D + r).
//
// Shading (digest §2.9, the opengl-tutorial shader the thesis copied; K_a = 0.1, C_s·K_s = 0.3,
// exponent 5, one point light at the eye, LightColor 1), at each fragment from the perspective-
// correctly interpolated world position p and vertex normal:
//   v = normalize(eye - p), l = v (light at the eye), d² = |eye - p|², E = light_power / d²
//   n = normalize(interpolated normal), flipped to face the viewer when n·v < 0 (two-sided: the
//       mesh is drawn without culling, so back faces are lit like front faces); n = v when the
//       interpolated normal is exactly zero (only next to vertices whose faces have no area)
//   r = reflect(-l, n) = 2(n·l)n - l
//   colour = albedo·(0.1 + E·max(0, n·l)) + 0.3·E·max(0, r·v)^5, each channel clamped to [0, 1]
// (with l = v, r·v = 2(n·v)² - 1: the digest's closed form).
// Depth test LESS against a cleared depth of 1, no culling, triangles in index order.
// render_phong also counts the covered pixels (depth < 1 after the draw): Rgb8Image::covered_pixels.
//
// Looks (one render twin, the look is a parameter, PhongScene::look):
//   plain    the formula above with the one albedo (seed 004's Phong).
//   cave     seed 004's full look: colour strip indexed by solid noise with a height-dependent
//            frequency, moss on upward normals, bump mapping by the analytic noise gradient
//            (cave_look.hpp documents it and the fix of the seed's frequency formula).
//   terrain  height and slope colouring for terrain meshes (TerrainLook below).
// Every look shades with the same Phong terms: with n the unit normal facing the viewer (as above)
// a look gives the albedo a(p, n) and the shading normal n' (n except for the cave's bump), and
//   colour = a·(0.1 + E·max(0, n'·l)) + 0.3·E·max(0, r'·v)^5, r' = 2(n'·l)n' - l, clamped to [0, 1]
// (phong_lit). The plain look is phong_colour itself.
//
// Terrain look (this project's, for heightmap meshes):
//   h = clamp((p·up - height_low)/(height_high - height_low), 0, 1)   (p·up = (p_x·u_x + p_y·u_y) + p_z·u_z)
//   ramp colour = strip_colour(ramp, h) (cave_look.hpp: GL_LINEAR lookup in a 256-entry strip)
//   c = n·up, w = clamp((cos(rock_start) - c)/(cos(rock_start) - cos(rock_full)), 0, 1),
//   w = w²(3 - 2w) (smoothstep), albedo = ground + w·(rock - ground), ground = the ramp colour
//   (or the drape's, see "Colour drape")
// so faces steeper than rock_start_deg (default 30°) turn towards the rock colour, fully rock from
// rock_full_deg (45°) on; walls and faces seen from below (c <= 0) are rock. terrain_height_ramp()
// is a hypsometric ramp, piecewise-linear between these stops at the entry centres (i + 0.5)/256,
// each channel rounded to k/255:
//   0.00 (0.16, 0.32, 0.14) lowland green   0.30 (0.36, 0.52, 0.20) grass
//   0.55 (0.62, 0.56, 0.36) dry grass       0.78 (0.50, 0.42, 0.34) bare earth
//   0.90 (0.60, 0.58, 0.56) scree           1.00 (0.96, 0.96, 0.98) snow
// rock = (0.42, 0.40, 0.38).
// Colour drape (optional, TerrainLook::drape): an RGB8 image laid over the terrain in plan
// view, projected along world y whatever `up` is (meant for up = +y, the terrain solid's). u runs
// along +x (east) from x_west (u = 0) to x_east (u = 1), v along +z (south) from z_north (v = 0) to
// z_south (v = 1); image row 0 is v = 0 (north, the top of the picture as stored), column 0 u = 0.
//   u = clamp((p_x - x_west)/(x_east - x_west), 0, 1), v likewise with p_z, z_north, z_south
//   x = W·u - 0.5, i = floor(x), f = x - i (texel centres at (i + 0.5)/W), y, j, g likewise with H
//   top = t(i0, j0) + f·(t(i1, j0) - t(i0, j0)), bottom = t(i0, j1) + f·(t(i1, j1) - t(i0, j1)),
//   drape colour = top + g·(bottom - top), t(i, j) = byte/255, i0 = clamp(i, 0, W - 1), i1 =
//   clamp(i + 1, 0, W - 1), j0, j1 likewise (bilinear with clamp to edge, the 2-D form of the strip
//   lookup in cave_look.hpp, in plain arithmetic on both twins for the same reason: GL leaves the
//   texture unit's weight precision open). The bytes are used as stored (sRGB-encoded, like the
//   strips); no mip-mapping, so a drape much finer than the pixels aliases.
// The drape colour replaces the ramp colour above (h is not used); the rock blend stays, so cliffs,
// skirts and the base stay rock. terrain_look(mesh, up) takes height_low/high from the mesh's extent
// along `up` (for a terrain solid with a base below the surface, set height_low to the lowest
// surface height instead, so the base does not stretch the ramp).
//
// Inputs:  mesh (positions in any unit, uint32 triangles), camera (Camera: eye, target, up, fov_y,
//          near, far, image size), look parameters (CaveLook, TerrainLook with an optional drape).
// Outputs: matrices, normals, the scene, fragment colours with channels in [0, 1], and Rgb8Image
//          (3 bytes per pixel, row 0 at the top, covered_pixels).
// Units:   positions, near and far in the mesh's unit; angles in degrees; colours in [0, 1], bytes
//          round(255·c).
// Throws:  InputError for a mesh without triangles or without extent, for a drape whose sides lie
//          outside [1, 16384], whose bytes are not 3·W·H or whose extent is empty, and for an unusable
//          camera (eye at the target, up along the view direction, fov_y outside (0, 180) degrees, not
//          0 < near < far, sides outside [1, 16384]); terrain_look also when `up` is not a unit vector
//          within 1e-9 or the mesh has no extent along it; render_phong also for an unusable look (an
//          empty strip or entries outside [0, 1], a cave colour frequency <= 0, an octave limit outside
//          [0, 60], a negative or non-finite bump amplitude or frequency, non-finite look values, a
//          terrain up not of unit length, no height_low < height_high, no 0 <= rock_start_deg <
//          rock_full_deg <= 180); render_phong std::invalid_argument for subpixel_bits outside [0, 16]
//          (rasterizer.hpp).
// Twin:    gpu/render/phong.hpp (PhongRenderer), which draws the same PhongScene (same normals, same
//          matrix rounded to float), with gpu/shaders/render/phong.{vert,frag} and phong_look.glsl.
// Decisions:
//   - light_power = D², the squared distance from the eye to the box centre, so E = 1 there
//     (surfaces nearer the eye get more, up to (2.5/1.5)² with orbit_camera, and clamp).
//   - In the plain look albedo is one colour for the whole mesh; the cave and terrain looks make it
//     per fragment (see "Looks").
//   - Vertex normals are the area-weighted average of the adjacent face normals (the sum of the
//     faces' cross products, normalised; zero when that sum is zero), computed once here and given to
//     both twins as a vertex attribute, so the twins differ only in rasterization and shading
//     arithmetic.
//   - The background is 0; the output is what GL writes to an RGBA8 target: round(255·c) per
//     channel, alpha dropped; rows top first (as in a PNG), i.e. GL row height - 1 - y.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.hpp"
#include "reference/render/cave_look.hpp"

namespace gt::reference {

using Matrix4 = std::array<double, 16>;  // row-major

struct Camera {
  Vec3 eye{}, target{}, up{0.0, 1.0, 0.0};
  double fov_y_deg = 45.0;  // vertical field of view, degrees
  double near = 0.1, far = 100.0;  // distances along the view direction, the mesh's unit
  int width = 256, height = 256;   // pixels
};

Matrix4 view_matrix(const Camera& camera);
Matrix4 projection_matrix(const Camera& camera);
Matrix4 multiply(const Matrix4& a, const Matrix4& b);
std::array<double, 4> transform_point(const Matrix4& m, const Vec3& p);  // m·(p, 1)

Camera orbit_camera(const Mesh& mesh, double azimuth_deg, double elevation_deg, double fov_y_deg, int width,
                    int height);

std::vector<Vec3> vertex_normals(const Mesh& mesh);

enum class Look { plain, cave, terrain };

std::vector<Vec3> terrain_height_ramp();

// The colour drape of the terrain look ("Colour drape" above).
struct TerrainDrape {
  int width = 0, height = 0;          // texels, each in [1, 16384]
  std::vector<std::uint8_t> rgb;      // 3 per texel, row-major, row 0 at v = 0 (north)
  double x_west = 0.0, x_east = 1.0;  // world x of u = 0 and u = 1
  double z_north = 0.0, z_south = 1.0;  // world z of v = 0 and v = 1
};

// The bilinear drape colour at (u, v) (each clamped to [0, 1]), channels in [0, 1].
Vec3 drape_colour(const TerrainDrape& drape, double u, double v);

struct TerrainLook {
  std::vector<Vec3> ramp = terrain_height_ramp();  // colour over normalised height (unused with a drape)
  Vec3 up{0.0, 1.0, 0.0};                          // unit vector: the height axis
  double height_low = 0.0, height_high = 1.0;      // p·up mapped to h = 0 and h = 1
  Vec3 rock{0.42, 0.40, 0.38};
  double rock_start_deg = 30.0, rock_full_deg = 45.0;  // slope angles of the rock blend
  std::optional<TerrainDrape> drape;                  // replaces the ramp when set
};

// height_low/high = the smallest and largest p·up over the mesh's vertices (InputError when they
// are equal or up is not a unit vector within 1e-9).
TerrainLook terrain_look(const Mesh& mesh, const Vec3& up = {0.0, 1.0, 0.0});

// Everything both twins draw, computed once on the CPU.
struct PhongScene {
  Mesh mesh;
  std::vector<Vec3> normals;  // per vertex (vertex_normals)
  Camera camera;
  Matrix4 view_projection{};  // P·V
  Vec3 albedo{0.8, 0.72, 0.6};
  double light_power = 1.0;  // |eye - box centre|²
  Look look = Look::plain;   // which albedo and normal the fragments get (see "Looks")
  CaveLook cave{};           // used when look == cave
  TerrainLook terrain{};     // used when look == terrain
};

PhongScene phong_scene(const Mesh& mesh, const Camera& camera);
// The same scene with `look` selected; for terrain, terrain = terrain_look(mesh) (+y up).
PhongScene phong_scene(const Mesh& mesh, const Camera& camera, Look look);

// The shading formula above for one fragment, unclamped channels clamped to [0, 1].
Vec3 phong_colour(const Vec3& position, const Vec3& normal, const Vec3& eye, const Vec3& albedo, double light_power);

// The Phong terms for a unit shading normal that is used as it is (no normalising, no flip).
Vec3 phong_lit(const Vec3& position, const Vec3& unit_normal, const Vec3& eye, const Vec3& albedo, double light_power);

// The terrain albedo at p for the unit viewer-facing normal n (see "Terrain look").
Vec3 terrain_albedo(const TerrainLook& look, const Vec3& p, const Vec3& facing_normal);

// One fragment of `scene` with its look: p and the interpolated (unnormalised) vertex normal.
Vec3 shade_fragment(const PhongScene& scene, const Vec3& position, const Vec3& normal);

std::uint8_t quantise_unorm8(double channel);  // round(255·c), c in [0, 1]

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 per pixel, row-major, row 0 at the top
  std::size_t covered_pixels = 0;  // pixels some fragment was written to (depth < 1)
};

Rgb8Image render_phong(const PhongScene& scene, int subpixel_bits = 8);

// A target's first three channels as 8-bit levels, rows top first (GL's row 0 is the bottom).
struct RasterTarget;
Rgb8Image quantised_top_first(const RasterTarget& target);

}  // namespace gt::reference
