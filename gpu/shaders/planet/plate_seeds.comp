#version 450
// Step 2's start (§4.4.2, §9.2, §9.3 step 2; core/params/planet.hpp): each plate's rate and seed
// region, twin of reference::plate_rates and plate_seeds. One invocation places the P <= 500 seeds
// in plate order, so that the duplicate rejection sees the earlier ones:
//   rate_k = max(lo + (hi − lo)·U(k, 0, rate), 1/256)   (erratum 9, floored so every plate grows)
//   seed_k = random_u32(seed, k, attempt, plate_seed) % N for attempt = 0, 1, ... until the region
//            has no plate yet; after 64 attempts the first free region in index order.
// Needs `plate` cleared to −1 by the host.
// Inputs:  PlanetBlock (uniform binding 0: rate bounds, P, N, seed) (planet.glsl); plate (3), cleared.
// Outputs: plate[seed_k] = k (3), plates[k].rate, .seed_region (7), and assigned_count (8) = the seeds
//          placed (P).
// Twin:    reference/planet/plates.cpp (plate_rates, plate_seeds).
layout(local_size_x = 1) in;

#include "planet/planet.glsl"

const int seed_attempts = 64;            // plate_seed_attempts
const float minimum_rate = 1.0 / 256.0;  // minimum_plate_rate

float plate_rate(uint k) {
  precise float spread = rate_high - rate_low;
  precise float rate = rate_low + spread * planet_draw(k, 0u, PLANET_STREAM_RATE);
  return max(rate, minimum_rate);
}

// One flat loop of bounded length. Observed on llvmpipe: the loops of this single invocation ran to
// their bounds whatever their exit conditions said, and its loops stopped for good after 65,535
// iterations in all (gallivm's loop limiter), which cut the plate loop short (at P = 18 with an O(N)
// scan per plate, at P = 116 with a nested 64 + 500). So each step of the one loop does one thing:
// a draw (at most 64 per plate), a move of the first-free cursor (it only moves forward, as seeds
// are only added: at most P moves in all) or a placement (P): at most 66·P <= 33,000 steps.
void place(int k, int region) {
  plate[region] = k;
  plates[k].seed_region = region;
  plates[k].rate = plate_rate(uint(k));
}

// Mutant planet.plates.gpu_last_seed_missing: the loop stops one plate short, so the last plate
// has no seed and grows no region.
#ifdef GT_MUTANT_PLANET_PLATES_GPU_LAST_SEED_MISSING
const int seeds_placed_short = 1;
#else
const int seeds_placed_short = 0;
#endif

void main() {
  int k = 0, attempt = 0, first_free = 0;
  int step_bound = plate_count * (seed_attempts + 2);
  for (int step = 0; step < step_bound && k < plate_count - seeds_placed_short; ++step) {
    int region = first_free;
    if (attempt < seed_attempts) {
      region = int(random_u32(seed, uint(k), uint(attempt), PLANET_STREAM_PLATE_SEED) % uint(region_count));
      ++attempt;
    } else if (plate[first_free] >= 0) {
      ++first_free;
      continue;
    }
#ifndef GT_MUTANT_PLANET_PLATES_SEEDS_REPEAT
    if (plate[region] >= 0) continue;  // mutant (both twins): the first draw is taken, free or not
#endif
    place(k, region);
    ++k;
    attempt = 0;
  }
#ifdef GT_MUTANT_PLANET_PLATES_SEEDS_COUNTED_TWICE
  assigned_count = 2u * uint(k);  // mutant (both twins): the seeds counted twice, the fill stops P early
#else
  assigned_count = uint(k);
#endif
}
