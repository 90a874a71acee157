// The noise sampler's twins (reference/noise/noise_field.cpp, gpu/noise/noise_field.cpp) agree,
// the origin reduction really is a period of every noise, and bad parameters are refused.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/refusal.hpp"

#include "compare/checks/field.hpp"
#include "compare/checks/noise_error_model.hpp"
#include "core/errors.hpp"
#include "core/params/noise.hpp"
#include "gpu/noise/noise_field.hpp"
#include "reference/noise/noise_field.hpp"
#include "tests/support/gl_test.hpp"

namespace {

using gt::testing::refusal;

using gt::Fractal;
using gt::NoiseBasis;

struct Kind {
  NoiseBasis basis;
  Fractal fractal;
  const char* name;
};

void PrintTo(const Kind& kind, std::ostream* out) { *out << kind.name; }

gt::NoiseParams params_of(const Kind& kind, nlohmann::json given, int width = 45, int height = 37) {
  if (kind.fractal != Fractal::none && kind.basis != NoiseBasis::perlin3) given["basis"] = gt::noise_basis_name(kind.basis);
  const auto specs = kind.fractal == Fractal::none ? gt::noise_param_specs(kind.basis) : gt::fractal_param_specs(kind.fractal);
  return gt::noise_params_from_json(kind.basis, kind.fractal, gt::resolve_params(kind.name, specs, given), width, height);
}

const Kind kinds[] = {
    {NoiseBasis::simplex2, Fractal::none, "simplex2"},
    {NoiseBasis::simplex3, Fractal::none, "simplex3"},
    {NoiseBasis::simplex4, Fractal::none, "simplex4"},
    {NoiseBasis::perlin3, Fractal::none, "perlin3"},
    {NoiseBasis::perlin3_texture, Fractal::none, "perlin3_texture"},
    {NoiseBasis::perlin3, Fractal::fbm, "fbm"},
    {NoiseBasis::perlin3, Fractal::ridged, "ridged"},
    {NoiseBasis::perlin3, Fractal::hetero_terrain, "hetero_terrain"},
    {NoiseBasis::voronoi_f1, Fractal::none, "voronoi_f1"},
    {NoiseBasis::voronoi_f4, Fractal::none, "voronoi_f4"},
    {NoiseBasis::voronoi_f2f1, Fractal::none, "voronoi_f2f1"},
    {NoiseBasis::voronoi_crackle, Fractal::none, "voronoi_crackle"},
    {NoiseBasis::cell_noise, Fractal::none, "cell_noise"},
    {NoiseBasis::voronoi_f2, Fractal::hetero_terrain, "hetero_terrain_voronoi_f2"},
};

class NoiseFieldGpu : public gt::testing::GlTestWithParam<Kind> {};

// Same float operations in the same order and no division: llvmpipe must give the same bits. A
// GPU that rounds differently would need the bound of compare/algorithms/noise.cpp instead.
TEST_P(NoiseFieldGpu, GpuGivesTheFloatReferenceBits) {
  const auto params = params_of(GetParam(), {{"step", 0.173}, {"origin_x", -13.25}, {"origin_y", 7.5}, {"seed", 99}});
  gt::gpu::NoiseField gpu(params);
  gpu.run();
  const auto on_gpu = gpu.result();
  const auto reference = gt::reference::noise_field<float>(params, gt::reduced_origin(params));
  const auto difference = gt::field_difference(reference, on_gpu);
  EXPECT_EQ(difference.nonfinite, 0u);
  EXPECT_EQ(difference.differing_bits, 0u) << "max |difference| " << difference.max_abs;
  EXPECT_GT(gt::field_totals(reference).high - gt::field_totals(reference).low, 0.1) << "a flat field proves nothing";
}

INSTANTIATE_TEST_SUITE_P(Kinds, NoiseFieldGpu, ::testing::ValuesIn(kinds),
                         [](const auto& info) { return std::string(info.param.name); });

// Seed 001's tileable blend, on a grid that is not square: the GPU gives ref<float>'s bits, and
// ref<double>'s sample one grid past each edge is the first of its row or column (the same points,
// weights 1 and 0 up to one rounding of W·(1/W) in double), where the plain field does not repeat.
TEST_P(NoiseFieldGpu, TileableFieldRepeatsWithTheGridsPeriodOnBothTwins) {
  const auto params = params_of(GetParam(), {{"step", 0.173}, {"origin_x", -13.25}, {"origin_y", 7.5}, {"tileable", true}});
  gt::gpu::NoiseField gpu(params);
  gpu.run();
  const auto reference = gt::reference::noise_field<float>(params, gt::reduced_origin(params));
  EXPECT_EQ(gt::field_difference(reference, gpu.result()).differing_bits, 0u);
  auto plain = params;
  plain.tileable = false;
  std::vector<std::array<int, 2>> cells;
  for (int j = 0; j < params.sampling.height; ++j) cells.insert(cells.end(), {{0, j}, {params.sampling.width, j}});
  for (int i = 0; i < params.sampling.width; ++i) cells.insert(cells.end(), {{i, 0}, {i, params.sampling.height}});
  const auto tiled = gt::reference::noise_samples_at(params, params.sampling.origin, cells);
  const auto untiled = gt::reference::noise_samples_at(plain, params.sampling.origin, cells);
  double tiled_seam = 0.0, plain_seam = 0.0;
  for (std::size_t pair = 0; pair + 1 < cells.size(); pair += 2) {
    tiled_seam = std::max(tiled_seam, std::abs(tiled[pair + 1] - tiled[pair]));
    plain_seam = std::max(plain_seam, std::abs(untiled[pair + 1] - untiled[pair]));
  }
  EXPECT_LE(tiled_seam, 1e-13);
  EXPECT_GT(plain_seam, 0.05) << "the plain field repeats by chance: the check proves nothing";
}

class NoiseOriginReduction : public ::testing::TestWithParam<Kind> {};

// The reduced origin is a period of the noise: in double, the field is the same up to the
// rounding of the shift itself (|origin|·2^-52 in the coordinates, times the gradient ~10).
TEST_P(NoiseOriginReduction, IsAPeriodOfTheNoise) {
  nlohmann::json given = {{"step", 0.31}, {"origin_x", 98765.4}, {"origin_y", -4321.1}, {"reduce_origin", true}};
  const int dimension = gt::noise_dimension(GetParam().basis);
  if (dimension >= 3) given["origin_z"] = 777.7;
  if (dimension == 4) given["origin_w"] = 55.5;
  const auto params = params_of(GetParam(), given, 9, 7);
  const auto reduced = gt::reduced_origin(params);
  for (int axis = 0; axis < 3; ++axis) EXPECT_LT(std::abs(reduced[axis]), 600.0);
  const auto original_field = gt::reference::noise_field<double>(params, params.sampling.origin);
  const auto reduced_field = gt::reference::noise_field<double>(params, reduced);
  EXPECT_LT(gt::field_difference(original_field, reduced_field).max_abs, 1e5 * 0x1p-52 * 100.0);
}

INSTANTIATE_TEST_SUITE_P(Kinds, NoiseOriginReduction, ::testing::ValuesIn(kinds),
                         [](const auto& info) { return std::string(info.param.name); });

// The cellular bases jump where a coordinate crosses a lattice plane. On a grid whose samples meet
// planes in exact arithmetic (origin (0.3, −2.7), step 0.3) ref<float>'s coordinate lands an ulp on
// the other side of some: every sample where ref<float> and ref<double> then differ by more than the
// precision bound was marked from the coordinates alone, and the marks are a small part of the grid.
TEST(NoisePrecision, TheCellularJumpsAreFoundFromTheCoordinatesBeforeTheTwinsRun) {
  // Voronoi distances jump only where the k-th nearest of the 27 cells' points lies beyond
  // distance 1, so F4 shows fewer jumps than cell noise, which jumps at every plane.
  const struct {
    Kind kind;
    int fewest_jumps;
  } grids[] = {{{NoiseBasis::cell_noise, Fractal::none, "cell_noise"}, 50},
               {{NoiseBasis::voronoi_f4, Fractal::none, "voronoi_f4"}, 5},
               {{NoiseBasis::cell_noise, Fractal::fbm, "fbm_cell_noise"}, 50}};
  for (const auto& [kind, fewest_jumps] : grids) {
    const auto params = params_of(kind, {{"step", 0.3}, {"origin_x", 0.3}, {"origin_y", -2.7}, {"origin_z", 0.5}}, 160, 128);
    const auto marked = gt::lattice_jump_samples(params);
    ASSERT_EQ(marked.size(), std::size_t{160 * 128}) << kind.name;
    const auto truth = gt::reference::noise_field<double>(params, params.sampling.origin);
    const auto in_float = gt::reference::noise_field<float>(params, gt::reduced_origin(params));
    const double bound = gt::noise_precision_bound(params, gt::largest_coordinate(params));
    int jumps = 0, unmarked_jumps = 0, marks = 0;
    for (std::size_t sample = 0; sample < marked.size(); ++sample) {
      marks += marked[sample];
      if (std::abs(truth.values[sample] - static_cast<double>(in_float.values[sample])) <= bound) continue;
      ++jumps;
      unmarked_jumps += marked[sample] == 0 ? 1 : 0;
    }
    EXPECT_GE(jumps, fewest_jumps) << kind.name << ": too few jumps on this grid, the test proves little";
    EXPECT_EQ(unmarked_jumps, 0) << kind.name;
    EXPECT_LT(marks, static_cast<int>(marked.size()) / 5) << kind.name;
  }
  EXPECT_TRUE(gt::lattice_jump_samples(params_of(kinds[3], {{"step", 0.3}, {"origin_x", 0.3}})).empty());
}

TEST(NoiseParams, BadFractalParametersAreRefused) {
  const Kind fbm{NoiseBasis::perlin3, Fractal::fbm, "noise.fbm"};
  using ::testing::HasSubstr;
  EXPECT_THAT(refusal([&] { params_of(fbm, {{"octaves", 0}}); }), HasSubstr("[1, 32]"));
  EXPECT_THAT(refusal([&] { params_of(fbm, {{"octaves", 1000}}); }), HasSubstr("out of range"));
  EXPECT_THAT(refusal([&] { params_of(fbm, {{"lacunarity", 0}}); }), HasSubstr("lacunarity"));
  EXPECT_THAT(refusal([&] { params_of(fbm, {{"lacunarity", 2.5}, {"reduce_origin", true}}); }),
              HasSubstr("integer lacunarity"));
  EXPECT_THAT(refusal([&] { params_of(fbm, {{"step", -1}}); }), HasSubstr("step"));
}

}  // namespace
