// Measurements on fields: mass ledgers and agreement of two grids. Totals are summed in double
// with compensated summation (core/sum.hpp). Only cells valid in both grids count.
#pragma once

#include <cstddef>

#include "core/grid.hpp"

namespace gt {

struct FieldTotals {
  double sum = 0.0;          // Σ h over valid cells
  double sum_abs = 0.0;      // Σ |h|
  double sum_squares = 0.0;  // Σ h²
  double low = 0.0;          // min and max over valid cells
  double high = 0.0;
  std::size_t cells = 0;
};

template <class T>
FieldTotals field_totals(const Grid<T>& field);

// |Σ after - Σ before| / Σ|before|: material created or destroyed, relative to the material there.
template <class A, class B>
double relative_mass_drift(const Grid<A>& before, const Grid<B>& after);

// ½Σ|after - before|: the material one step moved, when every cell either gains or loses (a cell
// that does both shows only its net change).
double moved_material(const Grid<double>& before, const Grid<double>& after);

struct FieldDifference {
  double max_abs = 0.0;          // max |b - a|; NaN when any compared value is NaN or infinite
  double rms = 0.0;              // sqrt(mean (b - a)²)
  std::size_t differing_bits = 0;  // cells whose values differ in any bit (as float when both are float)
  std::size_t nonfinite = 0;     // cells where a or b is NaN or infinite
};

template <class A, class B>
FieldDifference field_difference(const Grid<A>& a, const Grid<B>& b);

}  // namespace gt
