// What a run says as it goes (compare/progress.hpp): each case's outcome when it ends, with its
// own time, failing checks, counts so far and an ETA; a "still running" line whenever the
// heartbeat passes without a line when stderr is not a terminal (a CI log, a pipe).
#include <chrono>
#include <cstdio>
#include <regex>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "compare/progress.hpp"
#include "tests/support/cli_report.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace gt {
namespace {

using namespace std::chrono_literals;

// A Progress writing into a temporary file as into a log (not a terminal); text() reads it back.
class LoggedProgress {
 public:
  explicit LoggedProgress(ProgressOptions options) : file_(std::tmpfile()) {
    options.sink = file_;
    options.terminal = false;
    progress_.emplace(static_cast<int>(options.planned.size()), std::move(options));
  }
  ~LoggedProgress() {
    progress_.reset();
    std::fclose(file_);
  }
  Progress& operator*() { return *progress_; }
  Progress* operator->() { return &*progress_; }
  void stop() { progress_.reset(); }
  std::string text() const {
    std::fflush(file_);
    std::rewind(file_);
    std::string text;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) text += static_cast<char>(c);
    return text;
  }

 private:
  std::FILE* file_;
  std::optional<Progress> progress_;
};

int count_of(const std::string& text, const std::string& part) {
  int count = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

TEST(Progress, PrintsEachOutcomeWithItsFailingChecksAsTheCaseEnds) {
  LoggedProgress progress({.planned = {"a.first", "a.second"}, .heartbeat = 3600s});
  progress->start_case("a.first");
  progress->end_case("a.first", Outcome::pass, 1.5);
  const std::string after_first = progress.text();
  EXPECT_NE(after_first.find("groundtruth: pass a.first in 1.5 s [1/2: 1 pass;"), std::string::npos) << after_first;
  progress->start_case("a.second");
  progress->end_case("a.second", Outcome::fail, 2.0, {"mass.relative_drift.gpu = 0.1 (bound 1e-06)"});
  const std::string text = progress.text();
  EXPECT_NE(text.find("groundtruth: fail a.second in 2.0 s [2/2: 1 pass, 1 fail;"), std::string::npos) << text;
  EXPECT_NE(text.find("\n    mass.relative_drift.gpu = 0.1 (bound 1e-06)\n"), std::string::npos) << text;
  // The first outcome came before the second case started, not in a summary at the end.
  EXPECT_LT(text.find("pass a.first"), text.find("[case 2/2] a.second"));
}

TEST(Progress, QuietPrintsNothing) {
  LoggedProgress progress({.quiet = true, .planned = {"a"}, .heartbeat = 20ms});
  progress->start_case("a");
  progress->stage("cpu");
  std::this_thread::sleep_for(100ms);
  progress->end_case("a", Outcome::fail, 0.1, {"x = 1"});
  progress.stop();
  EXPECT_EQ(progress.text(), "");
}

TEST(Progress, HeartbeatNamesTheRunningCaseAndStageThroughALongStage) {
  // A stage of 20 heartbeats with no other line: a line is owed at every heartbeat. Half of them is
  // the floor: the heartbeat thread may be scheduled late on a loaded 2-core CI machine, but a
  // thread that prints once, or only on stage changes (the old behaviour), stays far below it.
  const auto heartbeat = 50ms;
  LoggedProgress progress({.planned = {"erosion.slow"}, .heartbeat = heartbeat});
  progress->start_case("erosion.slow");
  progress->stage("gpu shadow steps");
  std::this_thread::sleep_for(20 * heartbeat);
  progress.stop();
  const std::string text = progress.text();
  EXPECT_GE(count_of(text, "groundtruth: still running erosion.slow: gpu shadow steps (case "), 10) << text;
  EXPECT_NE(text.find(", stage "), std::string::npos) << text;
}

TEST(Progress, NoHeartbeatWhenNothingRuns) {
  LoggedProgress progress({.planned = {"a", "b"}, .heartbeat = 20ms});
  progress->start_case("a");
  progress->end_case("a", Outcome::pass, 0.0);
  std::this_thread::sleep_for(200ms);
  progress.stop();
  EXPECT_EQ(count_of(progress.text(), "still running"), 0) << progress.text();
}

TEST(Progress, EtaScalesTheExpectedTimesByThePaceSoFar) {
  // Expected 10 s and 30 s; the first took 20 s, twice its time: the second should take 60 s, and
  // two workers share it out.
  for (const int workers : {1, 2}) {
    LoggedProgress progress({.workers = workers, .planned = {"a", "b"}, .expected = {{"a", 10.0}, {"b", 30.0}}});
    EXPECT_NEAR(*progress->eta_seconds(), 40.0 / workers, 1e-9);
    progress->start_case("a");
    progress->end_case("a", Outcome::pass, 20.0);
    EXPECT_NEAR(*progress->eta_seconds(), 60.0 / workers, 1e-9);
    progress->start_case("b");
    progress->end_case("b", Outcome::pass, 55.0);
    EXPECT_EQ(*progress->eta_seconds(), 0.0);
  }
}

TEST(Progress, EtaWithoutExpectationsUsesTheMeanOfTheEndedCases) {
  LoggedProgress progress({.planned = {"a", "b", "c"}});
  EXPECT_FALSE(progress->eta_seconds().has_value());
  progress->start_case("a");
  progress->end_case("a", Outcome::pass, 4.0);
  EXPECT_NEAR(*progress->eta_seconds(), 8.0, 1e-9);
}

// The command as a user runs it with its stderr in a file (no terminal): the first case's outcome
// line comes before the second case starts, and a heartbeat of 0.1 s gives "still running" lines
// through the second case, at least half as many as its recorded seconds hold heartbeats (the same
// scheduling slack as above), so a 30 s heartbeat shows a 9-minute stage ~18 times.
TEST(ProgressCli, ALogShowsEachOutcomeAsItEndsAndHeartbeatsThroughALongCase) {
  const testing::TemporaryFolder folder("gt_progress_cli");
  const auto out = folder.path() / "report";
  const double heartbeat = 0.1;
  const auto run = testing::run_groundtruth({"run", "erosion.thermal.spec.example_3x3", "erosion.thermal.mutant_probe.cone",
                                             "--heartbeat", "0.1", "--out", out.string()},
                                            folder.path());
  ASSERT_EQ(run.status, 0) << run;
  const std::string& log = run.err;
  const auto first_outcome = log.find("groundtruth: pass erosion.thermal.spec.example_3x3 in ");
  const auto second_start = log.find("[case 2/2] erosion.thermal.mutant_probe.cone");
  ASSERT_NE(first_outcome, std::string::npos) << log;
  ASSERT_NE(second_start, std::string::npos) << log;
  EXPECT_LT(first_outcome, second_start) << log;
  EXPECT_NE(log.find("groundtruth: pass erosion.thermal.mutant_probe.cone in "), std::string::npos) << log;
  const auto report = testing::report_of(out);
  const double cone_seconds = report["cases"][1]["seconds"].get<double>();
  const int owed = static_cast<int>(cone_seconds / heartbeat);
  // Every line between the case's start and its outcome is a sign of life: a stage line (printed
  // when none came for a heartbeat) or a "still running" line.
  const auto cone_end = log.find("groundtruth: pass erosion.thermal.mutant_probe.cone in ");
  const std::string during = log.substr(second_start, cone_end - second_start);
  EXPECT_GE(count_of(during, "\n"), owed / 2) << "case " << cone_seconds << " s\n" << log;
  EXPECT_GE(count_of(during, "still running erosion.thermal.mutant_probe.cone"), 1) << log;
}

}  // namespace
}  // namespace gt
