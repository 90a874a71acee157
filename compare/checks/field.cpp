#include "compare/checks/field.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "core/sum.hpp"

namespace gt {
namespace {

template <class T>
bool same_bits(T a, T b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

template <class A, class B>
void require_same_shape(const Grid<A>& a, const Grid<B>& b) {
  if (a.width != b.width || a.height != b.height) throw std::invalid_argument("grids of different sizes compared");
}

}  // namespace

template <class T>
FieldTotals field_totals(const Grid<T>& field) {
  CompensatedSum sum, sum_abs, sum_squares;
  FieldTotals totals;
  totals.low = std::numeric_limits<double>::infinity();
  totals.high = -totals.low;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (!field.is_valid(i)) continue;
    const double value = static_cast<double>(field.values[i]);
    sum.add(value);
    sum_abs.add(std::abs(value));
    sum_squares.add(value * value);
    totals.low = std::min(totals.low, value);
    totals.high = std::max(totals.high, value);
    ++totals.cells;
  }
  totals.sum = sum.value();
  totals.sum_abs = sum_abs.value();
  totals.sum_squares = sum_squares.value();
  return totals;
}

template <class A, class B>
double relative_mass_drift(const Grid<A>& before, const Grid<B>& after) {
  require_same_shape(before, after);
  const auto totals_before = field_totals(before);
  const auto totals_after = field_totals(after);
  if (totals_before.sum_abs == 0.0) return std::abs(totals_after.sum);
  return std::abs(totals_after.sum - totals_before.sum) / totals_before.sum_abs;
}

double moved_material(const Grid<double>& before, const Grid<double>& after) {
  require_same_shape(before, after);
  CompensatedSum moved;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (before.is_valid(i) && after.is_valid(i)) moved.add(std::abs(after.values[i] - before.values[i]));
  }
  return 0.5 * moved.value();
}

template <class A, class B>
FieldDifference field_difference(const Grid<A>& a, const Grid<B>& b) {
  require_same_shape(a, b);
  FieldDifference difference;
  CompensatedSum squares;
  std::size_t compared = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a.is_valid(i) || !b.is_valid(i)) continue;
    const double value_a = static_cast<double>(a.values[i]);
    const double value_b = static_cast<double>(b.values[i]);
    if constexpr (std::is_same_v<A, B>) {
      difference.differing_bits += !same_bits(a.values[i], b.values[i]);
    } else {
      difference.differing_bits += value_a != value_b;
    }
    if (!std::isfinite(value_a) || !std::isfinite(value_b)) {
      ++difference.nonfinite;
      continue;
    }
    const double delta = value_b - value_a;
    difference.max_abs = std::max(difference.max_abs, std::abs(delta));
    squares.add(delta * delta);
    ++compared;
  }
  difference.rms = compared > 0 ? std::sqrt(squares.value() / static_cast<double>(compared)) : 0.0;
  if (difference.nonfinite > 0) difference.max_abs = std::nan("");
  return difference;
}

template FieldTotals field_totals(const Grid<float>&);
template FieldTotals field_totals(const Grid<double>&);
template double relative_mass_drift(const Grid<double>&, const Grid<double>&);
template double relative_mass_drift(const Grid<double>&, const Grid<float>&);
template double relative_mass_drift(const Grid<float>&, const Grid<float>&);
template FieldDifference field_difference(const Grid<float>&, const Grid<float>&);
template FieldDifference field_difference(const Grid<double>&, const Grid<float>&);
template FieldDifference field_difference(const Grid<double>&, const Grid<double>&);

}  // namespace gt
