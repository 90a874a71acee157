// Nothing a user gave us is lost, and nothing is written outside --out (compare/output_folder.hpp):
// a file added to a report folder at any depth, or while a run goes on, stays; a second process
// writing the same folder is refused; a user's folder that looks like a staging name stays; merge
// takes no case name that is a path, follows no link out of a shard and reads no impossible shard
// count; history and merge refuse an --out that would replace one of their inputs. Each refusal
// is exit 2 (InputError) with a message that names the file.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "compare/output_folder.hpp"
#include "core/errors.hpp"
#include "tests/support/run_program.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
constexpr const char* quick_case = "erosion.thermal.spec.example_3x3";

std::vector<std::string> entries_of(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void write_text(const fs::path& file, const std::string& text) { std::ofstream(file) << text; }

std::string input_error(const std::function<void()>& action) {
  try {
    action();
  } catch (const gt::InputError& error) {
    return error.what();
  }
  return "(no InputError)";
}

class OutputFolder : public ::testing::Test {
 protected:
  gt::testing::ProgramRun run(const std::vector<std::string>& args) {
    return gt::testing::run_program(groundtruth, args, work_.path());
  }
  gt::testing::ProgramRun run_case(const std::string& out, const std::vector<std::string>& more = {}) {
    std::vector<std::string> args = {"run", quick_case, "--quiet", "--out", out};
    args.insert(args.end(), more.begin(), more.end());
    return run(args);
  }
  fs::path path(const std::string& name) const { return work_ / name; }

  gt::testing::TemporaryFolder work_{"gt_output_folder"};
};

// The "user" adds a file while the report is built (the fill stands for the run's cases): at the
// swap it is found, and the folder stays as it was with the file in it.
TEST_F(OutputFolder, AFileAddedWhileTheRunGoesOnIsKept) {
  const fs::path out = path("report");
  gt::write_folder_atomically(out, [](const fs::path& folder) { write_text(folder / "earlier.txt", "run 1\n"); });
  const std::string refusal = input_error([&] {
    gt::write_folder_atomically(out, [&](const fs::path& folder) {
      write_text(folder / "earlier.txt", "run 2\n");
      write_text(out / "mine.txt", "the user's\n");
    });
  });
  EXPECT_THAT(refusal, HasSubstr("mine.txt was added to it while this run went on"));
  EXPECT_EQ(gt::testing::read_text(out / "mine.txt"), "the user's\n");
  EXPECT_EQ(gt::testing::read_text(out / "earlier.txt"), "run 1\n");
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"report"}) << "staging, previous or lock left";

  // The same when --out did not exist as the run started.
  const fs::path fresh = path("fresh");
  const std::string created = input_error([&] {
    gt::write_folder_atomically(fresh, [&](const fs::path&) {
      fs::create_directory(fresh);
      write_text(fresh / "mine.txt", "the user's\n");
    });
  });
  EXPECT_THAT(created, HasSubstr("holds files that are not a groundtruth report while this run went on"));
  EXPECT_EQ(gt::testing::read_text(fresh / "mine.txt"), "the user's\n");
}

TEST_F(OutputFolder, AFileAddedInsideACaseFolderIsKept) {
  ASSERT_EQ(run_case("report").status, 0);
  const fs::path notes = path("report") / quick_case / "notes.txt";
  ASSERT_TRUE(fs::is_directory(notes.parent_path()));
  write_text(notes, "the user's\n");
  const auto again = run_case("report");
  EXPECT_EQ(again.status, 2) << again;
  EXPECT_THAT(again.err, HasSubstr(std::string(quick_case) + "/notes.txt was added"));
  EXPECT_EQ(gt::testing::read_text(notes), "the user's\n");
}

// This process holds the folder (as a run does from its start to its swap): a second run into it
// is refused; once the holder has written, the folder is free and no lock file is left.
TEST_F(OutputFolder, ASecondWriterIsRefused) {
  const fs::path out = path("report");
  gt::check_output_folder(out);
  const auto second = run_case("report");
  EXPECT_EQ(second.status, 2) << second;
  EXPECT_THAT(second.err, HasSubstr("is being written by another groundtruth run"));
  gt::write_folder_atomically(out, [](const fs::path& folder) { write_text(folder / "first.txt", "first\n"); });
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"report"});
  const auto after = run_case("report");
  EXPECT_EQ(after.status, 0) << after;
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"report"});
}

// "report.tmp-20240101" was groundtruth's staging name (and 20240101 is no running process): a
// user's dated backup of that name stays. A killed run's staging folder does not (999999999 is
// above Linux's largest pid).
TEST_F(OutputFolder, AUsersFolderNamedLikeOldStagingStays) {
  fs::create_directory(path("report.tmp-20240101"));
  write_text(path("report.tmp-20240101") / "keep.txt", "backup\n");
  fs::create_directory(path(".report.groundtruth-staging-999999999"));
  const auto ran = run_case("report");
  ASSERT_EQ(ran.status, 0) << ran;
  EXPECT_EQ(gt::testing::read_text(path("report.tmp-20240101") / "keep.txt"), "backup\n");
  EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"report", "report.tmp-20240101"}));
}

class MergeInputs : public OutputFolder {
 protected:
  void SetUp() override {
    const auto shard = run_case("shard", {"--shard", "1/1"});
    ASSERT_EQ(shard.status, 0) << shard;
    report_ = json::parse(gt::testing::read_text(path("shard") / "report.json"));
  }
  // Rewrites the shard's report.json with `change` applied, then merges it into "merged".
  gt::testing::ProgramRun merge_changed(const std::function<void(json&)>& change) {
    json changed = report_;
    change(changed);
    write_text(path("shard") / "report.json", changed.dump());
    return run({"merge", "shard", "--out", "merged"});
  }
  json report_;
};

TEST_F(MergeInputs, ACaseNameThatIsAPathIsRefused) {
  for (const char* name : {"../../escaped", "..", "a/b"}) {
    const auto merged = merge_changed([&](json& report) {
      report["cases"][0]["name"] = name;
      report["shard"]["selection"][0] = name;
    });
    EXPECT_EQ(merged.status, 2) << merged;
    EXPECT_THAT(merged.err, HasSubstr("is not a dotted identifier")) << name;
  }
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"shard"});
}

TEST_F(MergeInputs, ImpossibleShardCountsAreRefused) {
  for (const int count : {0, 2147483647}) {
    const auto merged = merge_changed([&](json& report) { report["shard"]["count"] = count; });
    EXPECT_EQ(merged.status, 2) << merged;
    EXPECT_THAT(merged.err, HasSubstr("is not a shard")) << count;
  }
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"shard"});
}

TEST_F(MergeInputs, ALinkInAShardIsNotFollowed) {
  fs::create_directory(path("elsewhere"));
  write_text(path("elsewhere") / "secret.txt", "not the shard's\n");
  fs::create_directory_symlink(path("elsewhere"), path("shard") / quick_case / "link");
  const auto merged = run({"merge", "shard", "--out", "merged"});
  EXPECT_EQ(merged.status, 2) << merged;
  EXPECT_THAT(merged.err, HasSubstr("link is a symbolic link"));
  EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"elsewhere", "shard"}));
}

TEST_F(MergeInputs, MergeAndHistoryRefuseToReplaceTheirInput) {
  const std::string before = gt::testing::read_text(path("shard") / "report.json");
  for (const std::vector<std::string>& args : {std::vector<std::string>{"merge", "shard", "--out", "shard"},
                                               std::vector<std::string>{"history", "shard", "--out", "shard"},
                                               std::vector<std::string>{"history", "shard/report.json", "--out", "."}}) {
    const auto refused = run(args);
    EXPECT_EQ(refused.status, 2) << refused;
    EXPECT_THAT(refused.err, HasSubstr("which it reads")) << refused;
  }
  EXPECT_EQ(gt::testing::read_text(path("shard") / "report.json"), before);
}

}  // namespace
