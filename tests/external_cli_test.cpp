// An outside implementation graded where the GPU twin stands (`run --implementation`): the C BMI
// example of examples/thermal_bmi/ passes on real data, the same code with its seeded bug fails the
// shadow step, and models that break the interface's rules are refused before anything runs (exit
// 2, naming what is wrong) or, when they crash or hang inside a step, end their case alone.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "core/io/heightmap_io.hpp"
#include "tests/support/cli_report.hpp"
#include "tests/support/npy_writer.hpp"
#include "tests/support/temporary_folder.hpp"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using gt::testing::report_of;
using gt::testing::run_groundtruth;

const std::string examples = GT_BINARY_DIR "/examples/";
const std::string hostile = GT_BINARY_DIR "/tests/libhostile_bmi.so";
const std::string volcano = GT_DATASET_DIR "/real/volcano.json";

const nlohmann::json* find_check(const nlohmann::json& report_case, const std::string& name) {
  for (const auto& check : report_case["checks"]) {
    if (check["name"] == name) return &check;
  }
  return nullptr;
}

// The README's command, as written there.
std::vector<std::string> volcano_run(const std::string& implementation, const fs::path& out) {
  return {"run", "--algorithm", "erosion.thermal", "--input", volcano, "--implementation", implementation,
          "--out", out.string()};
}

TEST(ExternalCli, TheExampleLibraryPassesOnTheVolcano) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder / "out";
  const auto run = run_groundtruth(volcano_run(examples + "libthermal_bmi.so:register_bmi_thermal", out), folder.path());
  ASSERT_EQ(run.status, 0) << run;
  const auto report = report_of(out);
  ASSERT_EQ(report["cases"].size(), 1u);
  const auto& graded = report["cases"][0];
  EXPECT_EQ(graded["status"], "pass") << graded.dump(2);
  for (const char* name : {"parity.shadow.terrain.external_vs_float", "parity.shadow.terrain.multi.external_vs_float",
                           "determinism.external", "mass.relative_drift.external"}) {
    const auto* check = find_check(graded, name);
    ASSERT_NE(check, nullptr) << name;
    EXPECT_EQ((*check)["status"], "pass") << check->dump();
  }
  // The GPU twin did not run: the outside model stood in its place.
  EXPECT_EQ(find_check(graded, "parity.shadow.terrain.gpu_vs_float"), nullptr);
  const fs::path case_folder = out / graded["name"].get<std::string>();
  for (const char* file : {"bmi_config.txt", "terrain_external.npy", "after_external.png", "external_vs_float.png"}) {
    EXPECT_TRUE(fs::is_regular_file(case_folder / file)) << file;
  }
  EXPECT_THAT(gt::testing::read_text(case_folder / "bmi_config.txt"), HasSubstr("talus_angle 45"));
}

// Without ":FUNCTION" the registration function is register_bmi, which the example also exports.
TEST(ExternalCli, TheDefaultRegistrationFunctionIsRegisterBmi) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder / "out";
  const auto run = run_groundtruth(volcano_run(examples + "libthermal_bmi.so", out), folder.path());
  ASSERT_EQ(run.status, 0) << run;
  EXPECT_THAT(report_of(out)["cases"][0]["notes"].dump(), HasSubstr("registered by register_bmi"));
}

// Other neighbourhoods, real DEMs and a synthetic cone, in workers two at a time: each passes.
TEST(ExternalCli, TheExampleLibraryPassesTheBundledThermalCasesItSupports) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder / "out";
  const auto run = run_groundtruth({"run", "erosion.thermal.cardinal.*", "erosion.thermal.diagonal.*",
                                    "erosion.thermal.alternating.*", "-j", "2", "--implementation",
                                    examples + "libthermal_bmi.so:register_bmi_thermal", "--out", out.string()},
                                   folder.path());
  ASSERT_EQ(run.status, 0) << run;
  const auto report = report_of(out);
  EXPECT_GE(report["cases"].size(), 8u);
  for (const auto& graded : report["cases"]) {
    SCOPED_TRACE(graded["name"].get<std::string>());
    const auto* shadow = find_check(graded, "parity.shadow.terrain.external_vs_float");
    ASSERT_NE(shadow, nullptr);
    EXPECT_EQ((*shadow)["status"], "pass") << shadow->dump();
  }
}

// The diagonal pipes without √2: caught by the one-iteration shadow step at an odd (diagonal)
// checkpoint, while its ledger stays balanced (the bug moves material, it does not lose it).
TEST(ExternalCli, TheSeededBugFailsTheShadowStep) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder / "out";
  const auto run =
      run_groundtruth(volcano_run(examples + "libthermal_bmi_seeded_bug.so:register_bmi_thermal", out), folder.path());
  ASSERT_EQ(run.status, 1) << run;
  const auto report = report_of(out);
  const auto& graded = report["cases"][0];
  EXPECT_EQ(graded["status"], "fail");
  const auto* shadow = find_check(graded, "parity.shadow.terrain.external_vs_float");
  ASSERT_NE(shadow, nullptr);
  EXPECT_EQ((*shadow)["status"], "fail") << shadow->dump();
  const auto* ledger = find_check(graded, "mass.relative_drift.external");
  ASSERT_NE(ledger, nullptr);
  EXPECT_EQ((*ledger)["status"], "pass") << ledger->dump();
}

struct Refusal {
  std::string implementation;
  std::string algorithm;
  std::vector<std::string> said;  // each must be in the message
};

TEST(ExternalCli, ModelsThatBreakTheInterfaceAreRefusedBeforeAnythingRuns) {
  const std::vector<Refusal> refusals = {
      {hostile + ":register_wrong_name", "erosion.thermal", {"'terrain' (m, terrain height) is not among its output", "height"}},
      {hostile + ":register_wrong_units", "erosion.thermal", {"'terrain': units 'ft', expected 'm'"}},
      {hostile + ":register_wrong_shape", "erosion.thermal", {"'terrain': grid 0 has shape", "expected [", "(rows, columns)"}},
      {hostile + ":register_no_getter", "erosion.thermal", {"left these BMI functions NULL", "get_value"}},
      {hostile + ":register_crash_in_initialize", "erosion.thermal", {"crashed", "(signal 6"}},
      {hostile + ":no_such_function", "erosion.thermal", {"no function 'no_such_function'"}},
      {volcano, "erosion.thermal", {"not a shared library"}},
      {GT_BINARY_DIR "/nothing_here.so", "erosion.thermal", {"no such file"}},
      {examples + "libthermal_bmi.so:register_bmi_thermal", "noise.fbm", {"is not one"}},
  };
  for (const auto& refusal : refusals) {
    SCOPED_TRACE(refusal.implementation + " " + refusal.algorithm);
    gt::testing::TemporaryFolder folder;
    const auto out = folder / "out";
    const auto run = run_groundtruth({"run", "--algorithm", refusal.algorithm, "--input", volcano,
                                      "--implementation", refusal.implementation, "--out", out.string()},
                                     folder.path());
    EXPECT_EQ(run.status, 2) << run;
    for (const auto& words : refusal.said) EXPECT_THAT(run.err, HasSubstr(words)) << run;
    EXPECT_FALSE(fs::exists(out)) << "a refused run wrote its report folder";
  }
}

// A crash inside update() ends each case as `error` naming the signal, and the run goes on to the
// other case and writes its report; a step that never returns ends at --case-timeout (8 s: a
// case of the correct library takes 2 s on CI's machine). The crash runs under a 60 s limit it
// never reaches: under AddressSanitizer on a loaded machine the crashing worker (its start, the
// crash and ASan's report) outlasted 8 s once, and was killed as hung before it could name the
// signal.
TEST(ExternalCli, ACrashOrHangInsideAStepEndsOnlyItsCase) {
  const struct {
    std::string function, said, case_timeout;
  } faults[] = {{"register_crash", "signal", "60"}, {"register_hang", "timeout", "8"}};
  for (const auto& [function, said, case_timeout] : faults) {
    SCOPED_TRACE(function);
    gt::testing::TemporaryFolder folder;
    const auto out = folder / "out";
    const auto run = run_groundtruth({"run", "erosion.thermal.cardinal.volcano", "erosion.thermal.diagonal.volcano",
                                      "--implementation", hostile + ":" + function, "-j", "2", "--case-timeout",
                                      case_timeout, "--out", out.string()},
                                     folder.path());
    EXPECT_EQ(run.status, 1) << run;
    const auto report = report_of(out);
    ASSERT_EQ(report["cases"].size(), 2u);
    for (const auto& ended : report["cases"]) {
      EXPECT_EQ(ended["status"], "error") << ended.dump(2);
      EXPECT_THAT(ended["error"].get<std::string>(), HasSubstr(said));
    }
  }
}

}  // namespace

// ---- GLSL drop-ins: a user's shader files over the built-in ones (run --gpu-shaders) ----------

const std::string drop_ins = GT_TEST_DATA_DIR "/shaders/drop_ins/";

gt::testing::ProgramRun run_with_drop_ins(const std::string& folder, const fs::path& out, const fs::path& cwd) {
  return run_groundtruth({"run", "--algorithm", "erosion.thermal", "--input", volcano, "--set", "talus_angle=30",
                          "--set", "iterations=24", "--require-gpu", "--gpu-shaders", folder, "--out", out.string()},
                         cwd);
}

TEST(ExternalCli, AGpuShaderDropInIsGradedInTheGpuTwinsPlace) {
  gt::testing::TemporaryFolder folder;
  {
    const auto out = folder / "correct";
    const auto run = run_with_drop_ins(drop_ins + "branch_free", out, folder.path());
    ASSERT_EQ(run.status, 0) << run;
    const auto report = report_of(out);
    const auto& graded = report["cases"][0];
    const auto* shadow = find_check(graded, "parity.shadow.terrain.gpu_vs_float");
    ASSERT_NE(shadow, nullptr);
    EXPECT_EQ((*shadow)["status"], "pass") << shadow->dump();
    EXPECT_THAT(graded["notes"].dump(), HasSubstr("drop-in file(s)"));
    EXPECT_THAT(graded["notes"].dump(), HasSubstr("erosion/thermal_transfer.comp"));
    // The shader that ran is the drop-in, by its path in the report's provenance.
    EXPECT_THAT(report["environment"].dump(), HasSubstr("branch_free/erosion/thermal_transfer.comp"));
  }
  {
    const auto out = folder / "leaky";
    const auto run = run_with_drop_ins(drop_ins + "leaky", out, folder.path());
    ASSERT_EQ(run.status, 1) << run;
    const auto report = report_of(out);
    const auto& graded = report["cases"][0];
    // The shadow step fails; the mass ledger cannot: 0.1 % of the material moved in a step is of
    // the order of 1e-7 of the volcano's whole mass, inside the ledger's rounding bound (its
    // status is pass or warn, whichever the rounding of this run gives).
    const auto* shadow = find_check(graded, "parity.shadow.terrain.gpu_vs_float");
    ASSERT_NE(shadow, nullptr);
    EXPECT_EQ((*shadow)["status"], "fail") << shadow->dump();
    EXPECT_EQ(graded["status"], "fail");
  }
  {
    const auto out = folder / "swapped";
    const auto run = run_with_drop_ins(drop_ins + "swapped_block", out, folder.path());
    ASSERT_EQ(run.status, 1) << run;
    const auto report = report_of(out);
    const auto& graded = report["cases"][0];
    EXPECT_EQ(graded["status"], "error");
    EXPECT_THAT(graded["error"].get<std::string>(), HasSubstr("member request_factor"));
    EXPECT_THAT(graded["error"].get<std::string>(), HasSubstr("thermal_block.glsl"));
  }
}

TEST(ExternalCli, ADropInFolderThatNamesNoBuiltInShaderIsRefused) {
  gt::testing::TemporaryFolder folder;
  const auto out = folder / "out";
  auto run = run_with_drop_ins(drop_ins + "misnamed", out, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("erosion/thermal_transfr.comp name no built-in shader"));
  run = run_with_drop_ins(drop_ins + "no_such_folder", out, folder.path());
  EXPECT_EQ(run.status, 2) << run;
  EXPECT_THAT(run.err, HasSubstr("not a folder"));
  EXPECT_FALSE(fs::exists(out));
}

// ---- Outputs to judge: a user's noise field (run --candidate) ----------------------------------

// A 64 x 48 fBm field as noise.fbm's double reference samples it (its field file, float64).
fs::path reference_fbm(const fs::path& folder) {
  const auto out = folder / "reference";
  const auto run = run_groundtruth({"run", "--algorithm", "noise.fbm", "--size", "64x48", "--backend", "cpu", "--out",
                                    out.string(), "--quiet"},
                                   folder);
  EXPECT_EQ(run.status, 0) << run;
  return out / report_of(out)["cases"][0]["name"].get<std::string>() / "cpu.npy";
}

void write_npy(const fs::path& file, const gt::Heightmap& field) {
  std::ofstream(file, std::ios::binary) << gt::testing::npy_header("<f8", fmt::format("({}, {})", field.height, field.width))
                                        << gt::testing::npy_data(field.values);
}

gt::testing::ProgramRun grade_fbm(const fs::path& candidate, const fs::path& out, const fs::path& cwd,
                                  const std::string& size = "64x48") {
  return run_groundtruth({"run", "--algorithm", "noise.fbm", "--size", size, "--candidate", candidate.string(), "--out",
                          out.string()},
                         cwd);
}

TEST(ExternalCli, ACandidateNoiseFieldIsGradedInTheGpuTwinsPlace) {
  gt::testing::TemporaryFolder folder;
  const fs::path truth = reference_fbm(folder.path());
  ASSERT_TRUE(fs::is_regular_file(truth)) << truth;
  {  // The reference's own values, handed in as a user's file: they pass, graded against ref<double>.
    const auto out = folder / "same";
    const auto run = grade_fbm(truth, out, folder.path());
    ASSERT_EQ(run.status, 0) << run;
    const auto report = report_of(out);
    const auto& graded = report["cases"][0];
    const auto* parity = find_check(graded, "parity.max_abs.candidate_vs_double");
    ASSERT_NE(parity, nullptr);
    EXPECT_EQ((*parity)["status"], "pass");
    EXPECT_EQ((*parity)["value"], 0.0);
    EXPECT_EQ(find_check(graded, "parity.max_abs.gpu_vs_double"), nullptr);
  }
  {  // One gradient wrong: a 4 x 4 patch tilted by 0.02 a sample (a slope the function never has there).
    gt::Heightmap field = gt::read_heightmap(truth).heights;
    for (int y = 20; y < 24; ++y) {
      for (int x = 30; x < 34; ++x) field.at(x, y) += 0.02 * (x - 30);
    }
    const fs::path tilted = folder / "tilted.npy";
    write_npy(tilted, field);
    const auto out = folder / "tilted";
    const auto run = grade_fbm(tilted, out, folder.path());
    ASSERT_EQ(run.status, 1) << run;
    const auto report = report_of(out);
    const auto* parity = find_check(report["cases"][0], "parity.max_abs.candidate_vs_double");
    ASSERT_NE(parity, nullptr);
    EXPECT_EQ((*parity)["status"], "fail") << parity->dump();
  }
  {  // Another grid, another algorithm: refused before the run.
    const auto out = folder / "refused";
    auto run = grade_fbm(truth, out, folder.path(), "32x32");
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr("64 columns × 48 rows where the case samples 32 × 32"));
    run = run_groundtruth({"run", "--algorithm", "erosion.thermal", "--input", volcano, "--candidate", truth.string(),
                           "--out", out.string()},
                          folder.path());
    EXPECT_EQ(run.status, 2) << run;
    EXPECT_THAT(run.err, HasSubstr("--candidate grades a generated field"));
    EXPECT_FALSE(fs::exists(out));
  }
}
