// The looks of the Phong twin other than plain (reference/render/phong.hpp "Looks"), GLSL twin of
// reference/render/cave_look.cpp (cave: colour strip by solid noise with the fixed height-dependent
// frequency, moss, bump by the analytic noise gradient) and of the terrain look in
// reference/render/phong.cpp (height ramp, rock by slope). Formulas and decisions are documented in
// reference/render/cave_look.hpp and phong.hpp; the operation order follows the reference.
// Included by render/phong.frag when GT_PHONG_LOOK is 1 (cave) or 2 (terrain).
//
// Inputs:  (host: gpu/render/phong.cpp)
//   PhongLookBlock  std140, uniform binding 0, mirrored there, checked at link (GlProgram::check_block)
//   strip           storage buffer binding 6: the cave's colour strip or the terrain's height ramp,
//                   one vec4 (rgb, 1) per entry, look.strip_size entries
//   cave only: the permutation buffer (binding 5, noise/permutation.glsl) of the improved Perlin
//   bump and the texture of Gustavson's 2004 Perlin noise (unit 0, noise/perlin_texture.glsl).
//   terrain with GT_TERRAIN_DRAPE defined: the drape, storage buffer binding 7, one uint per texel
//   (RGBA8 as unpackUnorm4x8 reads it), row-major, row 0 at v = 0 (north); its colour replaces the
//   height ramp's (reference/render/phong.hpp "Colour drape").
// Outputs: the look's albedo and shading normal for phong.frag.
// Twin:    reference/render/cave_look.cpp (cave) and reference/render/phong.cpp (terrain).
#ifndef GT_RENDER_PHONG_LOOK_GLSL
#define GT_RENDER_PHONG_LOOK_GLSL

#if GT_PHONG_LOOK == 1
#include "noise/perlin_texture.glsl"
#endif

layout(std140, binding = 0) uniform PhongLookBlock {
  float colour_frequency;         // f0, noise cells per world unit at the reference height
  float colour_reference_height;  // y0
  float colour_octaves_per_unit;  // rate
  float bump_slope;               // a·s
  float bump_frequency;           // s
  float moss;
  float height_low;
  float inverse_height_range;     // 1/(height_high - height_low)
  vec3 up;
  float rock_start_cos;
  vec3 rock;
  float inverse_rock_width;       // 1/(cos(rock_start) - cos(rock_full))
  int strip_size;
  float colour_octave_limit;      // |L| <= limit
  int drape_width;                // texels
  int drape_height;
  float drape_x_west;             // world x of u = 0
  float drape_inverse_width;      // 1/(x_east - x_west)
  float drape_z_north;            // world z of v = 0
  float drape_inverse_depth;      // 1/(z_south - z_north)
} look;

layout(std430, binding = 6) readonly buffer PhongLookStrip { vec4 strip[]; };

// GL_LINEAR with GL_CLAMP_TO_EDGE on the strip, in shader arithmetic: x = N·s - 0.5,
// c = c[i0] + f·(c[i1] - c[i0]), i0 = clamp(floor(x)), i1 = clamp(floor(x) + 1), f = x - floor(x).
vec3 gt_strip_colour(float s) {
  precise float x = float(look.strip_size) * clamp(s, 0.0, 1.0) - 0.5;
  precise float lower = floor(x);
  precise float f = x - lower;
  int last = look.strip_size - 1;
  int i = int(lower);
  vec3 a = strip[clamp(i, 0, last)].rgb;
  vec3 b = strip[clamp(i + 1, 0, last)].rgb;
  precise vec3 blended = a + f * (b - a);
  return blended;
}

#if GT_PHONG_LOOK == 1

float gt_cave_texture_noise(vec3 p, float frequency) {
  precise vec3 q = p * frequency;
  return gt_perlin3_texture(q);
}

// shade = 0.5 + 0.5·N: the cross-fade of the octaves f0·2^k and f0·2^(k+1) around
// f(y) = f0·2^L, L = clamp((y0 - y)·rate, -limit, limit) (the fixed seed formula,
// reference/render/cave_look.hpp 2.).
float gt_cave_shade(vec3 p) {
  precise float octaves = clamp((look.colour_reference_height - p.y) * look.colour_octaves_per_unit,
                                -look.colour_octave_limit, look.colour_octave_limit);
  precise float lower = floor(octaves);
  precise float t = octaves - lower;
  int k = int(lower);
  float coarse = gt_cave_texture_noise(p, ldexp(look.colour_frequency, k));
  float fine = gt_cave_texture_noise(p, ldexp(look.colour_frequency, k + 1));
  precise float noise = ((1.0 - t) * coarse + t * fine) / sqrt((1.0 - t) * (1.0 - t) + t * t);
  precise float shade = 0.5 + 0.5 * noise;
  return shade;
}

// Strip colour plus moss on the unbumped, viewer-facing world normal n (green += moss·n.y, n.y > 0).
vec3 gt_cave_albedo(vec3 p, vec3 n) {
  vec3 albedo = gt_strip_colour(gt_cave_shade(p));
#ifdef GT_MUTANT_RENDER_PHONG_CAVE_MOSS_THRESHOLD_GPU
  if (n.y > 0.5) {  // mutant (this shader only): moss only on normals steeper than 60° from up
#else
  if (n.y > 0.0) {
#endif
    precise float green = albedo.g + look.moss * n.y;
    albedo.g = green;
  }
  return albedo;
}

// n' = normalize(n - (g - (g·n)·n)), g = (a·s)·∇P(s·p) with P improved Perlin noise.
vec3 gt_cave_bumped_normal(vec3 p, vec3 n) {
  if (look.bump_slope == 0.0) return n;
  precise vec3 q = p * look.bump_frequency;
  vec4 noise = gt_perlin3_gradient(q);
  precise vec3 g = look.bump_slope * noise.yzw;
  precise float along = (g.x * n.x + g.y * n.y) + g.z * n.z;
  precise vec3 m = n - (g - along * n);
  return normalize(m);
}

#endif  // GT_PHONG_LOOK == 1

#if GT_PHONG_LOOK == 2

float gt_terrain_height(vec3 p) {
  precise float height = (p.x * look.up.x + p.y * look.up.y) + p.z * look.up.z;
  return height;
}

#ifdef GT_TERRAIN_DRAPE

layout(std430, binding = 7) readonly buffer PhongTerrainDrape { uint drape_texels[]; };

vec3 gt_drape_texel(int column, int row) {
  return unpackUnorm4x8(drape_texels[row * look.drape_width + column]).rgb;
}

// Bilinear in arithmetic over the texels around p's plan position (u east, v south, texel centres
// at (i + 0.5)/W), clamped to the edge: the rows' blends along u, then the blend between the rows.
vec3 gt_drape_colour(vec3 p) {
  precise float u = clamp((p.x - look.drape_x_west) * look.drape_inverse_width, 0.0, 1.0);
  precise float v = clamp((p.z - look.drape_z_north) * look.drape_inverse_depth, 0.0, 1.0);
  precise float x = float(look.drape_width) * u - 0.5;
  precise float y = float(look.drape_height) * v - 0.5;
  precise float left = floor(x);
  precise float upper = floor(y);
  precise float fx = x - left;
  precise float fy = y - upper;
  int i0 = clamp(int(left), 0, look.drape_width - 1), i1 = clamp(int(left) + 1, 0, look.drape_width - 1);
  int j0 = clamp(int(upper), 0, look.drape_height - 1), j1 = clamp(int(upper) + 1, 0, look.drape_height - 1);
  vec3 north_west = gt_drape_texel(i0, j0), north_east = gt_drape_texel(i1, j0);
  vec3 south_west = gt_drape_texel(i0, j1), south_east = gt_drape_texel(i1, j1);
  precise vec3 north = north_west + fx * (north_east - north_west);
  precise vec3 south = south_west + fx * (south_east - south_west);
  precise vec3 blended = north + fy * (south - north);
  return blended;
}

#endif  // GT_TERRAIN_DRAPE

// Ground colour (the drape's at p, or the ramp's at the normalised height), blended towards rock by
// the slope of the facing normal n.
vec3 gt_terrain_albedo(vec3 p, vec3 n) {
#ifdef GT_TERRAIN_DRAPE
  vec3 ground = gt_drape_colour(p);
#else
  precise float h = clamp((gt_terrain_height(p) - look.height_low) * look.inverse_height_range, 0.0, 1.0);
#ifdef GT_MUTANT_RENDER_TERRAIN_RAMP_REVERSED_GPU
  h = 1.0 - h;  // mutant (this shader only): the height ramp read from the top, snow at the foot
#endif
  vec3 ground = gt_strip_colour(h);
#endif
  precise float w = clamp((look.rock_start_cos - gt_terrain_height(n)) * look.inverse_rock_width, 0.0, 1.0);
  precise float smooth_w = w * w * (3.0 - 2.0 * w);
  precise vec3 albedo = ground + smooth_w * (look.rock - ground);
  return albedo;
}

#endif  // GT_PHONG_LOOK == 2

#endif  // GT_RENDER_PHONG_LOOK_GLSL
