// planet.earth_like as a user runs it (issue 13): the planet.* cases pass with their pictures and
// fields, a user's global grid replaces the Earth, and bad input is refused with exit 2 and a
// message naming the problem.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/cli_report.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using gt::testing::check_names;
using gt::testing::report_of;
using gt::testing::run_groundtruth;

TEST(PlanetCli, TheProbeCasePassesWithItsMapsAndFields) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder.path() / "out";
  const auto result = run_groundtruth({"run", "planet.mutant_probe.r12", "--out", out.string()}, folder.path());
  ASSERT_EQ(result.status, 0) << result;
  const auto report = report_of(out);
  ASSERT_EQ(report["cases"].size(), 1u);
  const auto& planet = report["cases"][0];
  EXPECT_EQ(planet["status"], "pass");
  const auto names = check_names(planet);
  for (const char* expected : {"partition.disconnected_plates.cpu", "parity.elevation.float_vs_double",
                               "legacy.plate_difference", "fidelity.land_fraction", "spec.expansion_rate.cpu"}) {
    EXPECT_THAT(names, ::testing::Contains(std::string(expected)));
  }
  for (const char* file : {"elevation.png", "plates.png", "elevation_cpu.exr", "elevation_cpu.npy"}) {
    EXPECT_TRUE(fs::exists(out / "planet.mutant_probe.r12" / file)) << file;
  }
}

TEST(PlanetCli, ABadGlobalGridIsRefused) {
  gt::testing::TemporaryFolder folder;
  const auto grid = folder.path() / "mars.nc";
  std::ofstream(grid) << "not netCDF\n";
  const auto result = run_groundtruth({"run", "--algorithm", "planet.earth_like", "--set", "resolution=8", "--set",
                                       "plates=5", "--input", grid.string(), "--out", (folder.path() / "out").string()},
                                      folder.path());
  EXPECT_EQ(result.status, 2) << result;
  EXPECT_THAT(result.err, HasSubstr("mars.nc"));
}

TEST(PlanetCli, OutOfRangeParametersAreRefused) {
  gt::testing::TemporaryFolder folder;
  const struct {
    std::vector<std::string> sets;
    const char* message;
  } refused[] = {{{"resolution=0"}, "resolution"},
                 {{"resolution=301"}, "resolution"},
                 {{"resolution=2", "plates=25"}, "exceeds the 24 regions"},
                 {{"jitter=nan"}, "jitter"},
                 {{"plate_rule=random"}, "plate_rule"}};
  for (const auto& [sets, message] : refused) {
    std::vector<std::string> args = {"run", "--algorithm", "planet.earth_like", "--out", (folder.path() / "out").string()};
    for (const auto& set : sets) args.insert(args.end(), {"--set", set});
    const auto result = run_groundtruth(args, folder.path());
    EXPECT_EQ(result.status, 2) << result;
    EXPECT_THAT(result.err, HasSubstr(message)) << result;
    EXPECT_FALSE(fs::exists(folder.path() / "out" / "report.json"));
  }
}

}  // namespace
