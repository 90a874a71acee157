// A test fixture with one EGL context per suite. On this project's machines llvmpipe is always
// there, so failing to make a context is a test failure, not a skip.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "gpu/context/context.hpp"

namespace gt::testing {

class GlTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    try {
      context = GlContext::create(GlBackend::egl);
    } catch (const GpuUnavailable& unavailable) {
      context_failure = unavailable.what();
    }
  }
  static void TearDownTestSuite() { context.reset(); }
  void SetUp() override { ASSERT_TRUE(context) << "no GL context: " << context_failure; }

  static inline std::unique_ptr<GlContext> context;
  static inline std::string context_failure;
};

template <class Param>
class GlTestWithParam : public GlTest, public ::testing::WithParamInterface<Param> {};

}  // namespace gt::testing
