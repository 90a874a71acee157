// ComputeProgram and the #include expander: includes are expanded recursively, defines follow
// #version, and every error names the original file and line (a compile error inside an
// included file, a missing include, an include cycle). Test shaders are in tests/data/shaders/,
// loaded with ComputeProgram::load_from. The GPU tests share one context per suite; failing to
// create it is a failure, not a skip.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/gl_test.hpp"

#include "core/errors.hpp"
#include "gpu/buffer.hpp"
#include "gpu/context/context.hpp"
#include "gpu/shader_program.hpp"

namespace {

using testing::HasSubstr;
using testing::Not;

const std::filesystem::path test_shaders = std::filesystem::path(GT_TEST_DATA_DIR) / "shaders";

// The message of the std::runtime_error that `load` throws, or "" when it throws none.
template <class Load>
std::string error_message(Load load) {
  try {
    load();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

TEST(ExpandShader, PastesIncludesRecursivelyAndRemembersOrigins) {
  const auto shader = gt::expand_shader(test_shaders, "counting.comp", {"OFFSET=5"});
  EXPECT_THAT(shader.source, HasSubstr("uint nested_answer() { return 42u; }"));
  EXPECT_THAT(shader.source, HasSubstr("uint library_answer() { return nested_answer(); }"));
  EXPECT_THAT(shader.source, Not(HasSubstr("#include")));
  const auto lines = lines_of(shader.source);
  ASSERT_EQ(lines.size(), shader.origins.size());
  for (std::size_t index = 0; index < lines.size(); ++index) {
    if (lines[index] == "uint nested_answer() { return 42u; }") {
      EXPECT_EQ(shader.origins[index].file, "tests/data/shaders/lib/nested.glsl");
      EXPECT_EQ(shader.origins[index].line, 2);
    }
  }
}

TEST(ExpandShader, InsertsDefinesRightAfterVersion) {
  const auto shader = gt::expand_shader(test_shaders, "counting.comp", {"OFFSET=5", "FLAG"});
  const auto lines = lines_of(shader.source);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "#version 450");
  EXPECT_EQ(lines[1], "#define OFFSET 5");
  EXPECT_EQ(lines[2], "#define FLAG ");
  EXPECT_EQ(shader.origins[1].file, "<defines>");
  EXPECT_EQ(shader.origins[2].line, 2);
  EXPECT_EQ(shader.origins[3].file, "tests/data/shaders/counting.comp");
  EXPECT_EQ(shader.origins[3].line, 2);
}

TEST(ExpandShader, RejectsADefineThatIsNotAnIdentifier) {
  EXPECT_THROW(gt::expand_shader(test_shaders, "counting.comp", {"5X=1"}), std::invalid_argument);
}

TEST(ExpandShader, MissingIncludeNamesTheIncludingFileAndLine) {
  const auto message = error_message([] { gt::expand_shader(test_shaders, "missing_include.comp"); });
  EXPECT_THAT(message, HasSubstr("tests/data/shaders/missing_include.comp:4:"));
  EXPECT_THAT(message, HasSubstr("\"lib/does_not_exist.glsl\""));
}

TEST(ExpandShader, MissingShaderNamesItsPath) {
  const auto message = error_message([] { gt::expand_shader(test_shaders, "no_such_shader.comp"); });
  EXPECT_THAT(message, HasSubstr("tests/data/shaders/no_such_shader.comp"));
}

TEST(ExpandShader, IncludeCycleNamesTheChain) {
  const auto message = error_message([] { gt::expand_shader(test_shaders, "cycle.comp"); });
  EXPECT_THAT(message, HasSubstr("tests/data/shaders/lib/cycle_c.glsl:3:"));
  EXPECT_THAT(message, HasSubstr("cycle"));
  EXPECT_THAT(message, HasSubstr("cycle.comp -> tests/data/shaders/lib/cycle_b.glsl -> "));
}

TEST(LocateInfoLog, RewritesMesaAndNvidiaPrefixes) {
  gt::ExpandedShader shader;
  shader.origins = {{"a.comp", 1}, {"<defines>", 1}, {"lib/b.glsl", 7}};
  EXPECT_EQ(shader.locate_info_log("0:3(12): error: `x' undeclared"), "lib/b.glsl:7:12: error: `x' undeclared");
  EXPECT_EQ(shader.locate_info_log("0(3) : error C1008: undefined variable \"x\""),
            "lib/b.glsl:7: error C1008: undefined variable \"x\"");
  EXPECT_EQ(shader.locate_info_log("0:9(1): error: past the end"), "0:9(1): error: past the end");
  EXPECT_EQ(shader.locate_info_log("error: linking failed"), "error: linking failed");
}

class ComputeProgramTest : public gt::testing::GlTest {};

TEST_F(ComputeProgramTest, RunsWithIncludesDefinesAndRoundedUpGroups) {
  const auto program = gt::ComputeProgram::load_from(test_shaders, "counting.comp", {"OFFSET=5"});
  auto result = gt::StorageBuffer::from(std::vector<std::uint32_t>{0, 0});
  result.bind(0);
  program.dispatch(100, 30, 8, 8);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto values = result.download<std::uint32_t>(2);
  EXPECT_EQ(values[0], 47u);
  EXPECT_EQ(values[1], 13u * 4u * 64u);  // ceil(100 / 8) x ceil(30 / 8) groups of 8 x 8
}

TEST_F(ComputeProgramTest, CompileErrorNamesTheIncludedFileAndLine) {
  const auto message = error_message([] { gt::ComputeProgram::load_from(test_shaders, "compile_error.comp"); });
  EXPECT_THAT(message, HasSubstr("compiling tests/data/shaders/compile_error.comp failed"));
  EXPECT_THAT(message, HasSubstr("tests/data/shaders/lib/broken.glsl:5:"));
  EXPECT_THAT(message, HasSubstr("undeclared_name"));
}

TEST_F(ComputeProgramTest, DispatchRejectsALocalSizeTheShaderDoesNotDeclare) {
  const auto program = gt::ComputeProgram::load_from(test_shaders, "counting.comp", {"OFFSET=0"});
  EXPECT_THROW(program.dispatch(16, 16, 16, 16), std::invalid_argument);
}

TEST_F(ComputeProgramTest, MovedProgramKeepsItsId) {
  auto program = gt::ComputeProgram::load_from(test_shaders, "counting.comp", {"OFFSET=0"});
  const GLuint id = program.id();
  const gt::ComputeProgram moved = std::move(program);
  EXPECT_EQ(moved.id(), id);
  EXPECT_EQ(glIsProgram(id), GL_TRUE);
}

TEST_F(ComputeProgramTest, LoadsFromTheShaderTree) {
  const auto program = gt::ComputeProgram::load("test/rng_fill.comp");
  EXPECT_NE(program.uniform("rng_seed"), -1);
  EXPECT_EQ(program.uniform("no_such_uniform"), -1);
}

}  // namespace
