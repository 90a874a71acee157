// GlContext: both headless backends give a current OpenGL 4.5 core context on this machine
// (llvmpipe at least), and backend names are parsed strictly. A context that cannot be created
// is a failure here, not a skip: llvmpipe is always installed where these tests run.
#include <memory>
#include <stdexcept>
#include <utility>

#include <glad/gl.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "gpu/context/context.hpp"

namespace {

using testing::AnyOf;
using testing::Eq;

std::pair<GLint, GLint> current_gl_version() {
  GLint major = 0;
  GLint minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  return {major, minor};
}

void expect_core_45_context(gt::GlBackend backend) {
  std::unique_ptr<gt::GlContext> context;
  try {
    context = gt::GlContext::create(backend);
  } catch (const gt::GpuUnavailable& unavailable) {
    FAIL() << "no GL context: " << unavailable.what();
  }
  EXPECT_GE(current_gl_version(), std::make_pair(4, 5));
  EXPECT_FALSE(context->info().renderer.empty());
  EXPECT_FALSE(context->info().version.empty());
  EXPECT_FALSE(context->info().vendor.empty());
  testing::Test::RecordProperty("renderer", context->info().renderer);
  testing::Test::RecordProperty("platform", context->info().platform);
}

TEST(ParseGlBackend, AcceptsTheTwoBackendNames) {
  EXPECT_EQ(gt::parse_gl_backend("egl"), gt::GlBackend::egl);
  EXPECT_EQ(gt::parse_gl_backend("osmesa"), gt::GlBackend::osmesa);
}

TEST(ParseGlBackend, RejectsOtherNames) {
  EXPECT_THROW(gt::parse_gl_backend("vulkan"), gt::InputError);
  EXPECT_THROW(gt::parse_gl_backend("EGL"), gt::InputError);
  EXPECT_THROW(gt::parse_gl_backend(""), gt::InputError);
}

TEST(GlContext, EglGivesCore45) {
  expect_core_45_context(gt::GlBackend::egl);
}

// The driver turns a GL error during a case into that case's `error`: the context must report
// each error once, from the debug output or glGetError, and nothing when there was none.
TEST(GlContext, ErrorsAreReportedOnceEach) {
  const auto context = gt::GlContext::create(gt::GlBackend::egl);
  EXPECT_TRUE(context->take_errors().empty());
  glBindBuffer(GL_ARRAY_BUFFER, 0x7fff1234u);  // a name glGenBuffers never returned: GL_INVALID_OPERATION
  const auto errors = context->take_errors();
  ASSERT_FALSE(errors.empty());
  EXPECT_TRUE(context->take_errors().empty());
}

TEST(GlContext, EglNamesItsPlatform) {
  const auto context = gt::GlContext::create(gt::GlBackend::egl);
  EXPECT_THAT(context->info().platform, AnyOf(Eq("egl-device"), Eq("egl-surfaceless")));
}

TEST(GlContext, OsMesaGivesCore45) {
  expect_core_45_context(gt::GlBackend::osmesa);
}

TEST(GlContext, OsMesaNamesItsPlatform) {
  const auto context = gt::GlContext::create(gt::GlBackend::osmesa);
  EXPECT_EQ(context->info().platform, "osmesa");
}

TEST(GlContext, GlErrorsReachStderr) {
  const auto context = gt::GlContext::create(gt::GlBackend::egl);
  testing::internal::CaptureStderr();
  glEnable(GL_TEXTURE_1D);  // not a capability in the core profile: GL_INVALID_ENUM
  const std::string logged = testing::internal::GetCapturedStderr();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_THAT(logged, testing::StartsWith("[gl] error"));
}

TEST(GlContext, OnlyOneContextLivesAtATime) {
  const auto context = gt::GlContext::create(gt::GlBackend::osmesa);
  EXPECT_THROW(gt::GlContext::create(gt::GlBackend::egl), std::logic_error);
}

TEST(GlContext, BackendsCanFollowEachOther) {
  for (const auto backend : {gt::GlBackend::egl, gt::GlBackend::osmesa, gt::GlBackend::egl}) {
    const auto context = gt::GlContext::create(backend);
    EXPECT_GE(current_gl_version(), std::make_pair(4, 5));
  }
}

}  // namespace
