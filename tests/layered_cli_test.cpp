// erosion.layered as a user runs it (issue 14): the probe cases pass with their ledger, layer,
// repose and GPU checks and their pictures; a DEM the project has never seen, given ad hoc, runs
// with the same checks; bad layer definitions are refused with exit 2 and a message naming them.
#include <filesystem>
#include <fstream>
#include <string>
#include <algorithm>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/heightmap_io.hpp"
#include "tests/support/cli_report.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::Contains;
using ::testing::HasSubstr;

using gt::testing::check_names;
using gt::testing::report_of;
using gt::testing::run_groundtruth;

TEST(LayeredCli, TheProbesPassWithTheirLedgersAndPictures) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder.path() / "out";
  const auto result =
      run_groundtruth({"run", "erosion.layered.mutant_probe.*", "--out", out.string()}, folder.path());
  ASSERT_EQ(result.status, 0) << result;
  const auto report = report_of(out);
  ASSERT_EQ(report["cases"].size(), 5u);  // cone, cliff, and the water's: rain, river, the water schedule
  for (const auto& layered : report["cases"]) {
    EXPECT_EQ(layered["status"], "pass") << layered["name"];
    const auto names = check_names(layered);
    for (const char* expected : {"ledger.materials.cpu", "ledger.total.cpu", "ledger.conversions.cpu",
                                 "ledger.materials.cpu_float", "layers.invalid.cpu", "layers.surface.cpu",
                                 "ledger.materials.gpu", "parity.shadow.soil.gpu_vs_float"}) {
      EXPECT_THAT(names, Contains(std::string(expected))) << layered["name"];
    }
    const std::string name = layered["name"];
    for (const char* file : {"surface_material.png", "cross_section.png", "cross_section_axes.png", "mask_org.png",
                             "ledger.png", "soil_topsoil_org_cpu.npy", "mask_org.npy"}) {
      EXPECT_TRUE(fs::exists(out / name / file)) << name << ": " << file;
    }
    const bool wet = name.find("rain") != std::string::npos || name.find("river") != std::string::npos ||
                     name.find("water") != std::string::npos;
    EXPECT_EQ(std::find(names.begin(), names.end(), "ledger.water.cpu") != names.end(), wet) << name;
    EXPECT_EQ(fs::exists(out / name / "water_cpu.npy"), wet) << name;
  }
  EXPECT_THAT(check_names(report["cases"][0]), Contains(std::string("spec.repose.cpu")));
}

// Ad-hoc runs on a DEM written here (a tilted, bumpy 40×30 surface of 5 m cells in a .npy file), dry
// and under rain: the same ledger and layer checks hold.
TEST(LayeredCli, AnUnseenDemHoldsTheSameFigures) {
  gt::testing::TemporaryFolder folder;
  const auto dem = folder.path() / "unseen.npy";
  {
    std::ofstream file(dem, std::ios::binary);
    const std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (30, 40), }";
    std::string padded = header + std::string(64 - (10 + header.size() + 1) % 64, ' ') + "\n";
    file.write("\x93NUMPY\x01\x00", 8);
    const auto length = static_cast<std::uint16_t>(padded.size());
    file.put(static_cast<char>(length & 0xff));
    file.put(static_cast<char>(length >> 8));
    file << padded;
    for (int y = 0; y < 30; ++y) {
      for (int x = 0; x < 40; ++x) {
        const double height = 2.0 * x + 0.5 * y + 3.0 * ((x * 7 + y * 13) % 5);
        file.write(reinterpret_cast<const char*>(&height), sizeof height);
      }
    }
  }
  // Dry scree, then loam under rain (the water's processes and its ledger).
  const struct {
    const char* name;
    std::vector<std::string> sets;
    std::vector<std::string> checks;
  } runs[] = {{"dry", {"steps=50", "soil=scree"},
               {"ledger.materials.cpu", "ledger.total.cpu", "layers.invalid.cpu", "layers.surface.cpu"}},
              {"rain", {"steps=50", "rain_rate=0.01", "vegetation=0.5"},
               {"ledger.materials.cpu", "ledger.water.cpu", "ledger.water.cpu_float", "layers.invalid.cpu"}}};
  for (const auto& run : runs) {
    const auto out = folder.path() / run.name;
    std::vector<std::string> args{"run", "--algorithm", "erosion.layered", "--input", dem.string(), "--cell-size", "5",
                                  "--out", out.string()};
    for (const auto& set : run.sets) args.insert(args.end(), {"--set", set});
    const auto result = run_groundtruth(args, folder.path());
    ASSERT_EQ(result.status, 0) << run.name << ": " << result;
    const auto report = report_of(out);
    ASSERT_EQ(report["cases"].size(), 1u);
    EXPECT_EQ(report["cases"][0]["status"], "pass") << run.name;
    const auto names = check_names(report["cases"][0]);
    for (const auto& expected : run.checks) EXPECT_THAT(names, Contains(expected)) << run.name;
  }
}

TEST(LayeredCli, BadLayerDefinitionsAreRefused) {
  gt::testing::TemporaryFolder folder;
  const struct {
    std::vector<std::string> sets;
    const char* message;
  } refused[] = {{{"topsoil_thickness=-1"}, "topsoil_thickness"},
                 {{"topsoil_thickness=2", "topsoil_max=1.5"}, "topsoil_max"},
                 {{"repose_sand=0"}, "repose_sand"},
                 {{"repose_gravel=nan"}, "repose_gravel"},
                 {{"soil=clay"}, "soil"}};
  for (const auto& [sets, message] : refused) {
    std::vector<std::string> args = {"run", "--algorithm", "erosion.layered", "--input",
                                     GT_DATASET_DIR "/real/volcano.json", "--out", (folder.path() / "out").string()};
    for (const auto& set : sets) args.insert(args.end(), {"--set", set});
    const auto result = run_groundtruth(args, folder.path());
    EXPECT_EQ(result.status, 2) << result;
    EXPECT_THAT(result.err, HasSubstr(message)) << result;
    EXPECT_FALSE(fs::exists(folder.path() / "out" / "report.json"));
  }
}

// Seed 001's spatial inputs through a user's case file: the "profile" field picks each column's
// profile (loam left, bare rock right) and the "vegetation" field each column's cover; the report
// says which profile went where. A field the algorithm does not read, a profile value naming no
// profile, a field of another size, and soil_1 without a profile field are refused with exit 2.
TEST(LayeredCli, InputFieldsPickEachColumnsProfileAndVegetation) {
  gt::testing::TemporaryFolder folder;
  const nlohmann::json hills = {{"generator", "hills"}, {"count", 2},   {"width", 24},
                                {"height", 12},         {"peak", 4.0}, {"cell_size", 1.0}};
  const auto with_fields = [&](const nlohmann::json& fields) {
    nlohmann::json input = hills;
    input["fields"] = fields;
    return input;
  };
  const nlohmann::json strips = {{"generator", "strips"}, {"count", 2}};
  const nlohmann::json halves = {{"generator", "step"}, {"peak", 1.0}};
  const nlohmann::json cases = nlohmann::json::array({
      {{"name", "mine.maps.good"}, {"algorithm", "erosion.layered"},
       {"input", with_fields({{"profile", strips}, {"vegetation", halves}})},
       {"params", {{"steps", 10}, {"soil_1", "bare"}}}},
      {{"name", "mine.maps.unread"}, {"algorithm", "erosion.thermal"},
       {"input", with_fields({{"vegetation", halves}})}},
      {{"name", "mine.maps.half_profile"}, {"algorithm", "erosion.layered"},
       {"input", with_fields({{"profile", {{"generator", "strips"}, {"count", 2}, {"peak", 0.5}}}})},
       {"params", {{"steps", 10}, {"soil_1", "bare"}}}},
      {{"name", "mine.maps.other_size"}, {"algorithm", "erosion.layered"},
       {"input", with_fields({{"vegetation", {{"file", GT_DATASET_DIR "/real/volcano.json"}}}})},
       {"params", {{"steps", 10}}}},
      {{"name", "mine.maps.no_profile_field"}, {"algorithm", "erosion.layered"}, {"input", hills},
       {"params", {{"steps", 10}, {"soil_1", "sand"}}}},
  });
  const auto file = folder.path() / "maps.json";
  std::ofstream(file) << cases.dump(1);

  const auto out = folder.path() / "good";
  const auto result = run_groundtruth({"run", "mine.maps.good", "--cases", file.string(), "--out", out.string()},
                                      folder.path());
  ASSERT_EQ(result.status, 0) << result;
  const auto report = report_of(out);
  ASSERT_EQ(report["cases"].size(), 1u);
  const auto& run = report["cases"][0];
  EXPECT_EQ(run["status"], "pass");
  const std::string notes = run["notes"].dump();
  EXPECT_THAT(notes, HasSubstr("profile 0 (the profile field's value 0) in 144 of 288 columns"));
  EXPECT_THAT(notes, HasSubstr("profile 1 (the profile field's value 1) in 144 of 288 columns, top down: 0 m topsoil"));
  EXPECT_THAT(notes, HasSubstr("vegetation from the input field 'vegetation', 0 .. 1"));

  const struct {
    const char* name;
    const char* message;
  } refused[] = {{"mine.maps.unread", "reads no input field 'vegetation'"},
                 {"mine.maps.half_profile", "the profile field holds 0.5"},
                 {"mine.maps.other_size", "is 87x61 cells, the heightmap 24x12"},
                 {"mine.maps.no_profile_field", "no input field 'profile'"}};
  for (const auto& [name, message] : refused) {
    const auto refused_out = folder.path() / name;
    const auto refusal = run_groundtruth({"run", name, "--cases", file.string(), "--out", refused_out.string()},
                                         folder.path());
    EXPECT_EQ(refusal.status, 2) << name << ": " << refusal;
    EXPECT_THAT(refusal.err, HasSubstr(message)) << name;
    EXPECT_FALSE(fs::exists(refused_out / "report.json")) << name;
  }
}

// The same maps from the command line: `run --algorithm erosion.layered --input DEM --field
// profile=FILE` puts the file where a case file's "fields" would (and a worker of -j 2 gets it too);
// a malformed, repeated or misplaced --field is refused with exit 2 before anything is written.
TEST(LayeredCli, AFieldFromTheCommandLineIsACaseFilesField) {
  gt::testing::TemporaryFolder folder;
  gt::Heightmap heights(12, 8, 0.0), profile(12, 8, 0.0);
  for (int y = 0; y < heights.height; ++y) {
    for (int x = 0; x < heights.width; ++x) {
      heights.at(x, y) = 10.0 + 0.5 * x;
      profile.at(x, y) = x < 3 ? 1.0 : 0.0;
    }
  }
  gt::write_heightmap(heights, folder / "dem.npy");
  gt::write_heightmap(profile, folder / "profile.npy");
  const std::vector<std::string> ad_hoc = {"run", "--algorithm", "erosion.layered", "--input", "dem.npy",
                                           "--cell-size", "1", "--set", "steps=5", "--set", "soil_1=sand"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = ad_hoc;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  const auto result = run_groundtruth(with({"--field", "profile=profile.npy", "-j", "2", "--out", "good"}), folder.path());
  ASSERT_EQ(result.status, 0) << result;
  const std::string notes = report_of(folder / "good")["cases"][0]["notes"].dump();
  EXPECT_THAT(notes, HasSubstr("profile 1 (the profile field's value 1) in 24 of 96 columns"));
  EXPECT_THAT(notes, HasSubstr("of sand"));

  const struct {
    std::vector<std::string> args;
    const char* message;
  } refused[] = {{with({"--field", "profile"}), "expected name=file"},
                 {with({"--field", "profile=profile.npy", "--field", "profile=dem.npy"}), "names 'profile' twice"},
                 {with({"--field", "profile=missing.npy"}), "missing.npy"},
                 {{"run", "--algorithm", "noise.fbm", "--field", "profile=profile.npy"}, "ride on a heightmap file"}};
  for (const auto& [args, message] : refused) {
    auto out_args = args;
    out_args.insert(out_args.end(), {"--out", "refused"});
    const auto refusal = run_groundtruth(out_args, folder.path());
    EXPECT_EQ(refusal.status, 2) << message << ": " << refusal;
    EXPECT_THAT(refusal.err, HasSubstr(message));
    EXPECT_FALSE(fs::exists(folder / "refused")) << message;
  }
}

}  // namespace
