// Improved Perlin noise in 3-D (Perlin 2002; digest 002 §4.4.3): the same float operations in the
// same order as the reference (see the formulas and decisions there). Needs the permutation
// storage buffer of noise/permutation.glsl (binding 5, the table twice: 512 entries).
//
// gt_perlin3(p) -> noise value; gt_perlin3_gradient(p) -> (value, d/dx, d/dy, d/dz).
// Also used by noise/perlin_texture.glsl: gt_perlin_fade, gt_perlin_lerp.
// Coordinates in lattice units, |p| < 2^31; period 256.
// Inputs:  p in lattice units; the permutation buffer (binding 5, noise/permutation.glsl).
// Outputs: gt_perlin3, gt_perlin3_gradient, gt_perlin_fade, gt_perlin_lerp.
// Twin:    reference/noise/perlin.cpp.
#ifndef GT_NOISE_PERLIN_GLSL
#define GT_NOISE_PERLIN_GLSL

#include "noise/permutation.glsl"

// fade(t) = ((t·t)·t)·(t·(t·6 − 15) + 10). Mutants: GPU_SMOOTHSTEP_FADE (this twin
// alone) has Perlin 1985's 3t² − 2t³; FADE_SQUARE (both twins) t² where t³ belongs.
float gt_perlin_fade(float t) {
#if defined(GT_MUTANT_NOISE_PERLIN3_GPU_SMOOTHSTEP_FADE)
  precise float faded = t * t * (3.0 - 2.0 * t);
#elif defined(GT_MUTANT_NOISE_PERLIN3_FADE_SQUARE)
  precise float faded = t * t * (t * (t * 6.0 - 15.0) + 10.0);
#else
  precise float faded = t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
#endif
  return faded;
}

// fade'(t) = (t·t)·(t·(t·30 − 60) + 30)
float gt_perlin_fade_derivative(float t) {
  precise float slope = t * t * (t * (t * 30.0 - 60.0) + 30.0);
  return slope;
}

// lerp(t, a, b) = a + t·(b − a); the shaders never use mix(), whose operation order is the driver's.
float gt_perlin_lerp(float t, float a, float b) {
  precise float blended = a + t * (b - a);
  return blended;
}

vec4 gt_perlin_lerp(float t, vec4 a, vec4 b) {
  precise vec4 blended = a + t * (b - a);
  return blended;
}

// P[P[P[X + c.x] + Y + c.y] + Z + c.z] with the doubled table; every index stays below 512.
int gt_perlin_corner_hash(ivec3 lattice, ivec3 corner) {
  int hash_x = int(perm[lattice.x + corner.x]);
  int hash_xy = int(perm[hash_x + lattice.y + corner.y]);
  return int(perm[hash_xy + lattice.z + corner.z]);
}

// Grad's selection: the axes of u and v.
int gt_perlin_axis_u(int h) { return h < 8 ? 0 : 1; }
#ifdef GT_MUTANT_NOISE_PERLIN3_GRAD_SELECT
int gt_perlin_axis_v(int h) { return h < 4 ? 1 : ((h == 12 || h == 13) ? 0 : 2); }  // mutant: 13 for 14
#else
int gt_perlin_axis_v(int h) { return h < 4 ? 1 : ((h == 12 || h == 14) ? 0 : 2); }
#endif

float gt_perlin_grad(int h, vec3 offset) {
  float u = offset[gt_perlin_axis_u(h)];
  float v = offset[gt_perlin_axis_v(h)];
  precise float value = ((h & 1) != 0 ? -u : u) + ((h & 2) != 0 ? -v : v);
  return value;
}

// floor(p) & 255 and p − floor(p).
void gt_perlin_locate(vec3 p, out ivec3 lattice, out vec3 local_position) {
  precise vec3 lower = floor(p);
  lattice = ivec3(lower) & 255;
  precise vec3 local_offset = p - lower;
  local_position = local_offset;
}

float gt_perlin_corner_value(ivec3 lattice, vec3 local_position, ivec3 corner) {
  precise vec3 offset = local_position - vec3(corner);
  return gt_perlin_grad(gt_perlin_corner_hash(lattice, corner) & 15, offset);
}

float gt_perlin3(vec3 p) {
  ivec3 lattice;
  vec3 local_position;
  gt_perlin_locate(p, lattice, local_position);
  float u = gt_perlin_fade(local_position.x);
  float v = gt_perlin_fade(local_position.y);
  float w = gt_perlin_fade(local_position.z);
  float x00 = gt_perlin_lerp(u, gt_perlin_corner_value(lattice, local_position, ivec3(0, 0, 0)),
                             gt_perlin_corner_value(lattice, local_position, ivec3(1, 0, 0)));
  float x10 = gt_perlin_lerp(u, gt_perlin_corner_value(lattice, local_position, ivec3(0, 1, 0)),
                             gt_perlin_corner_value(lattice, local_position, ivec3(1, 1, 0)));
  float x01 = gt_perlin_lerp(u, gt_perlin_corner_value(lattice, local_position, ivec3(0, 0, 1)),
                             gt_perlin_corner_value(lattice, local_position, ivec3(1, 0, 1)));
  float x11 = gt_perlin_lerp(u, gt_perlin_corner_value(lattice, local_position, ivec3(0, 1, 1)),
                             gt_perlin_corner_value(lattice, local_position, ivec3(1, 1, 1)));
  return gt_perlin_lerp(w, gt_perlin_lerp(v, x00, x10), gt_perlin_lerp(v, x01, x11));
}

// (value, d/dx, d/dy, d/dz) of one corner term: Grad's axes carry ±1.
vec4 gt_perlin_corner_sample(ivec3 lattice, vec3 local_position, ivec3 corner) {
  int h = gt_perlin_corner_hash(lattice, corner) & 15;
  precise vec3 offset = local_position - vec3(corner);
  vec4 sample_value = vec4(gt_perlin_grad(h, offset), 0.0, 0.0, 0.0);
  sample_value[1 + gt_perlin_axis_u(h)] = (h & 1) != 0 ? -1.0 : 1.0;
  sample_value[1 + gt_perlin_axis_v(h)] = (h & 2) != 0 ? -1.0 : 1.0;
  return sample_value;
}

// lerp of value and gradient along `axis` with weight fade(t), plus fade'(t)·(b − a) in that axis.
vec4 gt_perlin_lerp_along(int axis, float t, vec4 a, vec4 b) {
  precise vec4 blended = gt_perlin_lerp(gt_perlin_fade(t), a, b);
  precise float chain = gt_perlin_fade_derivative(t) * (b.x - a.x);
  blended[1 + axis] = blended[1 + axis] + chain;
  return blended;
}

vec4 gt_perlin_along_x(ivec3 lattice, vec3 local_position, int cy, int cz) {
  return gt_perlin_lerp_along(0, local_position.x, gt_perlin_corner_sample(lattice, local_position, ivec3(0, cy, cz)),
                              gt_perlin_corner_sample(lattice, local_position, ivec3(1, cy, cz)));
}

vec4 gt_perlin3_gradient(vec3 p) {
  ivec3 lattice;
  vec3 local_position;
  gt_perlin_locate(p, lattice, local_position);
  vec4 z0 = gt_perlin_lerp_along(1, local_position.y, gt_perlin_along_x(lattice, local_position, 0, 0),
                                 gt_perlin_along_x(lattice, local_position, 1, 0));
  vec4 z1 = gt_perlin_lerp_along(1, local_position.y, gt_perlin_along_x(lattice, local_position, 0, 1),
                                 gt_perlin_along_x(lattice, local_position, 1, 1));
  return gt_perlin_lerp_along(2, local_position.z, z0, z1);
}

#endif  // GT_NOISE_PERLIN_GLSL
