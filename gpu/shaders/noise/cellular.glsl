// Cellular noise bases (Worley 1996, as Blender's VORONOI_F1..F4, VORONOI_F2F1, VORONOI_CRACKLE and
// CELLNOISE; seed 001 §3.18): the same float operations in the same order as the reference (see the
// definitions and decisions there). Needs the permutation storage buffer of noise/permutation.glsl
// (binding 5, the table twice: 512 entries).
//
// gt_voronoi_distances(p) -> (F1, F2, F3, F4), the four nearest feature points of the 27 cells around
// floor(p); gt_voronoi(p, feature) -> the signed value of feature 1..4 (F_k), 5 (F2 − F1) or 6
// (crackle); gt_cell_noise(p) -> the cell's signed value.
// Coordinates in lattice units, |p| < 2^31; period 256.
// Inputs:  p in lattice units; the permutation buffer (binding 5, noise/permutation.glsl).
// Outputs: gt_voronoi_distances, gt_voronoi, gt_cell_noise.
// Twin:    reference/noise/cellular.cpp.
#ifndef GT_NOISE_CELLULAR_GLSL
#define GT_NOISE_CELLULAR_GLSL

#include "noise/permutation.glsl"

const int gt_voronoi_f2f1 = 5, gt_voronoi_crackle = 6;

// P[P[P[X] + Y] + Z] of the cell, each coordinate & 255; every index stays below 512.
int gt_cellular_hash(ivec3 cell) {
  ivec3 wrapped = cell & 255;
  return int(perm[int(perm[int(perm[wrapped.x]) + wrapped.y]) + wrapped.z]);
}

// The entry P[h + entry] as (P + 1/2)/256, exact. Mutant GPU_JITTER_UNCENTRED (this twin alone):
// P/256, the points half a 1/256 step towards the cell's corner.
float gt_hashed_fraction(int hash, int entry) {
#ifdef GT_MUTANT_NOISE_VORONOI_GPU_JITTER_UNCENTRED
  precise float fraction = float(perm[hash + entry]) * 0.00390625;
#else
  precise float fraction = (float(perm[hash + entry]) + 0.5) * 0.00390625;
#endif
  return fraction;
}

// Mutant SQUARED_DISTANCE (both twins): the squared distance where the distance belongs.
float gt_cellular_distance(float squared) {
#ifdef GT_MUTANT_NOISE_VORONOI_SQUARED_DISTANCE
  return squared;
#else
  return sqrt(squared);
#endif
}

vec4 gt_voronoi_distances(vec3 p) {
  ivec3 cell = ivec3(floor(p));
  precise vec3 local = p - vec3(cell);
  vec4 nearest = vec4(1e10);
  for (int dz = -1; dz <= 1; ++dz) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        ivec3 offset = ivec3(dx, dy, dz);
        int hash = gt_cellular_hash(cell + offset);
        precise vec3 feature = vec3(offset) + vec3(gt_hashed_fraction(hash, 0), gt_hashed_fraction(hash, 85),
                                                   gt_hashed_fraction(hash, 170));
        precise vec3 apart = local - feature;
        precise float squared = (apart.x * apart.x + apart.y * apart.y) + apart.z * apart.z;
        float distance = gt_cellular_distance(squared);
        if (distance < nearest[3]) {
          int slot = 3;
          while (slot > 0 && distance < nearest[slot - 1]) {
            nearest[slot] = nearest[slot - 1];
            --slot;
          }
          nearest[slot] = distance;
        }
      }
    }
  }
  return nearest;
}

// feature 1..4: 2·F_k − 1; 5: 2·(F2 − F1) − 1; 6: 2·min(1, 10·(F2 − F1)) − 1.
float gt_voronoi(vec3 p, int feature) {
  vec4 nearest = gt_voronoi_distances(p);
  precise float gap = nearest[1] - nearest[0];
  precise float value;
  if (feature == gt_voronoi_f2f1) {
    value = 2.0 * gap - 1.0;
  } else if (feature == gt_voronoi_crackle) {
    precise float crackle = 10.0 * gap;
    value = 2.0 * (crackle < 1.0 ? crackle : 1.0) - 1.0;
  } else {
    value = 2.0 * nearest[feature - 1] - 1.0;
  }
  return value;
}

// The cell's value (P[h + 128] + 1/2)/128 − 1, exact. Mutants: VALUE_FROM_JITTER_HASH (both twins)
// reads P[h], the x jitter's entry; GPU_UNIT_INTERVAL (this twin alone) returns the unsigned
// (P + 1/2)/256.
float gt_cell_noise(vec3 p) {
  int hash = gt_cellular_hash(ivec3(floor(p)));
#ifdef GT_MUTANT_NOISE_CELL_VALUE_FROM_JITTER_HASH
  float fraction = gt_hashed_fraction(hash, 0);
#else
  float fraction = gt_hashed_fraction(hash, 128);
#endif
#ifdef GT_MUTANT_NOISE_CELL_GPU_UNIT_INTERVAL
  return fraction;
#else
  precise float value = 2.0 * fraction - 1.0;
  return value;
#endif
}

#endif
