#version 450
// Step 1 of the Earth-like generator (eq. 5.1, §9.3 step 1; core/params/planet.hpp): per region i,
// its jittered offset in its cell and its centroid on the unit sphere. Twin of
// reference/planet/jitter.cpp, in its order:
//   offset_axis = 0.5 + (U(i, axis, jitter) − 0.5)·j          (axis 0 = a, 1 = b)
//   a = (x + offset_a)/R, b = (y + offset_b)/R                 (eq. 4.1 corrected, erratum 4)
//   w = P_face·(f(2a − 1), f(1 − 2b), 1), f(t) = tan(θ·t)/tan θ (eq. 3.4/3.5, 4.3; erratum 8's y
//   flip), f(t) = t for no warp (θ = 0)
//   position = w·(1/sqrt(dot3(w, w)))
// θ and tan θ come rounded once to float. The offsets are exact twins (no division, no builtin);
// the positions differ from the reference by GLSL's tan (sin/cos-based, implementation-defined
// precision) and division.
// Inputs:  PlanetBlock (uniform binding 0: R, j, the face matrices, θ, tan θ, seed) (planet.glsl).
// Outputs: offsets (1): 2 per region; positions (2): xyz, w = 0.
// Twin:    reference/planet/jitter.cpp.
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

float jittered_offset(uint region, uint axis) {
  precise float offset = 0.5 + (planet_draw(region, axis, PLANET_STREAM_JITTER) - 0.5) * jitter;
  return offset;
}

// f(t) = tan(θt)/tan θ; t itself for no warp (θ = 0, where the formula is 0/0).
// Mutant NO_WARP_AS_TANGENT (this twin alone): with no warp asked, eq. 3.4's tan(πt/4) all the same.
float warped(float t) {
#ifdef GT_MUTANT_PLANET_JITTER_GPU_NO_WARP_AS_TANGENT
  if (warp_angle == 0.0) {
    precise float tangent = tan(0.785398163 * t);
    return tangent;
  }
#else
  if (warp_angle == 0.0) return t;
#endif
  precise float angle = warp_angle * t;
  precise float value = tan(angle) / tan_warp_angle;
  return value;
}

// P_face·w; P is a signed permutation, so every sum has one non-zero term: exact in any order.
vec3 to_cube(int face, vec3 face_space) {
  vec3 cube;
  for (int row = 0; row < 3; ++row) {
    ivec3 entries = face_rows[3 * face + row].xyz;
    precise float value = float(entries.x) * face_space.x + float(entries.y) * face_space.y;
    cube[row] = value + float(entries.z) * face_space.z;
  }
  return cube;
}

// The calibrated pair of the float position model (32u, planet_error_model.hpp), in both float
// twins (reference/planet/jitter.cpp alike): each component times 1 + 2^-17 (4 times the bound at
// |p| = 1) or 1 + 2^-23 (one rounding).
vec3 calibrated(vec3 position) {
#if defined(GT_MUTANT_PLANET_JITTER_FLOAT_OFF_ABOVE_BOUND)
  precise vec3 scaled = position * (1.0 + 1.0 / 131072.0);
  return scaled;
#elif defined(GT_MUTANT_PLANET_JITTER_FLOAT_OFF_BELOW_BOUND)
  precise vec3 scaled = position * (1.0 + 1.0 / 8388608.0);
  return scaled;
#else
  return position;
#endif
}

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
  int per_face = resolution * resolution;
  int cell = region % per_face;
#ifdef GT_MUTANT_PLANET_JITTER_GPU_SWAPPED_AXES
  float offset_a = jittered_offset(uint(region), 1u);  // mutant (this twin alone): a drawn on b's counter
  float offset_b = jittered_offset(uint(region), 0u);
#else
  float offset_a = jittered_offset(uint(region), 0u);
  float offset_b = jittered_offset(uint(region), 1u);
#endif
  precise float a = (float(cell % resolution) + offset_a) / float(resolution);
  precise float b = (float(cell / resolution) + offset_b) / float(resolution);
  precise float u = 2.0 * a - 1.0;
  precise float v = 1.0 - 2.0 * b;
  vec3 cube = to_cube(region / per_face, vec3(warped(u), warped(v), 1.0));
  offsets[2 * region] = offset_a;
  offsets[2 * region + 1] = offset_b;
  positions[region] = vec4(calibrated(normalise(cube)), 0.0);
}
