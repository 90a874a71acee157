// The pieces of issue 15's workflow that need no process: SHA-256, shard specs and assignment,
// the flaky outcome and the flake list, and report.json read back into a Report.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <numeric>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "compare/expectations.hpp"
#include "compare/report/report_read.hpp"
#include "compare/report/writers.hpp"
#include "compare/shards.hpp"
#include "core/errors.hpp"
#include "core/sha256.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using ::testing::HasSubstr;

// FIPS 180-2, appendix B.1 and B.2.
TEST(Sha256, MatchesThePublishedVectors) {
  EXPECT_EQ(gt::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(gt::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  const gt::testing::TemporaryFolder work("gt_sha");
  std::ofstream(work / "abc", std::ios::binary) << "abc";
  EXPECT_EQ(gt::sha256_file_hex(work / "abc"), gt::sha256_hex("abc"));
  EXPECT_THROW(gt::sha256_file_hex(work / "absent"), gt::InputError);
}

TEST(Shards, SpecsOutsideOneToNAreRefused) {
  EXPECT_EQ(gt::parse_shard("2/3").index, 2);
  EXPECT_EQ(gt::parse_shard("2/3").count, 3);
  for (const char* bad : {"3/2", "0/0", "0/3", "1/0", "-1/3", "1/", "/3", "2", "a/b", "1/3/5", "1/10001"}) {
    EXPECT_THROW(gt::parse_shard(bad), gt::InputError) << bad;
  }
}

// Each engine's variables; the test sets one engine's at a time.
class ShardEnvironment : public ::testing::Test {
 protected:
  void SetUp() override { clear(); }
  void TearDown() override { clear(); }
  static void clear() {
    for (const char* name : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN",
                             "SLURM_ARRAY_TASK_STEP", "CI_NODE_INDEX", "CI_NODE_TOTAL", "JOB_COMPLETION_INDEX",
                             "GROUNDTRUTH_SHARD_COUNT"}) {
      unsetenv(name);
    }
  }
};

TEST_F(ShardEnvironment, AutoReadsSlurmGitLabAndKubernetes) {
  EXPECT_THROW(gt::parse_shard("auto"), gt::InputError);
  setenv("SLURM_ARRAY_TASK_ID", "7", 1);  // --array=5-9:2 -> tasks 5, 7, 9
  setenv("SLURM_ARRAY_TASK_COUNT", "3", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "5", 1);
  setenv("SLURM_ARRAY_TASK_STEP", "2", 1);
  EXPECT_EQ(gt::parse_shard("auto").index, 2);
  EXPECT_EQ(gt::parse_shard("auto").count, 3);
  setenv("SLURM_ARRAY_TASK_ID", "8", 1);  // not on the array's step
  EXPECT_THROW(gt::parse_shard("auto"), gt::InputError);
  clear();
  setenv("CI_NODE_INDEX", "4", 1);
  setenv("CI_NODE_TOTAL", "4", 1);
  EXPECT_EQ(gt::parse_shard("auto").index, 4);
  setenv("CI_NODE_INDEX", "5", 1);
  EXPECT_THROW(gt::parse_shard("auto"), gt::InputError);
  clear();
  setenv("JOB_COMPLETION_INDEX", "0", 1);  // 0-based
  try {
    gt::parse_shard("auto");
    ADD_FAILURE() << "a Kubernetes index without a count must be refused";
  } catch (const gt::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("GROUNDTRUTH_SHARD_COUNT"));
  }
  setenv("GROUNDTRUTH_SHARD_COUNT", "4", 1);
  EXPECT_EQ(gt::parse_shard("auto").index, 1);
}

std::vector<std::string> names(int count, const std::string& prefix = "case.") {
  std::vector<std::string> out;
  for (int index = 0; index < count; ++index) out.push_back(prefix + std::to_string(index));
  return out;
}

// Without a baseline a case's shard depends on its name only: adding cases moves none of the others.
TEST(Shards, HashAssignmentIsStableWhenCasesAreAdded) {
  const auto before = gt::assign_shards(names(40), 4, nullptr);
  auto more = names(40);
  const auto extra = names(10, "new.");
  more.insert(more.begin() + 7, extra.begin(), extra.end());
  const auto after = gt::assign_shards(more, 4, nullptr);
  for (int index = 0; index < 40; ++index) {
    const auto position = std::find(more.begin(), more.end(), names(40)[index]) - more.begin();
    EXPECT_EQ(before[index], after[position]) << names(40)[index];
  }
  std::vector<int> per_shard(5, 0);
  for (int shard : before) ++per_shard.at(shard);
  for (int shard = 1; shard <= 4; ++shard) EXPECT_GT(per_shard[shard], 0) << "40 names leave no shard empty";
}

// With a baseline's case times, longest first to the least-loaded shard: one 10 s case and ten
// 1 s cases over two shards give 10 s and 10 s, which hashing cannot promise.
TEST(Shards, BaselineTimesBalanceTheShards) {
  nlohmann::json baseline = {{"cases", nlohmann::json::array()}};
  const auto cases = names(11);
  for (int index = 0; index < 11; ++index) {
    baseline["cases"].push_back({{"name", cases[index]}, {"seconds", index == 3 ? 10.0 : 1.0}});
  }
  const auto shard = gt::assign_shards(cases, 2, baseline);
  std::vector<double> load(3, 0.0);
  for (int index = 0; index < 11; ++index) load.at(shard[index]) += index == 3 ? 10.0 : 1.0;
  EXPECT_DOUBLE_EQ(load[1], 10.0);
  EXPECT_DOUBLE_EQ(load[2], 10.0);
}

gt::CaseResult flaky_case(const std::string& failing_check) {
  gt::CaseResult result;
  result.name = "erosion.pipe.flux.cone";
  result.checks = {{.name = "mass.relative_drift.gpu", .value = 1e-9, .threshold = 1e-6}};
  result.earlier_attempts = {{gt::Outcome::fail, "", {failing_check + " = 0.1 (bound 1e-06)"}}};
  result.status = gt::case_outcome(result);
  return result;
}

std::vector<gt::Expectation> flake_list(const std::string& text) {
  const gt::testing::TemporaryFolder work("gt_flakes");
  std::ofstream(work / "flakes.txt") << text;
  gt::CaseSpec spec;
  spec.name = "erosion.pipe.flux.cone";
  return gt::load_expectations(work / "flakes.txt", {spec}, gt::ExpectationFile::flakes_only);
}

// Failed, then passed: flaky, never pass. Known when the flake list names its failing check, and
// then it does not fail the run; a new flake does.
TEST(Flakes, AFlakyCaseFailsTheRunUnlessListed) {
  auto result = flaky_case("mass.relative_drift.gpu");
  EXPECT_EQ(result.status, gt::Outcome::flaky);
  gt::Report report;
  report.cases = {result};
  const auto listed = flake_list("erosion.pipe.* mass.* flaky the GPU's atomics race (issue 99)\n");
  EXPECT_TRUE(gt::apply_expectations(listed, report).empty());
  EXPECT_EQ(report.cases[0].known_flake, "the GPU's atomics race (issue 99)");
  EXPECT_FALSE(gt::run_failed(report));

  report.cases = {flaky_case("mesh.closed.gpu")};  // a check the list does not name
  EXPECT_TRUE(gt::apply_expectations(listed, report).empty());
  EXPECT_TRUE(report.cases[0].known_flake.empty());
  EXPECT_TRUE(gt::run_failed(report));
  EXPECT_TRUE(gt::named_as_flaky(listed, "erosion.pipe.flux.cone"));
  EXPECT_FALSE(gt::named_as_flaky(listed, "noise.simplex3.walk"));
}

TEST(Flakes, AFailingLastAttemptIsAFailureNotAFlake) {
  auto result = flaky_case("mass.relative_drift.gpu");
  result.checks[0].status = gt::Outcome::fail;
  EXPECT_EQ(gt::case_outcome(result), gt::Outcome::fail);
}

// report.json read back gives the same report.json: what workers and merge rely on.
TEST(ReportRead, RoundTripsCasesEnvironmentAndShard) {
  gt::Report report;
  report.environment.gl_renderer = "llvmpipe";
  report.environment.calibration_ms = 3.5;
  report.environment.git_revision = std::string(40, 'a');
  report.environment.git_dirty = true;
  report.environment.shaders = {{"gpu/shaders/x.comp", std::string(64, 'b')}};
  report.environment.data = {{"/data/x.npz", std::string(64, 'c')}};
  gt::CaseResult result = flaky_case("mass.relative_drift.gpu");
  result.checks.push_back({.name = "values.nan", .value = std::numeric_limits<double>::quiet_NaN(),
                           .status = gt::Outcome::fail, .detail = "not a number"});
  result.checks.push_back({.name = "values.inf", .value = std::numeric_limits<double>::infinity(),
                           .threshold = 1.0, .loose_threshold = 2.0, .status = gt::Outcome::fail,
                           .expected = gt::Outcome::fail, .expectation = "known"});
  result.timings.cpu_ms = 1.25;
  result.artifacts = {{"erosion.pipe.flux.cone/gpu.png", "image", "the GPU's result"}};
  result.descriptors = {{"hypsometry", {{"integral", 0.5}}}};
  result.seconds = 2.5;
  result.known_flake = "a reason";
  result.status = gt::case_outcome(result);
  report.cases = {result};
  report.shard = gt::ShardInfo{2, 3, {"a", "b"}, "base.json"};
  const auto written = gt::report_to_json(report);
  const auto read = gt::report_from_json(written);
  EXPECT_EQ(gt::report_to_json(read), written);
  EXPECT_TRUE(std::isnan(read.cases[0].checks[1].value));
  EXPECT_EQ(read.cases[0].artifacts[0].caption, "the GPU's result");
}

TEST(ReportRead, AnUnknownOutcomeNamesTheCase) {
  nlohmann::json document = {{"schema", 1}, {"cases", {{{"name", "a.b"}, {"status", "great"}}}}};
  try {
    gt::report_from_json(document);
    ADD_FAILURE();
  } catch (const gt::InputError& error) {
    EXPECT_THAT(error.what(), HasSubstr("case a.b"));
  }
}

}  // namespace
