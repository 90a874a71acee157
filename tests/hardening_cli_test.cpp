// Issue 18's promises, as far as this change keeps them, tried as a hostile user would: sizes and
// offsets read without overflow, wrong JSON types, case names that would write outside --out,
// non-finite numbers on the command line, report folders that hold a user's file, special and
// dangling output paths, interruptions (SIGINT, SIGTERM) and stale staging folders, and progress
// lines when stderr is not a terminal; files declaring more than they hold (tests/data/hostile,
// made by its generate.py), heights and cell sizes no twin can compute with, noise parameters
// that would overflow the lattice index, and memory estimates checked under an address-space
// limit. Every refusal is exit 2 with a message naming the problem, and leaves nothing behind.
#include <fcntl.h>
#include <sys/stat.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/run_program.hpp"
#include "tests/support/sanitizers.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

const std::string groundtruth = GT_BINARY_DIR "/groundtruth";
const fs::path hostile_data = fs::path(GT_TEST_DATA_DIR) / "hostile";

// groundtruth `args` under `ulimit <limit>` (through /bin/sh, which sets it and execs).
gt::testing::ProgramRun run_with_limit(const std::string& limit, const std::vector<std::string>& args,
                                       const fs::path& cwd) {
  std::vector<std::string> shell_args = {"-c", "ulimit " + limit + " && exec \"$0\" \"$@\"", groundtruth};
  shell_args.insert(shell_args.end(), args.begin(), args.end());
  return gt::testing::run_program("/bin/sh", shell_args, cwd);
}

// groundtruth `args` under `ulimit -v` of `kibibytes`.
gt::testing::ProgramRun run_with_address_space_limit(long kibibytes, const std::vector<std::string>& args,
                                                     const fs::path& cwd) {
  return run_with_limit("-v " + std::to_string(kibibytes), args, cwd);
}

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

// A crop cuts a heightmap; on a mesh, a volume or a global grid it was ignored without a word.
TEST_F(Hostile, ACropOfAnInputThatIsNoHeightmapIsRefused) {
  json entry = {{"name", "mine.cropped_mesh"},
                {"algorithm", "mesh.check"},
                {"input", {{"mesh", (fs::path(GT_DATASET_DIR) / "real" / "meshes" / "bunny00.off").string()}}},
                {"crop", {0, 0, 4, 4}}};
  expect_case_refused(entry, "cuts a heightmap ('file' or 'generator')");
}

// A user's case file names its global grid relative to itself, as it names a heightmap or mesh.
TEST_F(Hostile, ARelativeGlobalGridIsTheCaseFilesNeighbour) {
  const json entry = {{"name", "mine.relative_grid"}, {"algorithm", "planet.earth_like"},
                      {"input", {{"global_grid", "neighbour.nc"}}}};
  expect_case_refused(entry, (work_ / "neighbour.nc").string());
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

TEST_F(Hostile, FilesDeclaringMoreThanTheyHoldAreRefused) {
  json tiff = thermal_case("mine.tiff");
  tiff["input"] = {{"file", (hostile_data / "declares_37000.tif").string()}};
  expect_case_refused(tiff, "TIFF strip 0 of 37000 (148000 bytes at offset 8) is empty or runs past the end of the "
                            "150-byte file");
}

TEST_F(Hostile, HeightsBeyondFloatAndCellSizesWithoutLengthAreRefused) {
  const gt::testing::TemporaryFolder data("gt_hostile_data");
  std::ofstream(data / "huge.json") << json{{"width", 2}, {"height", 2}, {"values", {1e300, 0, 0, 0}}}.dump();
  json huge = thermal_case("mine.huge");
  huge["input"] = {{"file", (data / "huge.json").string()}};
  expect_case_refused(huge, "cell (x=0, y=0) is 1e+300, beyond ±2.13e+37");
  json flat = thermal_case("mine.flat");
  flat["input"] = {{"file", (hostile_data / "zero_cell_size.tif").string()}};
  expect_case_refused(flat, "cell size 0 x 0 deg is not a length");
}

// An eroder without an input once ran silently on a flat 256x256 grid, and a terrain generator
// naming an eroder ended in "internal error: bad_function_call": both are the user's mistake, and
// are refused by name (exit 2), with nothing written.
TEST_F(Hostile, AnEroderWithoutAnInputIsRefused) {
  const std::pair<const char*, const char*> runs[] = {{"erosion.pipe", "steps=2"},
                                                      {"erosion.thermal", "iterations=2"},
                                                      {"erosion.layered", "steps=2"},
                                                      {"erosion.particle", "iterations=2"}};
  for (const auto& [algorithm, assignment] : runs) {
    const auto run = gt::testing::run_program(
        groundtruth, {"run", "--algorithm", algorithm, "--set", assignment, "--out", (work_ / "out").string()},
        work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr(std::string(algorithm) + " works on a heightmap: give it one with --input")) << run;
    EXPECT_TRUE(entries_of(work_.path()).empty()) << run;
  }
}

// A malformed "expect" is refused before any case runs (it used to end its case in `error`, exit 1,
// with nlohmann's type_error as the reason).
TEST_F(Hostile, AMalformedExpectIsRefusedBeforeTheRun) {
  json entry = thermal_case("mine.expect");
  entry["expect"] = {{"cells", {{1, "x", 3}}}};
  expect_case_refused(entry, "case mine.expect: expect.cells[0][1] = \"x\": expected an integer");
  entry["expect"] = {{"tolerance", "big"}, {"total", 1}};
  expect_case_refused(entry, "case mine.expect: expect.tolerance = \"big\": expected a number");
  entry["expect"] = {{"talus_eq_4_10", "yes"}};
  expect_case_refused(entry, "case mine.expect: expect.talus_eq_4_10: expected a JSON object");
}

TEST_F(Hostile, ATerrainGeneratorNamingAnEroderIsRefused) {
  json entry = thermal_case("mine.generated_by_an_eroder");
  entry["input"] = {{"generator", "terrain"}, {"algorithm", "erosion.pipe"}, {"width", 16}, {"height", 16}};
  expect_case_refused(entry, "input generator terrain: erosion.pipe is not a noise algorithm");
}

TEST_F(Hostile, NoiseWhoseLatticeIndicesWouldOverflowIsRefused) {
  // The finest of 32 octaves of lacunarity 16 from an origin of 1e9: 1e9·16^31.
  const json entry = {{"name", "mine.noise"},
                      {"algorithm", "noise.fbm"},
                      {"input", {{"generator", "flat"}, {"width", 8}, {"height", 8}}},
                      {"params", {{"origin_x", 1e9}, {"octaves", 32}, {"lacunarity", 16}}}};
  expect_case_refused(entry, "would overflow 32 bits");
  // The cave's density at origin 500000 with 0.001 world units per noise unit: 5·10⁸ noise units.
  const json cave = {{"name", "mine.cave"},
                     {"algorithm", "cave.marching_tetrahedra"},
                     {"params", {{"origin_x", 500000}, {"scale", 0.001}, {"size_x", 4}, {"size_y", 4}, {"size_z", 4}}}};
  expect_case_refused(cave, "where the twins' lattice indices overflow 32 bits");
}

TEST_F(Hostile, MemoryEstimatesAreCheckedUnderAnAddressSpaceLimit) {
  if (gt::testing::under_address_sanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory ignores ulimit -v";
  constexpr long four_gibibytes = 4L << 20;  // in KiB
  // A real 8000² PNG: reading it fits (about 1.2 GB), pipe erosion on it does not.
  const auto pipe = run_with_address_space_limit(
      four_gibibytes,
      {"run", "--algorithm", "erosion.pipe", "--input", (hostile_data / "flat_8000.png").string(), "--out",
       (work_ / "out").string()},
      work_.path());
  EXPECT_EQ(pipe.status, 2) << pipe;
  EXPECT_THAT(pipe.err, HasSubstr("erosion.pipe needs about 280.7 GiB (64000000 cells x 1830 B")) << pipe;
  EXPECT_THAT(pipe.err, HasSubstr("ulimit -v")) << pipe;
  // A 66-byte PNG declaring 30000² 16-bit pixels: diff-image weighs both images before reading.
  const std::string declared = (hostile_data / "declares_30000.png").string();
  const auto diff = run_with_address_space_limit(four_gibibytes, {"diff-image", declared, declared}, work_.path());
  EXPECT_EQ(diff.status, 2) << diff;
  EXPECT_THAT(diff.err, HasSubstr("(30000x30000) needs about")) << diff;
  // stats reads the same PNG, then weighs the descriptors before it starts them.
  const auto stats = run_with_address_space_limit(
      four_gibibytes, {"stats", (hostile_data / "flat_8000.png").string()}, work_.path());
  EXPECT_EQ(stats.status, 2) << stats;
  EXPECT_THAT(stats.err, HasSubstr("stats: the descriptors of 8000x8000 cells needs about 7.7 GiB")) << stats;
  // Checkpoints: 1000 states of a 512² pipe run are counted before the run starts.
  const gt::testing::TemporaryFolder cases("gt_hostile_cases");
  std::ofstream(cases / "checkpoints.json")
      << json::array({{{"name", "mine.checkpoints"},
                       {"algorithm", "erosion.pipe"},
                       {"input", {{"generator", "flat"}, {"width", 512}, {"height", 512}}},
                       {"params", {{"steps", 1000}, {"checkpoints", 1000}}}}})
             .dump();
  const auto checkpoints = run_with_address_space_limit(
      four_gibibytes,
      {"run", "mine.checkpoints", "--cases", (cases / "checkpoints.json").string(), "--out", (work_ / "out").string()},
      work_.path());
  EXPECT_EQ(checkpoints.status, 2) << checkpoints;
  EXPECT_THAT(checkpoints.err, HasSubstr("262144000 cell-checkpoints x 180 B")) << checkpoints;
  EXPECT_TRUE(fs::is_empty(work_.path()));
}

// Issue 40's four memory bombs through every command that reads them, under a 4 GiB address-space
// cap: each is refused with exit 2 and what it would need (or why it cannot be read), never killed
// or "internal error", and nothing is written. The 8000² .npy and the 115 MiB report are sparse
// files: their sizes are what the readers weigh before reading a byte.
TEST_F(Hostile, EveryCommandRefusesEachMemoryBombUnderACap) {
  if (gt::testing::under_address_sanitizer) GTEST_SKIP() << "AddressSanitizer's shadow memory ignores ulimit -v";
  constexpr long four_gibibytes = 4L << 20;  // in KiB
  const std::string png_bomb = (hostile_data / "declares_30000.png").string();
  {
    std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (8000, 8000), }";
    header.append(63 - (10 + header.size()) % 64, ' ');
    header.push_back('\n');
    std::ofstream npy(work_ / "big.npy", std::ios::binary);
    npy << "\x93NUMPY\x01" << '\0' << char(header.size() & 0xff) << char(header.size() >> 8) << header;
  }
  fs::resize_file(work_ / "big.npy", fs::file_size(work_ / "big.npy") + std::uintmax_t{8000} * 8000 * 4);
  std::ofstream(work_ / "deep.json") << std::string(300000, '[') << std::string(300000, ']');
  std::ofstream(work_ / "big_report.json") << R"({"schema": 1, "cases": [)";
  fs::resize_file(work_ / "big_report.json", std::uintmax_t{115} << 20);
  for (const char* shard : {"s1", "s2"}) {
    fs::create_directory(work_ / shard);
    fs::copy_file(work_ / "big_report.json", work_ / shard / "report.json");
  }
  const std::vector<std::string> inputs = entries_of(work_.path());
  const std::string thermal = "erosion.thermal", spec_case = "erosion.thermal.spec.example_3x3";
  struct Bomb {
    std::vector<std::string> args;
    std::string message;
  };
  std::vector<Bomb> bombs;
  for (const auto& [heights, message] :
       {std::pair{png_bomb, "(30000x30000) needs about"}, std::pair{std::string("big.npy"), "needs about"},
        std::pair{std::string("deep.json"), "JSON nested deeper than 64 levels"}}) {
    bombs.push_back({{"run", "--algorithm", thermal, "--input", heights, "--out", "o"}, message});
    bombs.push_back({{"stats", heights}, message});
    bombs.push_back({{"render", heights, "--out", "o.png"}, message});
    bombs.push_back({{"sweep", "--algorithm", thermal, "--input", heights, "--vary", "iterations=1,2", "--out", "o"},
                     message});
    bombs.push_back(
        {{"ab", "--algorithm", thermal, "--input", heights, "--a", "iterations=1", "--b", "iterations=2", "--out", "o"},
         message});
  }
  bombs.push_back({{"diff-image", png_bomb, png_bomb}, "(30000x30000) needs about"});
  for (const auto& [document, message] : {std::pair{"deep.json", "JSON nested deeper than 64 levels"},
                                          std::pair{"big_report.json", "needs about 4.5 GiB (120586240 bytes x 40 B)"}}) {
    bombs.push_back({{"diff-reports", document, document}, message});
    bombs.push_back({{"history", document, "--out", "o"}, message});
    bombs.push_back({{"run", spec_case, "--baseline", document, "--out", "o"}, message});
    bombs.push_back({{"run", spec_case, "--cases", document, "--out", "o"}, message});
    bombs.push_back({{"sweep", "--algorithm", thermal, "--sets", document, "--out", "o"}, message});
  }
  bombs.push_back({{"run", spec_case, "--expectations", "big_report.json", "--out", "o"}, "larger than the 16.0 MiB"});
  bombs.push_back({{"merge", "s1", "s2", "--out", "o"}, "merge needs about 9.0 GiB"});
  for (const Bomb& bomb : bombs) {
    const auto run = run_with_address_space_limit(four_gibibytes, bomb.args, work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr(bomb.message)) << run;
    EXPECT_THAT(run.err, ::testing::Not(HasSubstr("internal error"))) << run;
    EXPECT_EQ(entries_of(work_.path()), inputs) << run;
  }
}

TEST_F(Hostile, MemoryLimitOptionCapsEveryEstimate) {
  json entry = thermal_case("mine.capped");
  entry["input"] = {{"generator", "cone"}, {"width", 1024}, {"height", 1024}};
  std::ofstream(work_ / "mine.json") << json::array({entry}).dump();
  const auto run = gt::testing::run_program(groundtruth,
                                            {"--memory-limit", "64", "run", "mine.capped", "--cases",
                                             (work_ / "mine.json").string(), "--out", (work_ / "out").string()},
                                            work_.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("erosion.thermal needs about 580.0 MiB (1048576 cells x 580 B)")) << run;
  EXPECT_THAT(run.err, HasSubstr("more than the 64.0 MiB this process may use (--memory-limit)")) << run;
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"mine.json"});

  // A picture's own size, and a report read whole (40 B of memory a byte once parsed).
  const auto render = gt::testing::run_program(
      groundtruth,
      {"--memory-limit", "3000", "render", (fs::path(GT_DATASET_DIR) / "real" / "volcano.json").string(), "--out",
       (work_ / "big.png").string(), "--width", "16384", "--height", "16384"},
      work_.path());
  EXPECT_EQ(render.status, 2) << render;
  EXPECT_THAT(render.err, HasSubstr("render: a 16384x16384 picture needs about 10.0 GiB")) << render;
  {
    std::ofstream padded(work_ / "padded.json");
    padded << R"({"schema": 1, "cases": [)" << std::string(std::size_t{30} << 20, ' ') << "]}";
  }
  const auto diff = gt::testing::run_program(
      groundtruth,
      {"--memory-limit", "1000", "diff-reports", (work_ / "padded.json").string(), (work_ / "padded.json").string()},
      work_.path());
  EXPECT_EQ(diff.status, 2) << diff;
  EXPECT_THAT(diff.err, HasSubstr("reading report")) << diff;
  EXPECT_THAT(diff.err, HasSubstr("(31457306 bytes x 40 B)")) << diff;
  // merge holds every shard's report at once: weighed together before the first is read.
  for (const char* shard : {"shard1", "shard2"}) {
    fs::create_directory(work_ / shard);
    fs::copy_file(work_ / "padded.json", work_ / shard / "report.json");
  }
  const auto merge = gt::testing::run_program(
      groundtruth, {"--memory-limit", "2000", "merge", "shard1", "shard2", "--out", "merged"}, work_.path());
  EXPECT_EQ(merge.status, 2) << merge;
  EXPECT_THAT(merge.err, HasSubstr("merge needs about 2.3 GiB (62914612 bytes of shard reports x 40 B)")) << merge;
  EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"mine.json", "padded.json", "shard1", "shard2"}));
}

TEST_F(Hostile, CommandLineNumbersMustBeFiniteAndFit) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", "--algorithm", "noise.simplex2", "--size", "4294967297x1"},
        std::vector<std::string>{"run", "--algorithm", "noise.simplex2", "--cell-size", "nan"},
        std::vector<std::string>{"diff-image", "a.png", "b.png", "--tolerance", "nan"},
        std::vector<std::string>{"render", "a.off", "--out", "a.png", "--cell-size", "nan"},
        std::vector<std::string>{"stats", "a.npy", "--stream-threshold", "nan"},
        std::vector<std::string>{"--memory-limit", "nan", "list"},
        std::vector<std::string>{"render", "a.off", "--out", "a.png", "--azimuth", "nan"}}) {
    const auto run = gt::testing::run_program(groundtruth, args, work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.output(), ::testing::AnyOf(HasSubstr("finite"), HasSubstr("4294967297x1"))) << run;
  }
  EXPECT_TRUE(fs::is_empty(work_.path()));
}

// JSON nested 200,000 levels deep overflowed the stack of every command that copied, compared or
// printed it; it is refused while it is read, as a case file and as a report given to diff-reports.
TEST_F(Hostile, JsonNestedDeeperThanAnyOfOursIsRefusedWhileRead) {
  const std::string deep = std::string(200000, '[') + std::string(200000, ']');
  std::ofstream(work_ / "mine.json") << R"([{"name": "mine.deep", "algorithm": "erosion.thermal", "params": )" << deep
                                     << "}]";
  const auto cases = gt::testing::run_program(
      groundtruth, {"run", "mine.deep", "--cases", (work_ / "mine.json").string(), "--out", (work_ / "out").string()},
      work_.path());
  EXPECT_EQ(cases.status, 2) << cases;
  EXPECT_THAT(cases.err, HasSubstr("JSON nested deeper than 64 levels")) << cases;
  std::ofstream(work_ / "deep_report.json") << R"({"schema": 1, "cases": )" << deep << "}";
  const auto diff = gt::testing::run_program(
      groundtruth, {"diff-reports", (work_ / "deep_report.json").string(), (work_ / "deep_report.json").string()},
      work_.path());
  EXPECT_EQ(diff.status, 2) << diff;
  EXPECT_THAT(diff.err, HasSubstr("deep_report.json: JSON nested deeper than 64 levels")) << diff;
  EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"deep_report.json", "mine.json"}));
}

// Rectangular cells need both spacings: the rows' alone is refused, in a case file and on the
// command line.
TEST_F(Hostile, ARowSpacingWithoutAColumnSpacingIsRefused) {
  json entry = thermal_case("mine.rows_only");
  entry["input"]["cell_size_y"] = 2.0;
  expect_case_refused(entry, "cell_size_y (the rows' spacing) needs cell_size");
  const auto run = gt::testing::run_program(
      groundtruth, {"run", "--algorithm", "noise.simplex2", "--cell-size-y", "2", "--out", (work_ / "out").string()},
      work_.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("--cell-size")) << run;
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"mine.json"});
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

// Where a file is expected only a regular file is read: a FIFO would block forever, /dev/zero
// never ends, a folder reads as empty.
TEST_F(Hostile, PipesDevicesAndFoldersAreRefusedWhereAFileIsExpected) {
  ASSERT_EQ(mkfifo((work_ / "fifo").c_str(), 0600), 0);
  ASSERT_EQ(mkfifo((work_ / "fifo.off").c_str(), 0600), 0);
  fs::create_directory(work_ / "folder");
  fs::create_directory(work_ / "folder.off");
  const std::string out = (work_ / "out").string();
  for (const std::string& special : {(work_ / "fifo").string(), std::string("/dev/zero"), (work_ / "folder").string()}) {
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"run", "erosion.thermal.spec.*", "--expectations", special, "--out", out},
          std::vector<std::string>{"run", "erosion.thermal.spec.*", "--flakes", special, "--out", out},
          std::vector<std::string>{"diff-reports", special, special},
          // The readers of heightmaps, meshes, images and volumes say so too, not "no such file".
          std::vector<std::string>{"stats", special},
          std::vector<std::string>{"check-mesh", special + ".off"},
          std::vector<std::string>{"compare-mesh", special + ".off", special + ".off"},
          std::vector<std::string>{"run", "cave.marching_tetrahedra.mutant_probe.solid8", "--candidate", special + ".off",
                                   "--out", out},
          std::vector<std::string>{"run", "render.phong.mutant_probe.quad", "--candidate", special, "--out", out},
          std::vector<std::string>{"diff-image", special, special},
          std::vector<std::string>{"run", "--algorithm", "cave.marching_tetrahedra", "--input", special, "--out", out}}) {
      // A mesh is read by its extension.
      if (std::ranges::any_of(args, [](const std::string& arg) { return arg.ends_with(".off") && !fs::exists(arg); })) continue;
      const auto run = gt::testing::run_program(groundtruth, args, work_.path());
      EXPECT_EQ(run.status, 2) << run;
      EXPECT_THAT(run.err, HasSubstr("not a regular file")) << run;
    }
  }
  EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"fifo", "fifo.off", "folder", "folder.off"}));
}

// diff-reports is as strict as history: an outcome it does not know, a name of the wrong type or a
// report without cases is bad input (exit 2), never "no change".
TEST_F(Hostile, ReportsWithUnknownOutcomesOrNoCasesAreRefused) {
  const auto made = gt::testing::run_program(
      groundtruth, {"run", "erosion.thermal.spec.*", "--quiet", "--out", (work_ / "out").string()}, work_.path());
  ASSERT_EQ(made.status, 0) << made;
  const json report = json::parse(gt::testing::read_text(work_ / "out" / "report.json"));
  const auto refused = [&](const std::function<void(json&)>& change, const std::string& message) {
    json changed = report;
    change(changed);
    std::ofstream(work_ / "changed.json") << changed.dump();
    const auto run = gt::testing::run_program(
        groundtruth, {"diff-reports", (work_ / "out" / "report.json").string(), (work_ / "changed.json").string()},
        work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr(message)) << run;
  };
  for (const char* word : {"FAIL", "failed", "eror"}) {
    refused([&](json& r) { r["cases"][0]["checks"][0]["status"] = word; }, fmt::format("'{}' is not an outcome", word));
    refused([&](json& r) { r["cases"][0]["status"] = word; }, fmt::format("'{}' is not an outcome", word));
  }
  refused([](json& r) { r["cases"][0]["name"] = 7; }, "malformed");
  refused([](json& r) { r["cases"] = json::array(); }, "holds no case");
}

TEST_F(Hostile, AnEmptyOrOverlongOutputIsBadInput) {
  const auto empty = gt::testing::run_program(groundtruth, {"run", "erosion.thermal.spec.*", "--out", ""}, work_.path());
  EXPECT_EQ(empty.status, 2) << empty;
  EXPECT_THAT(empty.err, HasSubstr("--out is empty")) << empty;
  const auto long_name =
      gt::testing::run_program(groundtruth, {"run", "erosion.thermal.spec.*", "--out", std::string(5000, 'x')}, work_.path());
  EXPECT_EQ(long_name.status, 2) << long_name;
  EXPECT_THAT(long_name.err, ::testing::Not(HasSubstr("internal error"))) << long_name;
  EXPECT_TRUE(entries_of(work_.path()).empty());
}

// A path the system refuses (here a loop of symbolic links in a --cases folder) is bad input with
// the system's reason, not an internal error.
TEST_F(Hostile, ALoopOfLinksIsBadInput) {
  fs::create_directory(work_ / "cases");
  fs::create_symlink("a.json", work_ / "cases" / "b.json");
  fs::create_symlink("b.json", work_ / "cases" / "a.json");
  const auto run = gt::testing::run_program(
      groundtruth, {"run", "mine.*", "--cases", (work_ / "cases").string(), "--out", (work_ / "out").string()},
      work_.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("Too many levels of symbolic links")) << run;
  EXPECT_EQ(entries_of(work_.path()), std::vector<std::string>{"cases"});
}

// Output that could not be written is not a success: stdout on a full device is exit 2.
TEST_F(Hostile, AnUnwritableStandardOutputIsNotASuccess) {
  const auto run = gt::testing::run_program("/bin/sh", {"-c", "exec \"$0\" list > /dev/full", groundtruth}, work_.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("cannot write to standard output")) << run;
}

// A full disk, simulated by a file-size limit (ulimit -f: a write beyond it fails with EFBIG, as
// one on a full disk fails with ENOSPC): every command that writes ends with exit 2 and the
// system's reason, leaves no partial file and keeps what --out held before.
TEST_F(Hostile, AFullDiskIsExitTwoWithNothingPartial) {
  const std::string volcano = (fs::path(GT_DATASET_DIR) / "real" / "volcano.json").string();
  for (const auto& [name, azimuth] : {std::pair{"a.png", "10"}, std::pair{"b.png", "20"}}) {
    const auto render = gt::testing::run_program(groundtruth, {"render", volcano, "--out", name, "--azimuth", azimuth},
                                                 work_.path());
    ASSERT_EQ(render.status, 0) << render;
  }
  const auto earlier = gt::testing::run_program(
      groundtruth, {"run", "erosion.thermal.spec.example_3x3", "--out", "report"}, work_.path());
  ASSERT_EQ(earlier.status, 0) << earlier;
  const std::string earlier_report = gt::testing::read_text(work_ / "report" / "report.json");
  // 40 blocks (20 KiB in dash's 512-byte blocks): each picture below is 50 to 70 KiB and
  // report.json over 20 KiB, while each input fits.
  const std::string limit = "-f 40";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", volcano, "--out", "c.png"},
        std::vector<std::string>{"diff-image", "a.png", "b.png", "--out", "d.png"},
        std::vector<std::string>{"stats", volcano, "--out", "stats"},
        std::vector<std::string>{"run", "erosion.thermal.spec.example_3x3", "--out", "report"}}) {
    const auto run = run_with_limit(limit, args, work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, ::testing::AnyOf(HasSubstr("File too large"), HasSubstr("not drawn"))) << run;
    EXPECT_THAT(run.err, ::testing::Not(HasSubstr("internal error"))) << run;
    EXPECT_EQ(entries_of(work_.path()), (std::vector<std::string>{"a.png", "b.png", "report"})) << run;
  }
  EXPECT_EQ(gt::testing::read_text(work_ / "report" / "report.json"), earlier_report);
}

// A reader that went away (`groundtruth list | head -1`) is a failed write, not SIGPIPE: exit 2
// with the reason, after the clean-up.
TEST_F(Hostile, AClosedPipeIsExitTwoNotADeathBySignal) {
  int ends[2] = {-1, -1};
  ASSERT_EQ(pipe(ends), 0);
  close(ends[0]);
  std::vector<std::string> words = {groundtruth, "list"};
  std::vector<char*> argv = gt::testing::argv_of(words);
  const std::string err_file = (work_ / "stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, groundtruth.c_str(), &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  close(ends[1]);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_THAT(gt::testing::read_text(err_file), HasSubstr("cannot write to standard output: Broken pipe"));
}

TEST_F(Hostile, AParameterGivenTwiceIsRefused) {
  const std::string volcano = (fs::path(GT_DATASET_DIR) / "real" / "volcano.json").string();
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"run", "--algorithm", "erosion.thermal", "--input", volcano, "--set", "iterations=1",
                                 "--set", "iterations=2", "--out", (work_ / "out").string()},
        std::vector<std::string>{"ab", "--algorithm", "erosion.thermal", "--input", volcano, "--a", "iterations=1",
                                 "--a", "iterations=2", "--b", "iterations=3", "--out", (work_ / "out").string()}}) {
    const auto run = gt::testing::run_program(groundtruth, args, work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr("names iterations twice (iterations=1 and iterations=2)")) << run;
  }
  for (const char* infinite : {"iterations=inf", "iterations=-inf", "iterations=nan"}) {
    const auto run = gt::testing::run_program(
        groundtruth,
        {"run", "--algorithm", "erosion.thermal", "--input", volcano, "--set", infinite, "--out", (work_ / "out").string()},
        work_.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr("is not finite")) << run;
  }
  EXPECT_TRUE(entries_of(work_.path()).empty());
}

TEST_F(Hostile, StaleStagingOfAKilledRunIsRemovedByTheNextRun) {
  // A run killed outright leaves .report.groundtruth-staging-PID; no process has that PID any more.
  pid_t gone = 0;
  {
    const pid_t child = fork();
    if (child == 0) _exit(0);
    waitpid(child, nullptr, 0);
    gone = child;
  }
  const fs::path stale = work_ / (".report.groundtruth-staging-" + std::to_string(gone));
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
  const fs::path staging = work / (".report.groundtruth-staging-" + std::to_string(pid));
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
// The signals issue 40 found leaving the staging folder: SIGUSR1 and SIGALRM (SIGPIPE is a failed
// write, AClosedPipeIsExitTwoNotADeathBySignal).
TEST(Interrupted, BySigusr1LeavesNothing) { expect_clean_interruption(SIGUSR1); }
TEST(Interrupted, BySigalrmLeavesNothing) { expect_clean_interruption(SIGALRM); }

}  // namespace
