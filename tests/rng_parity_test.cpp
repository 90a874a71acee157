// The counter-based RNG gives the same bits on the CPU (core/rng.hpp) and the GPU
// (gpu/shaders/common/rng.glsl, through gpu/shaders/test/rng_fill.comp), and the CPU side has the
// properties the algorithms rely on. The GPU suite creates one EGL context; failing to create it
// is a failure, not a skip.
#include <cstdint>
#include <cstring>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/support/gl_test.hpp"

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "gpu/buffer.hpp"
#include "gpu/context/context.hpp"
#include "gpu/shader_program.hpp"

namespace {

constexpr std::uint32_t cell_count = 65536;

struct Counters {
  std::uint32_t seed, step, stream;
};

void PrintTo(const Counters& counters, std::ostream* out) {
  *out << "seed " << counters.seed << ", step " << counters.step << ", stream " << counters.stream;
}

std::uint32_t float_bits(float value) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

TEST(Rng, MatchesAnIndependentLowbias32) {
  // Values from a separate Python implementation of lowbias32 and of the counter chain.
  EXPECT_EQ(gt::hash32(0u), 0u);
  EXPECT_EQ(gt::hash32(1u), 0x688990c0u);
  EXPECT_EQ(gt::hash32(0xdeadbeefu), 0xe628c683u);
  EXPECT_EQ(gt::hash32(0xffffffffu), 0x6768824au);
  EXPECT_EQ(gt::random_u32(7, 100, 3, 0), 0x8014900fu);
  EXPECT_EQ(gt::random_u32(1, 2, 3, 4), 0x934addd8u);
}

TEST(Rng, EveryCounterChangesTheNumber) {
  const std::uint32_t base = gt::random_u32(7, 100, 3, 0);
  EXPECT_NE(gt::random_u32(8, 100, 3, 0), base);
  EXPECT_NE(gt::random_u32(7, 101, 3, 0), base);
  EXPECT_NE(gt::random_u32(7, 100, 4, 0), base);
  EXPECT_NE(gt::random_u32(7, 100, 3, 1), base);
}

TEST(Rng, StreamsAreDistinctSequences) {
  std::size_t equal = 0;
  for (std::uint32_t cell = 0; cell < cell_count; ++cell) {
    equal += gt::random_u32(1, cell, 0, 0) == gt::random_u32(1, cell, 0, 1) ? 1 : 0;
  }
  EXPECT_LE(equal, 2u);  // chance agreement is about 65536 / 2^32 per pair
}

TEST(Rng, Uniform01StaysInTheHalfOpenUnitInterval) {
  EXPECT_EQ(gt::uniform01(0u), 0.0f);
  EXPECT_LT(gt::uniform01(0xffffffffu), 1.0f);
  EXPECT_EQ(gt::uniform01(0xffffffffu), 1.0f - 1.0f / 16777216.0f);
  double sum = 0.0;
  for (std::uint32_t cell = 0; cell < cell_count; ++cell) {
    const float value = gt::uniform01(gt::random_u32(3, cell, 0, 0));
    ASSERT_GE(value, 0.0f);
    ASSERT_LT(value, 1.0f);
    sum += value;
  }
  EXPECT_NEAR(sum / cell_count, 0.5, 0.01);
}

class RngParity : public gt::testing::GlTestWithParam<Counters> {};

TEST_P(RngParity, GpuDrawsTheSameBitsAsTheCpu) {
  const Counters counters = GetParam();
  const auto program = gt::ComputeProgram::load("test/rng_fill.comp");
  gt::StorageBuffer bits(cell_count * sizeof(std::uint32_t));
  gt::StorageBuffer uniforms(cell_count * sizeof(float));
  bits.bind(0);
  uniforms.bind(1);
  program.use();
  glUniform1ui(program.uniform("rng_seed"), counters.seed);
  glUniform1ui(program.uniform("rng_step"), counters.step);
  glUniform1ui(program.uniform("rng_stream"), counters.stream);
  glUniform1ui(program.uniform("count"), cell_count);
  program.dispatch(cell_count, 1, 64, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  const auto gpu_bits = bits.download<std::uint32_t>(cell_count);
  const auto gpu_uniforms = uniforms.download<float>(cell_count);
  std::size_t mismatches = 0;
  for (std::uint32_t cell = 0; cell < cell_count; ++cell) {
    const std::uint32_t expected = gt::random_u32(counters.seed, cell, counters.step, counters.stream);
    const bool same = gpu_bits[cell] == expected &&
                      float_bits(gpu_uniforms[cell]) == float_bits(gt::uniform01(expected));
    if (!same && mismatches++ < 5) {
      ADD_FAILURE() << "cell " << cell << ": gpu " << gpu_bits[cell] << " / " << gpu_uniforms[cell] << ", cpu "
                    << expected << " / " << gt::uniform01(expected);
    }
  }
  EXPECT_EQ(mismatches, 0u);
}

INSTANTIATE_TEST_SUITE_P(Counters, RngParity,
                         testing::Values(Counters{0, 0, 0}, Counters{1, 0, 0}, Counters{0x9e3779b9u, 17, 3},
                                         Counters{0xffffffffu, 0xffffffffu, 0xffffffffu}, Counters{42, 1000, 7}));

}  // namespace
