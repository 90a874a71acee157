// Seed 004's cave look (digest 004_cave.md §2.9) for the Phong twin (phong.hpp, look = cave), CPU reference in double.
//
// The colour strip indexed by solid noise with a height-dependent frequency, the moss tint on upward
// normals and bump mapping by the analytic noise gradient; plus the scene of a camera inside a block
// of the seed's cave (cave_scene).
// sampled_strip(stops), seed_colour_strip(), strip_colour(strip, s) -> the colour strip and its lookup (1.)
// cave_shade(look, p) -> shade(p) = 0.5 + 0.5·N(p), the strip coordinate (2.)
// cave_albedo(look, p, n) -> the strip colour at shade(p) plus the moss on an upward unit normal (1.–3.)
// cave_bump_height(look, p), cave_bump_gradient(look, p) -> b(p) and ∇b(p) of the bump height field (4.)
// cave_bumped_normal(look, p, n) -> n' of 4. for a unit normal
// cave_scene(block, camera, look, light_power) -> PhongScene of a camera inside a block (below the struct)
//
// Per fragment, with p the interpolated world position (world units, +y up) and n the unit normal
// facing the viewer (phong.hpp: normalised, flipped when it points away, v when it is zero):
//
// 1. Colour strip (the seed's 256×1 tex1.png, hand-painted and not published). Decision: the
//    strip is data, not code: CaveLook::colour_strip holds 256 RGB entries in [0, 1] that both
//    twins receive as they are. seed_colour_strip() is this project's stand-in for tex1.png, a
//    limestone cave palette: piecewise-linear between the stops below, sampled at the entry
//    centres (i + 0.5)/256 and rounded to 8 bits (k/255, as a PNG stores them):
//       0.00 (0.20, 0.16, 0.13) dark brown      0.53 (0.78, 0.75, 0.68) pale limestone
//       0.25 (0.42, 0.33, 0.25) umber           0.58 (0.56, 0.40, 0.30) red clay band
//       0.35 (0.62, 0.50, 0.36) ochre           0.64 (0.70, 0.60, 0.46) sandstone
//       0.42 (0.74, 0.66, 0.54) buff            0.72 (0.50, 0.48, 0.46) grey
//       0.48 (0.60, 0.58, 0.55) grey limestone  1.00 (0.85, 0.82, 0.76) flowstone white
//    The noise spends most of its time in shade 0.3–0.7, so the bands sit there.
//    Lookup strip_colour(strip, s), s clamped to [0, 1]: x = 256·s − 0.5, i = floor(x),
//    f = x − i, c = c[i0] + f·(c[i1] − c[i0]) with i0 = clamp(i, 0, 255), i1 = clamp(i + 1, 0, 255):
//    GL_LINEAR with GL_CLAMP_TO_EDGE on a 1-D texture (the seed's texture(tex1dSampler, shade)),
//    written out in shader arithmetic because GL leaves the filter's weight precision to the
//    implementation (8 fractional bits on llvmpipe and most GPUs), which no reference can match.
//
// 2. Solid texture value (Listing 3.4): shade = 0.5 + 0.5·N(p), N the seed's noise, Gustavson's
//    2004 texture-based Perlin noise (reference/noise/perlin_texture.hpp) at p times a frequency.
//    The seed's frequency is scaleFactor = 2 + y/100. FIX (digest §2.9 flags the first two):
//      (a) the stated intent is finer texture ("smaller stones") lower down, the formula makes it
//          finer higher up;
//      (b) it reaches 0 at y = −200 (one flat colour) and is negative below (mirrored pattern);
//      (c) it scales the whole position, so the pattern's local frequency along y is
//          f(y) + p·f'(y): it grows with the distance from the origin (at |x| = 200 the shear term
//          equals the base frequency), and an endless cave turns into stripes far away.
//    Here the frequency halves every 1/rate world units upwards and never reaches 0:
//      f(y) = f0·2^L, L = clamp((y0 − y)·rate, −limit, limit)
//    (f0 = colour_frequency = 2 at y0 = 0, the seed's value; rate = 1/(200·ln 2) ≈ 0.0072135 per
//    world unit, so that |f'(y0)| = 1/100 as the seed's; limit = colour_octave_limit = 4 octaves:
//    y is unbounded in an endless cave, digest §2.9 asks for a clamp, and beyond 16·f0 the texture
//    only aliases, below f0/16 a whole tunnel is one colour; the limits are reached 555 units
//    above and below y0)
//    and, against (c), the position is only ever multiplied by fixed octave frequencies: with
//    k = floor(L), t = L − k, N_j = N(p·f0·2^j) (f0·2^j by ldexp, exact),
//      N(p) = ((1 − t)·N_k + t·N_{k+1}) / sqrt((1 − t)² + t²)
//    a cross-fade between the two octaves around f(y), continuous in y (at t = 1 it equals the next
//    octave's t = 0), with the divisor keeping the spread of two uncorrelated octaves. rate = 0
//    gives the single octave N(p·f0) exactly (t = 0: (1·N_0 + 0·N_1)/1).
//
// 3. Moss (applied before the bump, as the seed): if n_y > 0, green += moss·n_y (seed: moss =
//    1/40). Decision: n is the world-space, viewer-facing, unbumped normal (the seed's camera-space
//    normal would make moss follow the camera's pitch; digest §2.9). Red and blue are untouched.
//
// 4. Bump (the seed's formula is not given; digest §2.9 proposes Blinn's): a height field
//    b(p) = a·P(s·p), P improved Perlin noise (reference/noise/perlin.hpp) with its analytic
//    gradient, a = bump_amplitude (world units), s = bump_frequency (per world unit; the seed:
//    "several times finer than the colour texture", default 4 = 2× the colour's f0). Then
//      g = ∇b = (a·s)·∇P(s·p),  n' = normalize(n − (g − (g·n)·n))
//    (the surface gradient of b subtracted from n: Blinn 1978 for a displacement along n). The
//    bump is skipped when a·s = 0 (n' = n exactly, so a zero amplitude is exactly unbumped Phong).
//
// 5. Phong (phong.hpp) with albedo = the strip colour plus moss and the normal n'.
//
// Both noises use seeded_permutation(noise_seed) (0: Perlin's table, the seed's). Valid while
// f0·2^(limit + 1)·|p| < 2^23 (the texture noise's range, perlin_texture.hpp): |p| < 262,144 world
// units at the defaults, beyond the cave's own lattice limit of 2^19 only by a factor of two.
//
// Inputs:  p world positions; n unit normals facing the viewer; CaveLook (the strip, 256 RGB entries
//          in [0, 1]; f0, y0, rate, limit; bump a and s; moss; noise_seed); strip stops at positions
//          in [0, 1], increasing, the first at 0 and the last at 1; cave_scene: the block's CaveParams,
//          a Camera (phong.hpp) and the light power.
// Outputs: colours (channels in [0, 1] for the strip), shades, heights, gradients, normals, a PhongScene.
// Units:   world units (+y up); frequencies in noise cells per world unit; rate in octaves per world
//          unit; colours dimensionless.
// Throws:  InputError: sampled_strip for fewer than two stops, a first stop not at 0 or a last not at 1,
//          or positions that do not increase; strip_colour for an empty strip; cave_scene as stated at
//          it, and for a light power that is not positive and finite, a block too large to check
//          (core/params/cave.hpp) and what marching_tetrahedra and phong_scene refuse.
// Twin:    gpu/shaders/render/phong_look.glsl (host: gpu/render/phong.hpp), with
//          gpu/shaders/noise/perlin_texture.glsl.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/params/cave.hpp"

namespace gt::reference {

using Vec3 = std::array<double, 3>;

inline constexpr int colour_strip_size = 256;

// A strip of colour_strip_size entries, piecewise-linear between `stops` (positions in [0, 1],
// increasing, the first at 0 and the last at 1) sampled at the entry centres (i + 0.5)/256, each
// channel rounded to k/255 (what an 8-bit strip image holds).
struct StripStop {
  double position;
  Vec3 colour;
};
std::vector<Vec3> sampled_strip(const std::vector<StripStop>& stops);

// The project's stand-in for the seed's tex1.png (see 1. above): 256 entries, each channel k/255.
std::vector<Vec3> seed_colour_strip();

// GL_LINEAR/CLAMP_TO_EDGE lookup of a strip (any size >= 1) at s (see 1. above).
Vec3 strip_colour(const std::vector<Vec3>& strip, double s);

struct CaveLook {
  std::vector<Vec3> colour_strip = seed_colour_strip();
  double colour_frequency = 2.0;            // f0, noise cells per world unit at colour_reference_height
  double colour_reference_height = 0.0;     // y0, world units
  double colour_octaves_per_unit = 0.0072134752044448170;  // rate = 1/(200 ln 2): octaves finer per unit down
  double colour_octave_limit = 4.0;         // |L| <= limit: f between f0/16 and 16·f0
  double bump_amplitude = 0.04;             // a, world units
  double bump_frequency = 4.0;              // s, noise cells per world unit
  double moss = 1.0 / 40.0;                 // green added per unit of n_y (seed: n.y/40)
  std::uint32_t noise_seed = 0;             // permutation of both noises
};

// shade(p) = 0.5 + 0.5·N(p), the strip coordinate (see 2. above).
double cave_shade(const CaveLook& look, const Vec3& p);

// The strip colour at shade(p) plus the moss on an upward `facing_normal` (unit) (1.–3. above).
Vec3 cave_albedo(const CaveLook& look, const Vec3& p, const Vec3& facing_normal);

// b(p) and ∇b(p) of the bump height field (4. above), world units.
double cave_bump_height(const CaveLook& look, const Vec3& p);
Vec3 cave_bump_gradient(const CaveLook& look, const Vec3& p);

// n' of 4. above for a unit `facing_normal`.
Vec3 cave_bumped_normal(const CaveLook& look, const Vec3& p, const Vec3& facing_normal);

// A camera inside a block of the seed's cave (render.phong's generated cave, compare/algorithms/render_phong.cpp).
//
// cave_scene(block, camera, look, light_power, normals) meshes `block` (CaveParams: the seed's density,
// marching_tetrahedra<double> in reference/cave, welded, wound into the air) and gives its vertices
// normals of the noise (reference/cave/normals.hpp, in double): `analytic`, the simplex gradient
// (gradient_normals: exact, the default), or `central_difference`, the seed's own Listing 3.3 with
// ND = 1 (central_difference_normals: what the seed's shader draws, §2.8), then a
// PhongScene with look = cave, `look`, the given light power (the seed's LIGHTPOWER; opengl-tutorial's
// default is 50) and `camera`. Throws InputError when the eye lies outside the block, or in rock
// (density below the threshold: such a camera sees the inside of the rock) or when the block has
// no surface.
struct PhongScene;
struct Camera;
enum class CaveNormals { analytic, central_difference };
PhongScene cave_scene(const CaveParams& block, const Camera& camera, const CaveLook& look, double light_power,
                      CaveNormals normals = CaveNormals::analytic);

}  // namespace gt::reference
