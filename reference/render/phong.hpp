// Seed 004's Phong look (digest 004_cave.md §2.9) on a mesh seen through a perspective camera, by
// the reference rasterizer (rasterizer.hpp) in double. Slow by design; the GPU twin is
// gpu/render/phong.hpp, which draws the same PhongScene (same normals, same matrix rounded to float).
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
// (with l = v, r·v = 2(n·v)² - 1: the digest's closed form). Decisions:
//   - light_power = D², the squared distance from the eye to the box centre, so E = 1 there
//     (surfaces nearer the eye get more, up to (2.5/1.5)² with orbit_camera, and clamp).
//   - albedo is one colour for the whole mesh (no procedural texture, bump or moss here).
//   - Vertex normals are the area-weighted average of the adjacent face normals (the sum of the
//     faces' cross products, normalised; zero when that sum is zero), computed once here and given to
//     both twins as a vertex attribute, so the twins differ only in rasterization and shading
//     arithmetic.
//   - The background is 0; the output is what GL writes to an RGBA8 target: round(255·c) per
//     channel, alpha dropped; rows top first (as in a PNG), i.e. GL row height - 1 - y.
// Depth test LESS against a cleared depth of 1, no culling, triangles in index order.
// Throws InputError for a mesh without triangles or without extent, and for an unusable camera
// (eye at the target, up along the view direction, fov_y outside (0, 180) degrees, not
// 0 < near < far, sides outside [1, 16384]).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/mesh.hpp"

namespace gt::reference {

using Vec3 = std::array<double, 3>;
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

// Everything both twins draw, computed once on the CPU.
struct PhongScene {
  Mesh mesh;
  std::vector<Vec3> normals;  // per vertex (vertex_normals)
  Camera camera;
  Matrix4 view_projection{};  // P·V
  Vec3 albedo{0.8, 0.72, 0.6};
  double light_power = 1.0;  // |eye - box centre|²
};

PhongScene phong_scene(const Mesh& mesh, const Camera& camera);

// The shading formula above for one fragment, unclamped channels clamped to [0, 1].
Vec3 phong_colour(const Vec3& position, const Vec3& normal, const Vec3& eye, const Vec3& albedo, double light_power);

std::uint8_t quantise_unorm8(double channel);  // round(255·c), c in [0, 1]

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // 3 per pixel, row-major, row 0 at the top
};

Rgb8Image render_phong(const PhongScene& scene, int subpixel_bits = 8);

}  // namespace gt::reference
