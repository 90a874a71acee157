// Counter-based random numbers, bit for bit the same as the C++ side
// (tests/rng_parity_test.cpp checks it). Only 32-bit unsigned integer arithmetic, which wraps
// modulo 2^32 in GLSL as uint32_t does in C++. uniform01 keeps the top 24 bits, so the float in
// [0, 1) is exact. Guarded, so several included files may include it.
// Inputs:  seed, counters and stream (uint).
// Outputs: hash32, random_u32, uniform01.
// Twin:    core/rng.hpp.
#ifndef GT_COMMON_RNG_GLSL
#define GT_COMMON_RNG_GLSL

// Chris Wellons' "lowbias32" integer finaliser.
uint hash32(uint x) {
  x ^= x >> 16u;
  x *= 0x7feb352du;
  x ^= x >> 15u;
  x *= 0x846ca68bu;
  x ^= x >> 16u;
  return x;
}

uint random_u32(uint seed, uint cell, uint step, uint stream) {
  return hash32(hash32(hash32(hash32(seed) ^ cell) ^ step) ^ stream);
}

float uniform01(uint bits) { return float(bits >> 8u) * (1.0 / 16777216.0); }

#endif
