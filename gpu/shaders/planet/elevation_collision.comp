#version 450
// Step 8 per region (eq. 5.3 as coded, errata 12–13, §9.3 step 8; core/params/planet.hpp), twin of
// reference::planet_elevation<float>'s E1 and reference::pressure<float>:
//   edge region: E1(i) = E0(i) + C·total, total = 0 + pressure(i, n) for each valid neighbour n of
//                another plate, in table order;
//   other regions (and all without PLANET_COLLISIONS): E1(i) = E0(i).
// pressure(p, s_A, q, s_B), p = pos(i), q = pos(n), s_A, s_B the plates' shifts:
//   code (default): d = normalise(q − p), t_p = normalise(p + s_A) − p, t_q = normalise(q + s_B) − q,
//     pressure = sqrt(dot3(s_A, s_A))·dot3(t_p, d) + sqrt(dot3(s_B, s_B))·dot3(t_q, −d);
//   thesis (PLANET_PRESSURE_THESIS): v = s_A − dot3(s_A, p)·p, v_q = s_B − dot3(s_B, q)·q,
//     pressure = sqrt(dot3(v, v))·dot3(v, q − p) + sqrt(dot3(v_q, v_q))·dot3(v_q, p − q).
// Both are bit-symmetric: pressure(i, n) = pressure(n, i) (normalise(−x) = −normalise(x), and the
// two terms swap places in a commutative addition).
// Inputs:  PlanetBlock (uniform binding 0), neighbours (0), positions (2), plate (3), is_edge (6),
//          plates (7: shifts), noisy (10: E0) (planet.glsl).
// Outputs: collided (11): E1.
// Twin:    reference/planet/elevation.cpp (planet_elevation's E1, pressure).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

float magnitude(vec3 v) {
  precise float length = sqrt(dot3(v, v));
  return length;
}

#ifdef PLANET_PRESSURE_THESIS
// The plate's motion made tangent at `position`.
vec3 tangential(vec3 shift, vec3 position) {
  precise vec3 tangent = shift - dot3(shift, position) * position;
  return tangent;
}

float pressure(vec3 p, vec3 shift_p, vec3 q, vec3 shift_q) {
  vec3 v_p = tangential(shift_p, p);
  vec3 v_q = tangential(shift_q, q);
  precise vec3 towards_q = q - p;
  precise vec3 towards_p = p - q;
  precise float value = magnitude(v_p) * dot3(v_p, towards_q) + magnitude(v_q) * dot3(v_q, towards_p);
  return value;
}
#else
// The chord a region moves along when its plate shifts it: normalise(p + s) − p.
vec3 chord(vec3 p, vec3 shift) {
  precise vec3 moved = p + shift;
  precise vec3 displacement = normalise(moved) - p;
  return displacement;
}

float pressure(vec3 p, vec3 shift_p, vec3 q, vec3 shift_q) {
  precise vec3 difference = q - p;
  vec3 direction = normalise(difference);
#if defined(GT_MUTANT_PLANET_COLLISION_GPU_NEIGHBOUR_SIGN) || defined(GT_MUTANT_PLANET_COLLISION_NEIGHBOUR_SIGN)
  // mutants GPU_NEIGHBOUR_SIGN (this twin alone) and NEIGHBOUR_SIGN (both twins): the neighbour's
  // chord projected on d instead of −d
  precise float value = magnitude(shift_p) * dot3(chord(p, shift_p), direction) +
                        magnitude(shift_q) * dot3(chord(q, shift_q), direction);
#else
  precise float value = magnitude(shift_p) * dot3(chord(p, shift_p), direction) +
                        magnitude(shift_q) * dot3(chord(q, shift_q), -direction);
#endif
  return value;
}
#endif

// The calibrated pair of the collision's float model in both float twins (reference/planet/
// elevation.cpp's calibration_factor): C·Σ pressure times 1 + 2^-9 above the bound, 1 + 2^-23 below.
#if defined(GT_MUTANT_PLANET_COLLISION_FLOAT_OFF_ABOVE_BOUND)
const float drift = 1.0 + 1.0 / 512.0;
#elif defined(GT_MUTANT_PLANET_COLLISION_FLOAT_OFF_BELOW_BOUND)
const float drift = 1.0 + 1.0 / 8388608.0;
#else
const float drift = 1.0;
#endif

float collided_elevation(int region) {
  int own = plate[region];
  vec3 p = positions[region].xyz;
  vec3 shift_p = plates[own].shift.xyz;
  precise float total = 0.0;
  for (int k = 0; k < neighbour_count; ++k) {
    int neighbour = neighbours[neighbour_count * region + k];
    if (neighbour < 0) continue;
    int other = plate[neighbour];
    if (other == own) continue;
    total = total + pressure(p, shift_p, positions[neighbour].xyz, plates[other].shift.xyz);
  }
  precise float elevation = noisy[region] + collision_strength * total * drift;
  return elevation;
}

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
#ifdef PLANET_COLLISIONS
  collided[region] = is_edge[region] != 0u ? collided_elevation(region) : noisy[region];
#else
  collided[region] = noisy[region];
#endif
}
