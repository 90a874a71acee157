// Issue 18's promises, as far as this change keeps them, tried as a hostile user would: sizes and
// offsets read without overflow, wrong JSON types, case names that would write outside --out,
// non-finite numbers on the command line, report folders that hold a user's file, special and
// dangling output paths, interruptions (SIGINT, SIGTERM) and stale staging folders, and progress
// lines when stderr is not a terminal. Every refusal is exit 2 with a message naming the problem,
// and leaves nothing behind.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
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

std::vector<std::string> entries_of(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Hostile : public ::testing::Test {
 protected:
  // A case file of the user's holding `entry`, run by name; must be refused with `message`,
  // leaving only the case file in the work folder.
  void expect_case_refused(const json& entry, const std::string& message) {
    std::ofstream(work_ / "mine.json") << json::array({entry}).dump();
    const std::string name = entry.at("name");
    const auto run = gt::testing::run_program(
        groundtruth, {"run", name.empty() ? "*" : name, "--cases", (work_ / "mine.json").string(), "--out",
                      (work_ / "out").string()},
        work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr(message)) << run;
    EXPECT_THAT(run.err, ::testing::Not(HasSubstr("internal error"))) << run;
    EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"mine.json"});
  }

  gt::testing::TemporaryFolder work_{"gt_hostile"};
};

const json cone_input = {{"generator", "cone"}, {"width", 16}, {"height", 16}};

json thermal_case(const std::string& name) {
  return {{"name", name}, {"algorithm", "erosion.thermal"}, {"input", cone_input}, {"params", {{"iterations", 2}}}};
}

TEST_F(Hostile, CropNearTheLargestIntegerIsRefusedNotOverflowed) {
  json entry = thermal_case("mine.crop");
  entry["crop"] = {2147483647, 0, 1, 1};
  expect_case_refused(entry, "crop: x = 2147483647 is out of range");
}

TEST_F(Hostile, CaseNamesThatLeaveTheReportFolderAreRefused) {
  expect_case_refused(thermal_case("../x"), "must be a dotted identifier");
  expect_case_refused(thermal_case("/tmp/abs"), "must be a dotted identifier");
  expect_case_refused(thermal_case(""), "must be a dotted identifier");
}

TEST_F(Hostile, WrongTypesAndTruncatingSizesAreRefused) {
  json big = thermal_case("mine.big");
  big["input"]["width"] = "big";
  expect_case_refused(big, "width = \"big\" is not a number");
  json wrapped = thermal_case("mine.wrapped");
  wrapped["input"]["width"] = 4294967312ULL;  // 2^32 + 16: must not become 16
  expect_case_refused(wrapped, "width = 4294967312 is out of range");
  json fraction = thermal_case("mine.fraction");
  fraction["input"]["height"] = 2.5;
  expect_case_refused(fraction, "height = 2.5 is not whole");
}

TEST_F(Hostile, CommandLineNumbersMustBeFiniteAndFit) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", "--algorithm", "noise.simplex2", "--size", "4294967297x1"},
        std::vector<std::string>{"run", "--algorithm", "noise.simplex2", "--cell-size", "nan"},
        std::vector<std::string>{"diff-image", "a.png", "b.png", "--tolerance", "nan"},
        std::vector<std::string>{"render", "a.off", "--out", "a.png", "--cell-size", "nan"}}) {
    const auto run = gt::testing::run_program(groundtruth, args, work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.output(), ::testing::AnyOf(HasSubstr("finite"), HasSubstr("4294967297x1"))) << run;
  }
  EXPECT_TRUE(fs::is_empty(work_.path()));
}

TEST_F(Hostile, SpecialAndDanglingOutputsAreBadInput) {
  fs::create_symlink(work_ / "nowhere", work_ / "dangling");
  for (const fs::path& out : {work_ / "dangling", fs::path("/proc/groundtruth-report")}) {
    const auto run = gt::testing::run_program(groundtruth, {"run", "erosion.thermal.spec.*", "--out", out.string()},
                                              work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr("output")) << run;
  }
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"dangling"});
  EXPECT_FALSE(fs::exists(work_ / "nowhere"));
}

TEST_F(Hostile, ProgressLinesWithoutATerminalAndQuietSilencesThem) {
  const auto out = (work_ / "out").string();
  const auto loud = gt::testing::run_program(groundtruth, {"run", "erosion.thermal.spec.*", "--out", out}, work_.path());
  ASSERT_EQ(loud.status, 0) << loud;
  EXPECT_THAT(loud.err, HasSubstr("groundtruth: [case 1/1] erosion.thermal.spec.example_3x3"));
  const auto quiet =
      gt::testing::run_program(groundtruth, {"run", "erosion.thermal.spec.*", "--quiet", "--out", out}, work_.path());
  ASSERT_EQ(quiet.status, 0) << quiet;
  EXPECT_THAT(quiet.err, ::testing::Not(HasSubstr("[case")));
}

TEST_F(Hostile, StaleStagingOfAKilledRunIsRemovedByTheNextRun) {
  // A run killed outright leaves report.tmp-PID; no process has that PID any more.
  pid_t gone = 0;
  {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    gone = child;
  }
  const fs::path stale = work_ / ("report.tmp-" + std::to_string(gone));
  fs::create_directories(stale / "half.case");
  const auto run = gt::testing::run_program(
      groundtruth, {"run", "erosion.thermal.spec.*", "--out", (work_ / "report").string()}, work_.path());
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"report"});
}

// Starts a long run (a 256² pipe case of 500 steps), waits until its staging folder exists,
// interrupts it with `signal_number` and expects a prompt exit 128 + signal with nothing left.
void expect_clean_interruption(int signal_number) {
  const gt::testing::TemporaryFolder work("gt_interrupt");
  const std::string out = (work / "report").string();
  std::vector<std::string> words = {groundtruth, "run", "erosion.pipe.flux.slope500", "--out", out};
  std::vector<char*> argv = gt::testing::argv_of(words);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, groundtruth.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const fs::path staging = out + ".tmp-" + std::to_string(pid);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(staging) && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(fs::exists(staging)) << "the run never started writing";
  kill(pid, signal_number);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 128 + signal_number);
  EXPECT_TRUE(entries_of(work.path()).empty()) << "left behind: " << ::testing::PrintToString(entries_of(work.path()));
}

TEST(Interrupted, BySigintLeavesNothing) { expect_clean_interruption(SIGINT); }
TEST(Interrupted, BySigtermLeavesNothing) { expect_clean_interruption(SIGTERM); }

}  // namespace
