// Issue 18's memory promise: every algorithm states what a case of it needs before it runs
// (Algorithm::memory, core/memory.hpp), and a real run stays within that estimate plus the stated
// margin, the process's fixed cost.
#include <sys/resource.h>

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "compare/inputs.hpp"
#include "core/params.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/sanitizers.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using nlohmann::json;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";

// The fixed cost outside every estimate: code, the GL driver and LLVM's JIT under llvmpipe, the
// bundled case suite. Measured 180 to 215 MiB for runs of a few cells; 256 MiB is the margin the
// README's exit-status section states.
constexpr double fixed_cost_margin = 256.0 * 1024 * 1024;

json cone_of_side(int side) {
  return {{"generator", "cone"}, {"width", side}, {"height", side}, {"noise", 0.5}};
}

gt::LoadedInput input_for(const gt::Algorithm& algorithm) {
  if (algorithm.ad_hoc_input == gt::AdHocInput::mesh) {
    gt::LoadedInput input;
    input.mesh = gt::Mesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}, {}};
    return input;
  }
  if (algorithm.ad_hoc_input == gt::AdHocInput::heightmap) return gt::load_input(cone_of_side(16), nullptr, {});
  return {};
}

TEST(MemoryEstimates, EveryAlgorithmStatesWhatACaseNeeds) {
  for (const gt::Algorithm& algorithm : gt::algorithms()) {
    ASSERT_TRUE(static_cast<bool>(algorithm.memory)) << algorithm.name << " has no memory estimate";
    json given = json::object();
    if (algorithm.name == "cave.endless") given["solid"] = false;
    const json resolved = gt::resolve_params(algorithm.name, *algorithm.params, given);
    const gt::MemoryEstimate estimate = algorithm.memory(resolved, input_for(algorithm));
    EXPECT_GT(estimate.bytes, 0.0) << algorithm.name;
    EXPECT_FALSE(estimate.basis.empty()) << algorithm.name;
  }
}

// Peak resident memory of the children this test process has waited for: one, as ctest runs each
// test in a process of its own (gtest_discover_tests).
double peak_of_children_bytes() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

struct MeasuredRun {
  const char* algorithm;
  int side;
  json params;
  const char* variant = nullptr;  // appended to the test's name when an algorithm is measured twice
};

class PeakMemory : public ::testing::TestWithParam<MeasuredRun> {};

TEST_P(PeakMemory, StaysWithinTheEstimatePlusTheFixedCost) {
  if (gt::testing::under_address_sanitizer) {
    GTEST_SKIP() << "AddressSanitizer's shadow memory and quarantine inflate the resident size";
  }
  const MeasuredRun& measured = GetParam();
  const gt::Algorithm& algorithm = gt::find_algorithm(measured.algorithm);
  const json cone = cone_of_side(measured.side);
  const gt::testing::TemporaryFolder work("gt_peak_memory");
  std::ofstream(work / "peak.json") << json::array(
      {{{"name", "mine.peak"}, {"algorithm", measured.algorithm}, {"params", measured.params}, {"input", cone}}});
  const auto run = gt::testing::run_program(groundtruth,
                                            {"run", "mine.peak", "--cases", (work / "peak.json").string(), "--quiet",
                                             "--cpu-reps", "1", "--gpu-reps", "1", "--out", (work / "out").string()},
                                            work.path());
  ASSERT_EQ(run.status, 0) << run;
  const json resolved = gt::resolve_params(algorithm.name, *algorithm.params, measured.params);
  const gt::MemoryEstimate estimate = algorithm.memory(resolved, gt::load_input(cone, nullptr, {}));
  EXPECT_LE(peak_of_children_bytes(), estimate.bytes + fixed_cost_margin)
      << measured.algorithm << ": estimate " << estimate.basis;
}

INSTANTIATE_TEST_SUITE_P(FieldTwins, PeakMemory,
                         ::testing::Values(MeasuredRun{"erosion.thermal", 768, {{"iterations", 16}}},
                                           MeasuredRun{"erosion.pipe", 384, {{"steps", 16}, {"checkpoints", 16}}},
                                           MeasuredRun{"noise.fbm", 1024, json::object()},
                                           // Droplets: one short iteration in batch ordering (no race
                                           // statistics), large enough that the estimate dominates.
                                           MeasuredRun{"erosion.particle", 768,
                                                       {{"iterations", 1}, {"lifetime", 5}, {"ordering", "batch"}}},
                                           MeasuredRun{"erosion.beyer", 768,
                                                       {{"iterations", 1}, {"lifetime", 5}, {"ordering", "batch"}}},
                                           MeasuredRun{"erosion.layered", 384, {{"steps", 4}}},
                                           MeasuredRun{"erosion.layered", 384, {{"steps", 4}, {"rain_rate", 0.01}}, "water"}),
                         [](const ::testing::TestParamInfo<MeasuredRun>& info) {
                           std::string name = info.param.algorithm;
                           for (char& c : name) c = (c == '.') ? '_' : c;
                           return info.param.variant ? name + "_" + info.param.variant : name;
                         });

}  // namespace
