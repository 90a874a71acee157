// The distribution of a descriptor over the cells of a terrain (slope, curvature): count, mean and
// fixed quantiles, the form the report tables and plots use for "before", "after" and a real DEM.
//
// Quantiles interpolate linearly between order statistics (Hyndman & Fan 1996 type 7, numpy's
// default): level q of n sorted values is v[floor(h)] + (h - floor(h))·(v[floor(h)+1] - v[floor(h)])
// with h = q·(n - 1). A quantile moves by at most max|Δv| when every value moves by at most |Δv|
// (order statistics are 1-Lipschitz in the largest change), which the parity bounds rely on.
#pragma once

#include <cstddef>
#include <vector>

namespace gt {

// The levels every Distribution carries, in this order.
const std::vector<double>& quantile_levels();  // 0.01 0.05 0.10 0.25 0.50 0.75 0.90 0.95 0.99

struct Distribution {
  std::size_t count = 0;
  double mean = 0.0;
  std::vector<double> quantiles;  // at quantile_levels()
  double quantile(double level) const;  // one of quantile_levels(); std::logic_error otherwise
};

// Throws InputError for an empty set (the caller says which descriptor had no cell).
Distribution distribution_of(std::vector<double> values);

}  // namespace gt
