// The regression-suite workflow of issue 15, run as a user runs it: worker processes (-j,
// --case-timeout), a worker that crashes, retries, the user's own suite and expectations,
// provenance, and shards merged back into one report.
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/report_diff.hpp"
#include "core/sha256.hpp"
#include "gpu/shader_program.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using ::testing::HasSubstr;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const fs::path volcano = fs::path(GT_DATASET_DIR) / "real" / "volcano.json";

gt::testing::ProgramRun run(const std::vector<std::string>& args, const fs::path& cwd) {
  return gt::testing::run_program(groundtruth, args, cwd);
}

json report_of(const fs::path& folder) { return gt::read_report_json(folder / "report.json"); }

// Cases with CPU and GPU halves, pictures and descriptors, that run in seconds.
const std::vector<std::string> quick_cases = {"erosion.thermal.cardinal.volcano", "noise.simplex3.*", "mesh.check.cow",
                                              "erosion.thermal.spec.example_3x3"};

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

std::vector<std::string> case_names(const json& report) {
  std::vector<std::string> names;
  for (const auto& entry : report["cases"]) names.push_back(entry["name"]);
  return names;
}

// Same cases, same checks, same outcomes, no value moved (bit-identical for .cpu checks): what
// diff-reports calls no change; timings may differ.
void expect_same_checks(const json& base, const json& next, const std::string& what) {
  EXPECT_EQ(case_names(base), case_names(next)) << what;
  const gt::ReportDiff diff = gt::diff_reports(base, next);
  EXPECT_TRUE(diff.regressions.empty() && diff.fixes.empty() && diff.outcome_changes.empty() && diff.added.empty() &&
              diff.removed.empty() && diff.moved.empty())
      << what << ":\n"
      << gt::describe(diff);
}

// -j 2 runs each case in its own worker process and must say exactly what -j 1 says; so must
// three shards merged. The shards are given to merge out of order.
TEST(Workflow, ParallelAndShardedRunsGiveTheSerialChecks) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  const auto serial = run(with(with({"run"}, quick_cases), {"--out", "serial", "--quiet"}), work.path());
  ASSERT_EQ(serial.status, 0) << serial;
  const auto parallel = run(with(with({"run"}, quick_cases), {"--out", "parallel", "-j", "2", "--quiet"}), work.path());
  ASSERT_EQ(parallel.status, 0) << parallel;
  expect_same_checks(report_of(work / "serial"), report_of(work / "parallel"), "-j 2 against -j 1");
  const json parallel_report = report_of(work / "parallel");
  for (const auto& entry : parallel_report["cases"]) {
    for (const auto& artifact : entry["artifacts"]) {
      EXPECT_TRUE(fs::exists(work / "parallel" / artifact.get<std::string>())) << artifact;
    }
  }
  EXPECT_FALSE(fs::exists(work / "parallel" / ".workers")) << "the workers' folders are cleaned away";

  std::size_t sharded_cases = 0;
  for (int shard = 1; shard <= 3; ++shard) {
    const auto part = run(with(with({"run"}, quick_cases), {"--shard", std::to_string(shard) + "/3", "--quiet", "--out",
                                                            "shard-" + std::to_string(shard)}),
                          work.path());
    ASSERT_EQ(part.status, 0) << part;
    sharded_cases += report_of(work / ("shard-" + std::to_string(shard)))["cases"].size();
  }
  EXPECT_EQ(sharded_cases, report_of(work / "serial")["cases"].size()) << "each case runs in exactly one shard";
  const auto merged = run({"merge", "shard-3", "shard-1", "shard-2", "--out", "merged"}, work.path());
  ASSERT_EQ(merged.status, 0) << merged;
  expect_same_checks(report_of(work / "serial"), report_of(work / "merged"), "merged shards against one run");
  EXPECT_TRUE(fs::exists(work / "merged" / "junit.xml"));
  EXPECT_TRUE(fs::exists(work / "merged" / "index.html"));

  // A merge that would be partial or double is refused, and writes nothing.
  const auto missing = run({"merge", "shard-1", "shard-3", "--out", "partial"}, work.path());
  EXPECT_EQ(missing.status, 2) << missing;
  EXPECT_THAT(missing.err, HasSubstr("shard 2 of 3 is missing"));
  const auto twice = run({"merge", "shard-1", "shard-2", "shard-2", "shard-3", "--out", "partial"}, work.path());
  EXPECT_EQ(twice.status, 2) << twice;
  EXPECT_THAT(twice.err, HasSubstr("given twice"));
  const auto unsharded = run({"merge", "serial", "--out", "partial"}, work.path());
  EXPECT_EQ(unsharded.status, 2) << unsharded;
  EXPECT_THAT(unsharded.err, HasSubstr("not a shard's report"));
  EXPECT_FALSE(fs::exists(work / "partial"));
}

// The worker processes of this test's run (their command line names its folder), by pid.
std::vector<pid_t> workers_of(const fs::path& folder, const std::string& case_word) {
  std::vector<pid_t> pids;
  for (const auto& entry : fs::directory_iterator("/proc")) {
    const std::string name = entry.path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::string command = gt::testing::read_text(entry.path() / "cmdline");
    std::replace(command.begin(), command.end(), '\0', ' ');
    if (command.find("--worker") != std::string::npos && command.find(folder.string()) != std::string::npos &&
        command.find(case_word) != std::string::npos) {
      pids.push_back(static_cast<pid_t>(std::stol(name)));
    }
  }
  return pids;
}

// workers_of(folder, case_word) polled every 0.1 s until it lists some (`present`) or none, for at
// most `seconds`; the last listing.
std::vector<pid_t> await_workers(const fs::path& folder, const std::string& case_word, bool present, int seconds) {
  std::vector<pid_t> workers = workers_of(folder, case_word);
  for (int poll = 0; poll < 10 * seconds && workers.empty() == present; ++poll) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    workers = workers_of(folder, case_word);
  }
  return workers;
}

// A case of a --backend cpu run that ran: its CPU checks pass, its GPU half is skipped as asked
// (shown as skips, not deciding the case).
void expect_ran_on_the_cpu(const json& entry) {
  EXPECT_EQ(entry["status"], "pass") << entry["name"];
  const auto& checks = entry["checks"];
  EXPECT_TRUE(std::any_of(checks.begin(), checks.end(), [](const json& check) { return check["status"] == "pass"; }))
      << entry["name"];
}

// A worker that dies of a signal ends only its case, as `error` naming the signal, with its log;
// the other case and the report are whole, and the run exits 1.
TEST(Workflow, AWorkerKilledBySignalIsAnErrorAndTheRunGoesOn) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  auto finished = std::async(std::launch::async, [&] {
    return run({"run", "noise.simplex3.walk", "--algorithm", "erosion.thermal", "--input", volcano.string(), "--set",
                "iterations=100000", "--backend", "cpu", "--cpu-reps", "1", "-j", "2", "--out", "crashed"},
               work.path());
  });
  const std::vector<pid_t> slow = await_workers(work.path(), "--algorithm", true, 60);  // the worker to start
  ASSERT_EQ(slow.size(), 1u) << "the long ad-hoc case's worker never showed up";
  kill(slow.front(), SIGSEGV);
  const auto result = finished.get();
  EXPECT_EQ(result.status, 1) << result;
  const json report = report_of(work / "crashed");
  ASSERT_EQ(report["cases"].size(), 2u);
  for (const auto& entry : report["cases"]) {
    if (entry["name"] == "noise.simplex3.walk") {
      expect_ran_on_the_cpu(entry);
      continue;
    }
    EXPECT_EQ(entry["status"], "error");
    EXPECT_THAT(entry["error"].get<std::string>(), HasSubstr("killed by SIGSEGV (signal 11)"));
    ASSERT_EQ(entry["artifacts"].size(), 1u);
    EXPECT_TRUE(fs::exists(work / "crashed" / entry["artifacts"][0].get<std::string>()));
  }
}

// The parent of process `pid`, from /proc/PID/stat ("pid (comm) state ppid ...").
pid_t parent_of(pid_t pid) {
  const std::string stat = gt::testing::read_text(fs::path("/proc") / std::to_string(pid) / "stat");
  std::istringstream fields(stat.substr(stat.rfind(')') + 1));
  std::string state;
  pid_t parent = 0;
  fields >> state >> parent;
  return parent;
}

// A run killed outright cannot end its workers itself: the kernel does (PR_SET_PDEATHSIG), so a
// long case does not run on for nobody.
TEST(Workflow, WorkersEndWithAParentKilledOutright) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  auto finished = std::async(std::launch::async, [&] {
    return run({"run", "--algorithm", "erosion.thermal", "--input", volcano.string(), "--set", "iterations=100000",
                "--backend", "cpu", "-j", "2", "--out", "killed"},
               work.path());
  });
  const std::vector<pid_t> workers = await_workers(work.path(), "--algorithm", true, 60);  // the worker to start
  ASSERT_EQ(workers.size(), 1u) << "the long ad-hoc case's worker never showed up";
  kill(parent_of(workers.front()), SIGKILL);
  EXPECT_EQ(finished.get().status, 128 + SIGKILL);
  EXPECT_TRUE(await_workers(work.path(), "--algorithm", false, 10).empty())
      << "the worker ran on after its parent was killed";
}

// The plotting helpers do as the workers do (compare/report/helper_lifetime.py): a helper whose
// parent is killed outright ends with it, and one started for a parent that is already gone does
// not start drawing.
TEST(Workflow, PlottingHelpersEndWithTheirParent) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  const fs::path scripts = fs::path(GT_TEST_DATA_DIR).parent_path().parent_path() / "compare" / "report";
  const std::string helper = "import sys, time; sys.path.insert(0, sys.argv[1]); "
                             "from helper_lifetime import end_with_parent; end_with_parent(); "
                             "open('ready', 'w').close(); time.sleep(120)";
  // sh is the parent: it names itself, starts the helper in the background and waits.
  std::vector<std::string> words = {"/bin/sh", "-c",
                                    "GROUNDTRUTH_PARENT_PID=$$ python3 -c \"$0\" \"$1\" & echo $! > helper.pid; wait",
                                    helper, scripts.string()};
  std::vector<char*> argv = gt::testing::argv_of(words);
  pid_t shell = 0;
  const std::string cwd = work.path().string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, cwd.c_str());
  ASSERT_EQ(posix_spawn(&shell, argv[0], &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(work / "ready") && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_TRUE(fs::exists(work / "ready")) << "the helper never started";
  const pid_t helper_pid = std::stoi(gt::testing::read_text(work / "helper.pid"));
  kill(shell, SIGKILL);
  waitpid(shell, nullptr, 0);
  const auto gone = [&] {
    const fs::path stat = fs::path("/proc") / std::to_string(helper_pid) / "stat";
    if (!fs::exists(stat)) return true;
    const std::string fields = gt::testing::read_text(stat);
    return fields.substr(fields.rfind(')') + 2, 1) == "Z";  // ended, not yet reaped by its new parent
  };
  const auto patience = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (!gone() && std::chrono::steady_clock::now() < patience) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_TRUE(gone()) << "the helper ran on after its parent was killed";

  // The plot helpers call it first: named a parent that is not theirs, they exit 128 + 9 at once.
  for (const char* script : {"plot_series.py", "plot_timings.py"}) {
    const auto run = gt::testing::run_program("/usr/bin/python3", {(scripts / script).string(), "none.json", "none.png"},
                                              work.path(), {{"GROUNDTRUTH_PARENT_PID", "1"}});
    EXPECT_EQ(run.status, 128 + SIGKILL) << script << run;
  }
}

// A case past --case-timeout is killed and named; the rest of the run is unaffected. 20 s: the
// quick case takes about 2 s in its worker (8 s seen under the suite's load), the long one about
// 40 s on this machine's CPU and longer under any load or a sanitizer.
TEST(Workflow, ACaseTimeoutEndsOnlyThatCase) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  const auto result = run({"run", "erosion.thermal.spec.example_3x3", "--algorithm", "erosion.thermal", "--input",
                           volcano.string(), "--set", "iterations=100000", "--backend", "cpu", "--cpu-reps", "1",
                           "--case-timeout", "20", "--out", "timed"},
                          work.path());
  EXPECT_EQ(result.status, 1) << result;
  EXPECT_THAT(result.out, HasSubstr("ran past --case-timeout 20 s"));
  const json report = report_of(work / "timed");
  expect_ran_on_the_cpu(report["cases"][0]);
  EXPECT_EQ(report["cases"][1]["status"], "error");
}

// A case that fails every time stays `fail` after its retries, which are listed; --retries does
// not turn a real failure into a flake.
TEST(Workflow, RetriesOfAStableFailureLeaveItFailed) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  const auto result = run({"run", "erosion.thermal.mutant_probe.cone", "--mutant", "erosion.thermal.swapped_gather",
                           "--retries", "2", "--out", "retried"},
                          work.path());
  EXPECT_EQ(result.status, 1) << result;
  EXPECT_THAT(result.err, HasSubstr("running it again (attempt 3)"));
  const json entry = report_of(work / "retried")["cases"][0];
  EXPECT_EQ(entry["status"], "fail");
  ASSERT_EQ(entry["earlier_attempts"].size(), 2u);
  EXPECT_EQ(entry["earlier_attempts"][0]["status"], "fail");
  EXPECT_FALSE(entry["earlier_attempts"][0]["failing_checks"].empty());
}

// A user's suite beside their code: inputs relative to the case file, their own expectations
// (a known failure passes the run, a missing file is bad input), and a flake list that may only
// hold flaky entries.
TEST(Workflow, AUsersSuiteWithItsOwnExpectations) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  fs::create_directories(work / "suite" / "data");
  fs::copy_file(fs::path(GT_DATASET_DIR) / "real" / "meshes" / "elephant-with-holes.off",
                work / "suite" / "data" / "holes.off");
  std::ofstream(work / "suite" / "cases.json")
      << json::array({{{"name", "mine.holes"}, {"algorithm", "mesh.check"}, {"input", {{"mesh", "data/holes.off"}}}}})
             .dump();
  std::ofstream(work / "suite" / "expectations.txt") << "mine.holes mesh.closed.input fail the scan has holes\n"
                                                     << "mine.holes mesh.self_intersections.input fail it crosses itself\n"
                                                     << "mine.holes spec.watertight fail so it is not watertight\n";
  std::ofstream(work / "suite" / "flakes.txt") << "mine.holes mesh.closed.* fail not a flake entry\n";
  fs::create_directories(work / "elsewhere");

  const auto unexpected = run({"run", "mine.*", "--cases", "../suite/cases.json", "--out", "plain"}, work / "elsewhere");
  EXPECT_EQ(unexpected.status, 1) << unexpected;
  const auto expected = run({"run", "mine.*", "--cases", "../suite/cases.json", "--expectations",
                             "../suite/expectations.txt", "--out", "known"},
                            work / "elsewhere");
  EXPECT_EQ(expected.status, 0) << expected;
  EXPECT_THAT(expected.out, HasSubstr("(expected failure)"));
  const auto missing = run({"run", "mine.*", "--cases", "../suite/cases.json", "--expectations", "nope.txt", "--out",
                            "none"},
                           work / "elsewhere");
  EXPECT_EQ(missing.status, 2) << missing;
  const auto not_flakes = run({"run", "mine.*", "--cases", "../suite/cases.json", "--flakes", "../suite/flakes.txt",
                               "--out", "none"},
                              work / "elsewhere");
  EXPECT_EQ(not_flakes.status, 2) << not_flakes;
  EXPECT_THAT(not_flakes.err, HasSubstr("a flake list holds only `flaky` entries"));
  EXPECT_FALSE(fs::exists(work / "elsewhere" / "none"));
}

// Every report says what ran: the source tree's revision at run time, the command, and SHA-256
// digests of the data files read and of every shader stage compiled after #include expansion,
// which sha256sum and the expander reproduce.
TEST(Workflow, TheReportNamesWhatRan) {
  const gt::testing::TemporaryFolder work("gt_workflow");
  const auto result = run({"run", "erosion.thermal.cardinal.volcano", "--out", "provenance", "--quiet"}, work.path());
  ASSERT_EQ(result.status, 0) << result;
  const json environment = report_of(work / "provenance")["environment"];
  EXPECT_THAT(environment["command_line"].get<std::string>(), HasSubstr("run erosion.thermal.cardinal.volcano"));
  EXPECT_TRUE(std::regex_match(environment["run_started"].get<std::string>(),
                               std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  const std::string revision = environment["git_revision"];
  EXPECT_TRUE(std::regex_match(revision, std::regex("[0-9a-f]{40}")) || revision.starts_with("unknown: ")) << revision;

  const auto sums = gt::testing::run_program("/usr/bin/sha256sum", {volcano.string()});
  ASSERT_EQ(sums.status, 0) << sums;
  ASSERT_TRUE(environment["data"].contains(volcano.string())) << environment["data"].dump(1);
  EXPECT_EQ(environment["data"][volcano.string()], sums.out.substr(0, 64));

  if (environment["gl_platform"] == "none") GTEST_SKIP() << "no GL context: no shader was compiled";
  ASSERT_FALSE(environment["shaders"].empty());
  int reproduced = 0;
  for (const auto& [stage, digest] : environment["shaders"].items()) {
    if (stage.find(" (defines") != std::string::npos) continue;  // the expander is given no defines here
    const auto relative = fs::path(stage).lexically_relative("gpu/shaders");
    const auto expanded = gt::expand_shader(gt::shader_root(), relative.generic_string());
    EXPECT_EQ(digest, gt::sha256_hex(expanded.source)) << stage;
    ++reproduced;
  }
  EXPECT_GT(reproduced, 0);
}

}  // namespace
