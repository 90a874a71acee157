// Division rounded to nearest even on any GLSL 4.50 driver, for the layered ground's twins (digest
// 001 §3.10-3.11): `/` is only promised within 2.5 ulp (GLSL 4.50 §4.7.1), and in talus a 1-ulp
// change of a repose threshold can switch a whole flux on or off, so the shaders divide with gt_div
// and repeat the CPU's IEEE float division bit for bit. Checked against the CPU by
// tests/layered_gpu_test.cpp through division_probe.comp. Guarded: several files include it.
// Inputs:  a, b (float).
// Outputs: gt_div(a, b), the IEEE float quotient rounded to nearest even.
// Twin:    the CPU's float division a / b (as the layered references divide).
#ifndef GT_EROSION_LAYERED_DIVISION_GLSL
#define GT_EROSION_LAYERED_DIVISION_GLSL

// a/b rounded to nearest even, for a ≥ 0 and b > 0 both normal with a normal quotient (else the
// driver's a/b): integer long division of the 24-bit significands, 6 bits at a time, to 25 quotient
// bits (the last one the rounding bit), the remainder as sticky bit.
float gt_div(float a, float b) {
  uint ua = floatBitsToUint(a), ub = floatBitsToUint(b);
  int ea = int(ua >> 23u), eb = int(ub >> 23u);  // sign bit 0 when normal and positive
  if (ea <= 0 || eb <= 0 || ea >= 255 || eb >= 255) return a / b;
  uint ma = (ua & 0x7fffffu) | 0x800000u, mb = (ub & 0x7fffffu) | 0x800000u;
  int exponent = ea - eb + 127;
  if (ma < mb) {
    ma <<= 1u;
    exponent -= 1;
  }
  uint q = 1u, r = ma - mb;  // ma = q·mb + r with r < mb < 2^24
  for (int chunk = 0; chunk < 4; ++chunk) {
    r <<= 6u;  // < 2^30
    q = (q << 6u) | (r / mb);
    r %= mb;
  }
  // q ≤ 2^25 − 2 (ma ≤ 2·mb − 1), so rounding up never carries into the exponent.
  uint significand = q >> 1u;
  if ((q & 1u) != 0u && (r != 0u || (significand & 1u) != 0u)) significand += 1u;
  if (exponent <= 0 || exponent >= 255) return a / b;
  return uintBitsToFloat((uint(exponent) << 23u) | (significand & 0x7fffffu));
}

#endif
