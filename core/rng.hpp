// Counter-based random numbers shared bit for bit by the CPU references and the shaders.
//
// hash32 is Chris Wellons' "lowbias32" integer finaliser (bias 0.17, public domain idea, written
// here from its published constants). random_u32 chains it over (seed, cell, step, stream) so a
// number depends only on those four counters, never on execution order. Its GLSL twin is
// gpu/shaders/common/rng.glsl; tests/rng_parity_test.cpp checks that both give the same bits.
// uniform01 keeps the top 24 bits, so the float in [0, 1) is exact in both languages.
#pragma once

#include <cstdint>

namespace gt {

constexpr std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

constexpr std::uint32_t random_u32(std::uint32_t seed, std::uint32_t cell, std::uint32_t step, std::uint32_t stream) {
  return hash32(hash32(hash32(hash32(seed) ^ cell) ^ step) ^ stream);
}

constexpr float uniform01(std::uint32_t bits) { return static_cast<float>(bits >> 8) * (1.0f / 16777216.0f); }

}  // namespace gt
