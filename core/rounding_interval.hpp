// A number for a-priori rounding bounds of a float computation (interval arithmetic with the
// rounding of each operation folded in; Moore 1966, Higham "Accuracy and Stability of Numerical
// Algorithms" §26): beside its value (computed in double, the exact value to first order) it
// carries an interval [low, high] holding every value a float implementation of the same
// operations may hold at that point, so two implementations (ref<float> and a GPU or outside
// candidate) lie at most high − low apart. The error models of the stepping twins instantiate their
// CPU reference with it (reference/erosion/pipes.cpp) and read per-cell bounds off the result.
//
// Model, per operation: the exact operation on the operands' intervals, then widened outward by the
// rounding either implementation may make: a correctly rounded float operation errs by at most
// u·|z|, u = 2^-24; GLSL 4.50 §4.7.1 licenses 2.5 ulp (5u) for ÷ and √ and correct rounding for
// + − ×. Widening each end by its own magnitude keeps the sign (rounding a non-negative result
// gives a non-negative float), so a sum of max(0, ·) terms stays ≥ 0 and a quotient by it is
// bounded on one side. max and min are monotone and exact on intervals: a branch that switches
// between two values that meet there (max(0, ·), K = min(1, ·)) is covered whichever way either
// twin takes it. floor and ceil give their value's floor and ceil exactly; where p's interval holds
// a whole number, another implementation may take the floor on its other side, so a piecewise
// formula on floor(p) (the bilinear weights ceil(p) − p and p − floor(p)) is evaluated on every piece
// floor_range names and the pieces joined with hull (reference/erosion/pipes.cpp's tracing).
// A constant converted from double (static_cast<Real>(c)) holds c and its float.
// Comparisons read the values alone: a branch that jumps where one rounding can switch it (a talus
// threshold, a cell dry in one twin and wet by an ulp in the other) is not covered, which the error
// models that use this say. A product with an exact 0 is exact (0·∞ is taken as 0: a dry cell's
// share of an unbounded quotient moves nothing).
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

namespace gt {

struct RoundingInterval {
  static constexpr double float_unit = 0x1p-24;
  static constexpr double basic_unit = float_unit;            // + − ×
  static constexpr double licensed_unit = 5.0 * float_unit;  // ÷ √ (GLSL's 2.5 ulp)

  double value = 0.0;
  double low = 0.0;
  double high = 0.0;

  constexpr RoundingInterval() = default;
  // A constant as the implementations receive it: c, or c rounded to float.
  explicit RoundingInterval(double constant) : value(constant), low(constant), high(constant) {
    const auto rounded = static_cast<double>(static_cast<float>(constant));
    low = std::min(low, rounded);
    high = std::max(high, rounded);
  }
  static RoundingInterval exact(double value) { return of(value, value, value); }
  static RoundingInterval of(double value, double low, double high) {
    RoundingInterval number;
    number.value = value;
    number.low = low;
    number.high = high;
    return number;
  }
  // The bound on |one implementation − another| here.
  double width() const { return high - low; }

  explicit operator double() const { return value; }
  explicit operator float() const { return static_cast<float>(value); }
  explicit operator int() const { return static_cast<int>(value); }

  RoundingInterval operator-() const { return of(-value, -high, -low); }

  friend RoundingInterval operator+(const RoundingInterval& a, const RoundingInterval& b) {
    return rounded(a.value + b.value, a.low + b.low, a.high + b.high, basic_unit);
  }
  friend RoundingInterval operator-(const RoundingInterval& a, const RoundingInterval& b) {
    return rounded(a.value - b.value, a.low - b.high, a.high - b.low, basic_unit);
  }
  friend RoundingInterval operator*(const RoundingInterval& a, const RoundingInterval& b) {
    return hull(a.value * b.value,
                {product(a.low, b.low), product(a.low, b.high), product(a.high, b.low), product(a.high, b.high)},
                basic_unit);
  }
  friend RoundingInterval operator/(const RoundingInterval& a, const RoundingInterval& b) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    const double quotient = a.value / b.value;
    if (b.low > 0.0 || b.high < 0.0) {
      return hull(quotient, {a.low / b.low, a.low / b.high, a.high / b.low, a.high / b.high}, licensed_unit);
    }
    // The divisor may be 0: with a divisor in [0, high] (a sum of non-negative terms) and a dividend
    // of one sign, the quotient is bounded on that side.
    if (b.low == 0.0 && b.high > 0.0) {
      return rounded(quotient, a.low >= 0.0 ? a.low / b.high : -infinity, a.high <= 0.0 ? a.high / b.high : infinity,
                     licensed_unit);
    }
    return of(quotient, -infinity, infinity);
  }

  friend bool operator<(const RoundingInterval& a, const RoundingInterval& b) { return a.value < b.value; }
  friend bool operator>(const RoundingInterval& a, const RoundingInterval& b) { return a.value > b.value; }
  friend bool operator<=(const RoundingInterval& a, const RoundingInterval& b) { return a.value <= b.value; }
  friend bool operator>=(const RoundingInterval& a, const RoundingInterval& b) { return a.value >= b.value; }
  friend bool operator==(const RoundingInterval& a, const RoundingInterval& b) { return a.value == b.value; }

 private:
  static double product(double x, double y) { return x == 0.0 || y == 0.0 ? 0.0 : x * y; }
  // The interval spanned by the four corners of an operation on two intervals, rounded outward.
  static RoundingInterval hull(double value, std::initializer_list<double> corners, double unit) {
    const auto [low, high] = std::minmax(corners);
    return rounded(value, low, high, unit);
  }
  // [low, high] widened outward by `unit` of each end's magnitude.
  // An end that is NaN (∞ − ∞, ∞/∞ of unbounded operands) is unbounded.
  static RoundingInterval rounded(double value, double low, double high, double unit) {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    return of(value, std::isnan(low) ? -infinity : low - unit * std::abs(low),
              std::isnan(high) ? infinity : high + unit * std::abs(high));
  }
};

inline RoundingInterval max(const RoundingInterval& a, const RoundingInterval& b) {
  return RoundingInterval::of(std::max(a.value, b.value), std::max(a.low, b.low), std::max(a.high, b.high));
}
inline RoundingInterval min(const RoundingInterval& a, const RoundingInterval& b) {
  return RoundingInterval::of(std::min(a.value, b.value), std::min(a.low, b.low), std::min(a.high, b.high));
}

inline RoundingInterval sqrt(const RoundingInterval& a) {
  const double low = std::sqrt(std::max(0.0, a.low));
  const double high = std::sqrt(std::max(0.0, a.high));
  const double unit = RoundingInterval::licensed_unit;
  return RoundingInterval::of(std::sqrt(std::max(0.0, a.value)), low - unit * low, high + unit * high);
}

inline RoundingInterval floor(const RoundingInterval& a) { return RoundingInterval::exact(std::floor(a.value)); }
// The least and largest floor of a number an implementation may hold within a: one piece each of a
// formula that switches at whole numbers.
inline std::pair<double, double> floor_range(const RoundingInterval& a) { return {std::floor(a.low), std::floor(a.high)}; }
// The interval holding both a and b, with a's value: two pieces either implementation may take.
inline RoundingInterval hull(const RoundingInterval& a, const RoundingInterval& b) {
  return RoundingInterval::of(a.value, std::min(a.low, b.low), std::max(a.high, b.high));
}
inline RoundingInterval ceil(const RoundingInterval& a) { return RoundingInterval::exact(std::ceil(a.value)); }
inline bool isnan(const RoundingInterval& a) { return std::isnan(a.value); }

}  // namespace gt
