// The rounding-interval number (core/rounding_interval.hpp) and the pipe model's per-cell shadow
// bounds built on it (compare/checks/pipe_error_model.hpp): every float and double evaluation of an
// operation, and of whole pipe steps, lies inside the interval computed for it, and the interval is
// no wider than one rounding of each operation (so the bounds are sharp enough to matter).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compare/checks/pipe_error_model.hpp"
#include "compare/inputs.hpp"
#include "core/io/heightmap_io.hpp"
#include "core/params/hydraulic.hpp"
#include "core/rounding_interval.hpp"
#include "reference/erosion/pipes.hpp"
#include "tests/support/pipe_fields.hpp"

namespace {

using gt::HydraulicForcing;
using gt::HydraulicParams;
using gt::PipeState;
using gt::RoundingInterval;
using gt::testing::field;
using gt::testing::noise;

// Float operands of every sign over twelve decades.
std::vector<float> operands() {
  std::vector<float> values;
  for (int i = 0; i < 40; ++i) {
    const double magnitude = std::pow(10.0, -6.0 + 12.0 * noise(i, 0, 5)) * (1.0 + noise(i, 1, 6));
    values.push_back(static_cast<float>(i % 3 == 0 ? -magnitude : magnitude));
  }
  values.push_back(0.0f);
  return values;
}

void expect_inside(const RoundingInterval& interval, double computed, const std::string& what) {
  EXPECT_LE(interval.low, computed) << what;
  EXPECT_GE(interval.high, computed) << what;
}

TEST(RoundingInterval, HoldsEveryFloatAndDoubleResultOfAnOperationAndNoMore) {
  for (float a : operands()) {
    for (float b : operands()) {
      const auto x = RoundingInterval::exact(a), y = RoundingInterval::exact(b);
      const std::string pair = std::to_string(a) + ", " + std::to_string(b);
      // One operation on exact operands: the interval is the exact result widened by one rounding,
      // u·|z| for + − × and 5u·|z| for ÷ (GLSL's licence), and holds float's and double's result.
      const struct {
        RoundingInterval interval;
        float in_float;
        double in_double;
        double unit;
      } cases[] = {{x + y, a + b, double(a) + b, RoundingInterval::basic_unit},
                   {x - y, a - b, double(a) - b, RoundingInterval::basic_unit},
                   {x * y, a * b, double(a) * b, RoundingInterval::basic_unit},
                   {gt::max(x, y), std::max(a, b), std::max<double>(a, b), 0.0},
                   {gt::min(x, y), std::min(a, b), std::min<double>(a, b), 0.0}};
      for (const auto& c : cases) {
        expect_inside(c.interval, c.in_float, pair);
        expect_inside(c.interval, c.in_double, pair);
        // Sharp: no wider than the rounding of either end (double's own rounding of the ends, 2^-53
        // of them, allowed).
        const double magnitude = std::max(std::abs(c.interval.low), std::abs(c.interval.high));
        EXPECT_LE(c.interval.width(), 2.0 * (c.unit + 0x1p-52) * magnitude) << pair;
      }
      if (b != 0.0f) {
        expect_inside(x / y, a / b, pair);
        expect_inside(x / y, double(a) / b, pair);
      }
      if (a >= 0.0f) expect_inside(gt::sqrt(x), std::sqrt(a), pair);
    }
  }
}

TEST(RoundingInterval, AQuotientByASumThatMayBeZeroIsBoundedOnTheSideItsSignAllows) {
  // A sum of max(0, ·) terms: [0, h]. Dividing a positive amount by it bounds the quotient from
  // below only; min(1, ·) of that is then bounded on both sides, as the pipe model's K is.
  const auto total = gt::max(RoundingInterval::exact(0.0), RoundingInterval::of(1e-9, -1e-9, 3e-9));
  EXPECT_EQ(total.low, 0.0);
  const auto ratio = RoundingInterval::exact(2.0) / total;
  EXPECT_GT(ratio.low, 0.0);
  EXPECT_TRUE(std::isinf(ratio.high));
  const auto scale = gt::min(RoundingInterval::exact(1.0), ratio);
  EXPECT_LE(scale.high, 1.0);
  EXPECT_TRUE(std::isfinite(scale.width()));
  // 0 times an unbounded factor moves nothing.
  EXPECT_EQ((RoundingInterval::exact(0.0) * ratio).width(), 0.0);
  // A product of an unbounded and a bounded non-zero factor is unbounded, not NaN.
  EXPECT_TRUE(std::isinf((RoundingInterval::exact(-3.0) * ratio).width()));
}

// Every valid value of `got` inside the model's interval, field by field.
template <class Real>
void expect_state_inside(const PipeState<RoundingInterval>& model, const PipeState<Real>& got, const std::string& what) {
  const auto& mask = model.terrain;
  int outside = 0;
  std::string first;
  const auto check = [&](const RoundingInterval& interval, Real value, const char* name, std::size_t cell) {
    const double v = static_cast<double>(value);
    if (v >= interval.low && v <= interval.high) return;
    if (outside++ == 0) {
      first = std::string(name) + " at cell " + std::to_string(cell) + ": " + std::to_string(v) + " outside [" +
              std::to_string(interval.low) + ", " + std::to_string(interval.high) + "]";
    }
  };
  for (std::size_t cell = 0; cell < mask.size(); ++cell) {
    if (!mask.is_valid(cell)) continue;
    check(model.terrain.values[cell], got.terrain.values[cell], "terrain", cell);
    check(model.water.values[cell], got.water.values[cell], "water", cell);
    check(model.sediment.values[cell], got.sediment.values[cell], "sediment", cell);
    check(model.regolith.values[cell], got.regolith.values[cell], "regolith", cell);
    check(model.velocity_x.values[cell], got.velocity_x.values[cell], "velocity_x", cell);
    check(model.velocity_y.values[cell], got.velocity_y.values[cell], "velocity_y", cell);
    for (int k = 0; k < 8; ++k) check(model.outflow[cell][k], got.outflow[cell][k], "outflow", cell);
  }
  EXPECT_EQ(outside, 0) << what << ": first " << first;
}

// From ref<float>'s state after `warm_up` steps, ref<float>, ref<double> and the model each take
// `steps` steps; both references must lie in the model's intervals everywhere.
void expect_references_inside(const PipeState<double>& initial, const HydraulicParams& params,
                              const HydraulicForcing& forcing, int warm_up, const std::string& what) {
  const auto constants = gt::pipe_constants(params, initial.terrain);
  gt::reference::PipeErosion<float> run_up(gt::cast_pipe_state<float>(initial), constants, forcing);
  run_up.run(warm_up);
  const PipeState<float> start = run_up.state();
  for (int steps : {1, 4}) {
    const auto exact = [](float value) { return RoundingInterval::exact(value); };
    gt::reference::PipeErosion<RoundingInterval> model(gt::map_pipe_state<RoundingInterval>(start, exact), constants,
                                                       forcing);
    gt::reference::PipeErosion<float> in_float(start, constants, forcing);
    gt::reference::PipeErosion<double> in_double(gt::cast_pipe_state<double>(start), constants, forcing);
    model.run(steps);
    in_float.run(steps);
    in_double.run(steps);
    const std::string run = what + ", " + std::to_string(steps) + " step(s)";
    expect_state_inside(model.state(), in_float.state(), run + ", ref<float>");
    expect_state_inside(model.state(), in_double.state(), run + ", ref<double>");
  }
}

// A probe: a noisy slope at 500 m (ref<float> rounds every surface there), a source, rain, a rain
// map, evaporation, regolith and diffusion, with both transports.
TEST(PipeShadowModel, BothReferencesStayInsideTheIntervalsOnAProbe) {
  const auto terrain = field(40, 30, 1.0, 1.0, [](int x, int y) {
    return static_cast<float>(500.0 + 0.05 * x + 0.02 * y + 0.3 * noise(x, y, 31));
  });
  HydraulicForcing forcing;
  forcing.sources = {{25, 12, 0.2}};
  forcing.rain_map = field(40, 30, 1.0, 1.0, [](int x, int) { return 2e-4 * x / 40.0; });
  HydraulicParams params;
  params.rain_rate = 1e-3;
  params.capacity = 0.01;
  params.evaporation_rate = 0.05;
  params.regolith_depth = 0.02;
  params.sediment_diffusion = 0.05;
  for (auto transport : {gt::SedimentTransport::flux, gt::SedimentTransport::semi_lagrangian,
                         gt::SedimentTransport::maccormack}) {
    params.transport = transport;
    expect_references_inside(gt::dry_pipe_state(terrain), params, forcing, 30,
                             std::string("probe, ") + gt::sediment_transport_name(transport));
  }
}

// A real DEM (the volcano, 10 m cells) under 0.1 m of water and rain, open borders.
TEST(PipeShadowModel, BothReferencesStayInsideTheIntervalsOnARealDem) {
  const auto volcano = gt::read_heightmap(GT_DATASET_DIR "/real/volcano.json").heights;
  auto initial = gt::dry_pipe_state(volcano);
  for (auto& depth : initial.water.values) depth = 0.1;
  HydraulicParams params;
  params.rain_rate = 1e-4;
  params.time_step = 0.05;
  params.boundary = gt::PipeBoundary::open;
  expect_references_inside(initial, params, {}, 40, "volcano");
}

// The Jacksboro DEM (74×92 m cells) under 0.1 m of water at Δt = 1 s: the K scaling drives draining
// cells to a displacement of exactly one cell a step, where one rounding decides which side of the
// whole cell the backtrace's floor lands on, and the two implementations read different corners. The
// model joins the bilinear pieces on both sides (core/rounding_interval.hpp: floor_range); with the
// floor taken as exact, ref<double> fell outside it here (and the GPU in an honest run).
TEST(PipeShadowModel, BothReferencesStayInsideTheIntervalsWhereDisplacementsMeetWholeCells) {
  const auto jacksboro = gt::load_input({{"file", "real/jacksboro_fault_dem.npz"}}, nullptr, GT_DATASET_DIR).heights;
  auto initial = gt::dry_pipe_state(jacksboro);
  for (auto& depth : initial.water.values) depth = 0.1;
  HydraulicParams params;
  params.time_step = 1.0;
  params.capacity = 0.1;
  for (auto transport : {gt::SedimentTransport::semi_lagrangian, gt::SedimentTransport::maccormack}) {
    params.transport = transport;
    expect_references_inside(initial, params, {}, 24, std::string("jacksboro, ") + gt::sediment_transport_name(transport));
  }
}

}  // namespace
