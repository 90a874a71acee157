// Square root rounded to nearest even on any GLSL 4.50 driver, for the layered ground's twins
// (digest 001): the built-in sqrt is only promised as precise as 1.0 / inversesqrt(x) (GLSL 4.50
// §4.7.1: inversesqrt within 2 ulp, the division within 2.5 ulp), so a shader that must repeat the
// CPU's std::sqrt(float) bit for bit takes gt_sqrt, as it divides with gt_div (division.glsl).
// Checked against the CPU by tests/layered_gpu_test.cpp through square_root_probe.comp. Guarded:
// several files may include it.
// Inputs:  x (float).
// Outputs: gt_sqrt(x), the float square root rounded to nearest even.
// Twin:    the CPU's std::sqrt(float).
#ifndef GT_EROSION_LAYERED_SQUARE_ROOT_GLSL
#define GT_EROSION_LAYERED_SQUARE_ROOT_GLSL

// sqrt(x) rounded to nearest even (IEEE binary32's sqrt) for x normal and positive; x itself for
// ±0; else (subnormal, negative, infinite, NaN) the driver's sqrt(x).
// x = m·2^(e − 150), m the 24-bit significand with its implicit bit, e the biased exponent. For e odd
// (an even unbiased exponent) the radicand is R = m·2^25, for e even R = m·2^26, so R lies in
// [2^48, 2^50) and its integer square root q in [2^24, 2^25): 24 significand bits and a rounding
// bit; the remainder R − q² is the sticky bit. q is found digit by digit, two radicand bits a step,
// from the high and low words of R; the remainder stays ≤ 2q < 2^26 (< 2^28 before the
// subtraction). The root's biased exponent is (e + 127)/2, rounded down: always normal.
float gt_sqrt(float x) {
  if (x == 0.0) return x;
  uint u = floatBitsToUint(x);
  uint e = u >> 23u;  // ≥ 256 when the sign bit is set
  if (e == 0u || e >= 255u) return sqrt(x);
  uint m = (u & 0x7fffffu) | 0x800000u;
  uint shift = (e & 1u) != 0u ? 25u : 26u;
  uint hi = m >> (32u - shift), lo = m << shift;  // R = hi·2^32 + lo
  uint q = 0u, r = 0u;
  for (int pair = 24; pair >= 0; --pair) {
    uint bits = pair >= 16 ? (hi >> uint(2 * pair - 32)) & 3u : (lo >> uint(2 * pair)) & 3u;
    r = (r << 2u) | bits;
    uint trial = (q << 2u) | 1u;  // (2q + 1)² − (2q)²: the next bit is 1 when it fits
    q <<= 1u;
    if (r >= trial) {
      r -= trial;
      q |= 1u;
    }
  }
  // q ≤ 2^25 − 2 (R ≤ 2^50 − 2^26 < (2^25 − 1)²), so rounding up never carries into the exponent.
  uint significand = q >> 1u;
  if ((q & 1u) != 0u && (r != 0u || (significand & 1u) != 0u)) significand += 1u;
  return uintBitsToFloat((((e + 127u) >> 1u) << 23u) | (significand & 0x7fffffu));
}

#endif
