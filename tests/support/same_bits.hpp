// Bit-for-bit comparison of a twin's arrays (the layered ground's GPU tests): every entry of
// `actual` must have the bytes of `expected`'s; a failure names the array, the moment, how many
// entries differ and the first of them. And the premise of those tests' error model: no float is
// subnormal (a GPU may flush those to zero).
#pragma once

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace gt::testing {

template <class T>
void expect_same_bits(const char* name, const std::vector<T>& expected, const std::vector<T>& actual,
                      const std::string& when) {
  ASSERT_EQ(expected.size(), actual.size()) << when << ": " << name;
  std::size_t differing = 0, first = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    if (std::memcmp(&expected[i], &actual[i], sizeof(T)) == 0) continue;
    if (differing++ == 0) first = i;
  }
  EXPECT_EQ(differing, 0u) << when << ": " << name << " differs in " << differing << " entries, first at " << first
                           << " (reference " << expected[first] << ", GPU " << actual[first] << ")";
}

inline void expect_no_subnormals(const char* name, const std::vector<float>& values, const std::string& when) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    ASSERT_TRUE(values[i] == 0.0f || std::abs(values[i]) >= std::numeric_limits<float>::min())
        << when << ": " << name << "[" << i << "] = " << values[i];
  }
}

}  // namespace gt::testing
