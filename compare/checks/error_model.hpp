// Bounds for the field checks, derived from how rounding enters the algorithms.
//
// A field algorithm changes each height by a sequence of rounded additions h <- h + t. With unit
// roundoff u (2^-53 double, 2^-24 float) each addition errs by at most u·|h|.
//   worst case: the errors of all A additions into every cell point the same way:
//       |Δ mass| <= A·u·Σ|h|  ->  relative drift <= A·u (the loose bound).
//   random walk: round-to-nearest errors are spread over ±u|h| (standard deviation u|h|/√3) and
//       largely independent across cells and steps: σ(Δ mass) = u/√3·sqrt(A·Σh²). Six σ is the
//       strict bound; a drift between the two says rounding errors were correlated (many cells
//       doing the same arithmetic), not that material was lost.
// Both add 2u for the double ledger of two compensated sums.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "compare/checks/field.hpp"

namespace gt {

struct Bounds {
  double strict = 0.0;
  double loose = 0.0;
  std::string model;  // one line for the report
};

constexpr double unit_roundoff_double = 0x1p-53;
constexpr double unit_roundoff_float = 0x1p-24;

inline Bounds mass_drift_bounds(double unit_roundoff, double additions_per_cell, const FieldTotals& before) {
  Bounds bounds;
  const double ledger = 2.0 * unit_roundoff_double;
  const double scale = before.sum_abs > 0.0 ? std::sqrt(before.sum_squares) / before.sum_abs : 1.0;
  bounds.loose = additions_per_cell * unit_roundoff + ledger;
  bounds.strict = std::min(6.0 * unit_roundoff / std::sqrt(3.0) * std::sqrt(additions_per_cell) * scale + ledger,
                           bounds.loose);
  bounds.model = "rounding of " + std::to_string(static_cast<long long>(additions_per_cell)) +
                 " additions per cell: strict 6σ random walk, loose worst case A·u";
  return bounds;
}

// GPU vs ref<float>: both run the same float operations in the same order (no fused multiply-add
// on either side), so the only licensed difference is GLSL's division, accurate to 2.5 ulp where
// C++ rounds correctly. A share computed with a division then errs by <= 3u relative, so a
// transfer t errs by <= 3u·|t| <= 3u·range; the addition that follows may then round the other
// way, another u·|h| = u·magnitude·range. Over A additions per cell, relative to the range:
// worst case A·u·(3 + magnitude) (loose), random walk 6/√3·sqrt(A)·u·(3 + magnitude) (strict).
// A device that divides correctly (llvmpipe) gives 0.
inline Bounds parity_bounds_same_arithmetic(double additions_per_cell, double magnitude) {
  const double per_addition = unit_roundoff_float * (3.0 + magnitude);
  const double loose = additions_per_cell * per_addition;
  return {std::min(6.0 / std::sqrt(3.0) * std::sqrt(additions_per_cell) * per_addition, loose), loose,
          "same float operations; GLSL division within 2.5 ulp; relative to the input's height range"};
}

// float vs double: every addition rounds float heights by <= u·|h| = u·magnitude·range more than
// double does. If the method never amplified a perturbation, A additions would give at most
// A·u·magnitude (relative to the range) and typically the random walk 6/√3·sqrt(A)·u·magnitude
// (strict). Thermal erosion is not that tame: the shares max/Σ of Algorithm 10 change fast where
// the excess is small, and symmetric inputs (a cone's apex) break their ties either way. So the
// loose bound multiplies the worst case by the measured amplification κ of the method on this
// input: the largest change of the double result per unit of perturbation when every input
// height is moved by one float rounding (see measured_amplification in field_twin.cpp).
// A method that switches a transfer on at a threshold is discontinuous: one rounding on either side
// of the threshold moves a whole transfer, so the loose bound is at least that transfer.
inline Bounds parity_bounds_float_vs_double(double additions_per_cell, double magnitude, double amplification,
                                            double largest_switched_transfer) {
  const double per_addition = unit_roundoff_float * std::max(magnitude, 1.0);
  const double loose =
      std::max(additions_per_cell * per_addition * std::max(amplification, 1.0), largest_switched_transfer);
  const double strict = std::min(6.0 / std::sqrt(3.0) * std::sqrt(additions_per_cell) * per_addition, loose);
  char model[200];
  std::snprintf(model, sizeof model,
                "float rounding of heights relative to the height range; measured amplification %.3g; "
                "largest switched transfer %.3g",
                amplification, largest_switched_transfer);
  return {strict, loose, model};
}

}  // namespace gt
