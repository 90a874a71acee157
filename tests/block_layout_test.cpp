// GlProgram::check_block: a C++ mirror of a GLSL block checked against the linked program by
// program interface queries. The test shader tests/data/shaders/block_layout.comp declares a
// std140 uniform block, a std430 storage block and a packed block; the mirrors below state the
// right layouts, and each failure case changes one thing. Every real GPU twin checks its own
// mirrors when it loads its programs, so the GPU tests of the twins cover those.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/gl_test.hpp"

#include "gpu/shader_program.hpp"

namespace {

using testing::AllOf;
using testing::HasSubstr;

const std::filesystem::path test_shaders = std::filesystem::path(GT_TEST_DATA_DIR) / "shaders";

// Mirror of `Pair` (16 bytes in std140 and std430).
struct Pair {
  float first;
  float padding;
  float second[2];
};

// Mirror of `LayoutUniforms` (std140).
struct LayoutUniforms {
  float scale;
  float padding0[3];
  float direction[3];
  float padding1;
  struct {
    float value;
    float padding[3];
  } weights[3];  // std140: an array element takes 16 bytes
  Pair pair;
  std::int32_t count;
  float unread;
  float tail_padding[2];
};

// Mirror of `LayoutStorage` (std430) with one record.
struct LayoutStorage {
  float factor;
  float values[3];
  float normal[3];
  std::uint32_t flags;
  Pair records[1];
};

const gt::BlockLayout pair_layout = {{"first", offsetof(Pair, first)}, {"second", offsetof(Pair, second)}};

gt::BlockLayout uniforms_layout() {
  gt::BlockLayout layout = {{"scale", offsetof(LayoutUniforms, scale)},
                            {"direction", offsetof(LayoutUniforms, direction)},
                            {"weights", offsetof(LayoutUniforms, weights)},
                            {"count", offsetof(LayoutUniforms, count)},
                            {"unread", offsetof(LayoutUniforms, unread)}};
  for (auto& member : gt::nested_layout("pair.", offsetof(LayoutUniforms, pair), pair_layout)) layout.push_back(member);
  return layout;
}

gt::BlockLayout storage_layout() {
  gt::BlockLayout layout = {{"factor", offsetof(LayoutStorage, factor)},
                            {"values[0]", offsetof(LayoutStorage, values)},
                            {"normal", offsetof(LayoutStorage, normal)},
                            {"flags", offsetof(LayoutStorage, flags)}};
  for (auto& member : gt::nested_layout("records[0].", offsetof(LayoutStorage, records), pair_layout)) {
    layout.push_back(member);
  }
  return layout;
}

// The message of the std::runtime_error that `check` throws, or "" when it throws none.
template <class Check>
std::string error_message(Check check) {
  try {
    check();
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "";
}

class BlockLayoutCheck : public gt::testing::GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    program_.emplace(gt::ComputeProgram::load_from(test_shaders, "block_layout.comp"));
  }
  const gt::ComputeProgram& program() const { return *program_; }

 private:
  std::optional<gt::ComputeProgram> program_;
};

TEST_F(BlockLayoutCheck, RightMirrorsPass) {
  EXPECT_NO_THROW(program().check_block("LayoutUniforms", sizeof(LayoutUniforms), uniforms_layout()));
  EXPECT_NO_THROW(program().check_block("LayoutStorage", sizeof(LayoutStorage), storage_layout()));
}

TEST_F(BlockLayoutCheck, ArrayMembersAreNamedWithOrWithoutTheirFirstIndex) {
  EXPECT_NO_THROW(program().check_block("LayoutUniforms", sizeof(LayoutUniforms),
                                        {{"weights", offsetof(LayoutUniforms, weights)},
                                         {"weights[0]", offsetof(LayoutUniforms, weights)}}));
  EXPECT_NO_THROW(program().check_block("LayoutStorage", sizeof(LayoutStorage),
                                        {{"values", offsetof(LayoutStorage, values)},
                                         {"values[0]", offsetof(LayoutStorage, values)}}));
}

TEST_F(BlockLayoutCheck, WrongOffsetNamesTheMemberAndBothOffsets) {
  auto layout = uniforms_layout();
  for (auto& member : layout) {
    if (member.name == "count") member.offset = 100;  // the GLSL block has `count` at 96
  }
  const auto message = error_message([&] { program().check_block("LayoutUniforms", sizeof(LayoutUniforms), layout); });
  EXPECT_THAT(message, AllOf(HasSubstr("tests/data/shaders/block_layout.comp"), HasSubstr("block LayoutUniforms"),
                             HasSubstr("member count: C++ offset 100, GLSL offset 96")));
  EXPECT_THAT(message, testing::Not(HasSubstr("member scale")));
}

TEST_F(BlockLayoutCheck, WrongOffsetInAStorageBlockRecord) {
  auto layout = storage_layout();
  for (auto& member : layout) {
    if (member.name == "records[0].second") member.offset = 36;  // std430 aligns the vec2 to 8: 40
  }
  const auto message = error_message([&] { program().check_block("LayoutStorage", sizeof(LayoutStorage), layout); });
  EXPECT_THAT(message, AllOf(HasSubstr("storage block LayoutStorage"),
                             HasSubstr("member records[0].second: C++ offset 36, GLSL offset 40")));
}

TEST_F(BlockLayoutCheck, UnknownMemberIsNamed) {
  const auto message = error_message([&] {
    program().check_block("LayoutUniforms", sizeof(LayoutUniforms),
                          {{"scale", 0}, {"no_such_member", 8}, {"pair.no_such_field", 84}});
  });
  EXPECT_THAT(message, AllOf(HasSubstr("block LayoutUniforms"),
                             HasSubstr("member no_such_member: C++ offset 8, no such member in the GLSL block"),
                             HasSubstr("member pair.no_such_field: C++ offset 84, no such member")));
}

TEST_F(BlockLayoutCheck, MemberOfAnotherBlockIsAMismatch) {
  // read_value is an active uniform of PackedUniforms; factor a member of the storage block.
  const auto message = error_message([&] {
    program().check_block("LayoutUniforms", sizeof(LayoutUniforms), {{"read_value", 0}, {"factor", 0}});
  });
  EXPECT_THAT(message, AllOf(HasSubstr("member read_value: C++ offset 0, but in GLSL it is not a member of this block"),
                             HasSubstr("member factor: C++ offset 0, no such member in the GLSL block")));
}

TEST_F(BlockLayoutCheck, WrongSizeIsAMismatch) {
  const auto message = error_message([&] { program().check_block("LayoutUniforms", 104, uniforms_layout()); });
  EXPECT_THAT(message, AllOf(HasSubstr("block LayoutUniforms"), HasSubstr("block size: C++ 104 bytes, GLSL 112 bytes")));
  // A storage block ending in an unsized array counts one element.
  const auto storage_message =
      error_message([&] { program().check_block("LayoutStorage", offsetof(LayoutStorage, records), {}); });
  EXPECT_THAT(storage_message, HasSubstr("block size: C++ 32 bytes, GLSL 48 bytes"));
}

TEST_F(BlockLayoutCheck, MissingBlockIsAnError) {
  const auto message = error_message([&] { program().check_block("NoSuchBlock", 16, {{"scale", 0}}); });
  EXPECT_THAT(message, AllOf(HasSubstr("tests/data/shaders/block_layout.comp"), HasSubstr("NoSuchBlock"),
                             HasSubstr("no active uniform or shader storage block")));
}

TEST_F(BlockLayoutCheck, EveryMismatchIsListed) {
  const auto message = error_message([&] {
    program().check_block("LayoutUniforms", 96, {{"scale", 4}, {"direction", 12}, {"count", 96}});
  });
  EXPECT_THAT(message, AllOf(HasSubstr("block size: C++ 96 bytes, GLSL 112 bytes"),
                             HasSubstr("member scale: C++ offset 4, GLSL offset 0"),
                             HasSubstr("member direction: C++ offset 12, GLSL offset 16")));
  EXPECT_THAT(message, testing::Not(HasSubstr("member count")));
}

// A packed block's unread member is not active (Mesa drops it); a declared but inactive member is
// skipped rather than reported, while a name the block does not declare still is.
TEST_F(BlockLayoutCheck, InactiveMemberIsSkipped) {
  const GLuint index = glGetProgramResourceIndex(program().id(), GL_UNIFORM, "dropped_value");
  if (index != GL_INVALID_INDEX) GTEST_SKIP() << "this driver keeps the packed block's unread member active";
  GLint size = 0;
  const GLenum property = GL_BUFFER_DATA_SIZE;
  glGetProgramResourceiv(program().id(), GL_UNIFORM_BLOCK,
                         glGetProgramResourceIndex(program().id(), GL_UNIFORM_BLOCK, "PackedUniforms"), 1, &property, 1,
                         nullptr, &size);
  EXPECT_NO_THROW(program().check_block("PackedUniforms", static_cast<std::size_t>(size),
                                        {{"read_value", 0}, {"dropped_value", 4}}));
  EXPECT_THAT(error_message([&] {
                program().check_block("PackedUniforms", static_cast<std::size_t>(size), {{"read_value", 0}, {"gone", 4}});
              }),
              HasSubstr("member gone: C++ offset 4, no such member"));
}

}  // namespace
