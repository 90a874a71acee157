// `groundtruth specificity` (compare/specificity.hpp, issue 38): the draws are reproducible and
// inside the declared ranges, the tally counts a failed or erring run as a false alarm and names
// it, and the command runs end to end on honest code.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/algorithm.hpp"
#include "compare/specificity.hpp"
#include "core/errors.hpp"
#include "core/params.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using ::testing::HasSubstr;

std::vector<std::vector<std::string>> assignments_of(const gt::Sweep& sweep) {
  std::vector<std::vector<std::string>> all;
  for (const auto& variant : sweep.variants) all.push_back(variant.assignments);
  return all;
}

TEST(Specificity, DrawsAreReproducibleAndWithinTheDeclaredRanges) {
  const gt::Sweep sweep = gt::make_specificity({}, 12, 3);
  EXPECT_EQ(sweep.kind, gt::SweepKind::specificity);
  // 12 sets of each algorithm, each on two inputs, each case named once.
  EXPECT_EQ(sweep.variants.size(), gt::specificity_algorithms().size() * 12 * 2);
  std::set<std::string> names;
  for (const auto& variant : sweep.variants) {
    EXPECT_TRUE(names.insert(variant.name).second) << variant.name;
    const gt::Algorithm& algorithm = gt::find_algorithm(variant.algorithm);
    for (const auto& assignment : variant.assignments) {
      const auto equals = assignment.find('=');
      // parse_param_text refuses a value outside the declared range or choices (InputError).
      EXPECT_NO_THROW(gt::parse_param_text(algorithm.name, *algorithm.params, assignment.substr(0, equals),
                                           assignment.substr(equals + 1)))
          << variant.name << ": " << assignment;
    }
  }
  EXPECT_EQ(assignments_of(gt::make_specificity({}, 12, 3)), assignments_of(sweep));
  EXPECT_NE(assignments_of(gt::make_specificity({}, 12, 4)), assignments_of(sweep));
  // The two inputs of one set take the same parameters; two sets differ.
  const gt::Sweep pipe = gt::make_specificity({"erosion.pipe"}, 2, 3);
  ASSERT_EQ(pipe.variants.size(), 4u);
  EXPECT_EQ(pipe.variants[0].assignments, pipe.variants[1].assignments);
  EXPECT_NE(pipe.variants[0].assignments, pipe.variants[2].assignments);
  EXPECT_EQ(pipe.variants[0].name, "specificity.erosion.pipe.volcano.set_00");
  // Šťava's layers clear what the pipe model refuses beside them (regolith, the thermal step), and
  // the printed condition, refused without layers, is drawn only with them; some sets have layers.
  int layered = 0;
  for (const auto& variant : gt::make_specificity({"erosion.pipe"}, 40, 3).variants) {
    const auto& given = variant.assignments;
    const bool layers = std::ranges::find(given, "layers=0") == given.end();
    layered += layers ? 1 : 0;
    for (const auto& assignment : given) {
      const std::string name = assignment.substr(0, assignment.find('='));
      if (layers) {
        EXPECT_TRUE(name != "regolith_depth" && name != "thermal_step") << variant.name << ": " << assignment;
      } else {
        EXPECT_NE(name, "layer_erosion") << variant.name;
      }
    }
  }
  EXPECT_GT(layered, 0);
}

TEST(Specificity, UnknownPatternsAndCountsAreRefused) {
  EXPECT_THROW(gt::make_specificity({"noise.*"}, 2, 1), gt::InputError);
  EXPECT_THROW(gt::make_specificity({}, 0, 1), gt::InputError);
  EXPECT_THROW(gt::make_specificity({}, 101, 1), gt::InputError);
}

// A tally of three runs, one failed and one in error: two false alarms, each named with its
// parameters and failing check.
TEST(Specificity, FailedAndErringRunsAreCountedAsFalseAlarms) {
  const gt::testing::TemporaryFolder folder_owner("gt_specificity_tally");
  const gt::Sweep sweep = gt::make_specificity({"erosion.thermal_jako"}, 2, 1);
  ASSERT_EQ(sweep.variants.size(), 4u);
  gt::Report report;
  for (std::size_t i = 0; i < 3; ++i) {
    gt::CaseResult result;
    result.name = sweep.variants[i].name;
    result.algorithm = sweep.variants[i].algorithm;
    report.cases.push_back(result);
  }
  report.cases[1].status = gt::Outcome::fail;
  report.cases[1].checks.push_back({"parity.shadow.terrain.gpu_vs_float", 2.0, 1.0, std::nullopt, gt::Outcome::fail, ""});
  report.cases[2].status = gt::Outcome::error;
  report.cases[2].error = "a made-up error";
  gt::write_specificity_summary(sweep, report, folder_owner.path());
  std::ifstream in(folder_owner / "specificity.json");
  const json summary = json::parse(in);
  EXPECT_EQ(summary.at("runs"), 3);
  EXPECT_EQ(summary.at("false_alarms"), 2);
  EXPECT_DOUBLE_EQ(summary.at("specificity").get<double>(), 1.0 / 3.0);
  const json& alarms = summary.at("algorithms").at(0).at("alarms");
  ASSERT_EQ(alarms.size(), 2u);
  EXPECT_EQ(alarms[0].at("case"), sweep.variants[1].name);
  EXPECT_THAT(alarms[0].at("failing_checks").dump(), HasSubstr("parity.shadow.terrain.gpu_vs_float"));
  EXPECT_EQ(alarms[0].at("parameters"), json(sweep.variants[1].assignments));
  EXPECT_EQ(alarms[1].at("error"), "a made-up error");
  EXPECT_TRUE(fs::is_regular_file(folder_owner / "specificity.html"));
}

// As a user runs it: two sets of Jákó's thermal erosion on both inputs, all honest runs pass.
TEST(Specificity, TheCommandTalliesHonestRuns) {
  const gt::testing::TemporaryFolder work("gt_specificity");
  const fs::path out = work / "specificity";
  const auto run = gt::testing::run_program(
      GT_BINARY_DIR "/groundtruth",
      {"specificity", "erosion.thermal_jako", "--sets", "2", "--seed", "5", "--quiet", "--out", out.string()}, work.path());
  ASSERT_EQ(run.status, 0) << run;
  std::ifstream in(out / "specificity.json");
  const json summary = json::parse(in);
  EXPECT_EQ(summary.at("runs"), 4);
  EXPECT_EQ(summary.at("false_alarms"), 0);
  EXPECT_TRUE(fs::is_regular_file(out / "specificity.html"));
  EXPECT_TRUE(fs::is_directory(out / "specificity.erosion.thermal_jako.topobathy.set_01"));
}

}  // namespace
