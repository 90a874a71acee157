// Gustavson's 2004 texture-based Perlin noise, the noise of seed 004's fragment shader (digest 004
// §2.1): the 2004 code with its mix() and dot() written out in the reference's operation order,
// every intermediate precise (hazards: in the reference).
//
// gt_perlin3_texture(p) -> noise value; p in lattice units, |p| < 2^23; period 256.
// Texture: gt_perlin_texture on texture unit 0 (layout binding), the 256x256 GL_RGBA8 table of
// core/noise/perlin_texture_table.hpp with GL_NEAREST min/mag filters and GL_REPEAT wrap, no
// mipmaps (gt::gpu::PerlinTexture). texture() reads level 0 in every stage: the texture has one level.
// Inputs:  p in lattice units; the texture gt_perlin_texture (unit 0).
// Outputs: gt_perlin3_texture(p).
// Twin:    reference/noise/perlin_texture.cpp.
#ifndef GT_NOISE_PERLIN_TEXTURE_GLSL
#define GT_NOISE_PERLIN_TEXTURE_GLSL

#include "noise/perlin.glsl"

layout(binding = 0) uniform sampler2D gt_perlin_texture;

const float GT_PERLIN_TEXEL = 0.00390625;      // ONE = 1/256
const float GT_PERLIN_HALF_TEXEL = 0.001953125;  // ONEHALF = 0.5/256

// Corner values n(c.x, c.y, 0) and n(c.x, c.y, 1), which share the alpha (hash) lookup.
vec2 gt_perlin_texture_corner_pair(vec3 texel_centre, vec3 local_position, ivec2 corner) {
  precise vec2 shift = vec2(corner) * GT_PERLIN_TEXEL;
  precise vec2 hash_coordinate = texel_centre.xy + shift;
  float permuted = texture(gt_perlin_texture, hash_coordinate).a;
  vec2 values;
  for (int cz = 0; cz < 2; ++cz) {
    precise float row = texel_centre.z + float(cz) * GT_PERLIN_TEXEL;
#ifdef GT_MUTANT_NOISE_PERLIN3_TEXTURE_GPU_DECODE
    precise vec3 gradient = texture(gt_perlin_texture, vec2(permuted, row)).rgb * 2.0 - 1.0;  // mutant: unorm's usual decode
#else
    precise vec3 gradient = texture(gt_perlin_texture, vec2(permuted, row)).rgb * 4.0 - 1.0;
#endif
    precise vec3 offset = local_position - vec3(vec2(corner), float(cz));
    precise float value = gradient.x * offset.x + gradient.y * offset.y + gradient.z * offset.z;
    values[cz] = value;
  }
  return values;
}

float gt_perlin3_texture(vec3 p) {
  precise vec3 lower = floor(p);
  precise vec3 texel_centre = GT_PERLIN_TEXEL * lower + GT_PERLIN_HALF_TEXEL;
  precise vec3 local_position = p - lower;
  float u = gt_perlin_fade(local_position.x);
  float v = gt_perlin_fade(local_position.y);
  float w = gt_perlin_fade(local_position.z);
  vec2 x0y0 = gt_perlin_texture_corner_pair(texel_centre, local_position, ivec2(0, 0));
  vec2 x1y0 = gt_perlin_texture_corner_pair(texel_centre, local_position, ivec2(1, 0));
  vec2 x0y1 = gt_perlin_texture_corner_pair(texel_centre, local_position, ivec2(0, 1));
  vec2 x1y1 = gt_perlin_texture_corner_pair(texel_centre, local_position, ivec2(1, 1));
  float z0 = gt_perlin_lerp(v, gt_perlin_lerp(u, x0y0.x, x1y0.x), gt_perlin_lerp(u, x0y1.x, x1y1.x));
  float z1 = gt_perlin_lerp(v, gt_perlin_lerp(u, x0y0.y, x1y0.y), gt_perlin_lerp(u, x0y1.y, x1y1.y));
  return gt_perlin_lerp(w, z0, z1);
}

#endif  // GT_NOISE_PERLIN_TEXTURE_GLSL
