// diff-reports (issue 15): what changed between two report.json files, check by check.
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/report_diff.hpp"
#include "core/errors.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using json = nlohmann::json;
using ::testing::HasSubstr;

json check(const std::string& name, double value, const std::string& status, std::optional<double> threshold = {}) {
  json out = {{"name", name}, {"value", value}, {"status", status}};
  if (threshold) out["threshold"] = *threshold;
  return out;
}

json report(double calibration_ms, std::vector<json> cases) {
  return {{"schema", 1}, {"environment", {{"calibration_ms", calibration_ms}}}, {"cases", cases}};
}

json a_case(const std::string& name, const std::string& status, std::vector<json> checks, double cpu_ms = 100.0) {
  return {{"name", name}, {"status", status}, {"checks", checks}, {"timings", {{"cpu_ms", cpu_ms}}}};
}

std::vector<std::string> where(const std::vector<gt::ReportDiff::Change>& changes) {
  std::vector<std::string> out;
  for (const auto& change : changes) out.push_back(change.where);
  return out;
}

TEST(ReportDiff, SortsEveryChangeIntoItsList) {
  const json base = report(10.0, {a_case("c", "pass",
                                         {check("mass.drift.cpu", 1e-13, "pass", 1e-12),
                                          check("parity.max.gpu", 1e-7, "pass", 1e-5),
                                          check("parity.rms.gpu", 1e-7, "pass", 1e-5),
                                          check("mass.drift.gpu", 2e-6, "fail", 1e-6),
                                          check("image.psnr", 1.0, "pass"), check("gone", 0.0, "pass")})});
  const json next = report(10.0, {a_case("c", "fail",
                                         {check("mass.drift.cpu", 1.0000000000000001e-13 * 1.5, "pass", 1e-12),
                                          check("parity.max.gpu", 1e-7 + 0.5e-7, "pass", 1e-5),  // 0.5 % of the bound
                                          check("parity.rms.gpu", 3e-5, "fail", 1e-5),
                                          check("mass.drift.gpu", 1e-7, "pass", 1e-6),
                                          check("image.psnr", 1.0, "warn"), check("new", 0.0, "pass")})});
  const auto diff = gt::diff_reports(base, next);
  EXPECT_EQ(diff.common_cases, 1);
  EXPECT_EQ(where(diff.regressions), (std::vector<std::string>{"c: parity.rms.gpu", "c"}));
  EXPECT_EQ(where(diff.fixes), std::vector<std::string>{"c: mass.drift.gpu"});
  EXPECT_EQ(where(diff.outcome_changes), std::vector<std::string>{"c: image.psnr"});
  EXPECT_EQ(where(diff.added), std::vector<std::string>{"c: new"});
  EXPECT_EQ(where(diff.removed), std::vector<std::string>{"c: gone"});
  // The double reference must be bit for bit the same; a GPU value within 1 % of its bound has not moved.
  EXPECT_EQ(where(diff.moved), std::vector<std::string>{"c: mass.drift.cpu"});
}

TEST(ReportDiff, AnExpectedFailureIsNotARegression) {
  json failing = check("mesh.closed.cpu", 3.0, "fail", 0.0);
  failing["expected"] = "fail";
  json failing_case = a_case("c", "fail", {failing});
  failing_case["expected_failure"] = "the seed's marching cubes leaves holes";
  const auto diff = gt::diff_reports(report(1.0, {a_case("c", "pass", {check("mesh.closed.cpu", 3.0, "pass", 0.0)})}),
                                     report(1.0, {failing_case}));
  EXPECT_TRUE(diff.regressions.empty());
  EXPECT_EQ(where(diff.outcome_changes), std::vector<std::string>{"c: mesh.closed.cpu"});
}

// Timings are compared as ratios to each run's calibration kernel: a machine twice as slow doubles
// both and nothing is listed; a case 1.5 times slower against the same kernel is (beyond 1.25).
TEST(ReportDiff, TimingsAreNormalisedByTheCalibrationKernel) {
  const json base = report(10.0, {a_case("c", "pass", {}, 100.0)});
  EXPECT_TRUE(gt::diff_reports(base, report(20.0, {a_case("c", "pass", {}, 200.0)})).timings.empty());
  EXPECT_TRUE(gt::diff_reports(base, report(20.0, {a_case("c", "pass", {}, 240.0)})).timings.empty());
  const auto slower = gt::diff_reports(base, report(20.0, {a_case("c", "pass", {}, 300.0)}));
  ASSERT_EQ(slower.timings.size(), 1u);
  EXPECT_THAT(slower.timings[0].after, HasSubstr("1.50× slower"));
  EXPECT_EQ(gt::diff_reports(base, report(10.0, {a_case("c", "pass", {}, 50.0)})).timings.size(), 1u);
}

TEST(ReportDiff, RefusesOtherSchemasAndUnrelatedReports) {
  json other = report(1.0, {a_case("c", "pass", {})});
  other["schema"] = 2;
  EXPECT_THROW(gt::diff_reports(report(1.0, {a_case("c", "pass", {})}), other), gt::InputError);
  EXPECT_THROW(gt::diff_reports(report(1.0, {a_case("a", "pass", {})}), report(1.0, {a_case("b", "pass", {})})),
               gt::InputError);
  EXPECT_THROW(gt::diff_reports(json::object(), report(1.0, {})), gt::InputError);
  json malformed = report(1.0, {a_case("c", "pass", {})});
  malformed["cases"][0]["checks"] = {{{"name", 7}, {"status", "pass"}}};
  EXPECT_THROW(gt::diff_reports(report(1.0, {a_case("c", "pass", {check("x", 1.0, "pass")})}), malformed),
               gt::InputError);
}

// A seeded regression: the same case with a registered one-twin mutant shows as a regression and
// exits 1; a report against itself has no change and exits 0; a file that is not a report exits 2;
// run --baseline says the same at its end and atop index.html, and refuses an unrelated baseline.
TEST(ReportDiffCli, AMutantShowsAsARegression) {
  const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
  const gt::testing::TemporaryFolder work("gt_diff_reports");
  const std::string probe = "erosion.thermal.mutant_probe.cone";
  ASSERT_EQ(gt::testing::run_program(groundtruth, {"run", probe, "--out", "base", "--quiet"}, work.path()).status, 0);
  ASSERT_EQ(gt::testing::run_program(groundtruth,
                                     {"run", probe, "--mutant", "erosion.thermal.swapped_gather", "--out", "next", "--quiet"},
                                     work.path())
                .status,
            1);
  const auto regression = gt::testing::run_program(groundtruth, {"diff-reports", "base/report.json", "next/report.json"},
                                                   work.path());
  EXPECT_EQ(regression.status, 1) << regression;
  EXPECT_THAT(regression.out, HasSubstr("REGRESSIONS"));
  EXPECT_THAT(regression.out, HasSubstr(probe + ": parity.shadow.terrain.gpu_vs_float  pass → fail"));
  const auto same = gt::testing::run_program(groundtruth, {"diff-reports", "base/report.json", "base/report.json"},
                                             work.path());
  EXPECT_EQ(same.status, 0) << same;
  EXPECT_THAT(same.out, HasSubstr("no changes"));
  // run --baseline prints the same summary at the end and heads index.html with it.
  const auto against = gt::testing::run_program(
      groundtruth,
      {"run", probe, "--mutant", "erosion.thermal.swapped_gather", "--baseline", "base/report.json", "--out", "again",
       "--quiet"},
      work.path());
  EXPECT_EQ(against.status, 1) << against;
  EXPECT_THAT(against.out, HasSubstr("against base/report.json: 1 case in both reports\nREGRESSIONS"));
  EXPECT_THAT(gt::testing::read_text(work.path() / "again" / "index.html"), HasSubstr("Against the baseline: "));
  const auto unrelated = gt::testing::run_program(
      groundtruth, {"run", "erosion.thermal.spec.example_3x3", "--baseline", "base/report.json", "--out", "other"},
      work.path());
  EXPECT_EQ(unrelated.status, 2) << unrelated;
  EXPECT_THAT(unrelated.err, HasSubstr("a baseline from another suite or algorithm set"));
  EXPECT_FALSE(std::filesystem::exists(work.path() / "other"));
  std::ofstream(work.path() / "not_a_report.json") << "{\"cases\": []}";
  const auto refused = gt::testing::run_program(groundtruth, {"diff-reports", "not_a_report.json", "base/report.json"},
                                                work.path());
  EXPECT_EQ(refused.status, 2) << refused;
  EXPECT_THAT(refused.err, HasSubstr("not a groundtruth report.json"));
}

}  // namespace
