// What every pass of the GPU Earth-like planet generator shares (seed 002 §4.4, §9; the spec, step by
// step, is core/params/planet.hpp; host: gpu/planet/generator.cpp): the parameter block, the storage
// buffers at fixed bindings (a pass uses the ones it names; the others stay inactive), the random
// draws U(k, step, stream) and the vector helpers whose float operation order the CPU reference
// (reference/planet/*.cpp, Real = float) repeats.
//
// Decisions for exact float agreement (every intermediate `precise`: no fused multiply-add):
// - dot3(a, b) = (a.x·b.x + a.y·b.y) + a.z·b.z (never the builtin dot/length/normalize, whose
//   order is the driver's);
// - normalise(v) = v·(1/sqrt(dot3(v, v))), the zero vector for dot3(v, v) = 0 (the jitter's form);
// - vector sums and differences componentwise.
// Layout (§9.4): std430, vec3 padded to vec4. Units: positions on the unit sphere; elevations in
// generator units.
// Inputs:  declares PlanetBlock (uniform binding 0) and the storage buffers neighbours (0), offsets
//          (1), positions (2), plate (3), plate_next (4), is_edge (6), plates (7), assigned_count (8),
//          centre_sums (9), noisy (10), collided (11), smoothed (12); the permutation (5) through
//          noise/perlin.glsl.
// Outputs: U(k, step, stream), dot3, normalise and the vector helpers for the passes.
// Twin:    reference/planet/*.cpp (Real = float); host: gpu/planet/generator.cpp.
#ifndef GT_PLANET_PLANET_GLSL
#define GT_PLANET_PLANET_GLSL

#include "common/rng.glsl"
#include "noise/perlin.glsl"
#define FRACTAL_BASIS(q) gt_perlin3(q)
#include "noise/fractal.glsl"

// Mirrored by PlanetBlock in gpu/planet/generator.cpp (std140 offsets checked there).
layout(std140, binding = 0) uniform PlanetBlock {
  ivec4 face_rows[18];       // face_matrix(face) row r at 3·face + r (core/planet/cube_sphere.hpp)
  int region_count;          // N = 6R²
  int plate_count;           // P
  uint seed;
  int resolution;            // R
  float jitter;              // j
  float warp_angle;          // θ, rounded once to float
  float tan_warp_angle;      // tan θ, computed in double, rounded once
  float rate_low;            // plate_rate_bounds: lo
  float rate_high;           // hi
  float elevation_range;     // e_r
  float collision_strength;  // C
  float perlin_frequency;    // f
  float perlin_strength;     // S
  float ocean_share;         // with PLANET_BIMODAL_BASES: the share of oceanic plates
  GtFractalTerms fractal_terms;  // octaves o, lacunarity 2, gain 0.5
};

// One plate's state. Mirrored by PlateRecord in gpu/planet/generator.cpp.
struct PlateRecord {
  vec4 centre;     // xyz: c_k (step 4)
  vec4 shift;      // xyz: s_k (step 5)
  float base;      // b_k (step 6)
  float rate;      // rate_k (step 2)
  int expansions;  // expansions(k, cycle) of the cycle running (step 2)
  int seed_region; // the plate's seed (step 2)
};

layout(std430, binding = 0) readonly buffer Neighbours { int neighbours[]; };  // 8 per region, −1 invalid
layout(std430, binding = 1) buffer Offsets { float offsets[]; };                // a, b per region
layout(std430, binding = 2) buffer Positions { vec4 positions[]; };             // xyz per region
layout(std430, binding = 3) buffer Plate { int plate[]; };                      // the current partition
layout(std430, binding = 4) buffer PlateNext { int plate_next[]; };             // a claim sub-step's output
// binding 5: the Perlin permutation (noise/permutation.glsl)
layout(std430, binding = 6) buffer IsEdge { uint is_edge[]; };
layout(std430, binding = 7) buffer Plates { PlateRecord plates[]; };
layout(std430, binding = 8) buffer Assigned { uint assigned_count; };           // regions with a plate
layout(std430, binding = 9) buffer CentreSums { uint centre_sums[]; };          // 6 per plate, centre_sum.glsl
layout(std430, binding = 10) buffer Noisy { float noisy[]; };                   // E0
layout(std430, binding = 11) buffer Collided { float collided[]; };             // E1
layout(std430, binding = 12) buffer Smoothed { float smoothed[]; };             // E2

const int neighbour_count = 8;

// U(k, step, stream) of core/params/planet.hpp; the host defines the streams (PlanetStream) as
// PLANET_STREAM_JITTER, _PLATE_SEED, _RATE, _EXPANSION, _SHIFT, _ELEVATION.
float planet_draw(uint k, uint step, uint stream) { return uniform01(random_u32(seed, k, step, stream)); }

float dot3(vec3 a, vec3 b) {
  precise float sum = a.x * b.x + a.y * b.y;
  precise float result = sum + a.z * b.z;
  return result;
}

vec3 normalise(vec3 v) {
  precise float squared = dot3(v, v);
  if (squared == 0.0) return vec3(0.0);
  precise float inverse_length = 1.0 / sqrt(squared);
  precise vec3 unit = v * inverse_length;
  return unit;
}

#endif  // GT_PLANET_PLANET_GLSL
