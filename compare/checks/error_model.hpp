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

// The unit roundoff of a backend's arithmetic: ref<double> ("cpu") rounds in double, every other
// backend (ref<float>, the GPU, an outside float implementation) in float.
inline double unit_roundoff_of(const std::string& backend) {
  return backend == "cpu" ? unit_roundoff_double : unit_roundoff_float;
}

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
// The model holds for steps taken from one shared state (the shadow steps of field_twin.cpp): in
// the first iteration both sides compare identical numbers and branch alike. Over more iterations
// a division's ulps could flip a later talus comparison, which the model leaves out; that cannot
// happen where division rounds correctly, and the one-iteration check stands without it.
inline Bounds parity_bounds_same_arithmetic(double additions_per_cell, double magnitude) {
  const double per_addition = unit_roundoff_float * (3.0 + magnitude);
  const double loose = additions_per_cell * per_addition;
  return {std::min(6.0 / std::sqrt(3.0) * std::sqrt(additions_per_cell) * per_addition, loose), loose,
          "same float operations; GLSL division within 2.5 ulp; relative to the input's height range"};
}

// Material moved by one iteration (½Σ|h1 - h0|): a double twin against a double spec of the same
// iteration written apart from it (other loop order, so other roundings). Each computes a new
// height by A rounded additions of transfers, each transfer at most the range and within 8u of
// itself (difference, talus subtraction, share product and quotient, minimum); a partial sum is at
// most |h| + A·range. So either height is within A·u·(|h| + (A + 8)·range) of the exact one, and
// |moved_twin - moved_spec| <= ½Σ|h1_twin - h1_spec| <= A·u·(Σ|h| + cells·(A + 8)·range), plus 2u
// for the compensated sums; relative to the spec's moved material (no loose bound: worst case).
// One cell of the spec's first iteration against the twin's, both in double: each forms its cell's
// A transfers from differences, shares and a division, each within (A + 8)·u·range, and adds them
// into the height, each addition within u·(max|h| + A·range); the two sides err independently.
inline Bounds first_iteration_cell_bounds(double additions_per_iteration, const FieldTotals& before) {
  const double range = before.high - before.low;
  const double largest = std::max(std::abs(before.low), std::abs(before.high));
  const double bound = 2.0 * additions_per_iteration * unit_roundoff_double *
                       (largest + additions_per_iteration * range + (additions_per_iteration + 8.0) * range);
  return {bound, bound, "double roundings of one iteration in the twin and in the spec, per cell: 2·A·u·(max|h| + (2A + 8)·range)"};
}

inline Bounds moved_ledger_bounds(double additions_per_iteration, const FieldTotals& before, double moved_spec) {
  const double range = before.high - before.low;
  const double worst = additions_per_iteration * unit_roundoff_double *
                       (before.sum_abs + static_cast<double>(before.cells) * (additions_per_iteration + 8.0) * range);
  const double strict = worst / moved_spec + 2.0 * unit_roundoff_double;
  return {strict, strict,
          "double roundings of one iteration in the twin and in the spec: A·u·(Σ|h| + cells·(A + 8)·range) "
          "over the spec's moved material"};
}

}  // namespace gt
