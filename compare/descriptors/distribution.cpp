// Quantiles of type 7 and the mean (compensated summation, core/sum.hpp).
#include "compare/descriptors/distribution.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/sum.hpp"

namespace gt {

const std::vector<double>& quantile_levels() {
  static const std::vector<double> levels{0.01, 0.05, 0.10, 0.25, 0.50, 0.75, 0.90, 0.95, 0.99};
  return levels;
}

double Distribution::quantile(double level) const {
  const auto& levels = quantile_levels();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (levels[i] == level) return quantiles.at(i);
  }
  throw std::logic_error("Distribution::quantile: level is not one of quantile_levels()");
}

namespace {

double sorted_quantile(const std::vector<double>& sorted, double level) {
  const double position = level * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double weight = position - static_cast<double>(below);
  return sorted[below] + weight * (sorted[above] - sorted[below]);
}

}  // namespace

Distribution distribution_of(std::vector<double> values) {
  if (values.empty()) throw InputError("no cell to take a distribution of");
  std::sort(values.begin(), values.end());
  Distribution out;
  out.count = values.size();
  CompensatedSum total;
  for (double value : values) total.add(value);
  out.mean = total.value() / static_cast<double>(values.size());
  for (double level : quantile_levels()) out.quantiles.push_back(sorted_quantile(values, level));
  return out;
}

}  // namespace gt
