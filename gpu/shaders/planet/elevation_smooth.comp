#version 450
// Step 9 per region (erratum 14, §9.3 step 9 option A; core/params/planet.hpp), twin of
// reference::planet_elevation<float>'s E2 with Smoothing::jacobi:
//   E2(i) = (E1(i) + Σ valid E1(n)) / (1 + valid count)   (PLANET_SMOOTHS)
// the sum from E1(i), then the neighbours added in table order, then one division by the float
// count (7 + 1 or 8 + 1). Without PLANET_SMOOTHS (smoothing off, or only with collisions and
// collisions off): E2 = E1. Reads `collided`, writes `smoothed` (a Jacobi step).
// Inputs:  PlanetBlock (uniform binding 0), neighbours (0), collided (11: E1) (planet.glsl).
// Outputs: smoothed (12): E2.
// Twin:    reference/planet/elevation.cpp (planet_elevation's E2, smoothed_elevation).
layout(local_size_x = 256) in;

#include "planet/planet.glsl"

// The calibrated pair of the smoothing's float model in both float twins (reference/planet/
// elevation.cpp's calibration_factor): the mean times 1 + 2^-12 above the bound, 1 + 2^-23 below.
#if defined(GT_MUTANT_PLANET_SMOOTHING_FLOAT_OFF_ABOVE_BOUND)
const float drift = 1.0 + 1.0 / 4096.0;
#elif defined(GT_MUTANT_PLANET_SMOOTHING_FLOAT_OFF_BELOW_BOUND)
const float drift = 1.0 + 1.0 / 8388608.0;
#else
const float drift = 1.0;
#endif

void main() {
  int region = int(gl_GlobalInvocationID.x);
  if (region >= region_count) return;
#ifdef PLANET_SMOOTHS
  precise float sum = collided[region];
  int count = 1;
  for (int k = 0; k < neighbour_count; ++k) {
    int neighbour = neighbours[neighbour_count * region + k];
    if (neighbour < 0) continue;
    sum = sum + collided[neighbour];
    ++count;
  }
#ifdef GT_MUTANT_PLANET_SMOOTHING_COUNT_WITHOUT_SELF
  precise float mean = sum / float(count - 1) * drift;  // mutant (both twins): the region summed but not counted
#else
  precise float mean = sum / float(count) * drift;
#endif
  smoothed[region] = mean;
#else
  smoothed[region] = collided[region];
#endif
}
