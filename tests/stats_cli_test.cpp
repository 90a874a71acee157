// `groundtruth stats` and the descriptors of erosion cases, run as a user runs them (issue 16).
#include <filesystem>
#include <fstream>
#include <string>

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
const fs::path real_data = fs::path(GT_DATASET_DIR) / "real";

gt::testing::ProgramRun run(const std::vector<std::string>& args, const fs::path& cwd) {
  return gt::testing::run_program(groundtruth, args, cwd);
}

// Every bundled DEM: a table with the hypsometric integral, the Strahler streams and β (or why
// not), nothing written without --out. HI of any terrain lies in [0, 1]; slopes in [0, 90).
TEST(StatsCommand, MeasuresEveryBundledDem) {
  const gt::testing::TemporaryFolder work("gt_stats");
  for (const char* file : {"volcano.json", "jacksboro_fault_dem.npz", "topobathy.npz", "elev.tif"}) {
    const auto table = run({"stats", (real_data / file).string()}, work.path());
    ASSERT_EQ(table.status, 0) << table;
    EXPECT_THAT(table.out, HasSubstr("hypsometric integral HI")) << file;
    EXPECT_THAT(table.out, HasSubstr("Strahler streams per order")) << file;
    // β needs a band of two octaves: a shorter side of 128 cells (Jacksboro's 344 rows, not the others').
    EXPECT_THAT(table.out, HasSubstr(file == std::string("jacksboro_fault_dem.npz") ? "power-spectrum slope"
                                                                                   : "spectral slope not measured"))
        << file;
    const auto as_json = run({"stats", "--json", (real_data / file).string()}, work.path());
    ASSERT_EQ(as_json.status, 0) << as_json;
    const auto document = json::parse(as_json.out);
    const double integral = document["descriptors"]["hypsometry"]["integral"];
    EXPECT_GT(integral, 0.0) << file;
    EXPECT_LT(integral, 1.0) << file;
    for (double slope : document["descriptors"]["slope_deg"]["quantiles"]) {
      EXPECT_GE(slope, 0.0);
      EXPECT_LT(slope, 90.0);
    }
  }
  EXPECT_TRUE(fs::is_empty(work.path()));
}

TEST(StatsCommand, WritesItsJsonAndPlotIntoOutOnly) {
  const gt::testing::TemporaryFolder work("gt_stats");
  const auto written = run({"stats", (real_data / "elev.tif").string(), "--out", "stats"}, work.path());
  ASSERT_EQ(written.status, 0) << written;
  EXPECT_THAT(written.out, HasSubstr("no-data cells set to the fitted plane")) << "the masked cells are said";
  EXPECT_TRUE(fs::exists(work.path() / "stats" / "stats.json"));
  EXPECT_TRUE(fs::exists(work.path() / "stats" / "descriptors.png"));
  std::vector<std::string> entries;
  for (const auto& entry : fs::directory_iterator(work.path())) entries.push_back(entry.path().filename());
  EXPECT_EQ(entries, std::vector<std::string>{"stats"});
  // A folder with a user's file in it is not replaced.
  fs::create_directory(work.path() / "mine");
  std::ofstream(work.path() / "mine" / "notes.txt") << "keep me";
  const auto refused = run({"stats", (real_data / "elev.tif").string(), "--out", "mine"}, work.path());
  EXPECT_EQ(refused.status, 2) << refused;
  EXPECT_TRUE(fs::exists(work.path() / "mine" / "notes.txt"));
}

// Flat, tiny and empty DEMs: say what cannot be measured and why; exit 2 only for nothing at all.
TEST(StatsCommand, SaysWhatItCannotMeasure) {
  const gt::testing::TemporaryFolder work("gt_stats");
  // A volcano-JSON DEM whose cell i holds height(i) (null: no data).
  const auto write_volcano = [&](const std::string& name, int width, int height, auto height_of) {
    json values = json::array();
    for (int i = 0; i < width * height; ++i) values.push_back(height_of(i));
    std::ofstream(work.path() / name) << json{{"width", width}, {"height", height}, {"values", values}}.dump();
    return (work.path() / name).string();
  };
  const auto flat = run({"stats", write_volcano("flat.json", 20, 20, [](int) { return json(0.0); })}, work.path());
  EXPECT_EQ(flat.status, 0) << flat;
  EXPECT_THAT(flat.out, HasSubstr("hypsometry not measured: hypsometry: the terrain is flat")) << flat;
  const auto tiny = run({"stats", write_volcano("tiny.json", 8, 8, [](int i) { return json(i % 7); })}, work.path());
  EXPECT_EQ(tiny.status, 0) << tiny;
  EXPECT_THAT(tiny.out, HasSubstr("power spectrum not measured: too small for a spectrum")) << tiny;
  EXPECT_THAT(tiny.out, HasSubstr("hypsometric integral HI")) << tiny;
  const auto empty = run({"stats", write_volcano("empty.json", 8, 8, [](int) { return json(nullptr); })}, work.path());
  EXPECT_EQ(empty.status, 2) << empty;
  EXPECT_THAT(empty.err, HasSubstr("no valid cell")) << empty;
}

// An erosion case with "expect": {"fidelity": true}: descriptors of before and after, the twins'
// descriptor parity, fidelity checks that warn at worst, the plot, and the report's fidelity table.
TEST(CaseDescriptors, ErosionCasesReportDescriptorsAndTheFidelityTable) {
  const gt::testing::TemporaryFolder work("gt_case_descriptors");
  const json cases = json::array(
      {{{"name", "mine.fidelity"},
        {"algorithm", "erosion.thermal"},
        {"params", {{"iterations", 10}, {"talus_angle", 30.0}}},
        {"expect", {{"fidelity", true}}},
        {"input", {{"generator", "cone"}, {"width", 48}, {"height", 48}, {"peak", 30.0}, {"noise", 2.0}}}}});
  std::ofstream(work.path() / "mine.json") << cases.dump();
  const auto report = run({"run", "mine.fidelity", "--cases", "mine.json", "--out", "out"}, work.path());
  ASSERT_EQ(report.status, 0) << report;
  const auto document = json::parse(gt::testing::read_text(work.path() / "out" / "report.json"));
  const auto& result = document["cases"][0];
  for (const char* terrain : {"before", "cpu", "cpu_float"}) {
    EXPECT_TRUE(result["descriptors"]["terrains"].contains(terrain)) << terrain;
  }
  EXPECT_TRUE(result["descriptors"].contains("real"));
  int fidelity_checks = 0;
  bool parity_seen = false;
  for (const auto& check : result["checks"]) {
    const std::string name = check["name"];
    if (name.starts_with("fidelity.")) {
      ++fidelity_checks;
      EXPECT_NE(check["status"], "fail") << name << ": fidelity only warns";
    }
    parity_seen = parity_seen || name.starts_with("parity.descriptors.");
  }
  EXPECT_GT(fidelity_checks, 0);
  EXPECT_TRUE(parity_seen);
  EXPECT_TRUE(fs::exists(work.path() / "out" / "mine.fidelity" / "descriptors.png"));
  const std::string index = gt::testing::read_text(work.path() / "out" / "index.html");
  EXPECT_THAT(index, HasSubstr("Fidelity: does it look like Earth?"));
  // A row per descriptor in words with the literature's range (Horton's R_B of 3 to 5), a column
  // per case, inside a scrolling wrapper so that no column leaves a 1,280 px page.
  EXPECT_THAT(index, HasSubstr("hypsometric integral HI"));
  EXPECT_THAT(index, HasSubstr(">3–5</td>"));
  EXPECT_THAT(index, HasSubstr("<div class=\"wide\"><table>\n<tr><th>descriptor</th>"));
}

TEST(CaseDescriptors, FidelityMustBeABoolean) {
  const gt::testing::TemporaryFolder work("gt_case_descriptors");
  const json cases = json::array({{{"name", "mine.typo"},
                                   {"algorithm", "erosion.thermal"},
                                   {"expect", {{"fidelity", "yes"}}},
                                   {"input", {{"generator", "cone"}, {"width", 16}, {"height", 16}}}}});
  std::ofstream(work.path() / "mine.json") << cases.dump();
  const auto refused = run({"run", "mine.typo", "--cases", "mine.json", "--out", "out"}, work.path());
  EXPECT_EQ(refused.status, 2) << refused;
  EXPECT_THAT(refused.err, HasSubstr("expect.fidelity = \"yes\": expected a boolean")) << refused;
  EXPECT_FALSE(fs::exists(work.path() / "out"));
}

}  // namespace
