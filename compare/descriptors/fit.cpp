// Ordinary least squares about the means (two passes: the centred sums avoid the cancellation of
// Σx² - n·x̄² on logarithms of large areas).
#include "compare/descriptors/fit.hpp"

#include <cstddef>
#include <stdexcept>

namespace gt {

std::optional<LineFit> fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size()) throw std::logic_error("fit_line: x and y differ in length");
  const std::size_t n = x.size();
  if (n < 2) return std::nullopt;
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    mean_x += x[i];
    mean_y += y[i];
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - mean_x, dy = y[i] - mean_y;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }
  if (sxx == 0.0) return std::nullopt;
  LineFit fit;
  fit.slope = sxy / sxx;
  fit.intercept = mean_y - fit.slope * mean_x;
  const double residual = syy - fit.slope * sxy;
  fit.r_squared = syy == 0.0 ? 1.0 : 1.0 - residual / syy;
  fit.points = static_cast<int>(n);
  return fit;
}

}  // namespace gt
