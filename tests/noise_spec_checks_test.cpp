// The noise family's own checks that compare the double reference with something outside it
// (compare/algorithms/noise.cpp): spec.lattice_gradient (Perlin 2002's and Gustavson 2005's
// gradient tables at lattice vertices), spec.octave_sum (Musgrave's fractal sums written out
// with closed-form weights) and spec.cellular (the cellular bases written out from their definition). Each passes on the references as written and fails under the
// both-twins mutant it exists to kill (issue 11), so neither can pass whatever the reference does.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/algorithm.hpp"
#include "core/mutant.hpp"

namespace {

// Runs an algorithm's extra checks alone (no twins, no GPU) on a flat grid of the given size.
std::vector<gt::Check> noise_checks(const std::string& algorithm, const nlohmann::json& given, int width = 24,
                                    int height = 20) {
  const gt::Algorithm& entry = gt::find_algorithm(algorithm);
  gt::LoadedInput input;
  input.heights = gt::Heightmap(width, height, 0.0);
  const gt::PreparedTwin prepared = entry.prepare(gt::resolve_params(algorithm, *entry.params, given), input);
  gt::CaseResult result;
  result.name = "test." + algorithm;
  prepared.extra_checks(nlohmann::json::object(), gt::RunOptions{}, result);
  return result.checks;
}

const gt::Check* find_check(const std::vector<gt::Check>& checks, const std::string& name) {
  for (const auto& check : checks) {
    if (check.name == name) return &check;
  }
  return nullptr;
}

// The check's outcome, failing the test when it is missing.
gt::Outcome outcome_of(const std::string& algorithm, const nlohmann::json& given, const std::string& check_name) {
  const auto checks = noise_checks(algorithm, given);
  const gt::Check* check = find_check(checks, check_name);
  EXPECT_NE(check, nullptr) << algorithm << " has no " << check_name;
  return check != nullptr ? check->status : gt::Outcome::error;
}

// Restores "no mutant" however the test ends.
class WithMutant {
 public:
  explicit WithMutant(const std::string& name) { gt::set_active_mutant(name); }
  ~WithMutant() { gt::set_active_mutant(""); }
  WithMutant(const WithMutant&) = delete;
  WithMutant& operator=(const WithMutant&) = delete;
};

struct Probe {
  const char* algorithm;
  const char* params;  // JSON
  const char* check;
  const char* mutant;  // a both-twins mutant the check must kill
};

void PrintTo(const Probe& probe, std::ostream* out) { *out << probe.algorithm << " " << probe.params << " " << probe.mutant; }

class NoiseSpecCheck : public ::testing::TestWithParam<Probe> {};

TEST_P(NoiseSpecCheck, PassesOnTheReference) {
  const Probe& probe = GetParam();
  EXPECT_EQ(outcome_of(probe.algorithm, nlohmann::json::parse(probe.params), probe.check), gt::Outcome::pass);
}

TEST_P(NoiseSpecCheck, FailsUnderItsMutant) {
  const Probe& probe = GetParam();
  const WithMutant mutant(probe.mutant);
  EXPECT_EQ(outcome_of(probe.algorithm, nlohmann::json::parse(probe.params), probe.check), gt::Outcome::fail);
}

const Probe probes[] = {
    {"noise.perlin3", R"({"step": 0.1, "origin_x": 1.5})", "spec.lattice_gradient.cpu", "noise.perlin3.grad_select"},
    {"noise.perlin3", R"({"step": 0.1, "seed": 77})", "spec.lattice_gradient.cpu", "noise.perlin3.grad_select"},
    {"noise.simplex3", R"({"step": 0.1})", "spec.lattice_gradient.cpu", "noise.simplex3.grad3_swapped"},
    {"noise.simplex3", R"({"step": 0.1, "kernel": 0.5})", "spec.lattice_gradient.cpu", "noise.simplex3.grad3_swapped"},
    {"noise.simplex2", R"({"step": 0.1})", "spec.lattice_gradient.cpu", "noise.simplex3.grad3_swapped"},
    {"noise.fbm", R"({"step": 0.1, "octaves": 5})", "spec.octave_sum.cpu", "noise.fbm.gain_before_sample"},
    {"noise.fbm", R"({"step": 0.1, "octaves": 3.5, "lacunarity": 2.7, "gain": 0.6})", "spec.octave_sum.cpu",
     "noise.fbm.gain_before_sample"},
    {"noise.ridged", R"({"step": 0.1, "octaves": 4})", "spec.octave_sum.cpu", "noise.ridged.unclamped_weight"},
    {"noise.voronoi_f2", R"({"step": 0.1})", "spec.cellular.cpu", "noise.voronoi.squared_distance"},
    {"noise.voronoi_crackle", R"({"step": 0.1, "seed": 5, "origin_z": 3.3})", "spec.cellular.cpu",
     "noise.voronoi.squared_distance"},
    {"noise.cell_noise", R"({"step": 0.3})", "spec.cellular.cpu", "noise.cell.value_from_jitter_hash"},
    {"noise.hetero_terrain", R"({"step": 0.1, "basis": "voronoi_f1"})", "spec.cellular.cpu",
     "noise.voronoi.squared_distance"},
};

INSTANTIATE_TEST_SUITE_P(Noise, NoiseSpecCheck, ::testing::ValuesIn(probes));

// Hetero_terrain has no both-twins mutant of its own; its octave sum passes with the seed 001
// defaults (lacunarity 3: the running product rounds, the closed form does not) and a fraction.
TEST(NoiseSpecCheck, HeteroTerrainFollowsItsFormula) {
  EXPECT_EQ(outcome_of("noise.hetero_terrain", {{"step", 0.1}, {"lacunarity", 3.0}, {"octaves", 3.4}},
                       "spec.octave_sum.cpu"),
            gt::Outcome::pass);
  // Over cell noise, on a grid whose points meet lattice planes (the octave points p·3^k and the
  // running products may fall on either side: those points are left out).
  EXPECT_EQ(outcome_of("noise.hetero_terrain", {{"step", 0.3}, {"origin_x", 0.3}, {"origin_y", -2.7}, {"basis", "cell_noise"}},
                       "spec.octave_sum.cpu"),
            gt::Outcome::pass);
}

// The lattice check needs the reference's analytic gradient (simplex2, simplex3, perlin3 alone);
// the octave sum belongs to fractal sums only.
TEST(NoiseSpecCheck, OnlyTheBasesWithAnAnalyticGradientHaveALatticeCheck) {
  for (const char* algorithm : {"noise.simplex4", "noise.perlin3_texture", "noise.fbm"}) {
    const auto checks = noise_checks(algorithm, {{"step", 0.1}});
    EXPECT_EQ(find_check(checks, "spec.lattice_gradient.cpu"), nullptr) << algorithm;
  }
  EXPECT_EQ(find_check(noise_checks("noise.perlin3", {{"step", 0.1}}), "spec.octave_sum.cpu"), nullptr);
}

}  // namespace
