// Turning a measured value and its bounds into a Check with an outcome.
#pragma once

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

#include "compare/result.hpp"

namespace gt {

// pass when value <= strict, warn when value <= loose (if given), fail otherwise; a NaN value
// always fails.
inline Check bounded_check(std::string name, double value, double strict, std::optional<double> loose,
                           std::string detail) {
  Check check{std::move(name), value, strict, loose, Outcome::fail, std::move(detail)};
  if (value <= strict) {
    check.status = Outcome::pass;
  } else if (loose && value <= *loose) {
    check.status = Outcome::warn;
  }
  return check;
}

// A comparison whose error model may be too wide to mean anything: when the widest bound it
// licenses (the loose one if any) exceeds `tellable_share` of the field's `scale` (the share below
// which a real bug must still show, stated by the caller beside the check), a bug of that size
// would pass too, so a pass or warn is `inconclusive`; a value beyond every bound still fails.
// `widest`: where the bound differs from value to value, the one tellability is judged by (a high
// percentile of them); unset: the widest bound the check licenses.
inline Check decisive_check(std::string name, double value, double strict, std::optional<double> loose, double scale,
                            double tellable_share, std::string detail, std::optional<double> widest = std::nullopt) {
  Check check = bounded_check(std::move(name), value, strict, loose, std::move(detail));
  const bool passed = check.status == Outcome::pass || check.status == Outcome::warn;
  const double judged = widest.value_or(loose.value_or(strict));
  if (passed && judged > tellable_share * scale) {
    check.status = Outcome::inconclusive;
    char text[200];
    std::snprintf(text, sizeof text, " — inconclusive: the bound %.3g%s exceeds %g of the field's scale %.3g", judged,
                  widest ? " (the 90th percentile of the bounds over the cells)" : "", tellable_share, scale);
    check.detail += text;
  }
  return check;
}

// A measured value reported without a bound (always pass): sizes, topology, distances to read.
inline Check informative_check(std::string name, double value, std::string detail) {
  return Check{std::move(name), value, std::nullopt, std::nullopt, Outcome::pass, std::move(detail)};
}

// A check that does not apply to this input (the volume of an open mesh): recorded with the reason
// and no value, and not a skip, which says that something that should have run did not.
inline Check not_applicable_check(std::string name, std::string reason) {
  return Check{std::move(name), std::nan(""), std::nullopt, std::nullopt, Outcome::pass, "not applicable: " + reason};
}

// A check that should have run and did not (the GPU half without a GL context): the case is then
// `skip` at best, never `pass`.
inline Check skipped_check(std::string name, std::string reason) {
  Check check;
  check.name = std::move(name);
  check.value = std::nan("");
  check.status = Outcome::skip;
  check.detail = std::move(reason);
  return check;
}

// For every check of `result` whose name starts with `prefix` and ends with `from` (a backend the
// case ran: ".cpu"), the same check of the backend that did not run (`to`: ".gpu") as `skip`: for
// checks the two backends make alike (a mesh's watertightness), whose set depends on the input.
inline void skip_as_other_backend(CaseResult& result, const std::string& prefix, const std::string& from,
                                  const std::string& to, const std::string& reason) {
  std::vector<Check> skipped;
  for (const Check& check : result.checks) {
    const std::string& name = check.name;
    if (name.rfind(prefix, 0) != 0 || name.size() < from.size() || name.compare(name.size() - from.size(), from.size(), from) != 0) continue;
    skipped.push_back(skipped_check(name.substr(0, name.size() - from.size()) + to, reason));
  }
  result.checks.insert(result.checks.end(), skipped.begin(), skipped.end());
}

}  // namespace gt
