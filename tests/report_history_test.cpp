// history (issue 15): series of report.json values over revisions and where each first drifted.
#include <chrono>
#include <fstream>
#include <sstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/report_history.hpp"
#include "core/errors.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

using json = nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

json check(const std::string& name, double value, const std::string& status, std::optional<double> threshold = {}) {
  json out = {{"name", name}, {"value", value}, {"status", status}};
  if (threshold) out["threshold"] = *threshold;
  return out;
}

json a_case(const std::string& name, const std::string& status, std::vector<json> checks, double cpu_ms = 100.0,
            double gpu_ms = 10.0) {
  return {{"name", name}, {"status", status}, {"checks", checks}, {"timings", {{"cpu_ms", cpu_ms}, {"gpu_ms", gpu_ms}}}};
}

json report(const std::string& git, const std::string& run_started, std::optional<double> calibration_ms,
            std::vector<json> cases) {
  json environment = {{"git", git}, {"run_started", run_started}};
  if (calibration_ms) environment["calibration_ms"] = *calibration_ms;
  return {{"schema", 1}, {"environment", environment}, {"cases", cases}, {"benchmarks", json::array()},
          {"summary", json::object()}};
}

// Writes `document` as folder/report.json, creating folder; returns the file.
std::filesystem::path write_report(const std::filesystem::path& folder, const json& document) {
  std::filesystem::create_directories(folder);
  const auto file = folder / "report.json";
  std::ofstream(file) << document.dump(2);
  return file;
}

// One report per day from 2026-11-01 on, each with its list of cases, in folders day0, day1, ...,
// labelled rev0, rev1, ...
void write_days(const gt::testing::TemporaryFolder& folder, const std::vector<std::vector<json>>& cases_per_day,
                std::optional<double> calibration_ms = 10.0) {
  for (std::size_t day = 0; day < cases_per_day.size(); ++day) {
    write_report(folder / ("day" + std::to_string(day)),
                 report("rev" + std::to_string(day), "2026-11-0" + std::to_string(day + 1) + "T04:13:46Z", calibration_ms,
                        cases_per_day[day]));
  }
}

std::vector<std::string> labels(const gt::History& history) {
  std::vector<std::string> out;
  for (const auto& revision : history.revisions) out.push_back(revision.label);
  return out;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ReportHistory, OrdersTheReportsByWhenTheyRanWhateverTheArgumentOrder) {
  const gt::testing::TemporaryFolder folder("report_history");
  const auto late = write_report(folder / "a", report("ccc3333-dirty", "2026-12-02T04:13:46Z", 10.0, {a_case("c", "pass", {})}));
  const auto early = write_report(folder / "b", report("aaa1111", "2026-11-30T23:59:00Z", 10.0, {a_case("c", "pass", {})}));
  const auto middle = write_report(folder / "c", report("bbb2222", "2026-12-01T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  const std::vector<std::string> expected = {"aaa1111 2026-11-30 23:59", "bbb2222 2026-12-01 00:00",
                                             "ccc3333-dirty 2026-12-02 04:13"};
  EXPECT_EQ(labels(gt::read_history({late, early, middle})), expected);
  EXPECT_EQ(labels(gt::read_history({middle, late, early})), expected);
}

TEST(ReportHistory, RunsStartedAtTheSameTimeAreOrderedByPathAndUnknownGitIsSaidSo) {
  const gt::testing::TemporaryFolder folder("report_history");
  json no_git = report("", "2026-12-02T04:13:46Z", 10.0, {a_case("c", "pass", {})});
  no_git["environment"].erase("git");
  const auto second = write_report(folder / "b", no_git);
  const auto first = write_report(folder / "a", report("unknown: git cannot read /src", "2026-12-02T04:13:46Z", 10.0,
                                                        {a_case("c", "pass", {})}));
  const auto history = gt::read_history({second, first});
  EXPECT_EQ(history.revisions[0].path, first);
  EXPECT_EQ(history.revisions[1].path, second);
  EXPECT_EQ(labels(history), (std::vector<std::string>{"unknown 2026-12-02 04:13", "unknown 2026-12-02 04:13"}));
}

TEST(ReportHistory, AReportWithoutRunStartedIsPlacedByItsFileTime) {
  const gt::testing::TemporaryFolder folder("report_history");
  json old_report = report("old", "", std::nullopt, {a_case("c", "pass", {})});
  old_report["environment"].erase("run_started");
  const auto old_file = write_report(folder / "z", old_report);
  const auto new_file = write_report(folder / "a", report("new", "2026-12-02T04:13:46Z", 10.0, {a_case("c", "pass", {})}));
  std::filesystem::last_write_time(old_file, std::filesystem::file_time_type::clock::now() - std::chrono::hours(24 * 365 * 20));
  const auto history = gt::read_history({new_file, old_file});
  EXPECT_EQ(history.revisions[0].path, old_file);
  EXPECT_TRUE(history.revisions[0].time_from_file);
  EXPECT_FALSE(history.revisions[0].calibration_ms);
  EXPECT_FALSE(history.revisions[1].time_from_file);
}

// Revision 3 (index 2) is where the check fails first; its value also moved there, and the status
// change is what is reported.
TEST(ReportHistory, AStatusChangeIsTheFirstDriftAtTheRevisionWhereItHappened) {
  const gt::testing::TemporaryFolder folder("report_history");
  write_days(folder, {{a_case("c", "pass", {check("parity.max.gpu", 1e-7, "pass", 1e-5)})},
                      {a_case("c", "pass", {check("parity.max.gpu", 1e-7, "pass", 1e-5)})},
                      {a_case("c", "fail", {check("parity.max.gpu", 3e-5, "fail", 1e-5)})},
                      {a_case("c", "fail", {check("parity.max.gpu", 3e-5, "fail", 1e-5)})}});
  const auto history = gt::read_history({folder.path()});
  ASSERT_EQ(history.revisions.size(), 4u);
  ASSERT_EQ(history.cases.size(), 1u);
  const auto& series = history.cases[0];
  ASSERT_TRUE(series.status_drift);
  EXPECT_EQ(series.status_drift->revision, 2u);
  ASSERT_EQ(series.checks.size(), 1u);
  ASSERT_TRUE(series.checks[0].drift);
  EXPECT_EQ(series.checks[0].drift->revision, 2u);
  EXPECT_EQ(series.checks[0].drift->from, "pass");
  EXPECT_EQ(series.checks[0].drift->to, "fail");
  for (const auto& timing : series.timings) EXPECT_FALSE(timing.drift) << timing.key;
}

// 1 % of the bound is the tolerance of a check with one; 1e-9 of the value's size of one without.
TEST(ReportHistory, AValueMovedWithinToleranceIsNoDriftAndBeyondItIs) {
  const gt::testing::TemporaryFolder folder("report_history");
  write_days(folder, {{a_case("c", "pass", {check("bounded", 1e-7, "pass", 1e-5), check("free", 1.0, "pass")})},
                      {a_case("c", "pass", {check("bounded", 1.5e-7, "pass", 1e-5), check("free", 1.0 + 1e-12, "pass")})},
                      {a_case("c", "pass", {check("bounded", 3.5e-7, "pass", 1e-5), check("free", 1.001, "pass")})}});
  const auto history = gt::read_history({folder.path()});
  const auto& checks = history.cases.at(0).checks;
  ASSERT_EQ(checks.size(), 2u);
  ASSERT_TRUE(checks[0].drift);
  EXPECT_EQ(checks[0].drift->revision, 2u);  // 0.5 % of the bound at revision 2, 2 % at revision 3
  EXPECT_EQ(checks[0].drift->from, "1.5e-07");
  EXPECT_EQ(checks[0].drift->to, "3.5e-07");
  ASSERT_TRUE(checks[1].drift);
  EXPECT_EQ(checks[1].drift->revision, 2u);
  EXPECT_FALSE(history.cases[0].status_drift);
}

TEST(ReportHistory, AnAbsentCheckIsSkippedNotADrift) {
  const gt::testing::TemporaryFolder folder("report_history");
  write_days(folder, {{a_case("c", "pass", {check("k", 1.0, "pass")})}, {a_case("c", "pass", {})},
                      {a_case("c", "pass", {check("k", 1.0, "pass")})}});
  const auto history = gt::read_history({folder.path()});
  const auto& points = history.cases.at(0).checks.at(0).points;
  ASSERT_EQ(points.size(), 3u);
  EXPECT_FALSE(points[1]);
  EXPECT_FALSE(history.cases[0].checks[0].drift);
}

// A machine 1.5 times slower makes the case and the calibration kernel 1.5 times slower: no drift.
// The case alone 1.5 times slower against the same kernel is (beyond diff-reports' factor 1.25).
TEST(ReportHistory, TimingsDriftAsRatiosToTheCalibrationKernel) {
  const gt::testing::TemporaryFolder folder("report_history");
  const auto slower_machine = write_report(folder / "a", report("a", "2026-11-01T00:00:00Z", 10.0, {a_case("c", "pass", {}, 100.0, 10.0)}));
  const auto same_code = write_report(folder / "b", report("b", "2026-11-02T00:00:00Z", 15.0, {a_case("c", "pass", {}, 150.0, 15.0)}));
  const auto machine_only = gt::read_history({slower_machine, same_code});
  for (const auto& timing : machine_only.cases.at(0).timings) EXPECT_FALSE(timing.drift) << timing.key;

  const auto slower_code = write_report(folder / "c", report("c", "2026-11-03T00:00:00Z", 15.0, {a_case("c", "pass", {}, 225.0, 15.0)}));
  const auto history = gt::read_history({slower_machine, same_code, slower_code});
  const auto& cpu = history.cases.at(0).timings.at(0);
  EXPECT_EQ(cpu.key, "cpu_ms");
  ASSERT_TRUE(cpu.drift);
  EXPECT_EQ(cpu.drift->revision, 2u);
  EXPECT_THAT(cpu.drift->to, HasSubstr("calibration"));
  EXPECT_THAT(cpu.drift->to, HasSubstr("1.50× slower"));
  EXPECT_FALSE(history.cases[0].timings.at(1).drift);  // gpu_ms: the same ratio to the kernel throughout
}

TEST(ReportHistory, WithoutACalibrationTimingsAreComparedInRawMillisecondsAndSaySo) {
  const gt::testing::TemporaryFolder folder("report_history");
  write_days(folder, {{a_case("c", "pass", {}, 100.0)}, {a_case("c", "pass", {}, 150.0)}}, std::nullopt);
  const auto history = gt::read_history({folder.path()});
  const auto& cpu = history.cases.at(0).timings.at(0);
  ASSERT_TRUE(cpu.drift);
  EXPECT_THAT(cpu.drift->to, HasSubstr("raw"));
}

TEST(ReportHistory, FewerThanTwoReportsOrAMissingInputIsBadInput) {
  const gt::testing::TemporaryFolder folder("report_history");
  EXPECT_THROW(gt::read_history({folder.path()}), gt::InputError);
  const auto only = write_report(folder / "one", report("a", "2026-11-01T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  EXPECT_THROW(gt::read_history({only}), gt::InputError);
  EXPECT_THROW(gt::read_history({folder.path()}), gt::InputError);
  EXPECT_THROW(gt::read_history({only, only}), gt::InputError);  // the same report twice is one revision
  EXPECT_THROW(gt::read_history({only, folder / "missing"}), gt::InputError);
}

TEST(ReportHistory, ANonReportOrAMalformedCaseIsBadInput) {
  const gt::testing::TemporaryFolder folder("report_history");
  const auto good = write_report(folder / "good", report("a", "2026-11-01T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  const auto not_a_report = write_report(folder / "other", json{{"hello", 1}});
  EXPECT_THROW(gt::read_history({good, not_a_report}), gt::InputError);
  const auto nameless = write_report(folder / "nameless", report("b", "2026-11-02T00:00:00Z", 10.0, {json{{"status", "pass"}}}));
  EXPECT_THROW(gt::read_history({good, nameless}), gt::InputError);
  const auto bad_time = write_report(folder / "time", report("b", "yesterday", 10.0, {a_case("c", "pass", {})}));
  EXPECT_THROW(gt::read_history({good, bad_time}), gt::InputError);
}

// reports/<date>/report.json one level deep and reports/<machine>/<date>/report.json two levels
// deep; a report folder's own subfolders (its cases) are not searched.
TEST(ReportHistory, FindsTheReportsOfAFolderOfReportFolders) {
  const gt::testing::TemporaryFolder folder("report_history");
  write_report(folder / "2026-11-30", report("a", "2026-11-30T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  write_report(folder / "2026-11-30" / "c", report("stray", "2026-11-29T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  write_report(folder / "ci" / "2026-12-01", report("b", "2026-12-01T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  write_report(folder / "deep" / "er" / "still", report("too deep", "2026-12-02T00:00:00Z", 10.0, {a_case("c", "pass", {})}));
  const auto history = gt::read_history({folder.path()});
  EXPECT_EQ(labels(history), (std::vector<std::string>{"a 2026-11-30 00:00", "b 2026-12-01 00:00"}));
}

TEST(ReportHistory, ThePageNamesTheDriftingCaseAndEscapesNames) {
  const gt::testing::TemporaryFolder reports("report_history");
  write_days(reports, {{a_case("steady.case", "pass", {check("x<y", 1.0, "pass")}),
                        a_case("drifting.case", "pass", {check("parity.max.gpu", 1e-7, "pass", 1e-5)})},
                       {a_case("steady.case", "pass", {check("x<y", 1.0, "pass")}),
                        a_case("drifting.case", "fail", {check("parity.max.gpu", 3e-5, "fail", 1e-5)})}});
  const auto history = gt::read_history({reports.path()});
  ASSERT_EQ(history.cases.size(), 2u);

  const gt::testing::TemporaryFolder page("report_history_page");
  gt::write_history_page(history, page.path());
  const std::string html = read_text(page / "index.html");
  ASSERT_FALSE(html.empty());
  const std::string summary = html.substr(0, html.find("<h2>Revisions</h2>"));
  EXPECT_THAT(summary, HasSubstr("drifting.case"));
  EXPECT_THAT(summary, Not(HasSubstr("steady.case")));
  EXPECT_THAT(summary, HasSubstr("#2 rev1 2026-11-02 04:13"));
  EXPECT_THAT(html, HasSubstr("x&lt;y"));
  EXPECT_THAT(html, Not(HasSubstr("x<y")));
  EXPECT_THAT(html, HasSubstr("<td class=\"fail\""));
  // Plots need a Python with matplotlib; without one the page says why each is missing.
  for (const char* name : {"steady.case", "drifting.case"}) {
    EXPECT_TRUE(std::filesystem::exists(page / (std::string(name) + ".png")) || html.find("plot unavailable: ") != std::string::npos)
        << name;
  }
}

}  // namespace
