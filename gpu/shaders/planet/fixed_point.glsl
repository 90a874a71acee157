// The plate centre sums of step 4 (core/params/planet.hpp; §9.3 step 4 asks for a deterministic
// reduction): order-independent, so the same bits whichever invocation adds first, and exactly
// what a CPU computing with int64 gets.
//
// Each position component x (|x| <= 1) becomes the integer X = floor(x·2^40) (x·2^40 and the floor
// are exact in float), added to a two's-complement 64-bit sum held as two uints (low word, high
// word) by two atomicAdds, the carry of the low word found from the value it had before: integer
// addition modulo 2^64, exact in any order. |Σ X| <= N·2^40 <= 2^60 for N <= 540,000 regions: no
// overflow. The float sum is then
//   sum = (float(int(high))·2^32 + float(low))·2^−40   (both conversions and the addition rounded
//   to nearest, the scalings by powers of two exact).
// Error against the exact Σ x: the floor loses < 2^−40 per term (< N·2^−40 <= 5·10^−7 in all), the
// conversion of `low` <= 2^7 integer units (2^−33), the conversion of `high` and the addition
// <= 2^−24·|sum| each.
// A plate's sums occupy centre_sums[6k .. 6k + 5]: (low, high) for x, y, z.
// Inputs:  centre_sums (binding 9, planet.glsl); a position.
// Outputs: the atomic adds into a plate's sums and the float sums read back.
// Twin:    reference/planet/elevation.cpp (plate_centres, which sums in double; core/params/planet.hpp).
#ifndef GT_PLANET_FIXED_POINT_GLSL
#define GT_PLANET_FIXED_POINT_GLSL

const float fixed_point_scale = 1099511627776.0;   // 2^40
const float word_scale = 4294967296.0;             // 2^32

// (low, high) of the 64-bit two's complement of floor(x·2^40).
uvec2 fixed_point_words(float x) {
  precise float scaled = floor(x * fixed_point_scale);
  precise float magnitude = abs(scaled);
  precise float high = floor(magnitude * (1.0 / word_scale));
  precise float low = magnitude - high * word_scale;  // exact: magnitude mod 2^32 has <= 24 bits
  uvec2 words = uvec2(uint(low), uint(high));
  if (scaled < 0.0) {
    words.x = ~words.x + 1u;
    words.y = ~words.y + (words.x == 0u ? 1u : 0u);
  }
  return words;
}

void add_fixed_point(uint slot, float x) {
  uvec2 words = fixed_point_words(x);
  uint before = atomicAdd(centre_sums[slot], words.x);
  uint carry = before + words.x < before ? 1u : 0u;
  atomicAdd(centre_sums[slot + 1u], words.y + carry);
}

float fixed_point_sum(uint slot) {
  precise float whole = float(int(centre_sums[slot + 1u])) * word_scale + float(centre_sums[slot]);
  precise float sum = whole * (1.0 / fixed_point_scale);
  return sum;
}

#endif  // GT_PLANET_FIXED_POINT_GLSL
