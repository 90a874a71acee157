#version 450
// Step 2, per cycle (erratum 10, the intended Algorithm 3; core/params/planet.hpp): how many rings
// plate k grows in cycle c, twin of reference::plate_expansions:
//   whole = floor(rate_k), expansions(k, c) = whole + (U(k, c, expansion) < rate_k − whole ? 1 : 0)
// (rate_k − whole is exact). Writes plates[k].expansions for the cycle `cycle`.
// Inputs:  PlanetBlock (uniform binding 0), plates (7: rates) (planet.glsl); the uniform cycle.
// Outputs: plates[k].expansions (7).
// Twin:    reference/planet/plates.cpp (plate_expansions).
layout(local_size_x = 64) in;

#include "planet/planet.glsl"

uniform int cycle;

void main() {
  int k = int(gl_GlobalInvocationID.x);
  if (k >= plate_count) return;
  precise float rate = plates[k].rate;
#ifdef GT_MUTANT_PLANET_PLATES_CEIL_RATE
  precise float whole = ceil(rate);  // mutant (both twins): whole rings rounded up, no extra draw can win
#else
  precise float whole = floor(rate);
#endif
  precise float fraction = rate - whole;
  bool extra = planet_draw(uint(k), uint(cycle), PLANET_STREAM_EXPANSION) < fraction;
  plates[k].expansions = int(whole) + (extra ? 1 : 0);
}
