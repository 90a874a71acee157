// Parameter declarations refuse what they should and fill in defaults; case files load and select.
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/refusal.hpp"

#include "compare/cases.hpp"
#include "core/errors.hpp"
#include "core/params/thermal.hpp"

namespace {

using gt::testing::refusal;

using ::testing::HasSubstr;

TEST(Params, DefaultsFillEveryDeclaredParameter) {
  const auto resolved = gt::resolve_params("erosion.thermal", gt::thermal_param_specs(), {{"iterations", 7}});
  const auto params = gt::thermal_params_from_json(resolved);
  EXPECT_EQ(params.iterations, 7);
  EXPECT_EQ(params.talus_angle_deg, 45.0);
  EXPECT_EQ(params.neighbourhood, gt::Neighbourhood::alternating);
  EXPECT_FALSE(params.normalised);
}

TEST(Params, RefusalsNameTheProblem) {
  const auto& specs = gt::thermal_param_specs();
  EXPECT_THAT(refusal([&] { gt::resolve_params("t", specs, {{"talos", 3}}); }),
              HasSubstr("unknown parameter 'talos'; known: iterations, talus_angle"));
  EXPECT_THAT(refusal([&] { gt::resolve_params("t", specs, {{"talus_angle", 95}}); }), HasSubstr("[0, 85] degree"));
  EXPECT_THAT(refusal([&] { gt::resolve_params("t", specs, {{"iterations", 2.5}}); }), HasSubstr("not an integer"));
  EXPECT_THAT(refusal([&] { gt::resolve_params("t", specs, {{"neighbourhood", "hex"}}); }),
              HasSubstr("one of cardinal, diagonal, alternating"));
  EXPECT_THAT(refusal([&] { gt::parse_param_text("t", specs, "strength", "strong"); }), HasSubstr("not a number"));
  EXPECT_THAT(refusal([&] { gt::parse_param_text("t", specs, "normalised", "maybe"); }), HasSubstr("true or false"));
}

TEST(Params, TextValuesTakeTheDeclaredKind) {
  const auto& specs = gt::thermal_param_specs();
  EXPECT_EQ(gt::parse_param_text("t", specs, "iterations", "51"), 51);
  EXPECT_EQ(gt::parse_param_text("t", specs, "talus_angle", "12.5"), 12.5);
  EXPECT_EQ(gt::parse_param_text("t", specs, "normalised", "true"), true);
  EXPECT_EQ(gt::parse_param_text("t", specs, "neighbourhood", "diagonal"), "diagonal");
}

TEST(Cases, BundledCasesLoadAndSelectByGlob) {
  const auto cases = gt::load_cases(std::filesystem::path(GT_DATASET_DIR) / "cases");
  const auto thermal = gt::select_cases(cases, {"erosion.thermal.*"});
  EXPECT_GE(thermal.size(), 6u);
  for (const auto& spec : thermal) EXPECT_EQ(spec.algorithm, "erosion.thermal");
  EXPECT_THAT(refusal([&] { gt::select_cases(cases, {"nothing.*"}); }), HasSubstr("no case matches 'nothing.*'"));
}

TEST(Cases, MalformedCaseFilesAreRefused) {
  const auto folder = std::filesystem::temp_directory_path() / "groundtruth_params_test_cases";
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "bad.json") << R"([{"name": "a", "algorithm": "erosion.thermal", "input": {}, "colour": 1}])";
  EXPECT_THAT(refusal([&] { gt::load_cases(folder); }), HasSubstr("unknown key 'colour'"));
  std::ofstream(folder / "bad.json") << R"([{"name": "a", "algorithm": "x", "input": {}}, {"name": "a", "algorithm": "x", "input": {}}])";
  EXPECT_THAT(refusal([&] { gt::load_cases(folder); }), HasSubstr("used twice"));
  std::ofstream(folder / "bad.json") << "[{";
  EXPECT_THAT(refusal([&] { gt::load_cases(folder); }), HasSubstr("not valid JSON"));
  std::filesystem::remove_all(folder);
}

}  // namespace
