// Compensated (Neumaier) summation in double, used by every mass ledger so that the ledger's own
// rounding (about one unit in the last place of the total) stays far below what it measures.
#pragma once

#include <cmath>

namespace gt {

class CompensatedSum {
 public:
  void add(double value) {
    const double t = sum_ + value;
    if (std::abs(sum_) >= std::abs(value)) {
      compensation_ += (sum_ - t) + value;
    } else {
      compensation_ += (value - t) + sum_;
    }
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

}  // namespace gt
