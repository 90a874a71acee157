// Tests of compare/result.cpp and compare/report/: outcome arithmetic, the four report formats
// written from one fabricated Report, the height/difference pictures and the benchmark plot.
// Files go to a fresh folder under the system temporary directory, removed afterwards.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/report/report_common.hpp"
#include "compare/report/report_read.hpp"
#include "compare/report/writers.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/result.hpp"

namespace gt {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class TemporaryFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    folder = fs::temp_directory_path() / fmt::format("gt_report_test_{}_{}_{}", getpid(), test->test_suite_name(),
                                                     test->name());
    fs::remove_all(folder);
    fs::create_directories(folder);
  }
  void TearDown() override { fs::remove_all(folder); }
  fs::path folder;
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

int count_of(const std::string& text, const std::string& needle) {
  int count = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + needle.size())) ++count;
  return count;
}

struct Picture {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<unsigned char> pixels;

  const unsigned char* at(int x, int y) const { return &pixels[(static_cast<std::size_t>(y) * width + x) * channels]; }
};

Picture read_picture(const fs::path& png) {
  auto input = OIIO::ImageInput::open(png.string());
  if (!input) throw std::runtime_error(OIIO::geterror());
  const OIIO::ImageSpec& spec = input->spec();
  Picture picture{spec.width, spec.height, spec.nchannels, {}};
  picture.pixels.resize(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, picture.pixels.data());
  return picture;
}

Check make_check(std::string name, double value, std::optional<double> threshold, Outcome status,
                 std::string detail = "") {
  Check check;
  check.name = std::move(name);
  check.value = value;
  check.threshold = threshold;
  check.status = status;
  check.detail = std::move(detail);
  return check;
}

CaseResult make_case(std::string name, std::string algorithm, std::vector<Check> checks) {
  CaseResult result;
  result.name = std::move(name);
  result.algorithm = std::move(algorithm);
  result.input = "volcano.json (87x61, 10 m)";
  result.width = 87;
  result.height = 61;
  result.params = {{"iterations", 50}, {"talus_angle_deg", 33.0}, {"neighbourhood", "cardinal"}};
  result.checks = std::move(checks);
  result.status = case_outcome(result);
  return result;
}

// One case of each outcome, an expected failure and a NaN value; `detail` holds markup.
Report sample_report() {
  Report report;
  report.environment = {"llvmpipe (LLVM 15.0.6, 256 bits)", "4.5 (Core Profile) Mesa 22.3.6", "egl-surfaceless",
                        "Intel Xeon", "GCC 12.2.0", "Release", "3a932b0"};
  CaseResult pass = make_case("erosion.thermal.cardinal.volcano", "erosion.thermal",
                              {make_check("mass.relative_drift.gpu", 3.1e-7, 1e-5, Outcome::pass)});
  pass.timings = {812.0, 35.2, 3, 5};
  pass.artifacts = {{"erosion.thermal.cardinal.volcano/before.png", "image", "before"},
                    {"erosion.thermal.cardinal.volcano/gpu.exr", "field", "GPU heights"}};
  CaseResult fail = make_case("erosion.thermal.diagonal.volcano", "erosion.thermal",
                              {make_check("parity.max_abs", 0.5, 1e-3, Outcome::fail, "<b>far</b> apart & off")});
  Check warned = make_check("parity.rms", 2e-4, 1e-4, Outcome::warn, "between the bounds");
  warned.loose_threshold = 1e-3;
  CaseResult warn = make_case("erosion.thermal.cardinal.ramp", "erosion.thermal", {warned});
  CaseResult skip = make_case("cave.marching_tetrahedra.sphere", "cave.marching_tetrahedra",
                              {make_check("mesh.closed.gpu", 0.0, std::nullopt, Outcome::skip, "no GL context")});
  CaseResult error = make_case("planet.plates.seed1", "planet.plates", {});
  error.error = "shader failed to compile";
  error.status = case_outcome(error);
  CaseResult expected = make_case("cave.marching_cubes.sphere", "cave.marching_cubes",
                                  {make_check("mesh.closed.cpu", 12.0, 0.0, Outcome::fail, "12 boundary edges")});
  expected.expected_failure = "the seed's marching cubes leaves holes";
  CaseResult nan_value = make_case("noise.perlin3.nan", "noise.perlin3",
                                   {make_check("parity.max_abs", std::numeric_limits<double>::quiet_NaN(), 1e-6,
                                               Outcome::fail, "GPU produced NaN")});
  report.cases = {pass, fail, warn, skip, error, expected, nan_value};
  report.benchmarks = {
      {.algorithm = "erosion.thermal", .backend = "cpu", .size = 256, .iterations = 50, .reps = 3, .median_ms = 120.0,
       .mcell_iterations_per_s = 27.3, .device = "Intel Xeon"},
      {.algorithm = "erosion.thermal", .backend = "gpu", .size = 256, .iterations = 50, .reps = 5, .median_ms = 12.0,
       .mcell_iterations_per_s = 273.0, .device = "llvmpipe", .detail = "2 compute passes per iteration",
       .bytes_per_cell = 52.0, .floor_ms = 6.0},
      {.algorithm = "cave.marching_tetrahedra", .backend = "cpu", .size = 64, .iterations = 1, .reps = 3,
       .median_ms = 50.0, .mcell_iterations_per_s = 5.24288, .device = "Intel Xeon", .dimensions = 3,
       .mtriangles_per_s = 12.5, .times_peer = 4.0, .fastest_peer = "VTK vtkFlyingEdges3D"},
      {.algorithm = "cave.marching_tetrahedra", .backend = "gpu", .size = 256, .iterations = 1, .device = "llvmpipe",
       .dimensions = 3, .note = "triangles need 444 MB, more than GL_MAX_SHADER_STORAGE_BLOCK_SIZE"}};
  report.plots = {{"", "plot", "plot unavailable: test"}};
  return report;
}

// ---- outcomes ----------------------------------------------------------------------------------

TEST(Outcomes, NamesAndOrder) {
  EXPECT_STREQ(outcome_name(Outcome::pass), "pass");
  EXPECT_STREQ(outcome_name(Outcome::fail), "fail");
  EXPECT_STREQ(outcome_name(Outcome::warn), "warn");
  EXPECT_STREQ(outcome_name(Outcome::inconclusive), "inconclusive");
  EXPECT_STREQ(outcome_name(Outcome::skip), "skip");
  EXPECT_STREQ(outcome_name(Outcome::error), "error");
  const std::vector<Outcome> best_to_worst = {Outcome::pass, Outcome::warn, Outcome::inconclusive, Outcome::skip,
                                              Outcome::fail, Outcome::error};
  for (std::size_t i = 0; i < best_to_worst.size(); ++i) {
    for (std::size_t j = 0; j < best_to_worst.size(); ++j) {
      EXPECT_EQ(worse(best_to_worst[i], best_to_worst[j]), best_to_worst[std::max(i, j)]);
    }
  }
}

TEST(Outcomes, CaseOutcomeFromChecks) {
  CaseResult result;
  EXPECT_EQ(case_outcome(result), Outcome::skip);
  result.checks = {make_check("c", 0, {}, Outcome::pass)};
  EXPECT_EQ(case_outcome(result), Outcome::pass);
  result.checks.push_back(make_check("d", 0, {}, Outcome::warn));
  EXPECT_EQ(case_outcome(result), Outcome::warn);
  result.checks.push_back(make_check("a", 0, {}, Outcome::skip));
  EXPECT_EQ(case_outcome(result), Outcome::skip);  // a skipped half is never a pass
  result.checks.push_back(make_check("e", 0, {}, Outcome::fail));
  EXPECT_EQ(case_outcome(result), Outcome::fail);
  result.error = "could not run";
  EXPECT_EQ(case_outcome(result), Outcome::error);
}

// --backend cpu: the GPU checks the user left out are shown as skips with why, and the references'
// checks decide the case; a GPU half skipped for want of a context still makes it a skip.
TEST(Outcomes, ChecksLeftOutByRequestDoNotDecideTheCase) {
  CaseResult result;
  result.checks = {make_check("parity.gpu_vs_float", 0, {}, Outcome::skip, gpu_not_requested)};
  EXPECT_EQ(case_outcome(result), Outcome::skip);  // nothing ran
  result.checks.push_back(make_check("mass.relative_drift.cpu", 0, 1, Outcome::pass));
  EXPECT_EQ(case_outcome(result), Outcome::pass);
  result.checks.push_back(make_check("spec.cpu", 2, 1, Outcome::warn));
  EXPECT_EQ(case_outcome(result), Outcome::warn);
  result.checks.push_back(make_check("determinism.gpu", 0, {}, Outcome::skip, "no GL context: no EGL display"));
  EXPECT_EQ(case_outcome(result), Outcome::skip);
}

TEST(Outcomes, RunFailsOnUnlistedFailuresErrorsAndBrokenExpectations) {
  auto run_with = [](Outcome status, std::optional<Outcome> expected) {
    Report report;
    report.cases.resize(2);  // a case without checks beside the one under test
    Check check = make_check("mesh.closed.cpu", 1, 0, status);
    check.expected = expected;
    report.cases[1].checks = {check};
    report.cases[1].status = status;
    return run_failed(report);
  };
  EXPECT_FALSE(run_with(Outcome::pass, std::nullopt));
  EXPECT_FALSE(run_with(Outcome::warn, std::nullopt));
  EXPECT_FALSE(run_with(Outcome::skip, std::nullopt));
  EXPECT_FALSE(run_with(Outcome::inconclusive, std::nullopt));
  EXPECT_TRUE(run_with(Outcome::fail, std::nullopt));
  EXPECT_TRUE(run_with(Outcome::error, std::nullopt));
  EXPECT_FALSE(run_with(Outcome::fail, Outcome::fail));
  Report stale;
  stale.expectation_problems = {"a.b.c mesh.closed.cpu: expected fail (expectations.txt line 5), got pass"};
  EXPECT_TRUE(run_failed(stale));
  Report errored;
  errored.cases.resize(1);
  errored.cases[0].error = "GL error during the case";
  EXPECT_TRUE(run_failed(errored));
}

// ---- report formats ----------------------------------------------------------------------------

using ReportFiles = TemporaryFolder;

TEST_F(ReportFiles, WritesAllFourAndNoTemporaries) {
  write_report_files(sample_report(), folder);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"index.html", "junit.xml", "report.json", "report.md"}));
}

TEST_F(ReportFiles, JsonFollowsSchema1) {
  write_report_json(sample_report(), folder / "report.json");
  const json report = json::parse(read_text(folder / "report.json"));  // throws if invalid
  EXPECT_EQ(report["schema"], 1);
  for (const char* key : {"gl_renderer", "gl_version", "gl_platform", "cpu", "compiler", "build_type", "git"}) {
    EXPECT_TRUE(report["environment"].contains(key)) << key;
  }
  EXPECT_EQ(report["environment"]["gl_renderer"], "llvmpipe (LLVM 15.0.6, 256 bits)");
  ASSERT_EQ(report["cases"].size(), 7u);

  const json& pass = report["cases"][0];
  EXPECT_EQ(pass["name"], "erosion.thermal.cardinal.volcano");
  EXPECT_EQ(pass["algorithm"], "erosion.thermal");
  EXPECT_EQ(pass["status"], "pass");
  EXPECT_EQ(pass["width"], 87);
  EXPECT_EQ(pass["height"], 61);
  EXPECT_EQ(pass["params"]["iterations"], 50);
  EXPECT_FALSE(pass.contains("expected_failure"));
  EXPECT_FALSE(pass.contains("error"));
  EXPECT_EQ(pass["checks"][0]["name"], "mass.relative_drift.gpu");
  EXPECT_DOUBLE_EQ(pass["checks"][0]["value"].get<double>(), 3.1e-7);
  EXPECT_DOUBLE_EQ(pass["checks"][0]["threshold"].get<double>(), 1e-5);
  EXPECT_FALSE(pass["checks"][0].contains("loose_threshold"));
  EXPECT_FALSE(pass["checks"][0].contains("detail"));
  EXPECT_EQ(pass["timings"], json({{"cpu_ms", 812.0}, {"gpu_ms", 35.2}, {"cpu_reps", 3}, {"gpu_reps", 5}}));
  EXPECT_EQ(pass["artifacts"], json({"erosion.thermal.cardinal.volcano/before.png",
                                     "erosion.thermal.cardinal.volcano/gpu.exr"}));

  EXPECT_EQ(report["cases"][2]["checks"][0]["loose_threshold"], 1e-3);
  EXPECT_EQ(report["cases"][3]["status"], "skip");
  EXPECT_FALSE(report["cases"][3]["timings"].contains("cpu_ms"));
  EXPECT_EQ(report["cases"][4]["status"], "error");
  EXPECT_EQ(report["cases"][4]["error"], "shader failed to compile");
  EXPECT_EQ(report["cases"][5]["expected_failure"], "the seed's marching cubes leaves holes");

  const json& nan_check = report["cases"][6]["checks"][0];
  EXPECT_TRUE(nan_check["value"].is_null());
  EXPECT_EQ(nan_check["value_text"], "nan");
  EXPECT_EQ(nan_check["status"], "fail");

  ASSERT_EQ(report["benchmarks"].size(), 4u);
  EXPECT_EQ(report["benchmarks"][1]["device"], "llvmpipe");
  EXPECT_EQ(report["benchmarks"][1]["mcell_iterations_per_s"], 273.0);
  EXPECT_EQ(report["benchmarks"][1]["dimensions"], 2);
  EXPECT_TRUE(report["benchmarks"][1]["mtriangles_per_s"].is_null());
  EXPECT_EQ(report["benchmarks"][2]["dimensions"], 3);
  EXPECT_EQ(report["benchmarks"][2]["mtriangles_per_s"], 12.5);
  EXPECT_EQ(report["benchmarks"][1]["detail"], "2 compute passes per iteration");
  EXPECT_EQ(report["benchmarks"][1]["bytes_per_cell"], 52.0);
  EXPECT_EQ(report["benchmarks"][1]["times_floor"], 2.0);
  EXPECT_EQ(report["benchmarks"][2]["times_peer"], 4.0);
  EXPECT_TRUE(report["benchmarks"][0]["floor_ms"].is_null());
  EXPECT_TRUE(report["scaling"].empty());  // no line has 4 sizes
  EXPECT_EQ(report["benchmarks"][0]["detail"], "");
  EXPECT_NE(report["benchmarks"][3]["note"].get<std::string>().find("GL_MAX_SHADER_STORAGE_BLOCK_SIZE"), std::string::npos);
  EXPECT_EQ(report["summary"], json({{"pass", 1}, {"fail", 3}, {"warn", 1}, {"inconclusive", 0}, {"skip", 1},
                                     {"flaky", 0}, {"error", 1}, {"failed", true}}));
}

TEST_F(ReportFiles, JunitCountsAndEscapes) {
  write_report_junit(sample_report(), folder / "junit.xml");
  const std::string xml = read_text(folder / "junit.xml");
  EXPECT_EQ(count_of(xml, "<testsuite "), 5);  // thermal, tetrahedra, plates, cubes, perlin3
  EXPECT_EQ(count_of(xml, "<testcase "), 7);
  EXPECT_EQ(count_of(xml, "<failure "), 2);  // thermal diagonal, perlin NaN; the expected one passes
  EXPECT_EQ(count_of(xml, "<error "), 1);
  EXPECT_EQ(count_of(xml, "<skipped "), 1);
  EXPECT_NE(xml.find("classname=\"erosion.thermal\""), std::string::npos);
  EXPECT_NE(xml.find("name=\"erosion.thermal.diagonal.volcano\""), std::string::npos);
  EXPECT_NE(xml.find("&lt;b&gt;far&lt;/b&gt; apart &amp; off"), std::string::npos);
  EXPECT_EQ(xml.find("<b>"), std::string::npos);
  EXPECT_NE(xml.find("expected failure (fail): the seed&#39;s marching cubes leaves holes"), std::string::npos);
  EXPECT_NE(xml.find("warn parity.rms = 0.0002"), std::string::npos);
  EXPECT_NE(xml.find("<testsuites name=\"groundtruth\" tests=\"7\" failures=\"2\" errors=\"1\" skipped=\"1\">"),
            std::string::npos);
}

TEST_F(ReportFiles, JsonAndHtmlShowTheMutationScore) {
  Report report = sample_report();
  MutationReport mutation;
  mutation.baselines = {{.family = "erosion", .cases = {"erosion.pipe.mutant_probe.flux"}, .clean = true}};
  mutation.mutants = {{.name = "erosion.pipe.half_rain", .family = "erosion", .kind = "both-twins",
                       .description = "rain at half rate", .status = "killed",
                       .killed_by = {"erosion.pipe.mutant_probe.flux: mass.water_added.cpu = 0.049 (bound 1e-14)"}},
                      {.name = "erosion.pipe.gpu_x", .family = "erosion", .kind = "one-twin", .status = "survived"}};
  report.mutation = mutation;
  write_report_files(report, folder);
  const json written = json::parse(read_text(folder / "report.json"));
  EXPECT_EQ(written["mutation"]["killed"], 1);
  EXPECT_EQ(written["mutation"]["registered"], 2);
  EXPECT_EQ(written["mutation"]["mutants"][1]["status"], "survived");
  EXPECT_TRUE(written["summary"]["failed"].get<bool>());
  const std::string html = read_text(folder / "index.html");
  EXPECT_NE(html.find("1 of 2 killed (50 %)"), std::string::npos);
  EXPECT_NE(html.find("mass.water_added.cpu = 0.049"), std::string::npos);
  EXPECT_NE(html.find("<h2>Cases</h2>"), std::string::npos) << "a report with cases keeps its case table";
  // `groundtruth mutants` alone: the page is the mutation score, without "0 cases", an empty Cases
  // table or "No benchmarks".
  Report mutants_only;
  mutants_only.environment = report.environment;
  mutants_only.mutation = mutation;
  fs::create_directories(folder / "mutants");
  write_report_files(mutants_only, folder / "mutants");
  const std::string page = read_text(folder / "mutants" / "index.html");
  EXPECT_NE(page.find("1 of 2 killed (50 %)"), std::string::npos);
  for (const char* scaffolding : {"0 cases", "<h2>Cases</h2>", "No benchmarks", "<h2>Summary</h2>"}) {
    EXPECT_EQ(page.find(scaffolding), std::string::npos) << scaffolding;
  }
  const std::string markdown = read_text(folder / "mutants" / "report.md");
  EXPECT_EQ(markdown.find("No benchmarks"), std::string::npos);
  EXPECT_EQ(markdown.find("0 cases"), std::string::npos);
  // `groundtruth bench` alone: the performance table without the case run's scaffolding.
  Report bench_only;
  bench_only.environment = report.environment;
  bench_only.benchmarks = report.benchmarks;
  fs::create_directories(folder / "bench");
  write_report_files(bench_only, folder / "bench");
  const std::string bench_page = read_text(folder / "bench" / "index.html");
  EXPECT_NE(bench_page.find("<h2>Performance</h2>"), std::string::npos);
  for (const char* scaffolding : {"0 cases", "<h2>Cases</h2>", "<h2>Summary</h2>"}) {
    EXPECT_EQ(bench_page.find(scaffolding), std::string::npos) << scaffolding;
  }
  EXPECT_NE(read_text(folder / "bench" / "report.md").find("## Benchmarks"), std::string::npos);
}

// The kill matrix lists every graded check of the baselines with the mutants of its kind it killed
// (a graded check that killed none first, as not yet proved), and the specificity stands beside the
// mutation score (issue 38 item 5 and 6).
TEST_F(ReportFiles, TheMutantsSectionShowsTheKillMatrixAndTheSpecificity) {
  Report report = sample_report();
  MutationReport mutation;
  mutation.baselines = {{.family = "erosion",
                         .cases = {"erosion.pipe.mutant_probe.flux"},
                         .clean = true,
                         .graded_checks = {"mass.water_added.cpu", "parity.shadow.water.gpu_vs_float", "spec.cells.cpu"}}};
  mutation.mutants = {{.name = "erosion.pipe.half_rain", .family = "erosion", .kind = "both-twins", .status = "killed",
                       .killed_by = {"erosion.pipe.mutant_probe.flux: mass.water_added.cpu = 0.049 (bound 1e-14)"},
                       .killing_checks = {"mass.water_added.cpu"}},
                      {.name = "erosion.pipe.gpu_x", .family = "erosion", .kind = "one-twin", .status = "killed",
                       .killed_by = {"erosion.pipe.mutant_probe.flux: parity.shadow.water.gpu_vs_float = 3 (bound 1e-6)"},
                       .killing_checks = {"parity.shadow.water.gpu_vs_float"}}};
  mutation.specificity = SpecificitySummary{.runs = 240, .false_alarms = 2, .page = "specificity/specificity.html"};
  mutation.folder = "mutants/";
  const auto rows = mutation.kill_matrix();
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].check, "mass.water_added.cpu");
  EXPECT_EQ(rows[0].mutants, std::vector<std::string>{"erosion.pipe.half_rain"});
  EXPECT_TRUE(rows[2].mutants.empty()) << "spec.cells.cpu killed nothing";
  report.mutation = mutation;
  write_report_files(report, folder);
  const json written = json::parse(read_text(folder / "report.json"));
  EXPECT_EQ(written["mutation"]["kill_matrix"]["parity.shadow.water.gpu_vs_float"][0], "erosion.pipe.gpu_x");
  EXPECT_TRUE(written["mutation"]["kill_matrix"]["spec.cells.cpu"].empty());
  EXPECT_EQ(written["mutation"]["specificity"]["false_alarms"], 2);
  const std::string html = read_text(folder / "index.html");
  EXPECT_NE(html.find("2 of 3 graded checks killed a mutant of their kind; 1 killed none (first)"), std::string::npos);
  EXPECT_LT(html.find("<td>spec.cells.cpu</td>"), html.find("<td>mass.water_added.cpu</td>")) << "unproved first";
  EXPECT_NE(html.find("238 of 240 honest runs without a false alarm (99.2 %)"), std::string::npos);
  EXPECT_NE(html.find("href=\"mutants/specificity/specificity.html\""), std::string::npos);
  const std::string markdown = read_text(folder / "report.md");
  EXPECT_NE(markdown.find("Specificity: 238 of 240 honest runs"), std::string::npos);
  EXPECT_NE(markdown.find("Graded checks that killed no mutant: spec.cells.cpu."), std::string::npos);
}

TEST_F(ReportFiles, HtmlNamesEveryCaseAndEscapes) {
  const Report report = sample_report();
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");
  for (const CaseResult& result : report.cases) {
    EXPECT_NE(html.find(result.name), std::string::npos) << result.name;
    EXPECT_NE(html.find(fmt::format("id=\"case-{}\"", result.name)), std::string::npos) << result.name;
  }
  EXPECT_NE(html.find("&lt;b&gt;far&lt;/b&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<b>far"), std::string::npos);
  EXPECT_NE(html.find("llvmpipe (LLVM 15.0.6, 256 bits)"), std::string::npos);
  EXPECT_NE(html.find("<img loading=\"lazy\" src=\"erosion.thermal.cardinal.volcano/before.png\""), std::string::npos);
  EXPECT_EQ(html.find("src=\"erosion.thermal.cardinal.volcano/gpu.exr\""), std::string::npos);
  EXPECT_NE(html.find("plot unavailable: test"), std::string::npos);
  EXPECT_NE(html.find("64³"), std::string::npos);
  EXPECT_NE(html.find("not run: triangles need 444 MB"), std::string::npos);
  EXPECT_NE(html.find("<td>2 compute passes per iteration</td>"), std::string::npos) << "a timed row's detail";
  EXPECT_EQ(html.find("<script"), std::string::npos);
}

// A value shown without a bound wears a neutral `info` badge, never a green pass; a bounded
// passing check keeps its pass.
TEST_F(ReportFiles, HtmlShowsAValueWithoutABoundAsInfo) {
  Report report = sample_report();
  report.cases.resize(1);
  report.cases[0].status = Outcome::pass;
  report.cases[0].checks = {informative_check("parity.shown_only", 1.5, "shown"),
                            bounded_check("parity.bounded", 0.5, 1.0, std::nullopt, "bounded")};
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");
  const auto row_of = [&](const std::string& name) {
    const auto start = html.find("<td>" + name + "</td>");
    return start == std::string::npos ? std::string() : html.substr(start, html.find("</tr>", start) - start);
  };
  EXPECT_THAT(row_of("parity.shown_only"), ::testing::HasSubstr("<span class=\"badge info\">info</span>"));
  EXPECT_THAT(row_of("parity.bounded"), ::testing::HasSubstr("<span class=\"badge pass\">pass</span>"));
}

// Every map carries a colour bar in its unit (issue 37): the HTML draws the palette the picture
// was drawn with, labels its ends (and 0 of a diverging map) in the unit, and report.json keeps
// the scale so a report read back (diff-reports, merge) draws the same bar.
TEST_F(ReportFiles, MapsCarryAColourBarInTheirUnit) {
  Report report = sample_report();
  report.cases.resize(1);
  Heightmap before(6, 4, 2.0), after(6, 4, 2.0);
  after.at(1, 1) = 2.5;
  const DifferenceStats change = write_difference_image(before, after, folder / "change.png");
  // The input is 870 m wide (87 cells of 10 m): its scale bar is the round length below a quarter
  // of that, 200 m, drawn at 200/870 of the picture's width.
  report.cases[0].artifacts = {{"x/before.png", "image", "input", height_scale(-3.0, 11.6, "m"), map_width_m(87, 10.0)},
                               {"x/change.png", "image", "after - before", difference_scale(change, "m")},
                               {"x/view.png", "image", "a rendered view"}};
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");
  EXPECT_THAT(html, ::testing::HasSubstr("<span>-3\u202fm</span><span>11.6\u202fm</span>"));
  EXPECT_THAT(html, ::testing::HasSubstr("<span>-0.5\u202fm</span><span>0\u202fm</span><span>0.5\u202fm</span>"));
  // The diverging bar's ends are the picture's own colours at ±scale: blue and red.
  const Picture picture = read_picture(folder / "change.png");
  const auto& colours = report.cases[0].artifacts[1].scale->colours;
  const unsigned char* red = picture.at(1 * 43 + 21, 1 * 43 + 21);  // the cell at +scale (6 cells enlarged by 43)
  for (int channel = 0; channel < 3; ++channel) {
    EXPECT_NEAR(colours.back()[channel] * 255.0f, red[channel], 1.0f) << channel;
  }
  EXPECT_GT(colours.front()[2], colours.front()[0]);  // blue at −scale
  // A rendered view has no bar: three figures, two bars.
  std::size_t bars = 0;
  for (auto at = html.find("class=\"colourbar\""); at != std::string::npos; at = html.find("class=\"colourbar\"", at + 1)) {
    ++bars;
  }
  EXPECT_EQ(bars, 2u);
  EXPECT_THAT(html, ::testing::HasSubstr("<span class=\"bar\" style=\"width: 22.989%\"></span><span>200 m</span>"));
  EXPECT_EQ(html.find("class=\"scalebar\""), html.rfind("class=\"scalebar\"")) << "only the map with a width has one";
  EXPECT_THAT(report_detail::scale_bar(map_width_m(4, 2500.0)), ::testing::HasSubstr("<span>2 km</span>"));  // 10 km wide
  EXPECT_EQ(report_detail::scale_bar(map_width_m(0, 1.0)), "") << "no width, no bar";

  write_report_json(report, folder / "report.json");
  const Report read = report_from_json(json::parse(read_text(folder / "report.json")));
  ASSERT_TRUE(read.cases.at(0).artifacts.at(1).scale.has_value());
  EXPECT_EQ(read.cases[0].artifacts[1].scale->unit, "m");
  EXPECT_DOUBLE_EQ(read.cases[0].artifacts[1].scale->high, 0.5);
  EXPECT_EQ(read.cases[0].artifacts[1].scale->colours, colours);
  EXPECT_FALSE(read.cases[0].artifacts[2].scale.has_value());
  EXPECT_EQ(read.cases[0].artifacts[0].width_m, std::optional<double>(870.0));
  EXPECT_FALSE(read.cases[0].artifacts[1].width_m.has_value());
  // A hand-edited report: channels beyond [0, 1] (or float's range) are clamped, a colour that is not
  // three numbers leaves the bar grey; neither breaks the page.
  json edited = json::parse(read_text(folder / "report.json"));
  auto& details = edited["cases"][0]["artifact_details"];
  details[0]["scale"]["colours"] = json::array({json::array({1e300, -1.0, 0.5})});
  details[1]["scale"]["colours"] = json::array({json::array({"red", 0, 0})});
  details[0]["width_m"] = -5.0;
  const Report hostile = report_from_json(edited);
  EXPECT_FALSE(hostile.cases[0].artifacts[0].width_m.has_value()) << "a negative width draws no bar";
  EXPECT_EQ(hostile.cases[0].artifacts[0].scale->colours, (std::vector<std::array<float, 3>>{{1.0f, 0.0f, 0.5f}}));
  EXPECT_TRUE(hostile.cases[0].artifacts[1].scale->colours.empty());
  write_report_html(hostile, folder / "index.html");
}

// What failed comes first (issue 37): a table of every check that did not pass, unexpected before
// expected, with value, bound and reason, above the Cases table; the Cases table names each case's
// failing checks; a case section opens with its checks, failing rows first, before any picture; an
// expected outcome carries its reason; skips are counted by reason; every image loads lazily.
TEST_F(ReportFiles, HtmlPutsWhatFailedFirst) {
  Report report = sample_report();
  Check listed = make_check("mesh.closed.cpu", 12.0, 0.0, Outcome::fail, "12 boundary edges");
  listed.expected = Outcome::fail;
  listed.expectation = "the seed's marching cubes leaves holes";
  report.cases[5].checks = {listed};
  report.cases[1].checks.push_back(make_check("mass.relative_drift.gpu", 1e-7, 1e-5, Outcome::pass));
  std::swap(report.cases[1].checks.front(), report.cases[1].checks.back());  // the failing check last
  report.cases[1].artifacts = {{"erosion.thermal.diagonal.volcano/after.png", "image", "after"}};
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");
  const auto failures = html.find("<section class=\"failures\">");
  const auto failures_end = html.find("</section>", failures);
  ASSERT_NE(failures, std::string::npos);
  EXPECT_LT(failures, html.find("<h2>Cases</h2>"));
  // The environment is one collapsed line above it.
  EXPECT_LT(html.find("<details class=\"more\"><summary>Environment"), html.find("<table class=\"environment\">"));
  const std::string block = html.substr(failures, failures_end - failures);
  const auto unexpected = block.find("<td>parity.max_abs</td><td class=\"num\">0.5</td><td class=\"num\">≤ 0.001</td>");
  const auto listed_row = block.find("<td>mesh.closed.cpu</td>");
  EXPECT_NE(unexpected, std::string::npos) << block;
  EXPECT_NE(listed_row, std::string::npos) << block;
  EXPECT_LT(unexpected, listed_row) << "unexpected failures come before expected ones";
  EXPECT_NE(block.find("the seed&#39;s marching cubes leaves holes"), std::string::npos) << block;
  EXPECT_NE(block.find("<td>parity.rms</td>"), std::string::npos) << "a warn is listed too";
  EXPECT_NE(block.find("1 check: no GL context"), std::string::npos) << "skips counted by reason";
  EXPECT_NE(block.find("shader failed to compile"), std::string::npos) << "an error without checks says why";
  EXPECT_EQ(block.find("mass.relative_drift.gpu"), std::string::npos) << "a pass is not listed";
  const auto row = html.find("<a href=\"#case-erosion.thermal.diagonal.volcano\">", html.find("<h2>Cases</h2>"));
  EXPECT_NE(html.substr(row, html.find("</tr>", row) - row).find("<td>parity.max_abs</td>"), std::string::npos);
  const auto section = html.find("id=\"case-erosion.thermal.diagonal.volcano\"");
  const auto checks = html.find("<table class=\"checks\">", section);
  EXPECT_LT(checks, html.find("<img", section)) << "the verdicts come before the pictures";
  EXPECT_LT(html.find("<td>parity.max_abs</td>", checks), html.find("<td>mass.relative_drift.gpu</td>", checks))
      << "failing rows first";
  for (auto at = html.find("<img"); at != std::string::npos; at = html.find("<img", at + 1)) {
    const std::string lazy = "<img loading=\"lazy\" src=";
    EXPECT_EQ(html.compare(at, lazy.size(), lazy), 0) << html.substr(at, 60);
  }
}

TEST_F(ReportFiles, MarkdownHasSummaryDetailsAndBenchmarks) {
  write_report_markdown(sample_report(), folder / "report.md");
  const std::string markdown = read_text(folder / "report.md");
  // Read in a terminal: markup in a detail is escaped CommonMark's way, never as an HTML entity.
  EXPECT_NE(markdown.find("\\<b>far\\</b> apart & off"), std::string::npos) << markdown;
  for (const char* entity : {"&lt;", "&gt;", "&amp;", "&#", "&quot;"}) EXPECT_EQ(markdown.find(entity), std::string::npos) << entity;
  EXPECT_NE(markdown.find("RUN FAILED"), std::string::npos);
  EXPECT_NE(markdown.find("### erosion.thermal.diagonal.volcano — fail"), std::string::npos);
  EXPECT_EQ(markdown.find("### erosion.thermal.cardinal.volcano"), std::string::npos);  // all checks pass
  // Each backend's device once above the table; the GPU's speed-up over the CPU reference of the
  // same size (120 ms / 12 ms); B/cell, × floor (median over floor), × peer (and which), note
  EXPECT_NE(markdown.find("Devices: cpu: Intel Xeon; gpu: llvmpipe\n"), std::string::npos) << markdown;
  EXPECT_NE(markdown.find("| erosion.thermal | gpu | 256×256 | 50 | 5 | 12 | 10× | 273 |  | 52 | 2× |  | 2 compute passes per iteration |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| cave.marching_tetrahedra | cpu | 64³ | 1 | 3 | 50 |  | 5.24 | 12.5 |  |  | 4× VTK vtkFlyingEdges3D |  |"), std::string::npos)
      << markdown;
  EXPECT_NE(markdown.find("| 256³ | 1 | 0 | — |  | — | — |  |  |  | not run: triangles need 444 MB"), std::string::npos);
  // A merged report whose GPU rows come from two machines names the device in every row.
  Report merged = sample_report();
  for (BenchmarkRow& row : merged.benchmarks) {
    if (row.backend == "gpu" && row.algorithm == "cave.marching_tetrahedra") row.device = "NVIDIA H100";
  }
  write_report_markdown(merged, folder / "merged.md");
  const std::string merged_markdown = read_text(folder / "merged.md");
  EXPECT_EQ(merged_markdown.find("Devices:"), std::string::npos);
  EXPECT_NE(merged_markdown.find("| erosion.thermal | gpu | llvmpipe | 256×256 |"), std::string::npos) << merged_markdown;
  EXPECT_NE(markdown.find("not run: triangles need 444 MB"), std::string::npos);
  EXPECT_NE(markdown.find("| 2 compute passes per iteration |"), std::string::npos);
  EXPECT_NE(markdown.find("| nan |"), std::string::npos);
}

// ---- image comparisons (rendered twins side by side) --------------------------------------------

// A rendered case as compare/render_case.cpp writes it: the four pictures and the image checks (one
// failing, so that the tile's colour can be told apart).
CaseResult rendered_case() {
  CaseResult result = make_case(
      "render.terrain.volcano", "render.terrain",
      {make_check("mesh.closed.cpu", 0.0, 0.0, Outcome::pass), make_check("determinism.gpu", 0.0, 0.0, Outcome::pass),
       make_check("image.psnr.gpu_vs_cpu", -92.72, -40.0, Outcome::pass),
       make_check("image.share_beyond_tolerance_outside_edges.gpu_vs_cpu", 0.0125, 0.005, Outcome::fail),
       make_check("image.max_abs.gpu_vs_cpu", 4.0 / 255.0, std::nullopt, Outcome::pass),
       make_check("image.rms.gpu_vs_cpu", 2.3e-5, std::nullopt, Outcome::pass),
       make_check("image.share_beyond_tolerance.gpu_vs_cpu", 0.02, std::nullopt, Outcome::pass)});
  const std::string folder = result.name + "/";
  result.artifacts = {{folder + "cpu.png", "image", "CPU reference (double), rounded to 8 bits"},
                      {folder + "gpu.png", "image", "GPU (GL pipeline, RGBA8 target)"},
                      {folder + "gpu_vs_cpu_heat.png", "image", "max |gpu - cpu| over channels, white at 0.0157"},
                      {folder + "gpu_vs_cpu_mask.png", "image", "3×3-tolerant verdicts"},
                      {folder + "solid.ply", "mesh", "the terrain solid"}};
  return result;
}

// The same case run with --backend cpu: the reference alone and the skipped GPU checks.
CaseResult reference_only_case() {
  CaseResult result = make_case("render.phong.bunny00", "render.phong",
                                {make_check("image.gpu_vs_cpu", std::nan(""), std::nullopt, Outcome::skip,
                                            "GPU backend not requested (--backend cpu)"),
                                 make_check("determinism.gpu", std::nan(""), std::nullopt, Outcome::skip,
                                            "GPU backend not requested (--backend cpu)")});
  result.artifacts = {{"render.phong.bunny00/cpu.png", "image", "CPU reference (double)"}};
  return result;
}

// A heightmap render: a signed difference picture, no mask, parity checks.
CaseResult heightmap_render_case() {
  CaseResult result = make_case("render.heightmap_from_mesh.cow", "render.heightmap_from_mesh",
                                {make_check("parity.interior_max_abs.gpu_vs_cpu", 1.16e-5, 2.93e-4, Outcome::pass),
                                 make_check("parity.coverage_share.cpu", 0.47, std::nullopt, Outcome::pass)});
  result.artifacts = {{"render.heightmap_from_mesh.cow/cpu.png", "image", "CPU reference"},
                      {"render.heightmap_from_mesh.cow/gpu.png", "image", "GPU"},
                      {"render.heightmap_from_mesh.cow/gpu_vs_cpu.png", "image", "GPU - reference"}};
  return result;
}

// A field twin: before / after pictures and a noise field's cpu.png, gpu.png, gpu_vs_double.png
// are not rendered-image comparisons.
CaseResult field_case() {
  CaseResult result = make_case("noise.perlin.plain", "noise.perlin",
                                {make_check("parity.max_abs.gpu_vs_double", 1e-7, 1e-6, Outcome::pass)});
  result.artifacts = {{"noise.perlin.plain/cpu.png", "image", "CPU reference (double)"},
                      {"noise.perlin.plain/gpu.png", "image", "GPU"},
                      {"noise.perlin.plain/gpu_vs_double.png", "image", "GPU - reference"}};
  return result;
}

using report_detail::image_comparison;
using report_detail::metric_text;

TEST(ImageComparisons, PanelsAreFoundByFileName) {
  const CaseResult rendered = rendered_case();
  const auto comparison = image_comparison(rendered);
  ASSERT_TRUE(comparison);
  EXPECT_EQ(comparison->reference, &rendered.artifacts[0]);
  EXPECT_EQ(comparison->gpu, &rendered.artifacts[1]);
  EXPECT_EQ(comparison->difference, &rendered.artifacts[2]);
  EXPECT_EQ(comparison->mask, &rendered.artifacts[3]);
  EXPECT_TRUE(comparison->gpu_missing_reason.empty());
  EXPECT_TRUE(comparison->others.empty());  // the mesh is not an image
  ASSERT_EQ(comparison->metrics.size(), 5u);  // the *.gpu_vs_cpu checks, in order
  EXPECT_EQ(comparison->metrics[0]->name, "image.psnr.gpu_vs_cpu");
  EXPECT_EQ(comparison->metrics[4]->name, "image.share_beyond_tolerance.gpu_vs_cpu");

  const CaseResult reference_only = reference_only_case();
  const auto alone = image_comparison(reference_only);
  ASSERT_TRUE(alone);
  EXPECT_EQ(alone->gpu, nullptr);
  EXPECT_EQ(alone->difference, nullptr);
  EXPECT_EQ(alone->gpu_missing_reason, "GPU backend not requested (--backend cpu)");
  EXPECT_TRUE(alone->metrics.empty());

  const CaseResult heightmap = heightmap_render_case();
  const auto three = image_comparison(heightmap);
  ASSERT_TRUE(three);
  EXPECT_EQ(three->difference, &heightmap.artifacts[2]);
  EXPECT_EQ(three->mask, nullptr);
  ASSERT_EQ(three->metrics.size(), 1u);

  EXPECT_FALSE(image_comparison(field_case()));
  EXPECT_FALSE(image_comparison(sample_report().cases[0]));  // before.png and an EXR
  // A file that merely ends like cpu.png is not the reference.
  CaseResult lookalike = rendered_case();
  lookalike.artifacts[0].path = "render.terrain.volcano/not_cpu.png";
  EXPECT_FALSE(image_comparison(lookalike));
}

TEST(ImageComparisons, MetricsAreShownInTheirUnits) {
  const auto text = [](const char* name, double value, std::optional<double> threshold) {
    return metric_text(make_check(name, value, threshold, Outcome::pass));
  };
  const auto psnr = text("image.psnr.gpu_vs_cpu", -92.72, -40.0);
  EXPECT_EQ(psnr.label, "PSNR");
  EXPECT_EQ(psnr.value, "92.7 dB");
  EXPECT_EQ(psnr.bound, "≥ 40 dB");
  EXPECT_EQ(text("image.psnr.gpu_vs_cpu", -std::numeric_limits<double>::infinity(), -40.0).value, "∞ dB (identical)");
  const auto share = text("image.share_beyond_tolerance_outside_edges.gpu_vs_cpu", 0.0125, 0.005);
  EXPECT_EQ(share.value, "1.25 %");
  EXPECT_EQ(share.bound, "≤ 0.5 %");
  const auto max_abs = text("image.max_abs.gpu_vs_cpu", 4.0 / 255.0, std::nullopt);
  EXPECT_EQ(max_abs.value, "0.0157 (4/255)");
  EXPECT_EQ(max_abs.bound, "");
  EXPECT_EQ(text("image.rms.gpu_vs_cpu", 2.3e-5, std::nullopt).value, "2.3e-05");
  const auto parity = text("parity.interior_max_abs.gpu_vs_cpu", 1.16e-5, 2.93e-4);
  EXPECT_EQ(parity.label, "interior max abs");
  EXPECT_EQ(parity.bound, "≤ 0.000293");
}

// The section of one case in index.html.
std::string case_section(const std::string& html, const std::string& name) {
  const auto start = html.find(fmt::format("id=\"case-{}\"", name));
  if (start == std::string::npos) return "";
  return html.substr(start, html.find("</section>", start) - start);
}

// --backend cpu: the GPU checks the user left out are not "what did not pass" (one neutral line
// counts them) and come after the checks that ran in the case's table.
TEST_F(ReportFiles, HtmlListsChecksLeftOutByRequestLastAndNotAsFailures) {
  Report report;
  CaseResult alone = reference_only_case();
  alone.checks.push_back(make_check("mass.relative_drift.cpu", 0.0, 1e-15, Outcome::pass));
  alone.status = case_outcome(alone);
  report.cases = {alone};
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");
  const auto failures = html.find("<section class=\"failures\">");
  const std::string block = html.substr(failures, html.find("</section>", failures) - failures);
  EXPECT_NE(block.find("Not run, as asked: 2 checks (GPU backend not requested (--backend cpu))"), std::string::npos)
      << block;
  EXPECT_EQ(block.find("badge skip"), std::string::npos) << block;
  EXPECT_NE(block.find("Every check that ran passed."), std::string::npos) << block;
  const auto checks = html.find("<table class=\"checks\">");
  EXPECT_LT(html.find("<td>mass.relative_drift.cpu</td>", checks), html.find("<td>image.gpu_vs_cpu</td>", checks));
  EXPECT_EQ(alone.status, Outcome::pass);
}

TEST_F(ReportFiles, HtmlShowsRenderedTwinsSideBySideWithTheirMetrics) {
  Report report;
  report.environment = sample_report().environment;
  report.cases = {rendered_case(), reference_only_case(), heightmap_render_case(), field_case(),
                  sample_report().cases[0]};
  write_report_html(report, folder / "index.html");
  const std::string html = read_text(folder / "index.html");

  const std::string rendered = case_section(html, "render.terrain.volcano");
  ASSERT_FALSE(rendered.empty());
  ASSERT_EQ(count_of(rendered, "<div class=\"comparison\">"), 1);
  // The checks first (what failed before the pictures), then one row: reference, GPU, difference,
  // verdicts, in that order, each titled and captioned, then the parameters.
  std::vector<std::size_t> at;
  for (const char* needle : {"<table class=\"checks\">", "<div class=\"role\">Reference (CPU)</div><a href=\"render.terrain.volcano/cpu.png\">",
                             "<div class=\"role\">GPU</div><a href=\"render.terrain.volcano/gpu.png\">",
                             "<div class=\"role\">Difference</div><a href=\"render.terrain.volcano/gpu_vs_cpu_heat.png\">",
                             "<div class=\"role\">Verdicts</div><a href=\"render.terrain.volcano/gpu_vs_cpu_mask.png\">",
                             "<div class=\"metrics\">", "<dl class=\"params\">"}) {
    at.push_back(rendered.find(needle));
    EXPECT_NE(at.back(), std::string::npos) << needle;
  }
  EXPECT_TRUE(std::is_sorted(at.begin(), at.end()));
  EXPECT_NE(rendered.find("<figcaption>GPU (GL pipeline, RGBA8 target)</figcaption>"), std::string::npos);
  // Each picture appears once: not again in the generic row; the mesh stays a link.
  for (const char* picture : {"cpu.png", "gpu.png", "gpu_vs_cpu_heat.png", "gpu_vs_cpu_mask.png"}) {
    EXPECT_EQ(count_of(html, fmt::format("src=\"render.terrain.volcano/{}\"", picture)), 1) << picture;
  }
  EXPECT_EQ(rendered.find("<div class=\"figures\">"), std::string::npos);
  EXPECT_NE(rendered.find("<a href=\"render.terrain.volcano/solid.ply\">"), std::string::npos);
  // The metrics under the pictures: five tiles coloured by outcome, with their units and bounds.
  const std::string metrics = rendered.substr(at[5], at[6] - at[5]);
  EXPECT_EQ(count_of(metrics, "<div class=\"metric "), 5);
  EXPECT_EQ(count_of(metrics, "<div class=\"metric fail\""), 1);
  EXPECT_NE(metrics.find("<div class=\"label\">PSNR</div><div class=\"value\">92.7 dB</div>"
                         "<div class=\"bound\">≥ 40 dB · pass</div>"),
            std::string::npos)
      << metrics;
  EXPECT_NE(metrics.find("<div class=\"value\">1.25 %</div><div class=\"bound\">≤ 0.5 % · fail</div>"),
            std::string::npos)
      << metrics;
  EXPECT_NE(metrics.find("0.0157 (4/255)"), std::string::npos);
  EXPECT_EQ(metrics.find("mesh.closed"), std::string::npos);  // not an image metric
  // The three values without a bound are information, never a green pass.
  EXPECT_EQ(count_of(metrics, "<div class=\"metric info\""), 3) << metrics;
  EXPECT_EQ(count_of(metrics, " · pass</div>"), 1) << "only PSNR is a graded pass";

  // Reference only: the GPU panel says why, no difference or verdict panel, no metrics.
  const std::string alone = case_section(html, "render.phong.bunny00");
  EXPECT_NE(alone.find("<div class=\"placeholder\">not run: GPU backend not requested (--backend cpu)</div>"),
            std::string::npos)
      << alone;
  EXPECT_EQ(alone.find("Difference"), std::string::npos);
  EXPECT_EQ(alone.find("<div class=\"metrics\">"), std::string::npos);

  // Heightmap render: three panels, its parity metric under them.
  const std::string heightmap = case_section(html, "render.heightmap_from_mesh.cow");
  EXPECT_EQ(count_of(heightmap, "<figure class=\"panel\">"), 3);
  EXPECT_EQ(heightmap.find("Verdicts"), std::string::npos);
  EXPECT_NE(heightmap.find("<div class=\"label\">interior max abs</div>"), std::string::npos);

  // Other cases keep their pictures in the generic row, in their order.
  for (const std::string name : {"noise.perlin.plain", "erosion.thermal.cardinal.volcano"}) {
    const std::string section = case_section(html, name);
    EXPECT_EQ(section.find("class=\"comparison\""), std::string::npos) << name;
    EXPECT_NE(section.find("<div class=\"figures\">"), std::string::npos) << name;
  }
  const std::string noise = case_section(html, "noise.perlin.plain");
  EXPECT_LT(noise.find("noise.perlin.plain/cpu.png"), noise.find("noise.perlin.plain/gpu_vs_double.png"));
}

// ---- pictures ----------------------------------------------------------------------------------

using Pictures = TemporaryFolder;

bool reddish(const unsigned char* rgb) { return rgb[0] > 150 && rgb[1] < 100 && rgb[2] < 100; }
bool bluish(const unsigned char* rgb) { return rgb[2] > 200 && rgb[2] > rgb[0] + 50; }
bool white(const unsigned char* rgb) { return rgb[0] == 255 && rgb[1] == 255 && rgb[2] == 255; }
bool grey(const unsigned char* rgb) { return rgb[0] == rgb[1] && rgb[1] == rgb[2] && rgb[0] > 100 && rgb[0] < 230; }

TEST_F(Pictures, DifferenceStatsAndColours) {
  Heightmap a(8, 6, 10.0);
  Heightmap b = a;
  b.at(2, 3) += 2.0;
  b.at(5, 1) -= 1.0;
  const DifferenceStats stats = write_difference_image(a, b, folder / "difference.png");
  EXPECT_DOUBLE_EQ(stats.max_abs, 2.0);
  EXPECT_DOUBLE_EQ(stats.rms, std::sqrt(5.0 / 48.0));
  EXPECT_DOUBLE_EQ(stats.scale_used, 2.0);
  EXPECT_EQ(stats.compared_cells, 48u);

  const Picture picture = read_picture(folder / "difference.png");
  ASSERT_EQ(picture.channels, 3);
  EXPECT_EQ(picture.width, 256);  // 8 cells enlarged by 32
  EXPECT_EQ(picture.height, 192);
  EXPECT_TRUE(reddish(picture.at(2 * 32 + 16, 3 * 32 + 16)));
  EXPECT_TRUE(bluish(picture.at(5 * 32 + 16, 1 * 32 + 16)));
  EXPECT_TRUE(white(picture.at(0, 0)));
}

TEST_F(Pictures, DifferenceWithMaskNanAndGivenScale) {
  Heightmap a(4, 4, 0.0);
  a.valid.assign(16, 1);
  a.valid[a.index(0, 0)] = 0;
  Heightmap b(4, 4, 0.0);
  b.at(0, 0) = 100.0;  // no data in a: not compared
  b.at(3, 3) = std::numeric_limits<double>::quiet_NaN();
  b.at(1, 2) = 0.5;
  const DifferenceStats stats = write_difference_image(a, b, folder / "difference.png", 4.0);
  EXPECT_EQ(stats.compared_cells, 15u);
  EXPECT_TRUE(std::isinf(stats.max_abs));
  EXPECT_DOUBLE_EQ(stats.scale_used, 4.0);
  const Picture picture = read_picture(folder / "difference.png");
  EXPECT_EQ(picture.width, 256);
  EXPECT_TRUE(grey(picture.at(10, 10)));
  const unsigned char* nan_pixel = picture.at(3 * 64 + 32, 3 * 64 + 32);
  EXPECT_EQ(nan_pixel[0] + nan_pixel[1] + nan_pixel[2], 0);
  const unsigned char* small = picture.at(1 * 64 + 32, 2 * 64 + 32);  // 0.5 of scale 4: pale red
  EXPECT_GT(small[0], small[2] + 20);
  EXPECT_GT(small[2], 200);
}

TEST_F(Pictures, AllZeroDifferenceIsWhite) {
  const Heightmap a(87, 61, 3.0);
  const DifferenceStats stats = write_difference_image(a, a, folder / "difference.png");
  EXPECT_EQ(stats.max_abs, 0.0);
  EXPECT_EQ(stats.scale_used, 0.0);
  const Picture picture = read_picture(folder / "difference.png");
  EXPECT_EQ(picture.width, 87 * 3);
  EXPECT_EQ(picture.height, 61 * 3);
  EXPECT_TRUE(std::all_of(picture.pixels.begin(), picture.pixels.end(), [](unsigned char v) { return v == 255; }));
}

TEST_F(Pictures, LargeGridsAreReducedKeepingSpikes) {
  Heightmap a(2100, 30, 0.0);
  Heightmap b = a;
  b.at(1000, 15) = 1.0;  // a single cell in a 3 x 3 block
  write_difference_image(a, b, folder / "difference.png");
  const Picture difference = read_picture(folder / "difference.png");
  EXPECT_EQ(difference.width, 700);
  EXPECT_EQ(difference.height, 10);
  EXPECT_TRUE(reddish(difference.at(1000 / 3, 15 / 3)));
  write_height_image(b, 0.0, 1.0, folder / "height.png");
  const Picture heights = read_picture(folder / "height.png");
  EXPECT_EQ(heights.width, 700);
  EXPECT_EQ(heights.height, 10);
}

TEST_F(Pictures, HeightImageSizeShadingAndNoData) {
  Heightmap cone(87, 61, 0.0);
  cone.cell_size_x = cone.cell_size_y = 10.0;
  cone.valid.assign(cone.size(), 1);
  for (int y = 0; y < cone.height; ++y) {
    for (int x = 0; x < cone.width; ++x) cone.at(x, y) = std::max(0.0, 300.0 - 10.0 * std::hypot(x - 43, y - 30));
  }
  for (int x = 0; x < 10; ++x) cone.valid[cone.index(x, 0)] = 0;
  const double exaggeration = write_height_image(cone, 0.0, 300.0, folder / "height.png");
  EXPECT_GT(exaggeration, 0.0);
  const Picture picture = read_picture(folder / "height.png");
  EXPECT_EQ(picture.width, 261);
  EXPECT_EQ(picture.height, 183);
  EXPECT_TRUE(grey(picture.at(1, 1)));
  // The north-west flank faces the light, the south-east flank faces away.
  const unsigned char* lit = picture.at((43 - 10) * 3, (30 - 10) * 3);
  const unsigned char* shadowed = picture.at((43 + 10) * 3, (30 + 10) * 3);
  EXPECT_GT(lit[0] + lit[1] + lit[2], shadowed[0] + shadowed[1] + shadowed[2] + 60);
  EXPECT_EQ(write_height_image(cone, 0.0, 300.0, folder / "again.png", exaggeration), exaggeration);
}

TEST_F(Pictures, FlatAndSingleCellGrids) {
  EXPECT_EQ(write_height_image(Heightmap(1, 1, 5.0), 5.0, 5.0, folder / "one.png"), 1.0);
  const Picture one = read_picture(folder / "one.png");
  EXPECT_EQ(one.width, 256);
  EXPECT_EQ(one.height, 256);
  EXPECT_EQ(write_height_image(Heightmap(300, 2, 0.0), 0.0, 1.0, folder / "flat.png"), 1.0);
  EXPECT_EQ(read_picture(folder / "flat.png").height, 2);
}

TEST_F(Pictures, MismatchedGridsThrow) {
  EXPECT_THROW(write_difference_image(Heightmap(4, 4), Heightmap(4, 5), folder / "d.png"), std::invalid_argument);
}

// ---- plot ---------------------------------------------------------------------------------------

using Plots = TemporaryFolder;

TEST_F(Plots, BenchmarkPlotIsAPng) {
  std::vector<BenchmarkRow> rows;
  for (int size : {64, 128, 256, 512}) {
    const double cells = static_cast<double>(size) * size * 50;
    rows.push_back({.algorithm = "erosion.thermal", .backend = "cpu", .size = size, .iterations = 50, .reps = 3,
                    .median_ms = cells * 4e-6, .mcell_iterations_per_s = cells / (cells * 4e-3), .device = "Intel Xeon"});
    rows.push_back({.algorithm = "erosion.thermal", .backend = "gpu", .size = size, .iterations = 50, .reps = 5,
                    .median_ms = 1.0 + cells * 2e-7, .mcell_iterations_per_s = cells / ((1.0 + cells * 2e-7) * 1e3),
                    .device = "llvmpipe"});
  }
  std::string reason;
  const auto plot = plot_benchmarks(rows, folder, reason);
  if (!plot && reason.starts_with("no Python with matplotlib")) GTEST_SKIP() << reason;
  ASSERT_TRUE(plot) << reason;
  EXPECT_EQ(plot->path, "timings.png");
  EXPECT_EQ(plot->kind, "plot");
  const Picture picture = read_picture(folder / plot->path);
  EXPECT_GT(picture.width, 0);
  EXPECT_GT(picture.height, 0);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);
}

TEST_F(Plots, NoRowsGiveAReason) {
  std::string reason;
  EXPECT_FALSE(plot_benchmarks({}, folder, reason));
  EXPECT_EQ(reason, "no benchmark rows");
}

}  // namespace
// A user's image (run --candidate) gets the comparison panel under its own name.
TEST_F(ReportFiles, HtmlShowsACandidateImageBesideTheReference) {
  CaseResult result = make_case("render.phong.mutant_probe.quad", "render.phong",
                                {make_check("image.psnr.candidate_vs_cpu", -30.6, -40.0, Outcome::fail),
                                 make_check("image.max_abs.candidate_vs_cpu", 0.157, std::nullopt, Outcome::pass)});
  const std::string prefix = result.name + "/";
  result.artifacts = {{prefix + "cpu.png", "image", "CPU reference"},
                      {prefix + "candidate.png", "image", "candidate mine.png"},
                      {prefix + "candidate_vs_cpu_heat.png", "image", "max |candidate - cpu|"},
                      {prefix + "candidate_vs_cpu_mask.png", "image", "verdicts"}};
  Report report;
  report.environment = sample_report().environment;
  report.cases = {result};
  write_report_html(report, folder / "index.html");
  const std::string section = case_section(read_text(folder / "index.html"), result.name);
  EXPECT_NE(section.find("<div class=\"role\">Candidate</div><a href=\"render.phong.mutant_probe.quad/candidate.png\">"),
            std::string::npos)
      << section;
  EXPECT_NE(section.find("<div class=\"role\">Verdicts</div>"), std::string::npos);
  EXPECT_NE(section.find("<div class=\"label\">max |candidate − cpu|</div>"), std::string::npos) << section;
  EXPECT_EQ(section.find("<div class=\"figures\">"), std::string::npos) << "no picture left over";
}

// A case with more checks than a screen holds lists what needs attention in its table and keeps
// the passes and the values without a bound in two collapsed, counted lists after it.
TEST_F(ReportFiles, HtmlCollapsesTheManyPassesOfACase) {
  std::vector<Check> checks;
  for (int k = 0; k < 20; ++k) checks.push_back(make_check(fmt::format("parity.shadow.f{}.gpu_vs_float", k), 0.0, 0.0, Outcome::pass));
  for (int k = 0; k < 5; ++k) checks.push_back(make_check(fmt::format("parity.f{}.rms.gpu_vs_double", k), 1e-7, std::nullopt, Outcome::pass));
  checks.push_back(make_check("mass.relative_drift.gpu", 0.5, 1e-6, Outcome::fail));
  Report report;
  report.environment = sample_report().environment;
  report.cases = {make_case("erosion.layered.cone", "erosion.layered", checks)};
  write_report_html(report, folder / "index.html");
  const std::string section = case_section(read_text(folder / "index.html"), "erosion.layered.cone");
  const auto table = section.find("<table class=\"checks\">");
  const auto failing = section.find("<td>mass.relative_drift.gpu</td>");
  const auto passes = section.find("<details class=\"more\"><summary>20 checks passed within their bounds</summary>");
  const auto values = section.find("<details class=\"more\"><summary>5 values shown without a bound (info)</summary>");
  ASSERT_NE(passes, std::string::npos) << section;
  ASSERT_NE(values, std::string::npos) << section;
  EXPECT_LT(table, failing);
  EXPECT_LT(failing, passes);
  EXPECT_LT(section.find("<td>parity.shadow.f0.gpu_vs_float</td>"), values) << "passes inside their list";
  EXPECT_GT(section.find("<td>parity.f0.rms.gpu_vs_double</td>"), values);
  // Every check is still in the page, once.
  for (const Check& check : checks) EXPECT_EQ(count_of(section, "<td>" + check.name + "</td>"), 1) << check.name;
}

}  // namespace gt
