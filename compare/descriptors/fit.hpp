// Least-squares straight lines, the one fit every descriptor exponent uses (Hack's h, the
// exceedance exponent, Horton's ratios, the spectral slope β): y = intercept + slope·x by ordinary
// least squares over the given points, in double. Callers pass logarithms for power laws.
#pragma once

#include <optional>
#include <vector>

namespace gt {

struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
  double r_squared = 0.0;  // 1 - residual/total sum of squares; 1 when all y are equal
  int points = 0;
};

// std::nullopt with fewer than two points or when every x is the same (no slope is defined).
std::optional<LineFit> fit_line(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace gt
