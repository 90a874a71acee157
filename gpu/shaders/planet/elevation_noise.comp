#version 450
// Steps 6–7 per region (§4.4.3 phases 1 and 3, §9.3 step 7; core/params/planet.hpp), twin of
// reference::planet_elevation<float>'s E0:
//   E0(i) = b_plate(i) + S·fbm(f·pos(i))   (PLANET_NOISE; fbm: noise/fractal.glsl's gt_fbm of
//                                           improved Perlin noise, octaves o, lacunarity 2, gain 0.5)
//   E0(i) = b_plate(i)                     (without noise)
// f·pos componentwise, then S times the fbm, then the base added. No division or square root: the
// same bits as the reference on a device that honours `precise`.
// Inputs:  PlanetBlock (uniform binding 0: S, f, fractal terms), positions (2), plate (3), plates (7:
//          base), the permutation (5) (planet.glsl).
// Outputs: noisy (10): E0.
// Twin:    reference/planet/elevation.cpp (planet_elevation's E0).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

// The calibrated pairs of the elevation's float model (reference/planet/elevation.cpp's
// calibration_factor): E0 times 1 + 2^-12 in both float twins, 1 + 2^-14 in this one alone (the 4u
// model against ref<float>), 1 + 2^-23 (one rounding) below either bound; 1 on an honest run.
#if defined(GT_MUTANT_PLANET_NOISE_FLOAT_OFF_ABOVE_BOUND)
const float drift = 1.0 + 1.0 / 4096.0;
#elif defined(GT_MUTANT_PLANET_NOISE_GPU_OFF_ABOVE_BOUND)
const float drift = 1.0 + 1.0 / 16384.0;
#elif defined(GT_MUTANT_PLANET_NOISE_FLOAT_OFF_BELOW_BOUND) || defined(GT_MUTANT_PLANET_NOISE_GPU_OFF_BELOW_BOUND)
const float drift = 1.0 + 1.0 / 8388608.0;
#else
const float drift = 1.0;
#endif

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
  float base = plates[plate[region]].base;
#ifdef PLANET_NOISE
#ifdef GT_MUTANT_PLANET_NOISE_GPU_FREQUENCY_DROPPED
  precise vec3 sample_point = positions[region].xyz;  // mutant (GPU only): the frequency f dropped
#else
  precise vec3 sample_point = perlin_frequency * positions[region].xyz;
#endif
  precise float elevation = (base + perlin_strength * gt_fbm(sample_point, fractal_terms)) * drift;
  noisy[region] = elevation;
#else
  noisy[region] = base;
#endif
}
