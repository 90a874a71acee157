// Probe scenes of the render family whose answer is known in closed form, and the spec checks that
// compare each twin's output with that answer (issue 11: checks that a bug shared by both twins
// cannot pass). Everything here is computed from the geometry and the seeds' formulas, written
// again below; nothing calls the twins' camera, shading or rasterizer code.
//
// Phong quad (render.phong, generated = quad; seed 004 §2.9, digest 004_cave.md):
//   A square of side 2 centred at c = (0, 0.3, 0) with unit normal n = normalize(0.15, 0.25, 1),
//   spanned by the unit vectors a = normalize(up × n) (horizontal, up = +y) and b = n × a: corners
//   c ± a ± b, two triangles. Planar, so every vertex normal is ±n and the interpolated position
//   and normal are exact: the colour at a pixel is the formula at the point its centre's ray hits.
//   Expected colour at a pixel whose centre's ray (gluLookAt camera, gluPerspective field of view,
//   pixel centres at (i + 0.5, j + 0.5) of GL's window, image rows top first) hits the quad at p:
//     v = normalize(eye - p), n_f = ±n facing v, c = n_f·v, E = light_power / |eye - p|²
//     colour = clamp(albedo·(0.1 + E·max(0, c)) + 0.3·E·max(0, 2c² - 1)^5, 0, 1)
//   (the digest's closed form of the opengl-tutorial shader with the light at the eye: r·v = 2c² - 1);
//   background 0 elsewhere. Pixels whose centre lies within 1 pixel of the quad's projected outline
//   are left out (coverage there depends on the rasterization rules and on vertex snapping to
//   2^-8 pixel, not on the shading).
//   Error model of a compared channel value (in [0, 1]):
//     reference  double shading (relative error ~1e-15) then round(255·c)/255: at most 0.5/255,
//                bound 0.5/255 + 1e-9
//     GPU        GL converts to 8 bits by taking one of the two nearest levels (GL 4.5 §2.3.5.2:
//                convert_float_uint may round either way), so up to 1/255; the float pipeline
//                (position, matrix and interpolation within a few u = 2^-24 relative, moved by
//                snapping at most 2^-9 pixel, where the colour changes by under 0.02 per pixel
//                in the probe's framing) adds far less than 2^-12: bound 1/255 + 2^-12
//   A changed constant (ambient, exponent, facing rule, falloff) or a flipped image moves the
//   compared pixels by several 8-bit levels; see compare/mutants/render.cpp.
//
// Tent (render.heightmap_from_mesh, generated = tent; seed 000 §4.3, eqs. 4.1–4.4):
//   A closed solid over the right triangle (0, 0), (1, 0), (0, 1): its base at z = 0 (drawn first),
//   vertical walls up to a rim at z = 1/4 and a three-faced roof from the rim to the apex
//   (1/4, 1/4, 1). Its box is [0, 1]³, so the height seen from above is z itself:
//     h(x, y) = 1/4 + 3/4·min(4x, 4y, 2(1 - x - y)) on the footprint x, y >= 0, x + y <= 1,
//   uncovered elsewhere (a convex solid's top is the lowest of its upper faces' planes). The rim
//   keeps the outline above the box's bottom (a surface at z' = 1 has depth 1 and is never drawn),
//   so the footprint's edges are drawn, and the hypotenuse, through 64 texel centres of a 64×64 grid,
//   shows the edge rule. Texel (i, r) of a W×H grid has its centre at x = (i + 0.5)/W,
//   y = 1 - (r + 0.5)/H (row 0 at the largest y).
//   spec.tent_coverage   texels whose coverage differs from the footprint, among those whose centre
//                        lies more than 2^-8 texel from the outline (on the outline the tie rule,
//                        which GL leaves to the implementation, decides): bound 0, exact because
//                        every vertex is exact in float and snapping moves none of them
//   spec.tent_heights    max |h - h(x, y)| over texels whose centre lies at least one texel inside
//                        the footprint, bound B = 16u·(1 + s·(W + H)) of render_heightmap.hpp with
//                        s = max(3/W, 3/H, 1.5/W + 1.5/H) the steepest face's slope per texel and u
//                        the backend's unit roundoff (2^-53 for the reference, 2^-24 for the GPU)
//   All coordinates are dyadic, so both twins' window coordinates are exact: the tent is also the
//   case of parity.coverage_exact (render_heightmap.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/grid.hpp"
#include "core/mesh.hpp"
#include "core/vec3.hpp"

namespace gt {

// ---- Phong quad ----

struct PhongQuadProbe {
  Vec3 centre{0.0, 0.3, 0.0};
  Vec3 normal{};      // unit
  Vec3 side_a{}, side_b{};  // unit, spanning the plane; half the side is 1 along each
};

PhongQuadProbe phong_quad_probe();
Mesh phong_quad_mesh(const PhongQuadProbe& quad);

// The camera as the spec reads it: gluLookAt (eye, target, up) and gluPerspective.
struct ProbeCamera {
  Vec3 eye{}, target{}, up{0.0, 1.0, 0.0};
  double fov_y_deg = 40.0;
  int width = 64, height = 64;
};

// The seed's Phong with the light at the eye in the digest's closed form (see above).
Vec3 seed_phong_closed_form(const Vec3& position, const Vec3& normal, const Vec3& eye, const Vec3& albedo,
                            double light_power);

struct ProbeImageComparison {
  std::size_t compared_pixels = 0, quad_pixels = 0;  // quad_pixels: of the compared, those on the quad
  double max_abs = 0.0;                              // largest |image - expected| over channel values
  int max_x = 0, max_y = 0;                          // where (column, row from the top)
};

// rgb: 3 bytes per pixel, rows top first, camera.width × camera.height pixels.
ProbeImageComparison compare_with_phong_quad(const PhongQuadProbe& quad, const ProbeCamera& camera, const Vec3& albedo,
                                             double light_power, const std::vector<std::uint8_t>& rgb);

constexpr double phong_probe_bound_cpu = 0.5 / 255.0 + 1e-9;
constexpr double phong_probe_bound_gpu = 1.0 / 255.0 + 0x1p-12;

// ---- Tent ----

Mesh tent_mesh();
double tent_height(double x, double y);  // h(x, y) on the footprint

struct TentComparison {
  std::size_t coverage_compared = 0, coverage_mismatches = 0;
  std::size_t height_compared = 0;
  double height_max_abs = 0.0;
  double height_bound = 0.0;  // B for the unit roundoff given
};

// heights, covered: a W×H heightmap of the tent (row 0 at the largest y); unit_roundoff of the backend.
TentComparison compare_with_tent(const Grid<double>& heights, const Grid<std::uint8_t>& covered, double unit_roundoff);

}  // namespace gt
