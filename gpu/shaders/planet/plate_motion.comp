#version 450
// Steps 4–6 per plate (eq. 5.2, §9.3 steps 4–6; core/params/planet.hpp), twin of
// reference::plate_motion<float>:
//   centre c = normalise(sum), sum from planet/fixed_point.glsl (0 for a zero sum);
//   m = 0.5 + 0.5·U(k, 0, shift), α = 2·U(k, 1, shift) − 1, β = 2·U(k, 2, shift) − 1;
//   t_x = c × (1, 0, 0) = (0, c_z, −c_y), t_y = c × (0, 1, 0) = (−c_z, 0, c_x) (exact);
//   t = α·t_x + β·t_y componentwise (α's product first);
//   s = t·(m/sqrt(dot3(t, t))), 0 when dot3(t, t) = 0;
//   b = e_r·(2·U(k, 0, elevation) − 1), or with PLANET_BIMODAL_BASES: oceanic when
//   U(k, 1, elevation) < ocean_share, b = −(e_r·(0.5 + 0.5·U(k, 0, elevation))), else
//   b = (0.25·e_r)·U(k, 0, elevation) (0.25·e_r is exact).
// One invocation per plate.
// Inputs:  PlanetBlock (uniform binding 0), centre_sums (9) (planet.glsl, planet/fixed_point.glsl).
// Outputs: plates[k].centre, .shift, .base (7).
// Twin:    reference/planet/elevation.cpp (plate_motion).
layout(local_size_x = 64) in;

#include "planet/planet.glsl"
#include "planet/fixed_point.glsl"

vec3 centre_of(uint k) {
  uint slot = 6u * k;
  return normalise(vec3(fixed_point_sum(slot), fixed_point_sum(slot + 2u), fixed_point_sum(slot + 4u)));
}

vec3 shift_of(uint k, vec3 centre) {
  precise float magnitude = 0.5 + 0.5 * planet_draw(k, 0u, PLANET_STREAM_SHIFT);
  precise float alpha = 2.0 * planet_draw(k, 1u, PLANET_STREAM_SHIFT) - 1.0;
  precise float beta = 2.0 * planet_draw(k, 2u, PLANET_STREAM_SHIFT) - 1.0;
  vec3 tangent_x = vec3(0.0, centre.z, -centre.y);
  vec3 tangent_y = vec3(-centre.z, 0.0, centre.x);
  precise vec3 tangent = alpha * tangent_x + beta * tangent_y;
  precise float squared = dot3(tangent, tangent);
  if (squared == 0.0) return vec3(0.0);
  precise float scale = magnitude / sqrt(squared);
  precise vec3 shift = tangent * scale;
  return shift;
}

float base_of(uint k) {
  float level = planet_draw(k, 0u, PLANET_STREAM_ELEVATION);
#ifdef PLANET_BIMODAL_BASES
  bool oceanic = planet_draw(k, 1u, PLANET_STREAM_ELEVATION) < ocean_share;
  precise float base = oceanic ? -(elevation_range * (0.5 + 0.5 * level)) : (0.25 * elevation_range) * level;
#else
  precise float base = elevation_range * (2.0 * level - 1.0);
#endif
  return base;
}

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= uint(plate_count)) return;
  vec3 centre = centre_of(k);
  plates[k].centre = vec4(centre, 0.0);
  plates[k].shift = vec4(shift_of(k, centre), 0.0);
  plates[k].base = base_of(k);
}
