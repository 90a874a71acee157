// The GPU twin of the virtual-pipe erosion (gpu/erosion/pipes.hpp) against the CPU reference
// (reference/erosion/pipes.hpp) and on its own:
//   - one step from the same state agrees with ref<float> bit for bit in every field but the
//     terrain, whose base + change storage differs from ref<float>'s rounding of b by at most the
//     roundings ref<float> makes (half an ulp of |b| per write); every transport, border, variant,
//     with 4 pipes and with 8 (issue 3), and seed 001's code choices (raw-difference tilt, regolith
//     not diffused);
//   - many steps follow ref<double> within a linear growth model that does not involve the base
//     height (ref<float> at 500 m does not);
//   - the water ledger closes, the flux form conserves material at a 500 m base where ref<float>
//     does not (the float trap, issue 3), nothing turns negative or NaN;
//   - two runs are bitwise identical (with and without the ledger's downloads); bad input (a diagonal
//     flux in a 4-pipe state too) is refused.
//
// Rounding bounds use u = 2^-24 (float) or 2^-53 (double), the unit roundoff: one rounded
// operation changes a value v by at most u·|v| (half an ulp of v).
//
// Devices: llvmpipe (where this suite runs) divides and takes square roots with correctly rounded
// instructions, so the shaders' float operations are the reference's bit for bit. GLSL 4.50 §4.7.1
// only promises 2.5 ulp for those; on another device the one-step comparison falls back to the
// driver's model (compare/checks/pipe_error_model.hpp, pipe_rounding_growth): 32 float roundings
// of the field's scale. The driver's shadow steps (the GPU loaded with ref<float>'s state) and
// their a-priori bound (pipe_shadow_bounds) are tested here too, with a mutant they must catch.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "compare/checks/pipe_error_model.hpp"
#include "compare/inputs.hpp"
#include "core/mutant.hpp"
#include "core/params/hydraulic.hpp"
#include "core/rng.hpp"
#include "gpu/erosion/pipes.hpp"
#include "reference/erosion/pipes.hpp"
#include "tests/support/gl_test.hpp"
#include "tests/support/pipe_fields.hpp"
#include "tests/support/refusal.hpp"

namespace {

using gt::Grid;
using gt::HydraulicForcing;
using gt::HydraulicParams;
using gt::PipeBoundary;
using gt::PipeLedgerEntry;
using gt::PipeState;
using gt::SedimentTransport;

constexpr double float_roundoff = 0x1p-24;
constexpr double double_roundoff = 0x1p-53;

using gt::testing::field;
using gt::testing::noise;

double quantized(double value, double step) { return std::floor(value / step) * step; }
double as_float(double value) { return static_cast<double>(static_cast<float>(value)); }

// Largest |a − b| over the cells valid in `mask`.
template <class A, class B>
double largest_difference(const Grid<A>& a, const Grid<B>& b, const Grid<double>& mask) {
  double largest = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    const double difference = std::abs(static_cast<double>(a.values[i]) - static_cast<double>(b.values[i]));
    largest = std::max(largest, std::isnan(difference) ? INFINITY : difference);
  }
  return largest;
}

template <class T>
double largest_abs(const Grid<T>& grid, const Grid<double>& mask) {
  double largest = 0.0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (mask.is_valid(i)) largest = std::max(largest, std::abs(static_cast<double>(grid.values[i])));
  }
  return largest;
}

template <class T>
double lowest(const Grid<T>& grid, const Grid<double>& mask) {
  double low = INFINITY;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (mask.is_valid(i)) low = std::min(low, static_cast<double>(grid.values[i]));
  }
  return low;
}

template <class T>
bool all_finite(const Grid<T>& grid, const Grid<double>& mask) {
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (mask.is_valid(i) && !std::isfinite(static_cast<double>(grid.values[i]))) return false;
  }
  return true;
}

std::size_t differing_cells(const PipeState<double>& a, const PipeState<double>& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.terrain.size(); ++i) {
    const bool same = a.terrain.values[i] == b.terrain.values[i] && a.water.values[i] == b.water.values[i] &&
                      a.sediment.values[i] == b.sediment.values[i] && a.regolith.values[i] == b.regolith.values[i] &&
                      a.velocity_x.values[i] == b.velocity_x.values[i] &&
                      a.velocity_y.values[i] == b.velocity_y.values[i] && a.outflow[i] == b.outflow[i];
    differing += same ? 0 : 1;
  }
  return differing;
}

double material(const PipeLedgerEntry& entry) { return entry.terrain + entry.sediment + entry.regolith; }

class PipesGpu : public gt::testing::GlTest {
 protected:
  // llvmpipe's division and square root are correctly rounded (see the top of this file).
  static bool correctly_rounding_device() { return context->info().renderer.find("llvmpipe") != std::string::npos; }
};

// ---------------------------------------------------------------------------------------------
// One step against ref<float>.

// layers and layers_as_printed: Šťava's three layers (Algorithm 1 as the prose means it and as printed).
enum class Variant { plain, regolith_uniform_diffusion, regolith_water_diffusion, layers, layers_as_printed };

// Seed 001's code choices (the defaults are the thesis's): its raw-difference tilt and, in the
// regolith variants, a regolith that is not diffused.
struct OneStepCase {
  SedimentTransport transport;
  PipeBoundary boundary;
  Variant variant;
  int pipes = 4;
  gt::TiltDifferences tilt = gt::TiltDifferences::central;
  bool regolith_diffusion = true;
};

std::string case_name(const OneStepCase& c) {
  const char* variants[] = {"plain", "regolith_uniform_diffusion", "regolith_water_diffusion", "layers",
                            "layers_as_printed"};
  return std::string(gt::sediment_transport_name(c.transport)) + "_" + gt::pipe_boundary_name(c.boundary) + "_" +
         variants[static_cast<int>(c.variant)] + (c.pipes == 8 ? "_8_pipes" : "") +
         (c.tilt == gt::TiltDifferences::seed001_code ? "_code_tilt" : "") +
         (c.regolith_diffusion ? "" : "_regolith_undiffused");
}

void PrintTo(const OneStepCase& c, std::ostream* out) { *out << case_name(c); }

constexpr int small_width = 16, small_height = 12;

// 16 x 12 cells of 2 m x 1 m. Heights in [0.5, 3) m on a 2^-8 grid and depths below 0.55 m on a
// 2^-20 grid (rain, rain map and sources below add multiples of 2^-20 too), so every surface
// b + d_A (< 4 m: 22 significant bits) and every head is exact in float: ref<float>'s
// (b + d) − (b_n + d_n) and the GPU's (b0 − b0_n) + (Δb − Δb_n) + (d − d_n) are the same number and
// the comparison isolates the logic. No-data cells inside and on the border, dry cells, sediment,
// regolith and initial fluxes (in each of the `pipes` pipes) on some cells.
PipeState<double> small_state(int pipes = 4, int layers = 0) {
  auto terrain = field(small_width, small_height, 2.0, 1.0, [](int x, int y) {
    return quantized(1.5 + std::sin(0.7 * x) * std::cos(0.9 * y) + 0.5 * noise(x, y, 3), 0x1p-8);
  });
  terrain.valid.assign(terrain.size(), 1);
  terrain.valid[terrain.index(5, 6)] = terrain.valid[terrain.index(6, 6)] = terrain.valid[terrain.index(0, 3)] = 0;
  auto state = gt::dry_pipe_state(terrain, layers);
  for (int y = 0; y < small_height; ++y) {
    for (int x = 0; x < small_width; ++x) {
      const std::size_t i = terrain.index(x, y);
      state.water.values[i] = noise(x, y, 5) < 0.2 ? 0.0 : quantized(0.5 * noise(x, y, 7), 0x1p-20);
      state.sediment.values[i] = noise(x, y, 9) < 0.5 ? 0.0 : 0.01 * noise(x, y, 11);
      state.regolith.values[i] = noise(x, y, 21) < 0.5 ? 0.0 : 0.08 * noise(x, y, 23);
      for (int k = 0; k < pipes; ++k) state.outflow[i][k] = noise(x, y, 13) < 0.7 ? 0.0 : 0.1 * noise(x + k, y, 17);
      state.velocity_x.values[i] = noise(x, y, 25) - 0.5;  // overwritten by the step
      // Thicknesses on a 2^-12 grid, empty on about a third of the cells per layer.
      for (int k = 0; k < layers; ++k) {
        const double thickness = noise(x, y, 27 + k);
        state.layers[k].values[i] = thickness < 0.3 ? 0.0 : quantized(0.01 * thickness, 0x1p-12);
      }
    }
  }
  return state;
}

// Rain 2^-12 m/s plus a map on a 2^-14 m/s grid, Δt = 2^-5 s, sources whose depths
// rate·Δt/(l_x·l_y) are multiples of 2^-8 m (two on one cell, so their order matters).
HydraulicForcing small_forcing() {
  HydraulicForcing forcing;
  forcing.rain_map = field(small_width, small_height, 2.0, 1.0,
                           [](int x, int y) { return quantized(1e-3 * noise(x, y, 19), 0x1p-14); });
  forcing.sources = {{3, 4, 0.75}, {10, 8, 0.5}, {3, 4, 0.25}};
  return forcing;
}

HydraulicParams small_params(const OneStepCase& c) {
  HydraulicParams params;
  params.time_step = 0x1p-5;
  params.rain_rate = 0x1p-12;
  params.evaporation_rate = 0.5;
  params.capacity = 0.5;
  params.dissolving_rate = 2.0;
  params.deposition_rate = 2.0;
  params.depth_ramp = 0.05;
  params.transport = c.transport;
  params.boundary = c.boundary;
  params.pipe_count = c.pipes;
  params.tilt_differences = c.tilt;
  params.regolith_diffusion = c.regolith_diffusion;
  if (c.variant == Variant::layers || c.variant == Variant::layers_as_printed) {
    params.layers = 3;
    params.layer_capacity = {1.0, 2.0, 4.0};
    params.layer_erosion = c.variant == Variant::layers ? gt::LayerErosion::capacity_above_sediment
                                                        : gt::LayerErosion::as_printed;
    // As printed, saturated water both deposits k_d·(s − T_N) and erodes k_s·(s − T̂_k): k_s > k_d
    // so that it erodes.
    if (c.variant == Variant::layers_as_printed) params.dissolving_rate = 4.0;
  } else if (c.variant != Variant::plain) {
    params.regolith_depth = 0.05;
    params.regolith_dissolving_rate = 8.0;  // k_re = 1/4
    params.regolith_deposition_rate = 4.0;  // k_rd = 1/8
    params.sediment_diffusion = 0.125;
    params.diffusion_weighting =
        c.variant == Variant::regolith_water_diffusion ? gt::DiffusionWeighting::water : gt::DiffusionWeighting::uniform;
  }
  return params;
}

class PipesGpuOneStep : public gt::testing::GlTestWithParam<OneStepCase> {};

TEST_P(PipesGpuOneStep, MatchesTheFloatReference) {
  const auto params = small_params(GetParam());
  const auto initial = small_state(GetParam().pipes, params.layers);
  const auto forcing = small_forcing();
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::reference::PipeErosion<float> reference(gt::cast_pipe_state<float>(initial), constants, forcing);
  gt::gpu::PipeErosion gpu(initial, constants, forcing);
  reference.step();
  gpu.step();
  const auto& expected = reference.state();
  const auto actual = gpu.state();
  const auto& mask = initial.terrain;

  // Exact on llvmpipe; elsewhere 32 float roundings of each field's scale (see the top).
  const bool exact = context->info().renderer.find("llvmpipe") != std::string::npos;
  auto allowed = [&](const Grid<float>& scale) { return exact ? 0.0 : gt::pipe_rounding_growth(1, largest_abs(scale, mask)); };
  EXPECT_LE(largest_difference(actual.water, expected.water, mask), allowed(expected.water));
  EXPECT_LE(largest_difference(actual.sediment, expected.sediment, mask), allowed(expected.sediment));
  EXPECT_LE(largest_difference(actual.regolith, expected.regolith, mask), allowed(expected.regolith));
  EXPECT_LE(largest_difference(actual.velocity_x, expected.velocity_x, mask), allowed(expected.velocity_x));
  EXPECT_LE(largest_difference(actual.velocity_y, expected.velocity_y, mask), allowed(expected.velocity_y));
  ASSERT_EQ(actual.layers.size(), expected.layers.size());
  for (std::size_t k = 0; k < expected.layers.size(); ++k) {
    EXPECT_LE(largest_difference(actual.layers[k], expected.layers[k], mask), allowed(expected.layers[k])) << "layer " << k + 1;
    // As printed the walk goes deeper only where the sediment exceeds a layer's capacity left: the
    // top layer changes, the buried ones may not within a step.
    if (GetParam().variant == Variant::layers || k + 1 == expected.layers.size()) {
      EXPECT_GT(largest_difference(actual.layers[k], initial.layers[k].cast<float>(), mask), 0.0)
          << "the step should change layer " << k + 1;
    }
  }
  double flux_difference = 0.0, largest_flux = 0.0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    for (int k = 0; k < 8; ++k) {
      flux_difference = std::max(flux_difference, std::abs(actual.outflow[i][k] - expected.outflow[i][k]));
      largest_flux = std::max(largest_flux, static_cast<double>(expected.outflow[i][k]));
    }
  }
  EXPECT_LE(flux_difference, exact ? 0.0 : gt::pipe_rounding_growth(1, largest_flux));

  // The terrain: ref<float> rounds b at each write (erosion, and the regolith exchange), at most
  // u·|b| each; the GPU keeps b0 + Δb, Δb rounded at most u·|Δb| per write.
  const bool regolith = GetParam().variant == Variant::regolith_uniform_diffusion ||
                        GetParam().variant == Variant::regolith_water_diffusion;
  const int writes = regolith ? 2 : 1;
  double terrain_bound_volume = 0.0;
  double eroded = 0.0, deposited = 0.0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    const double change = actual.terrain.values[i] - static_cast<double>(static_cast<float>(initial.terrain.values[i]));
    eroded = std::min(eroded, change);
    deposited = std::max(deposited, change);
    const double bound = writes * float_roundoff * (std::abs(static_cast<double>(expected.terrain.values[i])) +
                                                    std::abs(change)) +
                         (exact ? 0.0 : gt::pipe_rounding_growth(1, std::abs(change)));
    EXPECT_LE(std::abs(actual.terrain.values[i] - expected.terrain.values[i]), bound) << "cell " << i;
    terrain_bound_volume += bound * constants.cell_area;
  }
  EXPECT_LT(eroded, 0.0) << "the step should erode somewhere";
  // As printed, saturated water erodes with k_s > k_d at least what it deposits: no cell rises.
  if (GetParam().variant != Variant::layers_as_printed) {
    EXPECT_GT(deposited, 0.0) << "and deposit somewhere";
  }

  // The ledgers: the same float quantities summed the same way; the terrain within the bound above
  // plus the double ledger's own rounding.
  const auto& mine = gpu.ledger().back();
  const auto& theirs = reference.ledger().back();
  ASSERT_EQ(gpu.ledger().size(), 2u);
  if (exact) {
    EXPECT_EQ(mine.water, theirs.water);
    EXPECT_EQ(mine.sediment, theirs.sediment);
    EXPECT_EQ(mine.regolith, theirs.regolith);
    EXPECT_EQ(mine.rain_in, theirs.rain_in);
    EXPECT_EQ(mine.source_in, theirs.source_in);
    EXPECT_EQ(mine.evaporated, theirs.evaporated);
    EXPECT_EQ(mine.boundary_out_water, theirs.boundary_out_water);
    EXPECT_EQ(mine.boundary_out_sediment, theirs.boundary_out_sediment);
    EXPECT_EQ(mine.boundary_out_regolith, theirs.boundary_out_regolith);
    EXPECT_EQ(mine.max_cfl, theirs.max_cfl);
  }
  EXPECT_LE(std::abs(mine.terrain - theirs.terrain), terrain_bound_volume + 4 * double_roundoff * theirs.terrain);
  EXPECT_GT(mine.source_in, 0.0);
  EXPECT_GT(mine.evaporated, 0.0);
  if (GetParam().boundary == PipeBoundary::open) {
    EXPECT_GT(mine.boundary_out_water, 0.0);
    EXPECT_GT(mine.boundary_out_sediment, 0.0);
    if (regolith) {
      EXPECT_GT(mine.boundary_out_regolith, 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PipesGpuOneStep,
    ::testing::Values(OneStepCase{SedimentTransport::flux, PipeBoundary::closed, Variant::plain},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::plain},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::closed, Variant::plain},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open, Variant::plain},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::closed, Variant::regolith_uniform_diffusion},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::regolith_water_diffusion},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open,
                                  Variant::regolith_uniform_diffusion},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::closed,
                                  Variant::regolith_water_diffusion},
                      // 8 pipes (issue 3): both borders and transports, diagonal fluxes in the
                      // initial state, exterior diagonals at the border and the no-data cells.
                      OneStepCase{SedimentTransport::flux, PipeBoundary::closed, Variant::plain, 8},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::plain, 8},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::closed, Variant::plain, 8},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open, Variant::plain, 8},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::regolith_water_diffusion, 8},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open,
                                  Variant::regolith_uniform_diffusion, 8},
                      // Seed 001's code choices: each alone, then both on 8 pipes. The 2 m x 1 m
                      // cells make the raw differences differ from the slopes along both axes.
                      OneStepCase{SedimentTransport::flux, PipeBoundary::closed, Variant::plain, 4,
                                  gt::TiltDifferences::seed001_code},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::regolith_uniform_diffusion, 4,
                                  gt::TiltDifferences::central, false},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::closed,
                                  Variant::regolith_water_diffusion, 4, gt::TiltDifferences::central, false},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open,
                                  Variant::regolith_water_diffusion, 8, gt::TiltDifferences::seed001_code, false},
                      // MacCormack's correction of the backtrace (one more pass): both borders, the
                      // regolith beside the sediment, 8 pipes.
                      OneStepCase{SedimentTransport::maccormack, PipeBoundary::closed, Variant::plain},
                      OneStepCase{SedimentTransport::maccormack, PipeBoundary::open, Variant::regolith_uniform_diffusion},
                      OneStepCase{SedimentTransport::maccormack, PipeBoundary::open, Variant::plain, 8},
                      // Šťava's layers: flux and semi-Lagrangian, Algorithm 1 as meant and as printed.
                      OneStepCase{SedimentTransport::flux, PipeBoundary::closed, Variant::layers},
                      OneStepCase{SedimentTransport::semi_lagrangian, PipeBoundary::open, Variant::layers, 8},
                      OneStepCase{SedimentTransport::flux, PipeBoundary::open, Variant::layers_as_printed}),
    [](const ::testing::TestParamInfo<OneStepCase>& info) { return case_name(info.param); });

TEST_F(PipesGpu, ThermalStepMatchesTheFloatReference) {
  // Jákó & Tóth's combined step. Without suspended sediment and with capacity 0 the pipe stages
  // leave the terrain alone (moved = −k_d·(0 − 0)), so the thermal iteration starts from Δb = 0 and
  // forms the same height differences as ref<float>: every transfer is the same float. ref<float>
  // then rounds b at each of its 16 updates (8 outflows, 8 inflows) by at most u·|b|; the GPU's Δb
  // rounds at most u·|Δb| per update.
  auto initial = small_state();
  std::fill(initial.sediment.values.begin(), initial.sediment.values.end(), 0.0);
  for (std::size_t i = 0; i < initial.terrain.size(); ++i) initial.terrain.values[i] *= 2.0;  // steeper: above talus
  auto params = small_params({SedimentTransport::flux, PipeBoundary::open, Variant::plain});
  params.capacity = 0.0;
  params.thermal_step = true;
  params.thermal_talus_angle = 30.0;
  params.thermal_rate = 0.5;
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::reference::PipeErosion<float> reference(gt::cast_pipe_state<float>(initial), constants, small_forcing());
  gt::gpu::PipeErosion gpu(initial, constants, small_forcing());
  reference.step();
  gpu.step();
  const auto actual = gpu.state();
  const auto& expected = reference.state();
  const auto& mask = initial.terrain;
  const bool exact = correctly_rounding_device();
  double moved = 0.0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    const double change = actual.terrain.values[i] - initial.terrain.values[i];
    moved = std::max(moved, std::abs(change));
    const double bound = 16 * float_roundoff * (std::abs(static_cast<double>(expected.terrain.values[i])) + std::abs(change));
    EXPECT_LE(std::abs(actual.terrain.values[i] - expected.terrain.values[i]), bound) << "cell " << i;
  }
  EXPECT_GT(moved, 0.01) << "the thermal step should move material";
  if (exact) {
    EXPECT_EQ(largest_difference(actual.water, expected.water, mask), 0.0);
    EXPECT_EQ(largest_difference(actual.velocity_x, expected.velocity_x, mask), 0.0);
  }
  // Material: the thermal transfers cancel pairwise; what remains is the rounding of Δb (16 per
  // cell, u·|Δb| each) and of s (no sediment here).
  const auto& ledger = gpu.ledger();
  EXPECT_LE(std::abs(gt::material_drift(ledger.back(), ledger.front())),
            16 * float_roundoff * moved * constants.cell_area * static_cast<double>(mask.size()) +
                4 * double_roundoff * material(ledger.front()));
}

// ---------------------------------------------------------------------------------------------
// Many steps.

// A slope on a base height with 0.2 m of roughness, 1 m cells; heights rounded to float so that
// every backend starts from the same numbers (the comparison then measures arithmetic only).
PipeState<double> slope_state(int width, int height, double base) {
  return gt::dry_pipe_state(
      field(width, height, 1.0, 1.0, [&](int x, int y) { return as_float(base + 0.05 * x + 0.2 * noise(x, y, 31)); }));
}

// Rain on the slope, erosion amounts of 1e-6..1e-5 m per step (the reference's float-trap test).
HydraulicParams slope_params() {
  HydraulicParams params;
  params.rain_rate = 1e-3;
  params.capacity = 0.01;
  params.dissolving_rate = 0.1;
  return params;
}

TEST_F(PipesGpu, StepsFollowTheDoubleReferenceAtAHighBase) {
  // Model (the driver's, compare/algorithms/pipes.cpp): each step adds at most 32 float roundings
  // of the scale S a field is computed from, and the stable pipe model (K ≤ 1, CFL ≤ 1) does not
  // amplify them, so e_n ≤ n·32·u·S. On the GPU S involves no base height: heads and slopes are
  // formed from (b0 − b0_n), exact, plus changes and depths; S = largest depth + largest terrain
  // change + largest sediment of the double run. ref<float> rounds b + d at |b| ≈ 500 m, so at a
  // high base it leaves this model (it fits only with S ≈ |b|).
  const int steps = 100;
  const auto initial = slope_state(32, 24, 500.0);
  const auto constants = gt::pipe_constants(slope_params(), initial.terrain);
  gt::reference::PipeErosion<double> truth(initial, constants);
  gt::reference::PipeErosion<float> in_float(gt::cast_pipe_state<float>(initial), constants);
  gt::gpu::PipeErosion gpu(initial, constants);
  const auto& mask = initial.terrain;
  int done = 0;
  for (int checkpoint : {10, 30, steps}) {
    truth.run(checkpoint - done);
    in_float.run(checkpoint - done);
    gpu.run(checkpoint - done);
    done = checkpoint;
    const auto& exact = truth.state();
    const auto actual = gpu.state();
    Grid<double> change = exact.terrain;
    for (std::size_t i = 0; i < change.size(); ++i) change.values[i] -= initial.terrain.values[i];
    const double scale = largest_abs(exact.water, mask) + largest_abs(change, mask) + largest_abs(exact.sediment, mask);
    const double model = gt::pipe_rounding_growth(checkpoint, scale);
    const double water = largest_difference(actual.water, exact.water, mask);
    const double terrain = largest_difference(actual.terrain, exact.terrain, mask);
    const double sediment = largest_difference(actual.sediment, exact.sediment, mask);
    const double float_terrain = largest_difference(in_float.state().terrain, exact.terrain, mask);
    std::printf("step %3d: gpu - double: water %.2e, terrain %.2e, sediment %.2e; ref<float> terrain %.2e; model %.2e\n",
                checkpoint, water, terrain, sediment, float_terrain, model);
    EXPECT_LE(water, model);
    EXPECT_LE(terrain, model);
    EXPECT_LE(sediment, model);
    if (checkpoint == steps) {
      EXPECT_GT(float_terrain, model) << "ref<float> should show the float trap here";
    }
  }
}

// The driver's shadow step: ref<float>'s state after 30 steps of rain on the 500 m slope loaded
// into the GPU (its floats as the base b0, Δb = 0), both stepped; every value of every field stays
// within its own a-priori bound from pipe_shadow_bounds (running error analysis of the step from
// that state). With the B pipe dropped in the outflow shader (a registered one_twin mutant) the
// flux and the water leave their bounds far behind.
struct ShadowRun {
  double worst_ratio = 0.0;  // max over fields and values of |gpu − ref<float>| / bound
  std::string worst;         // where
  double flux_distance = 0.0;
};

// |a − b| against `bound`, value by value over valid cells, into `run`.
template <class Actual>
void compare_grids(const char* name, const Grid<Actual>& actual, const Grid<float>& expected,
                   const Grid<double>& bound, const Grid<double>& mask, ShadowRun& run) {
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask.is_valid(i)) continue;
    const double distance = std::abs(double(actual.values[i]) - double(expected.values[i]));
    const double ratio = distance == 0.0 ? 0.0 : distance / bound.values[i];
    if (ratio > run.worst_ratio) {
      run.worst_ratio = ratio;
      run.worst = std::string(name) + " at cell " + std::to_string(i);
    }
  }
}

ShadowRun shadow_run(const std::string& mutant, int steps) {
  const auto initial = slope_state(32, 24, 500.0);
  HydraulicForcing forcing;
  forcing.sources = {{20, 12, 0.2}};
  auto params = slope_params();
  params.evaporation_rate = 0.2;
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::reference::PipeErosion<float> run_up(gt::cast_pipe_state<float>(initial), constants, forcing);
  run_up.run(30);
  const auto start = run_up.state();
  gt::set_active_mutant(mutant);
  gt::gpu::PipeErosion gpu(initial, constants, forcing, false);
  gt::set_active_mutant("");
  gpu.upload(gt::cast_pipe_state<double>(start));
  gt::reference::PipeErosion<float> reference(start, constants, forcing);
  gpu.run(steps);
  reference.run(steps);
  const auto actual = gpu.state();
  const auto& expected = reference.state();
  const auto bound = gt::pipe_shadow_bounds(gt::cast_pipe_state<double>(start), constants, forcing, steps);
  const auto& mask = initial.terrain;
  ShadowRun run;
  compare_grids("terrain", actual.terrain, expected.terrain, bound.terrain, mask, run);
  compare_grids("water", actual.water, expected.water, bound.water, mask, run);
  compare_grids("sediment", actual.sediment, expected.sediment, bound.sediment, mask, run);
  compare_grids("velocity_x", actual.velocity_x, expected.velocity_x, bound.velocity_x, mask, run);
  compare_grids("velocity_y", actual.velocity_y, expected.velocity_y, bound.velocity_y, mask, run);
  for (std::size_t i = 0; i < mask.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      const double distance = std::abs(double(actual.outflow[i][k]) - double(expected.outflow[i][k]));
      run.flux_distance = std::max(run.flux_distance, distance);
      const double ratio = distance == 0.0 ? 0.0 : distance / bound.outflow[i][k];
      if (ratio > run.worst_ratio) {
        run.worst_ratio = ratio;
        run.worst = "outflow " + std::to_string(k) + " at cell " + std::to_string(i);
      }
    }
  }
  return run;
}

TEST_F(PipesGpu, ShadowStepFromTheFloatStateStaysWithinItsBound) {
  for (int steps : {1, 4}) {
    const auto run = shadow_run("", steps);
    EXPECT_LE(run.worst_ratio, 1.0) << steps << " step(s): " << run.worst;
    // At a 500 m base ref<float> rounds every surface: the twins do differ, within the bound.
    EXPECT_GT(run.flux_distance, 0.0);
  }
}

TEST_F(PipesGpu, ShadowStepsCatchADroppedPipe) {
  const auto run = shadow_run("erosion.pipe.gpu_drops_bottom_pipe", 1);
  EXPECT_GT(run.worst_ratio, 1.0);
}

// One shadow step on a real DEM: ref<float> run `before` steps from `initial` water (a depth per
// cell from its height), then the GPU loaded with that state and both stepped once; the water and
// the sediment against pipe_shadow_bounds.
template <class InitialDepth>
ShadowRun real_dem_shadow_step(const std::string& file, const HydraulicParams& params, InitialDepth initial_depth,
                               int before) {
  const auto terrain = gt::load_input({{"file", file}}, nullptr, GT_DATASET_DIR).heights;
  const auto constants = gt::pipe_constants(params, terrain);
  auto initial = gt::dry_pipe_state(terrain);
  for (std::size_t cell = 0; cell < terrain.size(); ++cell) {
    initial.water.values[cell] = terrain.is_valid(cell) ? initial_depth(terrain.values[cell]) : 0.0;
  }
  gt::reference::PipeErosion<float> run_up(gt::cast_pipe_state<float>(initial), constants);
  run_up.run(before);
  const auto start = gt::cast_pipe_state<double>(run_up.state());
  gt::gpu::PipeErosion gpu(start, constants, {}, false);
  gpu.step();
  gt::reference::PipeErosion<float> reference(run_up.state(), constants);
  reference.step();
  const auto bound = gt::pipe_shadow_bounds(start, constants, {}, 1);
  ShadowRun run;
  compare_grids("water", gpu.state().water, reference.state().water, bound.water, terrain, run);
  compare_grids("sediment", gpu.state().sediment, reference.state().sediment, bound.sediment, terrain, run);
  return run;
}

// Where a cell's K lies within rounding of 1, the GPU and ref<float> may disagree on whether the
// pipes drained it: one keeps 0, the other the rounding residual of d_A − Σf·Δt/(l_x·l_y), about
// u·d_A. The water's bound holds that residual there (reference/erosion/pipes.cpp's error model).
// The honest run that met it: the volcano under its 0.1 m of water and light rain, with nothing
// eroded (the flow alone, as with capacity 0), at the state after 56 steps, where the water's
// bound without it was 6.2e-8 m and the GPU 1.6e-7 m from ref<float>.
TEST_F(PipesGpu, ShadowStepCoversCellsThatDrainInOneTwinOnly) {
  HydraulicParams params;
  params.time_step = 0.25;
  params.rain_rate = 1e-4;
  params.capacity = 0.0;
  const auto run = real_dem_shadow_step("real/volcano.json", params, [](double) { return 0.1; }, 56);
  EXPECT_LE(run.worst_ratio, 1.0) << run.worst;
}

// Where the capacity is within rounding of the sediment, one implementation erodes k_s·(C − s) and
// the other deposits k_d·(s − C), both about the rounding of C: the sediment's bound joins both
// sides. The honest run that met it: erosion.pipe.flux.topobathy's first step, the sea at rest
// (C = s = 0 in ref<double>'s values), where ref<float>'s rain-rounded heads move the water a
// little: ref<float> took 1.3e-10 m at cell (8, 11), the GPU nothing, against a bound of 0.
TEST_F(PipesGpu, ShadowStepCoversCellsWhereTheCapacityMeetsTheSediment) {
  HydraulicParams params;
  params.time_step = 5.0;
  params.rain_rate = 1e-4;
  params.capacity = 0.001;
  const auto run = real_dem_shadow_step("real/topobathy.npz", params, [](double height) { return std::max(0.0, -height); }, 0);
  EXPECT_LE(run.worst_ratio, 1.0) << run.worst;
}

TEST_F(PipesGpu, WaterLedgerClosesAndNothingTurnsNegative) {
  // A bowl at 500 m with a no-data hole and an open border, uniform rain, a rain map, two sources,
  // evaporation, regolith and diffusion: every water flow of the ledger is exercised. Each step
  // checks the state (NaN, infinities, negative water, sediment, regolith or flux throw).
  const int width = 64, height = 48, steps = 200;
  auto terrain = field(width, height, 1.0, 1.0, [&](int x, int y) {
    const double dx = x - 0.5 * (width - 1), dy = y - 0.5 * (height - 1);
    return as_float(500.0 + 0.01 * (dx * dx + dy * dy) + 0.3 * noise(x, y, 41));
  });
  terrain.valid.assign(terrain.size(), 1);
  for (int y = 20; y < 24; ++y) terrain.valid[terrain.index(40, y)] = 0;
  auto initial = gt::dry_pipe_state(terrain);
  for (std::size_t i = 0; i < terrain.size(); ++i) initial.water.values[i] = 0.1 * noise(static_cast<int>(i), 0, 43);
  HydraulicForcing forcing;
  forcing.rain_map = field(width, height, 1.0, 1.0, [](int x, int) { return 2e-4 * x / 64.0; });
  forcing.sources = {{10, 10, 0.3}, {50, 30, 0.1}};
  auto params = slope_params();
  params.evaporation_rate = 0.01;
  params.boundary = PipeBoundary::open;
  params.regolith_depth = 0.02;
  params.sediment_diffusion = 0.05;
  for (auto transport : {SedimentTransport::flux, SedimentTransport::semi_lagrangian}) {
    params.transport = transport;
    gt::gpu::PipeErosion gpu(initial, gt::pipe_constants(params, terrain), forcing);
    gpu.run(steps);
    const auto& ledger = gpu.ledger();
    const auto& first = ledger.front();
    const auto& last = ledger.back();
    // Handled water: what was there and what came in. The balance moves only by the rounding of
    // the depth updates (+ rain, + sources, − outflow, clamp at 0, + inflow; evaporation is counted
    // from the same floats): at most 6 roundings of u·d per cell and step, so in the worst case
    // |balance| ≤ steps·6·u·handled = 7e-5 of it. Most roundings walk randomly, but adding the same
    // rain depth to every cell rounds alike within a binade of d, a systematic part that dominates
    // on draining slopes (see the report). 1e-6 of the handled water is the project's acceptance
    // threshold for the GPU (compare/algorithms/pipes.cpp); this basin stays below it.
    const double handled = first.water + last.rain_in + last.source_in;
    const double balance = gt::water_balance(last, first);
    std::printf("%s: water balance %.3e of %.3e m³ handled (%.2e); out %.3e, evaporated %.3e m³\n",
                gt::sediment_transport_name(transport), balance, handled, balance / handled, last.boundary_out_water,
                last.evaporated);
    EXPECT_LE(std::abs(balance), steps * 6 * float_roundoff * handled);
    EXPECT_LE(std::abs(balance), 1e-6 * handled);
    EXPECT_GT(last.boundary_out_water, 0.0);
    EXPECT_GT(last.evaporated, 0.0);
    EXPECT_GT(last.regolith, 0.0);
    const auto state = gpu.state();
    for (const auto* grid : {&state.terrain, &state.water, &state.sediment, &state.regolith, &state.velocity_x,
                             &state.velocity_y}) {
      EXPECT_TRUE(all_finite(*grid, terrain));
    }
    EXPECT_GE(lowest(state.water, terrain), 0.0);
    EXPECT_GE(lowest(state.sediment, terrain), 0.0);
    EXPECT_GE(lowest(state.regolith, terrain), 0.0);
  }
}

// The float-trap setting: 256 x 256 cells on a 500 m base, 500 steps of rain and flux transport,
// an open border at the foot of the slope. Capacity and dissolving rate make erosion amounts of
// 1e-6..1e-5 m per step, below half an ulp of 500 m (1.5e-5 m): of the settings tried on 128²
// cells (K_c 0.002..0.02 s, K_s 0.05..0.3 /s, either border) this one drifts most in ref<float>,
// 1.7e-6 of the material; all of them drift about 1e-6 over 500 steps.
TEST_F(PipesGpu, FluxTransportConservesMaterialAt500Metres) {
  const int size = 256, steps = 500;
  const auto initial = slope_state(size, size, 500.0);
  auto params = slope_params();
  params.capacity = 0.002;
  params.boundary = PipeBoundary::open;
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::gpu::PipeErosion gpu(initial, constants);
  gpu.run(steps);
  gt::reference::PipeErosion<float> in_float(gt::cast_pipe_state<float>(initial), constants);
  in_float.run(steps);
  const auto state = gpu.state();
  double changes = 0.0;
  for (std::size_t i = 0; i < state.terrain.size(); ++i) {
    changes += std::abs(state.terrain.values[i] - initial.terrain.values[i]) + state.sediment.values[i] +
               state.regolith.values[i];
  }
  changes *= constants.cell_area;
  const auto& mine = gpu.ledger();
  const auto& theirs = in_float.ledger();
  const double total = material(mine.front());
  const double gpu_drift = std::abs(gt::material_drift(mine.back(), mine.front()));
  const double float_drift = std::abs(gt::material_drift(theirs.back(), theirs.front()));
  // Model: per step each cell's Δb and s go through at most 6 rounded operations on values no
  // larger than |Δb| + s (erosion: Δb − a and s + a; transport: the share products, what stays,
  // the gathered sum), u each, and the ledger's double sums add 4·2^-53 of the total:
  //   |drift| ≤ steps·6·u·Σ(|Δb| + s)·l_x·l_y + 4·2^-53·Σ(b + s)·l_x·l_y,
  // with Σ(|Δb| + s) taken at the end (it grows over the run). The base height does not enter.
  const double model = steps * 6 * float_roundoff * changes + 4 * double_roundoff * total;
  std::printf("material drift over %d steps at 500 m: gpu %.3e m³ (%.2e of %.3e m³), ref<float> %.3e m³ (%.2e); "
              "model %.3e m³; sediment %.3e m³\n",
              steps, gpu_drift, gpu_drift / total, total, float_drift, float_drift / total, model,
              mine.back().sediment);
  EXPECT_LE(gpu_drift, model);
  EXPECT_LE(gpu_drift, 1e-6 * total);
  // The test can fail: ref<float>, storing b, loses or gains the erosion amounts below half an ulp
  // of 500 m, and drifts beyond the same threshold.
  EXPECT_GT(float_drift, 1e-6 * total);
  EXPECT_GT(changes, 10.0) << "the run should erode";
}

TEST_F(PipesGpu, VariantStagesConserveMaterialAtAHighBase) {
  // Regolith, water-weighted diffusion and the thermal step on top of the flux form: each stage
  // moves material between Δb, s and r (or between cells) as equal and opposite floats, so the
  // drift stays within the rounding model of the flux-form test (6 roundings per stage and cell,
  // 4 stages: 24·u·Σ(|Δb| + s + r) per step).
  const int steps = 200;
  const auto initial = slope_state(48, 40, 500.0);
  auto params = slope_params();
  params.regolith_depth = 0.01;
  params.sediment_diffusion = 0.1;
  params.diffusion_weighting = gt::DiffusionWeighting::water;
  params.thermal_step = true;
  params.thermal_talus_angle = 10.0;
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::gpu::PipeErosion gpu(initial, constants);
  gpu.run(steps);
  const auto state = gpu.state();
  double changes = 0.0;
  for (std::size_t i = 0; i < state.terrain.size(); ++i) {
    changes += std::abs(state.terrain.values[i] - initial.terrain.values[i]) + state.sediment.values[i] +
               state.regolith.values[i];
  }
  changes *= constants.cell_area;
  const auto& ledger = gpu.ledger();
  const double drift = std::abs(gt::material_drift(ledger.back(), ledger.front()));
  const double model = steps * 24 * float_roundoff * changes + 4 * double_roundoff * material(ledger.front());
  std::printf("variants: drift %.3e m³, model %.3e m³, regolith %.3e m³, sediment %.3e m³\n", drift, model,
              ledger.back().regolith, ledger.back().sediment);
  EXPECT_LE(drift, model);
  EXPECT_GT(ledger.back().regolith, 0.0);
  EXPECT_GE(lowest(state.regolith, initial.terrain), 0.0);
  EXPECT_GE(lowest(state.sediment, initial.terrain), 0.0);
}

TEST_F(PipesGpu, UniformDiffusionSpreadsASpikeExactly) {
  // Seed 001 §3.8 with w = 1/8 on still water (no flux, no capacity, no deposition): a cell with
  // 1 m of sediment keeps 1 − 4w = 1/2 and each neighbour receives w = 1/8, exact in float; at a
  // wall (closed border) the pipe is exterior and nothing is sent through it.
  const auto terrain = field(7, 5, 1.0, 1.0, [](int, int) { return 500.0; });
  auto initial = gt::dry_pipe_state(terrain);
  std::fill(initial.water.values.begin(), initial.water.values.end(), 1.0);
  initial.sediment.at(3, 2) = 1.0;
  initial.sediment.at(0, 0) = 1.0;
  HydraulicParams params;
  params.deposition_rate = 0.0;
  params.sediment_diffusion = 0.125;
  gt::gpu::PipeErosion gpu(initial, gt::pipe_constants(params, terrain));
  gpu.step();
  const auto s = gpu.state().sediment;
  EXPECT_EQ(s.at(3, 2), 0.5);
  EXPECT_EQ(s.at(2, 2), 0.125);
  EXPECT_EQ(s.at(4, 2), 0.125);
  EXPECT_EQ(s.at(3, 1), 0.125);
  EXPECT_EQ(s.at(3, 3), 0.125);
  EXPECT_EQ(s.at(2, 1), 0.0);
  EXPECT_EQ(s.at(0, 0), 0.75);  // two exterior pipes
  EXPECT_EQ(s.at(1, 0), 0.125);
  EXPECT_EQ(s.at(0, 1), 0.125);
  EXPECT_EQ(gpu.ledger().back().sediment, 2.0);
}

TEST_F(PipesGpu, LakeAtRestStaysAtRestOnAHighBase) {
  // Terrain 500 m + eighths under a water surface at 504 m: d = 504 − b is exact, every head
  // (b0 − b0_n) + (Δb − Δb_n) + (d − d_n) is exactly 0, nothing may move, bit for bit.
  const auto terrain = field(17, 13, 1.0, 1.0, [](int x, int y) { return 500.0 + ((7 * x + 3 * y) % 11) / 8.0; });
  auto initial = gt::dry_pipe_state(terrain);
  for (std::size_t i = 0; i < terrain.size(); ++i) initial.water.values[i] = 504.0 - terrain.values[i];
  for (auto transport : {SedimentTransport::flux, SedimentTransport::semi_lagrangian}) {
    HydraulicParams params;
    params.transport = transport;
    gt::gpu::PipeErosion gpu(initial, gt::pipe_constants(params, terrain));
    gpu.run(50);
    const auto state = gpu.state();
    EXPECT_EQ(largest_difference(state.terrain, terrain, terrain), 0.0);
    EXPECT_EQ(largest_difference(state.water, initial.water, terrain), 0.0);
    EXPECT_EQ(largest_abs(state.velocity_x, terrain) + largest_abs(state.velocity_y, terrain) +
                  largest_abs(state.sediment, terrain),
              0.0);
    EXPECT_EQ(gpu.ledger().back().max_cfl, 0.0);
  }
}

TEST_F(PipesGpu, RepeatsBitForBitWithAndWithoutTheLedger) {
  // Every stage at once; the run without the ledger downloads nothing between steps.
  const auto initial = slope_state(40, 36, 500.0);
  auto params = slope_params();
  params.boundary = PipeBoundary::open;
  params.regolith_depth = 0.01;
  params.sediment_diffusion = 0.1;
  params.diffusion_weighting = gt::DiffusionWeighting::water;
  params.thermal_step = true;
  params.thermal_talus_angle = 10.0;
  HydraulicForcing forcing;
  forcing.sources = {{30, 20, 0.2}};
  const auto constants = gt::pipe_constants(params, initial.terrain);
  for (auto transport : {SedimentTransport::flux, SedimentTransport::semi_lagrangian}) {
    auto varied = constants;
    varied.transport = transport;
    gt::gpu::PipeErosion with_ledger(initial, varied, forcing, true);
    gt::gpu::PipeErosion without_ledger(initial, varied, forcing, false);
    EXPECT_EQ(with_ledger.passes_per_step(), 8);  // 4 + sources + diffusion + 2 thermal
    with_ledger.run(60);
    without_ledger.run(60);
    EXPECT_EQ(with_ledger.ledger().size(), 61u);
    EXPECT_EQ(without_ledger.ledger().size(), 1u);
    const auto first = with_ledger.state();
    EXPECT_EQ(differing_cells(first, without_ledger.state()), 0u);
    EXPECT_GT(largest_difference(first.terrain, initial.terrain, initial.terrain), 0.0);
  }
}

TEST_F(PipesGpu, CountsItsPasses) {
  const auto initial = slope_state(8, 8, 0.0);
  auto params = slope_params();
  EXPECT_EQ(gt::gpu::PipeErosion(initial, gt::pipe_constants(params, initial.terrain)).passes_per_step(), 4);
  HydraulicForcing forcing;
  forcing.sources = {{1, 1, 0.1}, {1, 1, 0.2}, {2, 5, 0.1}};
  EXPECT_EQ(gt::gpu::PipeErosion(initial, gt::pipe_constants(params, initial.terrain), forcing).passes_per_step(), 5);
  params.sediment_diffusion = 0.1;
  EXPECT_EQ(gt::gpu::PipeErosion(initial, gt::pipe_constants(params, initial.terrain)).passes_per_step(), 5);
}

TEST_F(PipesGpu, RefusesBadInput) {
  using gt::testing::refusal;
  const auto terrain = slope_state(6, 5, 0.0).terrain;
  const auto constants = gt::pipe_constants(slope_params(), terrain);
  auto refused = [&](const PipeState<double>& state, const HydraulicForcing& forcing = {}) {
    return refusal([&] { gt::gpu::PipeErosion(state, constants, forcing); });
  };
  auto nan_terrain = gt::dry_pipe_state(terrain);
  nan_terrain.terrain.at(2, 3) = std::nan("");
  EXPECT_NE(refused(nan_terrain).find("(x=2, y=3)"), std::string::npos);
  auto too_high = gt::dry_pipe_state(terrain);
  too_high.terrain.at(4, 1) = 1e39;  // finite in double, infinite as the GPU's float
  const auto too_high_message = refused(too_high);
  EXPECT_NE(too_high_message.find("(x=4, y=1)"), std::string::npos) << too_high_message;
  EXPECT_NE(too_high_message.find("rounded to the float the GPU stores"), std::string::npos) << too_high_message;
  auto negative_water = gt::dry_pipe_state(terrain);
  negative_water.water.at(1, 1) = -0.1;
  EXPECT_NE(refused(negative_water).find("water depth at cell (x=1, y=1)"), std::string::npos);
  auto negative_regolith = gt::dry_pipe_state(terrain);
  negative_regolith.regolith.at(3, 2) = -1e-3;
  EXPECT_NE(refused(negative_regolith).find("regolith at cell (x=3, y=2)"), std::string::npos);
  auto negative_flux = gt::dry_pipe_state(terrain);
  negative_flux.outflow[7][2] = -1.0;
  EXPECT_NE(refused(negative_flux).find("outflow flux"), std::string::npos);
  auto masked = gt::dry_pipe_state(terrain);
  masked.terrain.valid.assign(terrain.size(), 0);
  EXPECT_NE(refused(masked).find("mask covers"), std::string::npos);
  auto small_water = gt::dry_pipe_state(terrain);
  small_water.water = Grid<double>(5, 5);
  EXPECT_NE(refused(small_water).find("the water depth is 5x5"), std::string::npos);
  HydraulicForcing bad_rain;
  bad_rain.rain_map = field(6, 5, 1.0, 1.0, [](int, int) { return -1.0; });
  EXPECT_NE(refused(gt::dry_pipe_state(terrain), bad_rain).find("rain map"), std::string::npos);
  HydraulicForcing off_grid;
  off_grid.sources = {{6, 0, 1.0}};
  EXPECT_NE(refused(gt::dry_pipe_state(terrain), off_grid).find("point source at cell (x=6, y=0)"), std::string::npos);
  HydraulicForcing negative_source;
  negative_source.sources = {{1, 0, -1.0}};
  EXPECT_NE(refused(gt::dry_pipe_state(terrain), negative_source).find("rate -1"), std::string::npos);
}

TEST_F(PipesGpu, RefusesDiagonalFluxWithFourPipes) {
  // As the reference: a 4-pipe run holds no diagonal flux, so a state with some is refused.
  const auto terrain = slope_state(6, 5, 0.0).terrain;
  auto diagonal_flux = gt::dry_pipe_state(terrain);
  diagonal_flux.outflow[7][5] = 0.5;
  const auto message = gt::testing::refusal(
      [&] { gt::gpu::PipeErosion(diagonal_flux, gt::pipe_constants(slope_params(), terrain)); });
  EXPECT_NE(message.find("through pipe BR at cell 7: with 4 pipes it must be 0"), std::string::npos) << message;
  auto eight = slope_params();
  eight.pipe_count = 8;
  EXPECT_EQ(gt::gpu::PipeErosion(diagonal_flux, gt::pipe_constants(eight, terrain)).state().outflow[7][5], 0.5);
}

TEST_F(PipesGpu, RefusesAStateThatTurnsNaN) {
  // As the reference's test: heights of ±3e38 (finite floats) whose differences overflow; the K
  // scaling multiplies 0 by infinity and the first step's check names the step and the cell.
  const auto terrain = field(4, 4, 1.0, 1.0, [](int x, int y) { return (x + y) % 2 == 0 ? 3e38 : -3e38; });
  auto initial = gt::dry_pipe_state(terrain);
  std::fill(initial.water.values.begin(), initial.water.values.end(), 1.0);
  for (auto transport : {SedimentTransport::flux, SedimentTransport::semi_lagrangian}) {
    auto params = slope_params();
    params.transport = transport;
    gt::gpu::PipeErosion gpu(initial, gt::pipe_constants(params, terrain));
    const auto message = gt::testing::refusal([&] { gpu.step(); });
    EXPECT_NE(message.find("step 1, cell"), std::string::npos) << message;
    EXPECT_NE(message.find("nan"), std::string::npos) << message;
  }
}

}  // namespace
