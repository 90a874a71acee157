// Issue 11's verdict rules as units: the order of outcomes (a skipped GPU half is never a pass),
// the expectation list keyed on case and check, strict JSON keys with "did you mean", and the
// mutant registry's own invariants (unique dotted names, at least three of each kind per family,
// every named case exists, which checks may kill which kind).
#include <fstream>
#include <map>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/refusal.hpp"
#include "tests/support/temporary_folder.hpp"

#include "compare/cases.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/expectations.hpp"
#include "compare/mutants/mutants.hpp"
#include "compare/result.hpp"
#include "core/closest.hpp"
#include "core/errors.hpp"
#include "core/json_keys.hpp"
#include "core/mutant.hpp"

namespace {

using gt::Outcome;
using gt::testing::refusal;
using ::testing::HasSubstr;

gt::Check check_of(const std::string& name, Outcome status) {
  gt::Check check;
  check.name = name;
  check.status = status;
  return check;
}

gt::CaseResult case_of(const std::string& name, std::vector<gt::Check> checks) {
  gt::CaseResult result;
  result.name = name;
  result.checks = std::move(checks);
  result.status = gt::case_outcome(result);
  return result;
}

TEST(Outcomes, SkippedGpuHalfIsNeverAPass) {
  const auto result = case_of("a", {check_of("mass.cpu", Outcome::pass), check_of("parity.shadow.terrain.gpu_vs_float", Outcome::skip)});
  EXPECT_EQ(result.status, Outcome::skip);
  EXPECT_EQ(case_of("a", {check_of("x", Outcome::warn), check_of("y", Outcome::inconclusive)}).status,
            Outcome::inconclusive);
  EXPECT_EQ(case_of("a", {check_of("x", Outcome::skip), check_of("y", Outcome::fail)}).status, Outcome::fail);
  EXPECT_EQ(case_of("a", {check_of("x", Outcome::pass), check_of("y", Outcome::warn)}).status, Outcome::warn);
  EXPECT_EQ(case_of("a", {}).status, Outcome::skip);
  EXPECT_STREQ(gt::outcome_name(Outcome::inconclusive), "inconclusive");
}

TEST(Outcomes, SkipsAndInconclusivesDoNotFailTheRunButErrorsDo) {
  gt::Report report;
  report.cases = {case_of("a", {check_of("x", Outcome::skip)}), case_of("b", {check_of("y", Outcome::inconclusive)})};
  EXPECT_FALSE(gt::run_failed(report));
  report.cases[0].error = "GL error";
  EXPECT_TRUE(gt::run_failed(report));
}

TEST(Outcomes, ABoundWiderThanTheTellableShareIsInconclusive) {
  // scale 1, a bug of 10 % must still show: a bound of 0.5 cannot tell, one of 0.01 can.
  EXPECT_EQ(gt::decisive_check("parity.x", 0.0, 0.5, std::nullopt, 1.0, 0.1, "m").status, Outcome::inconclusive);
  EXPECT_EQ(gt::decisive_check("parity.x", 0.6, 0.5, std::nullopt, 1.0, 0.1, "m").status, Outcome::fail);
  EXPECT_EQ(gt::decisive_check("parity.x", 0.0, 0.01, std::nullopt, 1.0, 0.1, "m").status, Outcome::pass);
  EXPECT_EQ(gt::decisive_check("parity.x", 0.0, 0.01, 0.2, 1.0, 0.1, "m").status, Outcome::inconclusive);
}

std::vector<gt::CaseSpec> suite_of(std::initializer_list<const char*> names) {
  std::vector<gt::CaseSpec> suite;
  for (const char* name : names) suite.push_back({.name = name, .algorithm = "x"});
  return suite;
}

std::vector<gt::Expectation> expectations_from(const std::string& text, const std::vector<gt::CaseSpec>& suite) {
  const gt::testing::TemporaryFolder folder("gt_expectations");
  std::ofstream(folder / "expectations.txt") << text;
  return gt::load_expectations(folder / "expectations.txt", suite);
}

TEST(Expectations, KnownFailureOfANamedCheckDoesNotFailTheRun) {
  const auto entries = expectations_from("# comment\ncave.cubes mesh.closed.cpu fail the seed leaves holes\n",
                                         suite_of({"cave.cubes", "cave.tets"}));
  ASSERT_EQ(entries.size(), 1u);
  gt::Report report;
  report.cases = {case_of("cave.cubes", {check_of("mesh.closed.cpu", Outcome::fail), check_of("mesh.euler.cpu", Outcome::pass)}),
                  case_of("cave.tets", {check_of("mesh.closed.cpu", Outcome::pass)})};
  const auto problems = gt::apply_expectations(entries, report);
  EXPECT_TRUE(problems.empty());
  EXPECT_EQ(report.cases[0].expected_failure, "the seed leaves holes");
  EXPECT_EQ(report.cases[0].checks[0].expected, Outcome::fail);
  EXPECT_FALSE(report.cases[0].checks[1].expected.has_value());
  EXPECT_FALSE(gt::run_failed(report));
}

TEST(Expectations, AnotherFailingCheckOfAListedCaseFailsTheRun) {
  const auto entries = expectations_from("cave.cubes mesh.closed.cpu fail holes\n", suite_of({"cave.cubes"}));
  gt::Report report;
  report.cases = {case_of("cave.cubes", {check_of("mesh.closed.cpu", Outcome::fail), check_of("mesh.volume.cpu", Outcome::fail)})};
  EXPECT_TRUE(gt::apply_expectations(entries, report).empty());
  EXPECT_TRUE(report.cases[0].expected_failure.empty());
  EXPECT_TRUE(gt::run_failed(report));
}

TEST(Expectations, AFixedBugOrAVanishedCheckFailsTheRun) {
  const auto entries = expectations_from("cave.cubes mesh.closed.cpu fail holes\n", suite_of({"cave.cubes"}));
  gt::Report fixed;
  fixed.cases = {case_of("cave.cubes", {check_of("mesh.closed.cpu", Outcome::pass)})};
  auto problems = gt::apply_expectations(entries, fixed);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr("expected fail"));
  fixed.expectation_problems = problems;
  EXPECT_TRUE(gt::run_failed(fixed));

  gt::Report renamed;
  renamed.cases = {case_of("cave.cubes", {check_of("mesh.holes.cpu", Outcome::fail)})};
  problems = gt::apply_expectations(entries, renamed);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr("does not have"));

  gt::Report errored;
  errored.cases = {case_of("cave.cubes", {})};
  errored.cases[0].error = "crashed";
  problems = gt::apply_expectations(entries, errored);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_THAT(problems[0], HasSubstr("did not reach: crashed"));
}

TEST(Expectations, DevicePatternLimitsAnEntryToMatchingRenderers) {
  const auto entries = expectations_from("a parity.* warn device=NVIDIA* division within 2.5 ulp\n", suite_of({"a"}));
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_EQ(entries[0].device_pattern, "NVIDIA*");
  EXPECT_EQ(entries[0].reason, "division within 2.5 ulp");
  gt::Report report;
  report.environment.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
  report.cases = {case_of("a", {check_of("parity.max_abs", Outcome::pass)})};
  EXPECT_TRUE(gt::apply_expectations(entries, report).empty());
  EXPECT_FALSE(report.cases[0].checks[0].expected.has_value());
  report.environment.gl_renderer = "NVIDIA H200/PCIe/SSE2";
  EXPECT_EQ(gt::apply_expectations(entries, report).size(), 1u);  // expected warn, got pass
}

TEST(Expectations, MalformedEntriesAreBadInput) {
  const auto suite = suite_of({"cave.cubes"});
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubez mesh.closed.cpu fail holes\n", suite); }),
              HasSubstr("matches no case"));
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubes mesh.closed.cpu broken holes\n", suite); }),
              HasSubstr("not an outcome"));
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubes mesh.closed.cpu fail\n", suite); }), HasSubstr("reason"));
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubes\n", suite); }), HasSubstr("CASE CHECK OUTCOME"));
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubes mesh.closed.cpu fail device= holes\n", suite); }),
              HasSubstr("device= needs a pattern"));
  EXPECT_THAT(refusal([&] { expectations_from("cave.cubes mesh.closed.cpu fail device=llvmpipe*   \n", suite); }),
              HasSubstr("reason"));
}

TEST(Expectations, TheBundledListLoadsAgainstTheBundledSuite) {
  const std::filesystem::path datasets = GT_DATASET_DIR;
  EXPECT_NO_THROW(gt::load_expectations(datasets / "expectations.txt", gt::load_cases(datasets / "cases")));
}

TEST(StrictKeys, UnknownKeyNamesTheClosestKnownOne) {
  EXPECT_THAT(refusal([] { gt::require_known_keys({{"tolerence", 1}}, {"cells", "total", "tolerance"}, "case a: expect"); }),
              HasSubstr("case a: expect: unknown key 'tolerence' (did you mean 'tolerance'?)"));
  EXPECT_THAT(refusal([] { gt::require_known_keys({{"zzzzzz", 1}}, {"cells"}, "w"); }),
              ::testing::AllOf(HasSubstr("unknown key 'zzzzzz'; known: cells"), ::testing::Not(HasSubstr("did you mean"))));
  EXPECT_NO_THROW(gt::require_known_keys({{"cells", 1}}, {"cells", "total"}, "w"));
}

TEST(StrictKeys, ShapesAreCheckedBelowTheTopLevel) {
  const nlohmann::json shape = {{"talus", {{"angle", nullptr}, {"value", nullptr}}}, {"points", {{{"x", nullptr}}}}};
  EXPECT_NO_THROW(gt::require_shape({{"talus", {{"angle", 45}}}, {"points", {{{"x", 1}}}}}, shape, "e"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"talus", {{"angel", 45}}}}, shape, "e"); }),
              HasSubstr("e.talus: unknown key 'angel' (did you mean 'angle'?)"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"points", {{{"x", 1}}, {{"y", 2}}}}}, shape, "e"); }),
              HasSubstr("e.points[1]: unknown key 'y'"));
}

TEST(StrictKeys, ShapesCheckTypesAndTupleLengths) {
  using nlohmann::json;
  const json shape = {{"cells", json::array({json::array({"integer", "integer", "number"})})},
                      {"total", "number"},
                      {"at_rest", "boolean"},
                      {"walk", {{"magnitudes", json::array({"number"})}}}};
  EXPECT_NO_THROW(gt::require_shape({{"cells", {{1, 2, 0.5}, {0, 0, 1}}}, {"total", 3}, {"at_rest", true}}, shape, "e"));
  EXPECT_NO_THROW(gt::require_shape({{"walk", {{"magnitudes", {1, 10.5}}}}}, shape, "e"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"cells", "abc"}}, shape, "e"); }),
              HasSubstr("e.cells = \"abc\": expected an array"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"cells", {{1, 2, 0.5}, {1, 2}}}}, shape, "e"); }),
              HasSubstr("e.cells[1] = [1,2]: expected an array of 3 elements"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"cells", {{1.5, 2, 0.5}}}}, shape, "e"); }),
              HasSubstr("e.cells[0][0] = 1.5: expected an integer"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"total", "x"}}, shape, "e"); }), HasSubstr("e.total = \"x\": expected a number"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"at_rest", 1}}, shape, "e"); }), HasSubstr("e.at_rest = 1: expected a boolean"));
  EXPECT_THAT(refusal([&] { gt::require_shape({{"walk", {{"magnitudes", {1, "far"}}}}}, shape, "e"); }),
              HasSubstr("e.walk.magnitudes[1] = \"far\": expected a number"));
}

TEST(StrictKeys, EditDistanceCountsSingleCharacterEdits) {
  EXPECT_EQ(gt::edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(gt::edit_distance("", "abc"), 3u);
  EXPECT_EQ(gt::edit_distance("same", "same"), 0u);
  EXPECT_EQ(gt::closest_names("iteratons", {"iterations", "talus_angle"}), std::vector<std::string>{"iterations"});
}

TEST(MutantSwitch, NamesBecomeShaderDefinesAndOnlyTheActiveOneIsOn) {
  EXPECT_EQ(gt::mutant_define("erosion.pipe.half_rain"), "GT_MUTANT_EROSION_PIPE_HALF_RAIN");
  gt::set_active_mutant("noise.perlin3.swapped_gradient");
  EXPECT_TRUE(gt::mutant_active("noise.perlin3.swapped_gradient"));
  EXPECT_FALSE(gt::mutant_active("noise.perlin3"));
  gt::set_active_mutant("");
  EXPECT_FALSE(gt::mutant_active("noise.perlin3.swapped_gradient"));
  EXPECT_THAT(refusal([] { gt::set_active_mutant("Bad Name"); }), HasSubstr("dotted lower-case"));
}

TEST(MutantRegistry, EveryFamilyHasThreeOfEachKindAndNamesRealCases) {
  const auto suite = gt::load_cases(std::filesystem::path(GT_DATASET_DIR) / "cases");
  std::map<std::string, std::map<gt::MutantKind, int>> counts;
  for (const auto& mutant : gt::mutants()) {
    SCOPED_TRACE(mutant.name);
    EXPECT_NO_THROW(gt::set_active_mutant(mutant.name)) << "not a dotted lower-case name";
    EXPECT_FALSE(mutant.description.empty());
    ASSERT_FALSE(mutant.cases.empty());
    EXPECT_NO_THROW(gt::select_cases(suite, mutant.cases));
    ++counts[gt::mutant_family(mutant)][mutant.kind];
  }
  gt::set_active_mutant("");
  EXPECT_GE(gt::mutants().size(), 30u);
  for (const char* family : {"erosion", "noise", "cave", "render"}) {
    SCOPED_TRACE(family);
    EXPECT_GE(counts[family][gt::MutantKind::one_twin], 3);
    EXPECT_GE(counts[family][gt::MutantKind::both_twins], 3);
  }
  EXPECT_THAT(refusal([] { gt::find_mutant("erosion.pipe.half_rian"); }), HasSubstr("unknown mutant"));
}

TEST(MutantRegistry, EachKindIsKilledOnlyByTheChecksMeantForIt) {
  using gt::MutantKind;
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::one_twin, "parity.shadow.water.gpu_vs_float"));
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::one_twin, "image.psnr.gpu_vs_cpu"));
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::one_twin, "determinism.gpu"));
  // A float twin's own ledger sees a bug in that twin; ref<double>'s cannot.
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::one_twin, "mass.water_added.gpu"));
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::one_twin, "ledger.materials.cpu_float"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::one_twin, "mass.water_added.cpu"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::one_twin, "spec.points.cpu"));
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::both_twins, "mass.water_added.cpu"));
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::both_twins, "spec.points.cpu"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::both_twins, "parity.max_abs.gpu_vs_float"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::both_twins, "image.psnr.gpu_vs_cpu"));
  // One picture against what was asked (the camera must see rock), not a comparison of the twins.
  EXPECT_TRUE(gt::check_kind_kills(MutantKind::both_twins, "image.uncovered_share.cpu"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::one_twin, "image.uncovered_share.cpu"));
  EXPECT_FALSE(gt::check_kind_kills(MutantKind::both_twins, "determinism.gpu"));
}

}  // namespace
