// Every stepped algorithm of the registry against the stepper protocol (compare/stepper.hpp,
// compare/stepped_case.hpp): its declared state has unique plain names, units and meanings; a run
// exports every component of every declared field for the input and each backend. And every
// eroder, stepped or custom: a run without a GPU has `skip` for exactly the checks that a run with
// one adds, by the same names, and nothing else differs (dEQP's checkSupport: the harness says
// what did not run, under the name it would have had); the droplet eroders so in each ordering,
// whose GPU-only checks differ (race statistics, colour and flow map). A new algorithm joins these
// tests by its registry row alone.
#include <algorithm>
#include <filesystem>
#include <functional>
#include <ostream>
#include <set>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "compare/algorithm.hpp"
#include "compare/field_twin.hpp"
#include "compare/inputs.hpp"
#include "compare/stepped_case.hpp"
#include "core/params.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;

std::vector<std::string> algorithms_where(const std::function<bool(const gt::Algorithm&)>& wanted) {
  std::vector<std::string> names;
  for (const gt::Algorithm& algorithm : gt::algorithms()) {
    if (wanted(algorithm)) names.push_back(algorithm.name);
  }
  return names;
}

std::vector<std::string> stepped_algorithms() {
  return algorithms_where([](const gt::Algorithm& algorithm) { return algorithm.kind == gt::CaseKind::stepped; });
}

// An algorithm with parameters beside its defaults, named for the test by `label`.
struct Variant {
  std::string algorithm;
  nlohmann::json params = nlohmann::json::object();
  std::string label;
};

void PrintTo(const Variant& variant, std::ostream* out) { *out << variant.algorithm << " " << variant.params.dump(); }

std::vector<Variant> eroders() {
  std::vector<Variant> variants;
  for (const std::string& name : algorithms_where(
           [](const gt::Algorithm& algorithm) { return algorithm.name.rfind("erosion.", 0) == 0; })) {
    variants.push_back({name});
  }
  return variants;
}

// The droplet eroders in their other orderings (the defaults are batch): race with the colour and
// flow map, disjoint with droplets kept apart on the small cone.
std::vector<Variant> droplet_orderings() {
  return {{"erosion.particle", {{"ordering", "race"}, {"colour", "astronaut"}}, "race_colour"},
          {"erosion.particle", {{"ordering", "disjoint"}, {"lifetime", 5}, {"spacing", 15}, {"flow_spacing", 15}}, "disjoint"},
          {"erosion.beyer", {{"ordering", "race"}}, "race"},
          {"erosion.beyer", {{"ordering", "disjoint"}, {"lifetime", 5}, {"radius", 2.0}, {"spacing", 19}}, "disjoint"}};
}

// The algorithm's defaults (and `params`) on a small noisy cone, with a short run where it has a
// count to shorten.
gt::PreparedTwin prepare(const std::string& name, const nlohmann::json& params = nlohmann::json::object()) {
  const gt::Algorithm& algorithm = gt::find_algorithm(name);
  nlohmann::json given = params;
  for (const gt::ParamSpec& spec : *algorithm.params) {
    if (spec.name == "iterations" || spec.name == "steps") given[spec.name] = 6;
  }
  const nlohmann::json cone = {{"generator", "cone"}, {"width", 20}, {"height", 16}, {"cell_size", 1.0},
                               {"peak", 8.0},         {"noise", 0.3}, {"seed", 3}};
  return algorithm.prepare(gt::resolve_params(name, *algorithm.params, given), gt::load_input(cone, nullptr, {}));
}

// Runs write their field files under `report_dir`: a folder of the test's own, since ctest runs
// the variants of one algorithm side by side and their cases share a name.
gt::CaseResult run(const std::string& name, bool gpu_available, const fs::path& report_dir,
                   const nlohmann::json& params = nlohmann::json::object()) {
  gt::PreparedTwin prepared = prepare(name, params);
  gt::RunOptions options;
  options.cpu_reps = 0;
  options.gpu_reps = 0;
  options.gpu_available = gpu_available;
  options.gpu_unavailable_reason = "no GL context (stepped_protocol_test)";
  options.report_dir = report_dir;
  gt::CaseResult result;
  result.name = name;
  result.algorithm = name;
  const nlohmann::json expect = nlohmann::json::object();
  std::visit(
      [&](const auto& kind) {
        using Kind = std::decay_t<decltype(kind)>;
        if constexpr (std::is_same_v<Kind, gt::GeneratedCase>) gt::run_field_twin(kind.twin, kind.grid, expect, options, result);
        if constexpr (std::is_same_v<Kind, gt::SteppedTwin>) gt::run_stepped_case(kind, expect, options, result);
        if constexpr (std::is_same_v<Kind, gt::CaseRun>) kind(expect, options, result);
      },
      prepared.kind);
  if (prepared.extra_checks) prepared.extra_checks(expect, options, result);
  return result;
}

class SteppedProtocol : public gt::testing::GlTestWithParam<std::string> {};
class GpuSkips : public gt::testing::GlTestWithParam<Variant> {};

TEST_P(SteppedProtocol, DeclaresEachFieldOnceWithAUnitAndAMeaning) {
  const auto prepared = prepare(GetParam());
  const auto& twin = std::get<gt::SteppedTwin>(prepared.kind);
  ASSERT_FALSE(twin.fields.empty());
  std::set<std::string> names;
  for (const gt::FieldDecl& field : twin.fields) {
    EXPECT_TRUE(names.insert(field.name).second) << field.name << " declared twice";
    EXPECT_FALSE(field.unit.empty()) << field.name;
    EXPECT_FALSE(field.meaning.empty()) << field.name;
    EXPECT_GE(field.components, 1) << field.name;
  }
  EXPECT_NO_THROW(gt::check_state_decl(twin.fields, GetParam()));
  EXPECT_NO_THROW(gt::check_state_shape(twin.fields, twin.initial, GetParam()));
}

TEST_P(SteppedProtocol, ExportsEveryDeclaredFieldForEveryBackend) {
  const gt::testing::TemporaryFolder folder("stepped_protocol_test");
  const auto result = run(GetParam(), true, folder.path());
  ASSERT_TRUE(result.error.empty()) << result.error;
  std::set<std::string> artifacts;
  for (const auto& artifact : result.artifacts) artifacts.insert(artifact.path);
  const auto prepared = prepare(GetParam());
  const auto& twin = std::get<gt::SteppedTwin>(prepared.kind);
  for (const gt::FieldDecl& field : twin.fields) {
    for (int k = 0; k < field.components; ++k) {
      for (const char* backend : {"input", "cpu", "cpu_float", "gpu"}) {
        for (const char* extension : {".npy", ".exr"}) {
          const std::string path = result.name + "/" + gt::component_label(field, k) + "_" + backend + extension;
          EXPECT_TRUE(artifacts.contains(path)) << path << " is not among the artifacts";
          EXPECT_TRUE(fs::is_regular_file(folder.path() / path)) << path;
        }
      }
    }
  }
}

TEST_P(GpuSkips, ACpuOnlyRunSkipsExactlyTheChecksTheGpuRunAdds) {
  const Variant& variant = GetParam();
  const gt::testing::TemporaryFolder folder("stepped_protocol_test");
  const auto with_gpu = run(variant.algorithm, true, folder / "gpu", variant.params);
  const auto without = run(variant.algorithm, false, folder / "cpu", variant.params);
  ASSERT_TRUE(with_gpu.error.empty()) << with_gpu.error;
  ASSERT_TRUE(without.error.empty()) << without.error;
  std::set<std::string> gpu_run, skipped, ran;
  for (const auto& check : with_gpu.checks) {
    EXPECT_NE(check.status, gt::Outcome::skip) << check.name << ": " << check.detail;
    EXPECT_TRUE(gpu_run.insert(check.name).second) << check.name << " twice in the GPU run";
  }
  for (const auto& check : without.checks) {
    auto& into = check.status == gt::Outcome::skip ? skipped : ran;
    EXPECT_TRUE(into.insert(check.name).second) << check.name << " twice in the CPU-only run";
    if (check.status == gt::Outcome::skip) {
      EXPECT_EQ(check.detail, "no GL context (stepped_protocol_test)");
    }
  }
  std::set<std::string> added_by_gpu;
  std::set_difference(gpu_run.begin(), gpu_run.end(), ran.begin(), ran.end(),
                      std::inserter(added_by_gpu, added_by_gpu.begin()));
  EXPECT_EQ(skipped, added_by_gpu);
  EXPECT_TRUE(std::includes(gpu_run.begin(), gpu_run.end(), ran.begin(), ran.end()))
      << "the CPU-only run has a check the GPU run lacks";
  EXPECT_FALSE(skipped.empty());
}

// The stepped algorithms whose declared state holds a read-only input (Jákó's hardness map).
std::vector<std::string> algorithms_with_read_only_fields() {
  std::vector<std::string> names;
  for (const std::string& name : stepped_algorithms()) {
    const auto prepared = prepare(name);
    const auto& fields = std::get<gt::SteppedTwin>(prepared.kind).fields;
    if (std::any_of(fields.begin(), fields.end(), [](const gt::FieldDecl& field) { return field.read_only; })) {
      names.push_back(name);
    }
  }
  return names;
}

class ReadOnlyInputs : public gt::testing::GlTestWithParam<std::string> {};

// Each backend loads the start state, steps it and hands every read-only field back bit for bit,
// while the fields it models change; the runner grades that as state.<field>.unchanged.<backend>.
TEST_P(ReadOnlyInputs, EveryBackendHandsThemBackAsLoaded) {
  const auto prepared = prepare(GetParam());
  const auto& twin = std::get<gt::SteppedTwin>(prepared.kind);
  for (const auto& make : {twin.reference_double, twin.reference_float, twin.make_gpu}) {
    auto stepper = make();
    stepper->set_state(twin.initial, 0);
    stepper->update(3);
    const gt::State after = stepper->get_state();
    bool changed = false;
    for (std::size_t f = 0; f < twin.fields.size(); ++f) {
      if (twin.fields[f].read_only) {
        EXPECT_EQ(after.fields[f], twin.initial.fields[f]) << twin.fields[f].name;
      } else {
        changed = changed || after.fields[f] != twin.initial.fields[f];
      }
    }
    EXPECT_TRUE(changed) << "three iterations on the noisy cone change a modelled field";
  }
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

std::string variant_name(const ::testing::TestParamInfo<Variant>& info) {
  std::string name = info.param.algorithm + (info.param.label.empty() ? "" : "_" + info.param.label);
  std::replace(name.begin(), name.end(), '.', '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Registry, SteppedProtocol, ::testing::ValuesIn(stepped_algorithms()), test_name);
INSTANTIATE_TEST_SUITE_P(Registry, ReadOnlyInputs, ::testing::ValuesIn(algorithms_with_read_only_fields()), test_name);
INSTANTIATE_TEST_SUITE_P(Eroders, GpuSkips, ::testing::ValuesIn(eroders()), variant_name);
INSTANTIATE_TEST_SUITE_P(DropletOrderings, GpuSkips, ::testing::ValuesIn(droplet_orderings()), variant_name);

}  // namespace
