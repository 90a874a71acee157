// Issue 11's verdicts from the command line, as a user meets them: a missing GL context is never a
// pass and is an error under --require-gpu; a typo anywhere in a case is bad input (exit 2) that
// names the closest valid key; unknown mutants are refused the same way; `mutants --list` shows
// the registry. The mutation score itself is tests/mutants_test.cpp.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
// libglvnd finds no EGL vendor library, so no EGL display (hence no GL context) can be made.
const gt::testing::EnvChanges no_egl = {{"__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/egl_vendor.json"}};

gt::testing::ProgramRun run(const std::vector<std::string>& args, const fs::path& cwd,
                            const gt::testing::EnvChanges& env = {}) {
  return gt::testing::run_program(groundtruth, args, cwd, env);
}

json read_json(const fs::path& file) {
  std::ifstream stream(file);
  return json::parse(stream);
}

TEST(VerdictsCli, MissingContextSkipsTheGpuHalfAndTheCaseIsNotAPass) {
  const gt::testing::TemporaryFolder work;
  const auto result = run({"run", "erosion.thermal.spec.*", "--out", (work / "report").string()}, work.path(), no_egl);
  ASSERT_EQ(result.status, 0) << result;
  EXPECT_THAT(result.err, HasSubstr("never counted as passed"));
  const json report = read_json(work / "report" / "report.json");
  ASSERT_EQ(report.at("cases").size(), 1u);
  EXPECT_EQ(report.at("cases")[0].at("status"), "skip") << report.at("cases")[0].dump(2);
  EXPECT_EQ(report.at("summary").at("pass"), 0);
  EXPECT_EQ(report.at("summary").at("skip"), 1);
}

TEST(VerdictsCli, RequireGpuWithoutAContextIsAnError) {
  const gt::testing::TemporaryFolder work;
  const auto result = run({"run", "erosion.thermal.spec.*", "--require-gpu", "--out", (work / "report").string()},
                          work.path(), no_egl);
  EXPECT_EQ(result.status, 1) << result;
  EXPECT_THAT(result.out, HasSubstr("--require-gpu"));
  const json report = read_json(work / "report" / "report.json");
  EXPECT_EQ(report.at("cases")[0].at("status"), "error");
  EXPECT_THAT(report.at("cases")[0].at("error").get<std::string>(), HasSubstr("GPU half did not run"));
}

// An honest run a user's sweep leads to (issue 38: the pipe model on the volcano, 300 steps of
// 0.05 s in rain of 0.002 m/s) is not failed on its chaotic end state: after hundreds of steps the
// GPU's slope p90 sat 0.05° from ref<double>'s, over half the 0.1° a table quotes, and the run
// failed on parity.descriptors.gpu_vs_double. That check is now shown without a bound for an
// eroder's end (the shadow steps grade each step); every graded check passes or is inconclusive.
TEST(VerdictsCli, AnHonestLongPipeRunIsNotFailedOnItsChaoticEndState) {
  const gt::testing::TemporaryFolder work;
  const auto result = run({"run", "--algorithm", "erosion.pipe", "--input", GT_DATASET_DIR "/real/volcano.json",
                           "--set", "steps=300", "--set", "time_step=0.05", "--set", "rain_rate=0.002",
                           "--require-gpu", "--out", (work / "report").string()},
                          work.path());
  EXPECT_EQ(result.status, 0) << result;
  const json report = read_json(work / "report" / "report.json");
  const json& report_case = report.at("cases").at(0);
  bool descriptors_shown = false;
  for (const auto& check : report_case.at("checks")) {
    const auto name = check.at("name").get<std::string>();
    EXPECT_NE(check.at("status"), "fail") << check.dump(2);
    if (name == "parity.descriptors.gpu_vs_double") {
      descriptors_shown = true;
      EXPECT_FALSE(check.contains("threshold")) << "an end of a chaotic run graded: " << check.dump(2);
    }
  }
  EXPECT_TRUE(descriptors_shown) << report_case.dump(2);
}

// A run whose reference runs away is not an error of a twin (issue 38: `groundtruth specificity`
// drew Beyer's set_02 — the physical speed rule, capacity 5.04 — and the batch ordering's 32-bit
// counter overflowed in both inputs, two `error`s of 240 honest runs). The race ordering of the
// same parameters shows the run away: terrain tens of km apart between the references on a 100 m
// volcano. The case is inconclusive and names why; nothing fails.
TEST(VerdictsCli, ARunThatRunsAwayIsInconclusiveAndSaysWhy) {
  const gt::testing::TemporaryFolder work;
  const auto result =
      run({"run", "--algorithm", "erosion.beyer", "--input", GT_DATASET_DIR "/real/volcano.json", "--set", "iterations=7",
           "--set", "lifetime=31", "--set", "inertia=0.05105", "--set", "capacity_factor=5.04", "--set", "deposition=0.4881",
           "--set", "erosion=0.3602", "--set", "evaporation=0.03705", "--set", "radius=3.666", "--set", "ordering=batch",
           "--set", "speed_rule=physical", "--out", (work / "report").string()},
          work.path());
  EXPECT_EQ(result.status, 0) << result;
  const json report = read_json(work / "report" / "report.json");
  const json& report_case = report.at("cases").at(0);
  EXPECT_EQ(report_case.at("status"), "inconclusive") << report_case.dump(2);
  EXPECT_FALSE(report_case.contains("error")) << report_case.dump(2);
  bool named = false;
  for (const auto& check : report_case.at("checks")) {
    EXPECT_NE(check.at("status"), "fail") << check.dump(2);
    if (check.at("name") == "stability.runaway.cpu") {
      named = true;
      EXPECT_THAT(check.at("detail").get<std::string>(), HasSubstr("ran away")) << check.dump(2);
      EXPECT_GT(check.at("value").get<double>(), check.at("threshold").get<double>()) << check.dump(2);
    }
  }
  EXPECT_TRUE(named) << report_case.dump(2);
}

TEST(VerdictsCli, RequireGpuWithTheCpuBackendIsRefused) {
  const gt::testing::TemporaryFolder work;
  const auto result = run({"run", "erosion.thermal.spec.*", "--require-gpu", "--backend", "cpu"}, work.path());
  EXPECT_EQ(result.status, 2) << result;
  EXPECT_THAT(result.err, HasSubstr("contradict"));
}

// A case file of the user's with one typo in the given place; the run must refuse it before
// writing anything.
void expect_typo_refused(const json& entry, const std::string& message) {
  const gt::testing::TemporaryFolder work;
  std::ofstream(work / "mine.json") << json::array({entry}).dump();
  const auto out = work / "report";
  const auto result = run({"run", entry.at("name").get<std::string>(), "--cases", (work / "mine.json").string(), "--out",
                           out.string()},
                          work.path());
  EXPECT_EQ(result.status, 2) << result;
  EXPECT_THAT(result.err, HasSubstr(message)) << result;
  EXPECT_FALSE(fs::exists(out));
}

const json example_input = {{"generator", "example_3x3"}};

TEST(VerdictsCli, TypoInExpectIsBadInputNamingTheClosestKey) {
  expect_typo_refused({{"name", "mine.spec"}, {"algorithm", "erosion.thermal"}, {"input", example_input},
                       {"expect", {{"cells", json::array()}, {"tolerence", 1e-12}}}},
                      "unknown key 'tolerence' (did you mean 'tolerance'?)");
}

TEST(VerdictsCli, TypoInsideANestedExpectIsBadInput) {
  const json talus = {{"angle", 45}, {"widht", 512}, {"vertical_aspect", 1}, {"value", 0.002}};
  expect_typo_refused({{"name", "mine.talus"}, {"algorithm", "erosion.thermal"}, {"input", example_input},
                       {"expect", {{"talus_eq_4_10", talus}}}},
                      "unknown key 'widht' (did you mean 'width'?)");
}

TEST(VerdictsCli, TypoInAGeneratorOrParameterIsBadInput) {
  expect_typo_refused({{"name", "mine.cone"}, {"algorithm", "erosion.thermal"},
                       {"input", {{"generator", "cone"}, {"width", 16}, {"height", 16}, {"peek", 10}}}},
                      "unknown key 'peek' (did you mean 'peak'?)");
  expect_typo_refused({{"name", "mine.params"}, {"algorithm", "erosion.thermal"}, {"input", example_input},
                       {"params", {{"iteratons", 3}}}},
                      "unknown parameter 'iteratons' (did you mean 'iterations'?)");
  expect_typo_refused({{"name", "mine.top"}, {"algorithm", "erosion.thermal"}, {"input", example_input},
                       {"expcet", json::object()}},
                      "unknown key 'expcet' (did you mean 'expect'?)");
}

TEST(VerdictsCli, UnknownMutantIsBadInputNamingTheClosest) {
  const gt::testing::TemporaryFolder work;
  const auto listed = run({"mutants", "--list", "--json"}, work.path());
  ASSERT_EQ(listed.status, 0) << listed;
  const json registry = json::parse(listed.out);
  ASSERT_GE(registry.size(), 30u);
  const std::string name = registry[0].at("name");
  const std::string typo = name.substr(0, name.size() - 1) + "q";
  const auto result = run({"run", "erosion.thermal.spec.*", "--mutant", typo, "--out", (work / "r").string()}, work.path());
  EXPECT_EQ(result.status, 2) << result;
  EXPECT_THAT(result.err, HasSubstr("unknown mutant '" + typo + "' (did you mean '" + name + "'"));
  const auto pattern = run({"mutants", "nothing.*", "--out", (work / "m").string()}, work.path());
  EXPECT_EQ(pattern.status, 2) << pattern;
  EXPECT_FALSE(fs::exists(work / "m"));
}

}  // namespace
