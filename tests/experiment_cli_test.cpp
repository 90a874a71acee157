// Experiments (issue 19): `groundtruth sweep`, a parameter grid run as ad-hoc cases, tabled and
// plotted; `groundtruth ab`, two variants side by side; A/B pairs declared in case files.
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
using json = nlohmann::json;
using ::testing::HasSubstr;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const std::string volcano = (fs::path(GT_DATASET_DIR) / "real" / "volcano.json").string();

gt::testing::ProgramRun run(const std::vector<std::string>& args, const fs::path& cwd) {
  return gt::testing::run_program(groundtruth, args, cwd);
}

// Runs `args` (which write into `out`) and expects a refusal: exit 2, `message` on stderr, nothing
// written. `context` says which refusal in a failure message.
void expect_refusal(const std::vector<std::string>& args, const fs::path& out, const std::string& message,
                    const fs::path& cwd, const std::string& context = "") {
  const auto result = run(args, cwd);
  EXPECT_EQ(result.status, 2) << context << result;
  EXPECT_THAT(result.err, HasSubstr(message)) << context << result;
  EXPECT_FALSE(fs::exists(out)) << context;
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// Six talus angles on a real DEM: one case per value, a table with a row each, the slope of the
// result in it, and a page with a thumbnail per run. Thermal erosion stops where the slope is
// below the talus angle, so the lowest angle leaves the gentlest terrain: the table must show the
// mean slope after 15° below the mean slope after 40°.
TEST(Sweep, TalusAngleOverSixValuesOnARealDem) {
  const gt::testing::TemporaryFolder work("gt_sweep");
  const fs::path out = work / "sweep";
  const auto result = run({"sweep", "--algorithm", "erosion.thermal", "--input", volcano, "--vary",
                           "talus_angle=15,20,25,30,35,40", "--set", "iterations=20", "--out", out.string()},
                          work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json table = read_json(out / "sweep.json");
  EXPECT_EQ(table.at("varied"), json::array({"talus_angle"}));
  ASSERT_EQ(table.at("runs").size(), 6u);
  for (const json& row : table.at("runs")) {
    EXPECT_EQ(row.at("outcome"), "pass") << row.dump();
    EXPECT_TRUE(fs::is_directory(out / row.at("case").get<std::string>())) << row.dump();
  }
  const json& gentlest = table.at("runs").front();
  const json& steepest = table.at("runs").back();
  EXPECT_EQ(gentlest.at("params").at("talus_angle"), "15");
  EXPECT_EQ(steepest.at("params").at("talus_angle"), "40");
  EXPECT_LT(gentlest.at("metrics").at("descriptor.slope_deg.mean").get<double>(),
            steepest.at("metrics").at("descriptor.slope_deg.mean").get<double>());
  std::ifstream csv(out / "sweep.csv");
  std::string line;
  int lines = 0;
  while (std::getline(csv, line)) ++lines;
  EXPECT_EQ(lines, 7);  // header and six runs
  std::ifstream page_file(out / "sweep.html");
  const std::string page((std::istreambuf_iterator<char>(page_file)), std::istreambuf_iterator<char>());
  std::size_t thumbnails = 0;
  for (auto at = page.find("class=\"thumb\""); at != std::string::npos; at = page.find("class=\"thumb\"", at + 1)) {
    ++thumbnails;
  }
  EXPECT_EQ(thumbnails, 6u);
  EXPECT_THAT(page, HasSubstr("after_cpu.png"));
  // The plots: the parameter with its declared unit on the axis, a descriptor in words, the
  // descriptors before the checks and the timings last (what the parameter does before the noise).
  EXPECT_THAT(page, HasSubstr("against talus_angle (degree)"));
  EXPECT_THAT(page, HasSubstr("slope, mean (°)"));
  const auto first_descriptor = page.find("(descriptor.");
  const auto first_check = page.find("(parity.");
  const auto first_timing = page.find("against talus_angle (degree) (cpu_ms");
  ASSERT_NE(first_descriptor, std::string::npos);
  if (first_check != std::string::npos) EXPECT_LT(first_descriptor, first_check);
  if (first_timing != std::string::npos) EXPECT_LT(std::max(first_descriptor, first_check == std::string::npos ? std::size_t{0} : first_check), first_timing);
}

// Two varied parameters make every combination, named after their values; -j runs them in workers
// under the same names.
TEST(Sweep, TwoParametersRunEveryCombinationInWorkers) {
  const gt::testing::TemporaryFolder work("gt_sweep");
  const fs::path out = work / "sweep";
  const auto result = run({"sweep", "--algorithm", "erosion.thermal", "--input", volcano, "--vary", "talus_angle=20,40",
                           "--vary", "neighbourhood=cardinal,alternating", "--set", "iterations=5", "-j", "2",
                           "--out", out.string()},
                          work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json table = read_json(out / "sweep.json");
  std::vector<std::string> cases;
  for (const json& row : table.at("runs")) cases.push_back(row.at("case"));
  EXPECT_EQ(cases, (std::vector<std::string>{"sweep.erosion.thermal.volcano.talus_angle_20.neighbourhood_cardinal",
                                             "sweep.erosion.thermal.volcano.talus_angle_20.neighbourhood_alternating",
                                             "sweep.erosion.thermal.volcano.talus_angle_40.neighbourhood_cardinal",
                                             "sweep.erosion.thermal.volcano.talus_angle_40.neighbourhood_alternating"}));
}

// Bad sweeps are refused before anything runs: exit 2, a message, no output folder.
TEST(Sweep, BadVariationsAreRefused) {
  const gt::testing::TemporaryFolder work("gt_sweep");
  const fs::path out = work / "sweep";
  std::string many = "talus_angle=1";
  for (int angle = 2; angle <= 65; ++angle) many += "," + std::to_string(angle);
  // 1000^7 = 10^21 combinations, which a 64-bit count wrapped to 3.1e20's remainder: refused
  // even with --force.
  std::vector<std::string> immense = {"--force"};
  for (const char* name : {"a", "b", "c", "d", "e", "f", "g"}) {
    std::string axis = std::string(name) + "=0";
    for (int value = 1; value < 1000; ++value) axis += "," + std::to_string(value);
    immense.insert(immense.end(), {"--vary", axis});
  }
  const std::vector<std::pair<std::vector<std::string>, std::string>> refusals = {
      {immense, "1e+21 runs, more than any sweep may have"},
      {{"--vary", "talus=10,20"}, "unknown parameter 'talus'"},
      {{"--vary", "talus_angle=10,95"}, "out of range"},
      {{"--vary", many}, "more than the cap of 64"},
      {{"--vary", "talus_angle=10,20", "--set", "talus_angle=30"}, "both --set and --vary"},
      {{"--vary", "talus_angle=10,,20"}, "an empty value"},
      {{}, "or --sets FILE"},
  };
  for (const auto& [extra, message] : refusals) {
    std::vector<std::string> args = {"sweep", "--algorithm", "erosion.thermal", "--input", volcano, "--out",
                                     out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    expect_refusal(args, out, message, work.path());
  }
}

// Named parameter sets from a file: one run per set, in the file's order, tabled under "set" with
// the set's name. Seed 001's choices where its thesis and its code differ, and a third set that
// takes its code's diffusion weights with the thesis's tilt.
TEST(Sweep, NamedParameterSetsFromAFile) {
  const gt::testing::TemporaryFolder work("gt_sweep");
  std::ofstream(work / "sets.json") << R"({
    "thesis": {"tilt_differences": "central"},
    "code": {"tilt_differences": "seed001_code", "diffusion_weighting": "water"},
    "thesis tilt, code diffusion": {"tilt_differences": "central", "diffusion_weighting": "water"}})";
  const fs::path out = work / "sweep";
  const auto result = run({"sweep", "--algorithm", "erosion.pipe", "--input", volcano, "--sets",
                           (work / "sets.json").string(), "--set", "steps=20", "--set", "rain_rate=0.01", "--set",
                           "sediment_diffusion=0.1", "--backend", "cpu", "--out", out.string()},
                          work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json table = read_json(out / "sweep.json");
  EXPECT_EQ(table.at("varied"), json::array({"set"}));
  ASSERT_EQ(table.at("runs").size(), 3u);
  const std::vector<std::string> names = {"thesis", "code", "thesis tilt, code diffusion"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(table.at("runs")[i].at("params").at("set"), names[i]);
  }
  EXPECT_EQ(table.at("runs")[2].at("case"), "sweep.erosion.pipe.volcano.thesis_tilt__code_diffusion");
  // Each set took effect: the result's mean slope differs from the thesis's in both other runs.
  const auto mean_slope = [&](std::size_t run) {
    return table.at("runs")[run].at("metrics").at("descriptor.slope_deg.mean").get<double>();
  };
  EXPECT_NE(mean_slope(1), mean_slope(0));
  EXPECT_NE(mean_slope(2), mean_slope(0));
  const json report = read_json(out / "report.json");
  EXPECT_EQ(report.at("cases")[1].at("params").at("diffusion_weighting"), "water");
  EXPECT_TRUE(fs::exists(out / "sweep.html"));
}

// {"s0": {}, "s1": {}, ...}: `count` empty sets.
std::string many_sets(int count) {
  std::string text = "{";
  for (int index = 0; index < count; ++index) text += (index ? ", \"s" : "\"s") + std::to_string(index) + "\": {}";
  return text + "}";
}

TEST(Sweep, BadSetFilesAreRefused) {
  const gt::testing::TemporaryFolder work("gt_sweep");
  const fs::path out = work / "sweep";
  const std::vector<std::pair<std::string, std::string>> refusals = {
      {"{}", "a non-empty object of named parameter sets"},
      {"[1, 2]", "a non-empty object of named parameter sets"},
      {R"({"a": 3})", "set 'a' is not an object"},
      {R"({"a": {"talus_angle": [1, 2]}})", "must be a number, a bool or a string"},
      {R"({"a": {"talus_angle": 95}})", "talus_angle"},
      {R"({"a": {"talsu_angle": 30}})", "unknown parameter 'talsu_angle'"},
      {R"({"a b": {"talus_angle": 30}, "a.b": {"talus_angle": 40}})", "rename one"},
      {R"({"a": {"iterations": 3}})", "both --set and in set 'a'"},
      {"{", "not valid JSON"},
      {many_sets(300000), "300000 runs, more than the cap of 64"},  // counted before an ordered (quadratic) parse
  };
  for (const auto& [text, message] : refusals) {
    std::ofstream(work / "sets.json") << text;
    expect_refusal({"sweep", "--algorithm", "erosion.thermal", "--input", volcano, "--set", "iterations=2",
                    "--sets", (work / "sets.json").string(), "--out", out.string()},
                   out, message, work.path(), text);
  }
  expect_refusal({"sweep", "--algorithm", "erosion.thermal", "--input", volcano, "--vary", "talus_angle=1,2", "--sets",
                  (work / "sets.json").string(), "--out", out.string()},
                 out, "excludes", work.path());
}

// The pipe model's thesis (central differences over 2l) against its code (raw differences) for
// sin α, on the volcano with rain: both run, the difference map shows what the code's choice
// changes (the raw differences are 2l = 20 times steeper: more erosion), and the metrics table
// has A's, B's and their difference.
TEST(Ab, PipeThesisAgainstCodeTiltDifferences) {
  const gt::testing::TemporaryFolder work("gt_ab");
  const fs::path out = work / "ab";
  const auto result = run({"ab", "--algorithm", "erosion.pipe", "--input", volcano, "--set", "steps=30", "--set",
                           "rain_rate=0.01", "--a", "tilt_differences=central", "--b", "tilt_differences=seed001_code",
                           "--out", out.string()},
                          work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json table = read_json(out / "ab.json");
  EXPECT_EQ(table.at("a").at("case"), "ab.erosion.pipe.volcano.a");
  EXPECT_EQ(table.at("b").at("case"), "ab.erosion.pipe.volcano.b");
  EXPECT_GT(table.at("difference").at("rms").get<double>(), 0.0);
  EXPECT_TRUE(fs::exists(out / "ab_difference.png"));
  bool moved_material = false;
  for (const json& metric : table.at("metrics")) {
    ASSERT_TRUE(metric.contains("a") && metric.contains("b") && metric.contains("b_minus_a")) << metric.dump();
    if (metric.at("name") == "descriptor.slope_deg.mean") {
      moved_material = metric.at("b_minus_a").get<double>() != 0.0;
    }
  }
  EXPECT_TRUE(moved_material) << "the variants' terrains should differ in slope";
  std::ifstream page_file(out / "ab.html");
  const std::string page((std::istreambuf_iterator<char>(page_file)), std::istreambuf_iterator<char>());
  EXPECT_THAT(page, HasSubstr("ab.erosion.pipe.volcano.a/after_cpu.png"));
  EXPECT_THAT(page, HasSubstr("ab.erosion.pipe.volcano.b/after_cpu.png"));
  EXPECT_THAT(page, HasSubstr("ab_difference.png"));
  // The difference map carries its colour bar in metres; the descriptors and checks come before the
  // timings, which stand apart (one run each: noise).
  EXPECT_THAT(page, HasSubstr("class=\"colourbar\""));
  EXPECT_THAT(page, HasSubstr("\xE2\x80\xAFm</span>"));  // the ends labelled in metres
  const auto descriptors = page.find("<h3>Terrain descriptors of the results</h3>");
  const auto checks = page.find("<h3>Checks</h3>");
  const auto timings = page.find("<h3>Timings</h3>");
  ASSERT_NE(descriptors, std::string::npos);
  ASSERT_NE(checks, std::string::npos);
  ASSERT_NE(timings, std::string::npos);
  EXPECT_LT(descriptors, checks);
  EXPECT_LT(checks, timings);
}

TEST(Ab, BadVariantsAreRefused) {
  const gt::testing::TemporaryFolder work("gt_ab");
  const fs::path out = work / "ab";
  const std::vector<std::pair<std::vector<std::string>, std::string>> refusals = {
      {{"--a", "pipes=4", "--b", "pipes=4"}, "the same variant"},
      {{"--a", "pipes=4", "--b", "pipez=8"}, "unknown parameter 'pipez'"},
      {{"--a", "pipes=4", "--b", "pipes=6"}, "pipes"},
      {{"--a", "pipes=4", "--b", "pipes=8", "--set", "pipes=4"}, "both --set and --a/--b"},
      {{}, "--a name=value"},
  };
  for (const auto& [extra, message] : refusals) {
    std::vector<std::string> args = {"ab", "--algorithm", "erosion.pipe", "--input", volcano, "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    expect_refusal(args, out, message, work.path());
  }
}

// A case file's "ab" pair: the entry becomes two cases, <name>.a and <name>.b, and a run holding
// both writes the pair's page beside index.html. Thermal erosion at 20° and at 40° on a 45° cone:
// the lower talus angle leaves the gentler terrain, so B - A's mean slope is positive.
TEST(CaseAb, ADeclaredPairRunsBothSidesAndWritesItsPage) {
  const gt::testing::TemporaryFolder work("gt_case_ab");
  const json pair = json::array({{{"name", "mine.thermal.talus"},
                                  {"algorithm", "erosion.thermal"},
                                  {"params", {{"iterations", 30}}},
                                  {"input", {{"generator", "cone"}, {"width", 48}, {"height", 48}, {"peak", 20.0}}},
                                  {"ab", {{"a", {{"talus_angle", 20.0}}}, {"b", {{"talus_angle", 40.0}}}}}}});
  std::ofstream(work / "pair.json") << pair.dump(2);
  const fs::path out = work / "report";
  const auto result = run({"run", "mine.thermal.talus.*", "--cases", (work / "pair.json").string(), "--backend", "cpu",
                           "--out", out.string()},
                          work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json report = read_json(out / "report.json");
  ASSERT_EQ(report.at("cases").size(), 2u);
  EXPECT_EQ(report.at("cases")[0].at("params").at("talus_angle"), 20.0);
  EXPECT_EQ(report.at("cases")[1].at("params").at("talus_angle"), 40.0);
  const json table = read_json(out / "ab.mine.thermal.talus.json");
  EXPECT_EQ(table.at("a").at("case"), "mine.thermal.talus.a");
  EXPECT_EQ(table.at("b").at("assignments"), json::array({"talus_angle=40.0"}));
  bool slope_compared = false;
  for (const json& metric : table.at("metrics")) {
    if (metric.at("name") != "descriptor.slope_deg.mean") continue;
    slope_compared = true;
    EXPECT_GT(metric.at("b_minus_a").get<double>(), 0.0) << metric.dump();
  }
  EXPECT_TRUE(slope_compared);
  EXPECT_TRUE(fs::exists(out / "ab.mine.thermal.talus_difference.png"));
  std::ifstream page_file(out / "ab.mine.thermal.talus.html");
  const std::string page((std::istreambuf_iterator<char>(page_file)), std::istreambuf_iterator<char>());
  EXPECT_THAT(page, HasSubstr("mine.thermal.talus.a/after_cpu.png"));
  EXPECT_THAT(page, HasSubstr("ab.mine.thermal.talus_difference.png"));
  std::ifstream index_file(out / "index.html");
  const std::string index((std::istreambuf_iterator<char>(index_file)), std::istreambuf_iterator<char>());
  EXPECT_THAT(index, HasSubstr("ab.mine.thermal.talus_difference.png"));
}

TEST(CaseAb, BadPairsAreRefusedBeforeAnythingRuns) {
  const gt::testing::TemporaryFolder work("gt_case_ab");
  const json base = {{"name", "mine.pair"},
                     {"algorithm", "erosion.thermal"},
                     {"params", {{"iterations", 3}}},
                     {"input", {{"generator", "cone"}, {"width", 16}, {"height", 16}}}};
  const std::vector<std::pair<json, std::string>> refusals = {
      {{{"a", {{"talus_angle", 20.0}}}, {"b", {{"talus_angle", 20.0}}}}, "the same variant"},
      {{{"a", {{"talus_angle", 20.0}}}}, "\"ab\" must be"},
      {{{"a", {{"iterations", 5}}}, {"b", {{"iterations", 6}}}}, "both in \"params\" and in \"ab\""},
      {{{"a", {{"talus_angle", 20.0}}}, {"b", {{"talus_angle", 95.0}}}}, "talus_angle"},
  };
  for (const auto& [ab, message] : refusals) {
    json entry = base;
    entry["ab"] = ab;
    std::ofstream(work / "pair.json") << json::array({entry}).dump(2);
    const fs::path out = work / "report";
    expect_refusal({"run", "mine.pair.*", "--cases", (work / "pair.json").string(), "--out", out.string()}, out,
                   message, work.path());
  }
}

}  // namespace
