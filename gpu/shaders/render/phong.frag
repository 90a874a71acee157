#version 450 core
// Seed 004's Phong look (digest 004_cave.md §2.9: the opengl-tutorial shader with K_a = 0.1,
// specular 0.3, exponent 5, one point light at the eye), fragment stage; the formula and its
// decisions are documented in reference/render/phong.hpp:
//   v = l = normalize(eye - p), E = light_power / |eye - p|²
//   n = normalize(normal), facing the viewer (two-sided); v when the normal is exactly zero
//   colour = clamp(albedo·(0.1 + E·max(0, n·l)) + 0.3·E·max(0, r·v)^5, 0, 1), r = reflect(-l, n)
// Written to an RGBA8 target (alpha 1), which rounds to 8 bits.
//
// Looks (reference/render/phong.hpp "Looks"): GT_PHONG_LOOK, defined by the host
// (gpu/render/phong.cpp), picks how albedo and n are made before the Phong terms:
//   0 plain    the uniform albedo and n (the #if blocks vanish)
//   1 cave     albedo from the colour strip and moss, n bumped (render/phong_look.glsl)
//   2 terrain  albedo from the height ramp (or, with GT_TERRAIN_DRAPE, the colour drape) and the
//              slope (render/phong_look.glsl)
// Inputs:  world_position, vertex_normal from the vertex stage; eye, albedo, light_power (uniform
//          locations 1-3); for the cave and terrain looks, phong_look.glsl's inputs.
// Outputs: colour (location 0).
// Twin:    reference/render/phong.cpp (and cave_look.cpp for the cave look).

#ifndef GT_PHONG_LOOK
#define GT_PHONG_LOOK 0
#endif

// The seed's K_a = 0.1 and exponent 5, or the mutants' (compare/mutants/render.cpp):
// render.phong.no_ambient (both twins) drops the ambient term; render.phong.specular_exponent (both
// twins) and render.phong.specular_exponent_gpu (this shader only) use the exponent 10.
#ifdef GT_MUTANT_RENDER_PHONG_NO_AMBIENT
const float ambient = 0.0;
#else
const float ambient = 0.1;
#endif
#if defined(GT_MUTANT_RENDER_PHONG_SPECULAR_EXPONENT) || defined(GT_MUTANT_RENDER_PHONG_SPECULAR_EXPONENT_GPU)
const float specular_exponent = 10.0;
#else
const float specular_exponent = 5.0;
#endif

#if GT_PHONG_LOOK != 0
#include "render/phong_look.glsl"
#endif

in vec3 world_position;
in vec3 vertex_normal;

layout(location = 1) uniform vec3 eye;
layout(location = 2) uniform vec3 albedo;
layout(location = 3) uniform float light_power;

layout(location = 0) out vec4 colour;

void main() {
  vec3 to_eye = eye - world_position;
#ifdef GT_MUTANT_RENDER_PHONG_NO_FALLOFF_GPU
  float irradiance = light_power;  // mutant (this shader only): the 1/d² falloff dropped
#else
  float irradiance = light_power / dot(to_eye, to_eye);
#endif
  vec3 v = normalize(to_eye);
  vec3 l = v;
  vec3 n = dot(vertex_normal, vertex_normal) > 0.0 ? normalize(vertex_normal) : v;
#ifdef GT_MUTANT_RENDER_PHONG_FACING_REVERSED
  if (!(dot(n, v) < 0.0)) n = -n;  // mutant (both twins): the normal turned away from the viewer
#else
  if (dot(n, v) < 0.0) n = -n;
#endif
#if GT_PHONG_LOOK == 1
  vec3 surface_albedo = gt_cave_albedo(world_position, n);
  n = gt_cave_bumped_normal(world_position, n);
#elif GT_PHONG_LOOK == 2
  vec3 surface_albedo = gt_terrain_albedo(world_position, n);
#else
  vec3 surface_albedo = albedo;
#endif
  float diffuse = max(0.0, dot(n, l));
  float specular = pow(max(0.0, dot(reflect(-l, n), v)), specular_exponent);
  colour = vec4(clamp(surface_albedo * (ambient + irradiance * diffuse) + 0.3 * irradiance * specular, 0.0, 1.0), 1.0);
}
