// The driver's view of seed 001's layered ground (issue 14; digest 001 §3.1, §3.3-3.5, §3.10–3.16,
// §3.19, §4): a heightmap given a stated soil–rock profile in every column, then `steps` iterations
// (reference/erosion/layered/iteration.hpp: creep, talus, vegetation, weathering and, when water is
// given — initial_water, rain_rate or the river — sources and sinks, the pipe flow, force erosion,
// dissolution and wetness), in ref<double> and ref<float>, beside the GPU twin, with a ledger per
// material and the pictures a geologist reads.
//
// The initial profile (the same in every column, hung from the input's surface) and its parameters:
// compare/layered_case.hpp.
//
// Checks (ledgers as volumes, m³; V the total volume of all materials at the start; S steps):
//   ledger.materials.cpu, .cpu_float   the largest |V_m(end) − V_m(start) − converted into m + converted
//                        out of m + sunk| / V over the materials (5 components in the ground and in the
//                        water, suspended or as regolith; each bedrock type); `sunk` what the river's
//                        sink rows took
//   ledger.total.cpu, .cpu_float       |ΣV(end) − ΣV(start)| / V: conversions (fragmentation,
//                        weathering, soil formation) move volume between materials and never create
//                        or destroy it
//   ledger.conversions.cpu             |volume converted out of all materials − into them| / V
//     Bound of all three: S·R·2u (tests/layered_reference_test.cpp's model: each stored thickness
//     passes through at most R = 36 roundings an iteration, each within u of what the cell holds of the
//     material, and what moved is at most V), u the unit roundoff of the run's type. With water R = 64:
//     the flow rounds a carried amount 13 times (4 shares sent, their sum, the rest, 4 arrivals and
//     their sums), force erosion and dissolution a stored amount up to 15 more (erode_component's
//     take and subtraction per source size, the settling, the deposit).
//   ledger.water.cpu, .cpu_float       (with water) |W(end) − W(start) − added + sunk| / (W(start) +
//                        added): rain and the river's rise in, the sinks out; bound S·13·2u (the flow's
//                        roundings of a depth, the rain's addition)
//   spec.courant.cpu     (with water; informative) the pipe flow's Courant number Δt·sqrt(g·w_max)/l
//                        at its largest; above 1/√2 a note warns that the water oscillates
//   layers.invalid.cpu                 columns with a negative or non-finite thickness, or a topsoil
//                        above topsoil_max·(1 + 64u) (two organizes leave it at the maximum within a
//                        few roundings), or (with water) a negative or non-finite depth, flux, carried
//                        amount or wetness
//   layers.surface.cpu                 the largest |surface − Σ thicknesses − its start value| over
//                        columns: the surface moves with every layer change; bound S·R·2u·(|surface| +
//                        Σ thickness), the largest over the columns at the start
//   spec.repose.cpu      (expect {"at_rest": true}) the largest slope to a lower neighbour over the
//                        column's repose slope, written out here from eq. 3.1 (min over non-empty soil
//                        layers j of K_depth^j·Σ_i tan φ_i·V_i/V·(1 + K_sveg·veg)), over columns with
//                        soil: at rest it is below 1 (eq. 3.3 moves Δt·Δh/2 whenever a slope reaches
//                        tan φ, so a resting slope lies below it)
//   parity.surface.float_vs_double     informative: the largest |Δ surface|
//   parity.state.gpu_vs_float          the GPU twin (gpu/erosion/layered/) stepped beside ref<float>,
//                        compared at every ledger checkpoint: values differing in any bit, plus
//                        conversion totals beyond their summation bound (bound 0; GpuShadow below)
// Performance: ms an iteration by grid side, CPU and GPU, beside Šťava et al. 2008's published figure.
// Pictures: the surface material (the top non-empty layer's colour, mixed by composition, green by
// vegetation), the cross-section along the middle row, topsoil and subsoil thickness and
// vegetation as fields, the material masks with transparency (§3.17) as fields and one picture, with
// water its depth, the wetness and the carried material as fields, the terrain as given and after each backend (field `terrain`, as every
// erosion algorithm hands it back), the ledger over the steps.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compare/algorithm.hpp"
#include "compare/inputs.hpp"
#include "compare/layered_case.hpp"
#include "compare/layered_look.hpp"
#include "compare/checks/threshold.hpp"
#include "compare/field_files.hpp"
#include "compare/report/images.hpp"
#include "compare/report/plots.hpp"
#include "compare/timing.hpp"
#include "core/errors.hpp"
#include "core/layered/layered_ground.hpp"
#include "core/layered/layered_water.hpp"
#include "core/params/layered.hpp"
#include "gpu/erosion/layered/ground_buffers.hpp"
#include "gpu/erosion/layered/iteration.hpp"
#include "gpu/erosion/layered/water_buffers.hpp"
#include "reference/erosion/layered/column.hpp"
#include "reference/erosion/layered/iteration.hpp"
#include "reference/erosion/layered/material_masks.hpp"

namespace gt {
namespace {

// tests/layered_reference_test.cpp's ledger model: creep and talus round a stored value at most 32
// times an iteration, weathering 4 more; with water, the flow, force erosion and dissolution up to 28
// more (see the header). A depth of water: 13 roundings an iteration.
constexpr double roundings_per_step = 36.0;
constexpr double roundings_per_step_with_water = 64.0;
constexpr double water_roundings_per_step = 13.0;

double material_roundings(const LayeredParams& params) {
  return has_water(params) ? roundings_per_step_with_water : roundings_per_step;
}
constexpr int ledger_points = 50;            // checkpoints of the ledger plot

// Every material's volume in one list: the 5 components (in the ground and in the water), then each
// bedrock type.
std::vector<double> material_volumes(const LayeredLedger& ledger, const LayeredWaterLedger& in_water) {
  std::vector<double> volumes;
  for (std::size_t i = 0; i < ledger.components.size(); ++i) volumes.push_back(ledger.components[i] + in_water.carried[i]);
  volumes.insert(volumes.end(), ledger.bedrock.begin(), ledger.bedrock.end());
  return volumes;
}

// Each material's net change the ledger accounts for, m³: converted into it minus out of it
// (fragmentation, weathering, soil formation, force erosion's breakdown), minus what sank, in
// material_volumes' order.
std::vector<double> conversion_net(const LayeredConversions& conversions, std::size_t types) {
  std::vector<double> net;
  for (int component = 0; component < soil_component_count; ++component) {
    net.push_back(conversions.converted_into(component) - conversions.converted_from(component) -
                  conversions.sunk[std::size_t(component)]);
  }
  for (std::size_t type = 0; type < types; ++type) net.push_back(-conversions.bedrock_converted(type));
  return net;
}

std::string material_name(std::size_t material) {
  return material < soil_component_count ? soil_component_name(int(material))
                                         : fmt::format("bedrock type {}", material - soil_component_count);
}

template <class Real>
struct LayeredRun {
  LayeredGround<Real> start;                       // as made from the setup, before the first step
  LayeredGround<Real> ground;                      // after the last step
  std::optional<LayeredWater<Real>> water;         // after the last step, when the setup gives water
  LayeredConversions conversions;
  double largest_courant = 0.0;                    // Δt·sqrt(g·w)/min(l_x, l_y) over the checkpoints
  std::vector<double> water_volumes;               // per checkpoint, m³ (with water)
  std::vector<int> checkpoints;                    // steps done at each ledger point
  std::vector<std::vector<double>> volumes;        // per checkpoint, per material, m³
  std::vector<std::vector<double>> converted;      // per checkpoint, per material, net conversion m³
};

// Called at each ledger checkpoint with the steps done and the state then (water: null without).
template <class Real>
using CheckpointObserver = std::function<void(int done, const LayeredGround<Real>& ground,
                                              const LayeredWater<Real>* water, const LayeredConversions&)>;

// The pipe model's wave Courant number at the deepest column: Δt·sqrt(g·w_max)/min(l_x, l_y). The
// flux update is explicit, so shallow-water waves (speed sqrt(g·w)) must cross less than a cell a
// step: in 2-D, C ≤ 1/√2; beyond it the water oscillates from column to column in a checkerboard.
template <class Real>
double courant_number(const LayeredWater<Real>& water, const LayeredParams& params, const LayeredGround<Real>& ground) {
  double deepest = 0.0;
  for (Real depth : water.water) deepest = std::max(deepest, static_cast<double>(depth));
  return params.time_step * std::sqrt(params.gravity * deepest) / std::min(ground.cell_size_x, ground.cell_size_y);
}

template <class Real>
LayeredRun<Real> run_layered(const LayeredSetup& setup, const CheckpointObserver<Real>& observe = {}) {
  const std::size_t types = setup.params.bedrock_types.size();
  LayeredRun<Real> run;
  run.start = make_layered_ground<Real>(setup.surface, setup.profile, setup.params, setup.vegetation);
  run.ground = run.start;
  if (has_water(setup.params)) run.water = make_layered_water<Real>(run.ground.cells(), setup.params.initial_water);
  run.conversions = no_conversions(types);
  const double area = run.ground.cell_size_x * run.ground.cell_size_y;
  const int every = std::max(1, setup.steps / ledger_points);
  const auto record = [&](int done) {
    const auto in_water = run.water ? layered_water_ledger(*run.water, area) : LayeredWaterLedger{};
    run.checkpoints.push_back(done);
    run.volumes.push_back(material_volumes(layered_ledger(run.ground, types), in_water));
    run.converted.push_back(conversion_net(run.conversions, types));
    run.water_volumes.push_back(in_water.water);
    if (run.water) run.largest_courant = std::max(run.largest_courant, courant_number(*run.water, setup.params, run.ground));
    if (observe) observe(done, run.ground, run.water ? &*run.water : nullptr, run.conversions);
  };
  record(0);
  for (int step = 0; step < setup.steps; ++step) {
    reference::layered_iteration(run.ground, setup.params, static_cast<std::uint32_t>(step), run.conversions,
                                 run.water ? &*run.water : nullptr);
    if ((step + 1) % every == 0 || step + 1 == setup.steps) record(step + 1);
  }
  return run;
}

template <class Real>
double ledger_bound(int steps, double roundings) {
  return steps * roundings * 2.0 * std::numeric_limits<Real>::epsilon() / 2.0;
}

// ledger.water.<backend>: the water in against the water out (see the header).
template <class Real>
void add_water_ledger_check(const LayeredRun<Real>& run, int steps, const std::string& backend, CaseResult& result) {
  const double start = run.water_volumes.front(), end = run.water_volumes.back();
  const double added = run.conversions.water_added, sunk = run.conversions.water_sunk, net = added - sunk;
  const double scale = std::max(start + added, std::numeric_limits<double>::min());
  result.checks.push_back(bounded_check(
      "ledger.water." + backend, std::abs(end - start - net) / scale, ledger_bound<Real>(steps, water_roundings_per_step),
      std::nullopt,
      fmt::format("|W_end − W_start − added + sunk| / (W_start + added): W {:.6g} → {:.6g} m³, {:.6g} m³ added (rain, "
                  "the river's rise), {:.6g} m³ sunk; bound S·{}·2u",
                  start, end, added, sunk, water_roundings_per_step)));
}

template <class Real>
void add_ledger_checks(const LayeredRun<Real>& run, const LayeredSetup& setup, const std::string& backend,
                       CaseResult& result) {
  const int steps = setup.steps;
  const double roundings = material_roundings(setup.params);
  if (run.water) add_water_ledger_check(run, steps, backend, result);
  const auto& start = run.volumes.front();
  const auto& end = run.volumes.back();
  const auto& converted = run.converted.back();
  double total_start = 0.0, total_end = 0.0, worst = 0.0;
  std::size_t worst_material = 0;
  for (std::size_t material = 0; material < start.size(); ++material) {
    total_start += start[material];
    total_end += end[material];
  }
  for (std::size_t material = 0; material < start.size(); ++material) {
    const double drift = std::abs(end[material] - start[material] - converted[material]) / total_start;
    if (drift > worst) {
      worst = drift;
      worst_material = material;
    }
  }
  const double bound = ledger_bound<Real>(steps, roundings);
  result.checks.push_back(bounded_check(
      "ledger.materials." + backend, worst, bound, std::nullopt,
      fmt::format("largest |V_end − V_start − converted + sunk| / V over the materials ({}; components in the ground "
                  "and in the water), V = {:.6g} m³; bound S·R·2u with S = {} steps, R = {}",
                  material_name(worst_material), total_start, steps, roundings)));
  double sunk = 0.0;
  for (double volume : run.conversions.sunk) sunk += volume;
  result.checks.push_back(bounded_check("ledger.total." + backend,
                                        std::abs(total_end + sunk - total_start) / total_start, bound, std::nullopt,
                                        fmt::format("|ΣV_end + sunk − ΣV_start| / V: {:.6g} m³ and {:.6g} m³ sunk "
                                                    "against {:.6g} m³",
                                                    total_end, sunk, total_start)));
  if (backend != "cpu") return;
  double from = 0.0, into = 0.0;
  for (int component = 0; component < soil_component_count; ++component) {
    from += run.conversions.converted_from(component);
    into += run.conversions.converted_into(component);
  }
  for (std::size_t type = 0; type < start.size() - soil_component_count; ++type) from += run.conversions.bedrock_converted(type);
  result.checks.push_back(bounded_check(
      "ledger.conversions." + backend, std::abs(from - into) / total_start, bound, std::nullopt,
      fmt::format("|converted out of all materials − converted into them| / V: {:.6g} m³ out (bedrock fragmented, "
                  "eroded or turned to soil, rock weathered or broken by water), {:.6g} m³ in",
                  from, into)));
}

// Whether column c's water is broken: a negative or non-finite depth, flux, carried amount or wetness.
bool invalid_water(const LayeredWater<double>& water, std::size_t c) {
  const auto bad = [](double value) { return !std::isfinite(value) || value < 0.0; };
  bool broken = bad(water.water[c]) || bad(water.wetness[c]);
  for (int pipe = 0; pipe < water_pipe_count; ++pipe) broken = broken || bad(water.flux_at(pipe, c));
  for (int kind = 0; kind < carried_kind_count; ++kind) broken = broken || bad(water.carried_at(kind, c));
  return broken;
}

// Columns breaking an invariant of the state (see the header).
std::size_t invalid_columns(const LayeredGround<double>& ground, const LayeredWater<double>* water,
                            double topsoil_max) {
  const double allowance = 64.0 * std::numeric_limits<double>::epsilon() / 2.0;
  std::size_t invalid = 0;
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    bool bad = !std::isfinite(ground.surface[c]) || ground.soil_thickness(0, c) > topsoil_max * (1.0 + allowance);
    for (int layer = 0; layer < soil_layer_count; ++layer) {
      for (int component = 0; component < soil_component_count; ++component) {
        const double thickness = ground.soil_at(layer, component, c);
        bad = bad || !std::isfinite(thickness) || thickness < 0.0;
      }
    }
    for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) {
      bad = bad || !std::isfinite(ground.bedrock_at(layer, c)) || ground.bedrock_at(layer, c) < 0.0;
    }
    bad = bad || (water != nullptr && invalid_water(*water, c));
    invalid += bad ? 1 : 0;
  }
  return invalid;
}

double column_thickness(const LayeredGround<double>& ground, std::size_t c) {
  double thickness = 0.0;
  for (int layer = 0; layer < soil_layer_count; ++layer) thickness += ground.soil_thickness(layer, c);
  for (int layer = 0; layer < ground.bedrock_layer_count; ++layer) thickness += ground.bedrock_at(layer, c);
  return thickness;
}

void add_state_checks(const LayeredRun<double>& run, const LayeredSetup& setup, CaseResult& result) {
  const LayeredGround<double>& start = run.start;
  const LayeredGround<double>& end = run.ground;
  result.checks.push_back(bounded_check(
      "layers.invalid.cpu", double(invalid_columns(end, run.water ? &*run.water : nullptr, setup.params.topsoil_max)),
      0.0, std::nullopt,
      "columns with a negative or non-finite thickness or surface, or a topsoil above topsoil_max·(1 + 64u), or a "
      "negative or non-finite depth, flux, carried amount or wetness"));
  double worst = 0.0, scale = 0.0;
  for (std::size_t c = 0; c < start.cells(); ++c) {
    const double base_start = start.surface[c] - column_thickness(start, c);
    const double base_end = end.surface[c] - column_thickness(end, c);
    worst = std::max(worst, std::abs(base_end - base_start));
    scale = std::max(scale, std::abs(start.surface[c]) + column_thickness(start, c));
  }
  result.checks.push_back(bounded_check(
      "layers.surface.cpu", worst, ledger_bound<double>(setup.steps, material_roundings(setup.params)) * scale,
      std::nullopt,
      "largest change of surface − Σ thicknesses over the columns, m (the surface moves with every layer change)"));
}

// Eq. 3.1 with the depth factor, written apart from the reference's soil_repose: the least repose
// slope over the column's non-empty soil layers; +∞ without soil.
double repose_slope(const LayeredGround<double>& ground, const LayeredParams& params, std::size_t c) {
  double least = std::numeric_limits<double>::infinity();
  for (int layer = 0; layer < soil_layer_count; ++layer) {
    const double thickness = ground.soil_thickness(layer, c);
    if (thickness <= 0.0) continue;
    double mixed = 0.0;
    for (int component = 0; component < soil_component_count; ++component) {
      mixed += params.repose_tan[std::size_t(component)] * ground.soil_at(layer, component, c) / thickness;
    }
    const double vegetation = 1.0 + params.vegetation_repose * ground.vegetation[c];
    least = std::min(least, std::pow(params.depth_factor, layer) * mixed * vegetation);
  }
  return least;
}

void add_repose_check(const LayeredGround<double>& ground, const LayeredParams& params, CaseResult& result) {
  double worst = 0.0;
  for (int y = 0; y < ground.height; ++y) {
    for (int x = 0; x < ground.width; ++x) {
      const std::size_t c = ground.cell(x, y);
      const double repose = repose_slope(ground, params, c);
      if (!std::isfinite(repose)) continue;
      for (int k = 0; k < layered_neighbour_count; ++k) {
        const auto n = layered_neighbour(ground, params.border, x, y, k);
        if (!n) continue;
        const double slope = (ground.surface[c] - ground.surface[*n]) /
                             layered_neighbour_distance(ground.cell_size_x, ground.cell_size_y, k);
        worst = std::max(worst, slope / repose);
      }
    }
  }
  result.checks.push_back(bounded_check(
      "spec.repose.cpu", worst, 1.0, std::nullopt,
      "largest slope to a neighbour over the column's repose slope (eq. 3.1, written apart), columns with soil: "
      "below 1 at rest"));
}

// ---- the GPU twin ---------------------------------------------------------------------------

// The GPU twin (gpu/erosion/layered/) stepped beside ref<float> and compared with it at every ledger
// checkpoint. Error model (gpu/erosion/layered/ground_buffers.hpp, tests/layered_gpu_test.cpp): the
// same float operations in the same order, every division rounded to nearest by gt_div, so every
// stored value is the same float: bound 0 bits. The fragments made are summed per column in float
// on the GPU (up to 8 terms) before the host's double sum, so they may differ from the reference's
// by (γ_7 + 2(N + 1)·2^-53) of the total, N the terms summed (columns × steps).
class GpuShadow {
 public:
  explicit GpuShadow(const LayeredSetup& setup)
      : buffers_(make_layered_ground<float>(setup.surface, setup.profile, setup.params, setup.vegetation), setup.params),
        iteration_(has_water(setup.params)),
        conversions_(no_conversions(setup.params.bedrock_types.size())) {
    if (has_water(setup.params)) {
      water_.emplace(buffers_, make_layered_water<float>(buffers_.shape().cells(), setup.params.initial_water));
    }
  }

  // Steps the GPU to `done` iterations and compares with the reference.
  void compare_at(int done, const LayeredGround<float>& reference, const LayeredWater<float>* reference_water,
                  const LayeredConversions& converted) {
    stepping_ms_ += gpu_wall_ms([&] {
      for (; steps_ < done; ++steps_) {
        iteration_.step(buffers_, static_cast<std::uint32_t>(steps_), conversions_, water_ ? &*water_ : nullptr);
      }
    });
    state_ = buffers_.download();
    const LayeredGround<float>& state = state_;
    std::size_t differing = differing_bits(state.surface, reference.surface) + differing_bits(state.soil, reference.soil) +
                            differing_bits(state.bedrock, reference.bedrock) +
                            differing_bits(state.vegetation, reference.vegetation);
    if (water_ && reference_water) {
      const LayeredWater<float> water = water_->download();
      for (const auto member : {&LayeredWater<float>::water, &LayeredWater<float>::previous_water,
                                &LayeredWater<float>::water_flux, &LayeredWater<float>::carried,
                                &LayeredWater<float>::wetness}) {
        differing += differing_bits(water.*member, reference_water->*member);
      }
    }
    differing += conversions_differing(converted, reference.cells() * static_cast<std::size_t>(done));
    if (differing > 0 && first_differing_ < 0) first_differing_ = done;
    differing_ += differing;
    ++checkpoints_;
  }

  // The GPU's time is its stepping between the checkpoints (each step reads its conversions back;
  // the checkpoints' downloads are left out).
  const LayeredGround<float>& last_state() const { return state_; }

  void add_checks(CaseResult& result) const {
    result.timings.gpu_ms = stepping_ms_;
    result.timings.gpu_reps = 1;
    result.checks.push_back(bounded_check(
        "parity.state.gpu_vs_float", double(differing_), 0.0, std::nullopt,
        fmt::format("values (surface, soil components, bedrock, vegetation; water, flux, carried material, "
                    "wetness) differing in any bit from ref<float>'s, plus conversion totals beyond their bound, over "
                    "{} checkpoints{}",
                    checkpoints_, first_differing_ < 0 ? std::string() : fmt::format("; first at step {}", first_differing_))));
  }

 private:
  static std::size_t differing_bits(const std::vector<float>& a, const std::vector<float>& b) {
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += std::bit_cast<std::uint32_t>(a[i]) == std::bit_cast<std::uint32_t>(b[i]) ? 0 : 1;
    return differing;
  }

  std::size_t conversions_differing(const LayeredConversions& reference, std::size_t terms) const {
    const double u = 0x1p-24, gamma7 = 7.0 * u / (1.0 - 7.0 * u);
    std::size_t differing = 0;
    for (std::size_t type = 0; type < reference.fragmented_from.size(); ++type) {
      differing += conversions_.fragmented_from[type] == reference.fragmented_from[type] ? 0 : 1;
    }
    // Weathering and soil formation: per-column floats the host adds in the reference's order.
    const auto exact = [&](const auto& gpu, const auto& cpu) {
      for (std::size_t i = 0; i < cpu.size(); ++i) differing += gpu[i] == cpu[i] ? 0 : 1;
    };
    exact(conversions_.weathered_from, reference.weathered_from);
    exact(conversions_.weathered_into, reference.weathered_into);
    exact(conversions_.soil_formed_from, reference.soil_formed_from);
    exact(conversions_.soil_formed_into, reference.soil_formed_into);
    // Force erosion and the sinks: per-column floats too (tests/layered_water_gpu_test.cpp).
    exact(conversions_.broken_from, reference.broken_from);
    exact(conversions_.broken_into, reference.broken_into);
    exact(conversions_.bedrock_eroded_from, reference.bedrock_eroded_from);
    exact(conversions_.bedrock_eroded_into, reference.bedrock_eroded_into);
    exact(conversions_.sunk, reference.sunk);
    differing += conversions_.water_added == reference.water_added ? 0 : 1;
    differing += conversions_.water_sunk == reference.water_sunk ? 0 : 1;
    for (std::size_t size = 0; size < reference.fragmented_into.size(); ++size) {
      const double bound = (gamma7 + 2.0 * double(terms + 1) * 0x1p-53) * reference.fragmented_into[size];
      differing += std::abs(conversions_.fragmented_into[size] - reference.fragmented_into[size]) <= bound ? 0 : 1;
    }
    return differing;
  }

  gpu::LayeredGroundBuffers buffers_;
  std::optional<gpu::LayeredWaterBuffers> water_;
  gpu::LayeredIteration iteration_;
  LayeredConversions conversions_;
  LayeredGround<float> state_;  // as downloaded at the last checkpoint
  int steps_ = 0;
  std::size_t differing_ = 0;
  int first_differing_ = -1;
  int checkpoints_ = 0;
  double stepping_ms_ = 0.0;
};

// ---- pictures -------------------------------------------------------------------------------

using Colour = LayeredColour;

// The middle row: above, the surface's elevation (grey ground under white air, its range stretched
// to the panel); below, a dark rule, then the layers from the surface down to 1.2 times the deepest
// soil plus soft rock of the row, true to scale in depth.
void write_cross_section(const LayeredGround<double>& ground, const std::filesystem::path& png, double& depth_shown) {
  constexpr int elevation_rows = 120, rule_rows = 3, layer_rows = 240;
  const int row = ground.height / 2;
  const int scale = std::max(1, 720 / ground.width);
  const int width = ground.width * scale;
  double low = std::numeric_limits<double>::infinity(), high = -low, deepest = 0.0;
  for (int x = 0; x < ground.width; ++x) {
    const std::size_t c = ground.cell(x, row);
    low = std::min(low, ground.surface[c]);
    high = std::max(high, ground.surface[c]);
    double soft = ground.soil_thickness(0, c) + ground.soil_thickness(1, c);
    if (ground.bedrock_layer_count > 0) soft += ground.bedrock_at(0, c);
    deepest = std::max(deepest, soft);
  }
  depth_shown = std::max(1.2 * deepest, 1.0);
  const double span = std::max(high - low, 1e-9);
  std::vector<Colour> pixels(std::size_t(width) * (elevation_rows + rule_rows + layer_rows));
  for (int px = 0; px < width; ++px) {
    const std::size_t c = ground.cell(px / scale, row);
    const double ground_rows = 8.0 + (elevation_rows - 16.0) * (ground.surface[c] - low) / span;
    for (int py = 0; py < elevation_rows; ++py) {
      const bool below = elevation_rows - py <= ground_rows;
      pixels[std::size_t(py) * width + px] = below ? layered_surface_colour(ground, c) : Colour{1, 1, 1};
    }
    for (int py = elevation_rows; py < elevation_rows + rule_rows; ++py) pixels[std::size_t(py) * width + px] = {0.1f, 0.1f, 0.1f};
    for (int py = 0; py < layer_rows; ++py) {
      const double depth = (py + 0.5) / layer_rows * depth_shown;
      pixels[std::size_t(elevation_rows + rule_rows + py) * width + px] = layered_colour_at_depth(ground, c, depth);
    }
  }
  write_colour_image(width, elevation_rows + rule_rows + layer_rows, pixels, png);
}

// The surface as every erosion algorithm hands its terrain back (field `terrain`): as given, and after
// the run from each backend that ran.
template <class Real>
Grid<double> surface_grid(const LayeredGround<Real>& ground) {
  Grid<double> grid(ground.width, ground.height);
  grid.cell_size_x = ground.cell_size_x;
  grid.cell_size_y = ground.cell_size_y;
  for (std::size_t c = 0; c < ground.cells(); ++c) grid.values[c] = static_cast<double>(ground.surface[c]);
  return grid;
}

void write_terrain_fields(const LayeredSetup& setup, const LayeredGround<double>& cpu, const LayeredGround<float>& single,
                          const LayeredGround<float>* gpu, const RunOptions& options, CaseResult& result) {
  write_field_files(setup.surface, {"terrain_input", "terrain", "input", "m", "the surface as given"}, options, result);
  write_field_files(surface_grid(cpu), {"terrain_cpu", "terrain", "cpu", "m", "surface after the run, ref<double>"},
                    options, result);
  write_field_files(surface_grid(single),
                    {"terrain_cpu_float", "terrain", "cpu_float", "m", "surface after the run, ref<float>"}, options,
                    result);
  if (gpu) {
    write_field_files(surface_grid(*gpu), {"terrain_gpu", "terrain", "gpu", "m", "surface after the run, the GPU twin"},
                      options, result);
  }
}

// The material masks (§3.17, reference/erosion/layered/material_masks.hpp) as fields `mask_<material>`
// and one picture: a panel per material, left to right, each mask from black (0) to the material's
// colour (1).
void write_material_masks(const LayeredGround<double>& ground, const LayeredParams& params, const RunOptions& options,
                          CaseResult& result) {
  const std::size_t materials = soil_component_count + params.bedrock_types.size();
  std::vector<Grid<double>> masks(materials, Grid<double>(ground.width, ground.height));
  for (std::size_t c = 0; c < ground.cells(); ++c) {
    const auto column = reference::material_masks(ground, params, c);
    for (std::size_t m = 0; m < materials; ++m) masks[m].values[c] = column[m];
  }
  constexpr int gap = 2;
  const int scale = std::max(1, 240 / std::max(ground.width, ground.height));
  const int panel = ground.width * scale;
  const int width = int(materials) * (panel + gap) - gap;
  std::vector<Colour> pixels(std::size_t(width) * std::size_t(ground.height * scale), Colour{1, 1, 1});
  for (std::size_t m = 0; m < materials; ++m) {
    auto& mask = masks[m];
    mask.cell_size_x = ground.cell_size_x;
    mask.cell_size_y = ground.cell_size_y;
    const Colour colour = m < soil_component_count ? layered_component_colour(int(m))
                                                   : layered_bedrock_colour(int(m - soil_component_count));
    for (int py = 0; py < ground.height * scale; ++py) {
      for (int px = 0; px < panel; ++px) {
        const auto value = float(mask.values[ground.cell(px / scale, py / scale)]);
        Colour& pixel = pixels[std::size_t(py) * std::size_t(width) + std::size_t(int(m) * (panel + gap) + px)];
        for (int channel = 0; channel < 3; ++channel) pixel[channel] = value * colour[channel];
      }
    }
    const std::string name = material_name(m);
    std::string key = "mask_" + name;
    std::replace(key.begin(), key.end(), ' ', '_');
    write_field_files(mask, {key, key, "cpu", "1", fmt::format("share of the surface showing {} (§3.17), ref<double>", name)},
                      options, result);
  }
  const auto folder = options.report_dir / result.name;
  write_colour_image(width, ground.height * scale, pixels, folder / "material_masks.png");
  std::string order;
  for (std::size_t m = 0; m < materials; ++m) order += (m ? ", " : "") + material_name(m);
  result.artifacts.push_back(
      {result.name + "/material_masks.png", "image",
       fmt::format("material masks after the run with the thesis's transparency (§3.17: a layer thinner than "
                   "K_pmin lets the one below show), a panel per material from black (0) to its colour (1): {}",
                   order)});
}

void write_pictures(const LayeredGround<double>& ground, const LayeredRun<double>& run, const LayeredParams& params,
                    const RunOptions& options, CaseResult& result) {
  const auto field = [&](auto value) {
    Grid<double> grid(ground.width, ground.height);
    grid.cell_size_x = ground.cell_size_x;
    grid.cell_size_y = ground.cell_size_y;
    for (std::size_t c = 0; c < ground.cells(); ++c) grid.values[c] = value(c);
    return grid;
  };
  const auto folder = options.report_dir / result.name;
  std::filesystem::create_directories(folder);
  std::vector<Colour> surface;
  for (std::size_t c = 0; c < ground.cells(); ++c) surface.push_back(layered_surface_colour(ground, c));
  // Each cell a square of pixels, so a small grid is still readable.
  const int scale = std::max(1, 512 / ground.width);
  std::vector<Colour> pixels;
  for (int py = 0; py < ground.height * scale; ++py) {
    for (int px = 0; px < ground.width * scale; ++px) pixels.push_back(surface[ground.cell(px / scale, py / scale)]);
  }
  write_colour_image(ground.width * scale, ground.height * scale, pixels, folder / "surface_material.png");
  result.artifacts.push_back({result.name + "/surface_material.png", "image",
                              "surface material after the run, ref<double> (a cell a square of pixels): the top non-empty layer's mixture (organic "
                              "dark brown, sand pale yellow, gravel light grey, stones grey, boulders slate; bedrock: "
                              "soft rock red, hard rock dark grey), greened by 35 % of the vegetation density"});
  write_material_masks(ground, params, options, result);
  double depth_shown = 0.0;
  write_cross_section(ground, folder / "cross_section.png", depth_shown);
  result.artifacts.push_back(
      {result.name + "/cross_section.png", "image",
       fmt::format("cross-section along row {} after the run: above, the surface (elevation stretched to the panel); "
                   "below, the layers from the surface down to {:.3g} m, true to scale in depth (topsoil, the subsoil "
                   "darker, soft rock red, hard rock grey; colours as the surface material)",
                   ground.height / 2, depth_shown)});
  write_field_files(field([&](std::size_t c) { return ground.soil_thickness(0, c); }),
                    {"topsoil_cpu", "topsoil", "cpu", "m", "topsoil thickness after the run, ref<double>"}, options,
                    result);
  write_field_files(field([&](std::size_t c) { return ground.soil_thickness(1, c); }),
                    {"subsoil_cpu", "subsoil", "cpu", "m", "subsoil thickness after the run, ref<double>"}, options,
                    result);
  write_field_files(field([&](std::size_t c) { return ground.vegetation[c]; }),
                    {"vegetation_cpu", "vegetation", "cpu", "1", "vegetation density after the run, ref<double>"},
                    options, result);
  if (run.water) {
    const LayeredWater<double>& water = *run.water;
    write_field_files(field([&](std::size_t c) { return water.water[c]; }),
                      {"water_cpu", "water", "cpu", "m", "water depth after the run, ref<double>"}, options, result);
    write_field_files(field([&](std::size_t c) { return water.wetness[c]; }),
                      {"wetness_cpu", "wetness", "cpu", "m·s", "wetness after the run (eq. 3.12), ref<double>"}, options,
                      result);
    write_field_files(field([&](std::size_t c) {
                        double carried = 0.0;
                        for (int kind = 0; kind < carried_kind_count; ++kind) carried += water.carried_at(kind, c);
                        return carried;
                      }),
                      {"carried_cpu", "carried", "cpu", "m",
                       "material the water carries after the run (suspended and regolith, all sizes), ref<double>"},
                      options, result);
  }
  double total = 0.0;
  for (const double volume : run.volumes.front()) total += volume;
  SeriesPlot changes{"each material's volume", "step", "(V − V_start) / V_all", false, false, {}};
  for (std::size_t material = 0; material < run.volumes.front().size(); ++material) {
    Series series{material_name(material), {}, {}, false, {}};
    for (std::size_t point = 0; point < run.checkpoints.size(); ++point) {
      series.x.push_back(run.checkpoints[point]);
      series.y.push_back((run.volumes[point][material] - run.volumes.front()[material]) / total);
    }
    changes.series.push_back(series);
  }
  SeriesPlot drift{"ledger drift", "step", "|V − V_start − converted| / V_all", false, false, {}};
  for (std::size_t material = 0; material < run.volumes.front().size(); ++material) {
    Series series{material_name(material), {}, {}, false, {}};
    for (std::size_t point = 0; point < run.checkpoints.size(); ++point) {
      series.x.push_back(run.checkpoints[point]);
      series.y.push_back(std::abs(run.volumes[point][material] - run.volumes.front()[material] -
                                  run.converted[point][material]) / total);
    }
    drift.series.push_back(series);
  }
  attach_plot({changes, drift}, options.report_dir, "ledger.png",
              "the ledger per material over the steps, ref<double>: each material's volume change (fragmentation turns "
              "bedrock into sand..boulders) and what the ledger cannot account for",
              result);
}

// ---- the case -------------------------------------------------------------------------------

void run_layered_case(const LayeredSetup& setup, const nlohmann::json& expect, const RunOptions& options,
                      CaseResult& result) {
  if (options.progress) options.progress->stage("CPU reference (double)");
  LayeredRun<double> run;
  time_cpu(1, [&] { run = run_layered<double>(setup); }, result.timings);
  add_ledger_checks(run, setup, "cpu", result);
  add_state_checks(run, setup, result);
  if (run.water) {
    const double stable = 1.0 / std::sqrt(2.0);
    result.checks.push_back(informative_check(
        "spec.courant.cpu", run.largest_courant,
        fmt::format("the pipe flow's wave Courant number Δt·sqrt(g·w_max)/min(l) at its largest over the checkpoints; "
                    "the explicit flux update is stable for C ≤ 1/√2 = {:.3f}", stable)));
    if (run.largest_courant > stable) {
      result.notes.push_back(fmt::format(
          "warning: the Courant number reached {:.3g} > 1/√2: the water oscillates between columns (a checkerboard); "
          "a time_step below {:.3g} s keeps it stable at this depth",
          run.largest_courant, setup.params.time_step * stable / run.largest_courant));
    }
  }
  if (expect.is_object() && expect.value("at_rest", false)) add_repose_check(run.ground, setup.params, result);
  std::optional<GpuShadow> shadow;
  if (options.gpu_available) shadow.emplace(setup);
  if (options.progress) options.progress->stage(shadow ? "CPU reference (float) and the GPU beside it" : "CPU reference (float)");
  const LayeredRun<float> single = run_layered<float>(
      setup, shadow ? CheckpointObserver<float>([&](int done, const LayeredGround<float>& ground,
                                                   const LayeredWater<float>* water,
                                                   const LayeredConversions& conversions) {
        shadow->compare_at(done, ground, water, conversions);
      })
                    : CheckpointObserver<float>());
  if (shadow) {
    shadow->add_checks(result);
  } else {
    result.checks.push_back(skipped_check("parity.state.gpu_vs_float", options.gpu_unavailable_reason));
  }
  add_ledger_checks(single, setup, "cpu_float", result);
  double largest = 0.0;
  for (std::size_t c = 0; c < run.ground.cells(); ++c) {
    largest = std::max(largest, std::abs(double(single.ground.surface[c]) - run.ground.surface[c]));
  }
  result.checks.push_back(informative_check("parity.surface.float_vs_double", largest,
                                            "largest |surface_float − surface_double| over the columns, m"));
  if (options.report_dir.empty()) return;
  write_pictures(run.ground, run, setup.params, options, result);
  write_terrain_fields(setup, run.ground, single.ground, shadow ? &shadow->last_state() : nullptr, options, result);
}

PreparedTwin prepare_layered(const nlohmann::json& resolved, const LoadedInput& input) {
  const LayeredSetup setup = layered_setup(resolved, input.heights);
  PreparedTwin prepared;
  prepared.kind = CaseRun([setup](const nlohmann::json& expect, const RunOptions& options, CaseResult& result) {
    result.notes.push_back(fmt::format(
        "initial profile in every column, top down: {} m topsoil and {} m subsoil of {}, {} m soft rock (type 0), "
        "{} m hard rock (type 1); vegetation {}",
        std::accumulate(setup.profile.topsoil.begin(), setup.profile.topsoil.end(), 0.0),
        std::accumulate(setup.profile.subsoil.begin(), setup.profile.subsoil.end(), 0.0), setup.soil,
        setup.profile.bedrock[0].thickness, setup.profile.bedrock[1].thickness, setup.vegetation));
    const LayeredParams& params = setup.params;
    result.notes.push_back(
        has_water(params)
            ? fmt::format("water: {} m on every column at the start, rain {} m/s{}; the water processes run each step "
                          "(pipe flow, force erosion, dissolution with K_r = {} m, wetness and the flood death)",
                          params.initial_water, params.rain_rate,
                          params.river ? fmt::format(", the river: {} m held at column ({}, {}), rows y >= {} a sink",
                                                     params.river_depth, setup.surface.width / 2,
                                                     setup.surface.height / 16, (15 * setup.surface.height + 15) / 16)
                                       : std::string(),
                          params.regolith_depth)
            : "no water given (initial_water, rain_rate and river all off): the water processes do not run");
    run_layered_case(setup, expect, options, result);
  });
  return prepared;
}

// ---- performance ----------------------------------------------------------------------------

// Šťava et al. 2008 (issue 14): at least 20 frames per second at 2048×1024 with 4 layers on the
// GPU of 2008, one erosion step a frame: at most 50 ms a step. Other work (their layers are
// (material, thickness) pairs under water erosion), named for scale.
BenchmarkRow published_layered_row() {
  BenchmarkRow row{.algorithm = "erosion.layered", .backend = "published", .size = 2048, .iterations = 1, .reps = 1,
                   .median_ms = 50.0, .device = "Šťava et al. 2008 (GPU of 2008)", .dimensions = 2};
  row.mcell_iterations_per_s = 2048.0 * 1024.0 / 0.05 / 1e6;
  row.detail = "≥ 20 fps at 2048×1024 cells (not 2048²), 4 layers, water erosion: other work, as published";
  return row;
}

// `iterations` iterations on a noisy cone under the default loam profile, without water and with
// rain; the CPU in ref<double>, the GPU as the case runs it (creep and talus: a snapshot
// copy, an outflow and the apply pass each; vegetation two passes, weathering one; the conversions
// read back after each process).
std::vector<BenchmarkRow> benchmark_layered(const BenchmarkOptions& options, bool gpu_available,
                                            const Environment& environment) {
  std::vector<BenchmarkRow> rows{published_layered_row()};
  const int steps = std::max(1, std::min(options.iterations, 4));
  // The processes without water, then the whole model under rain (backends suffixed "+water").
  struct Variant {
    std::string suffix;
    nlohmann::json overrides;
    std::string cpu_detail, gpu_detail;
  };
  const std::vector<Variant> variants{
      {"", {{"steps", steps}}, "creep, talus, vegetation, weathering; ref<double>, one thread",
       "9 passes an iteration (creep and talus: snapshot copy, outflow, apply; vegetation 2; weathering 1) and the "
       "conversions read back after each process"},
      {"+water", {{"steps", steps}, {"rain_rate", 0.01}},
       "the whole model under rain 0.01 m/s (sources, creep, talus, flow, force erosion, dissolution, wetness, "
       "vegetation, weathering); ref<double>, one thread",
       "17 passes an iteration (the 9 above; sources 1; flow: flux, snapshot copy, move; force erosion: surface copy "
       "and its pass; dissolution 1; wetness 1) and the conversions read back after each process"}};
  for (const int size : options.sizes) {
    const nlohmann::json cone = {{"generator", "cone"}, {"width", size}, {"height", size}, {"cell_size", 1.0},
                                 {"peak", 0.2 * size}, {"noise", 1.0}, {"seed", 7}};
    const Heightmap surface = load_input(cone, nullptr, {}).heights;
    for (const Variant& variant : variants) {
      const auto resolved = resolve_params("erosion.layered", layered_case_param_specs(), variant.overrides);
      const LayeredSetup setup = layered_setup(resolved, surface);
      const bool wet = has_water(setup.params);
      const auto row = [&](const std::string& backend, const std::vector<double>& times, const std::string& device,
                           const std::string& detail) {
        BenchmarkRow timed{.algorithm = "erosion.layered", .backend = backend + variant.suffix, .size = size,
                           .iterations = steps, .reps = options.reps, .median_ms = median(times), .device = device,
                           .dimensions = 2};
        timed.mcell_iterations_per_s = double(size) * size * steps / (timed.median_ms * 1e-3) / 1e6;
        timed.detail = fmt::format("{:.1f} ms a step; {}", timed.median_ms / steps, detail);
        return timed;
      };
      std::vector<double> cpu_times;
      for (int rep = 0; rep < options.reps; ++rep) {
        auto ground = make_layered_ground<double>(setup.surface, setup.profile, setup.params, 0.0);
        std::optional<LayeredWater<double>> water;
        if (wet) water = make_layered_water<double>(ground.cells(), 0.0);
        auto conversions = no_conversions(setup.params.bedrock_types.size());
        cpu_times.push_back(cpu_wall_ms([&] {
          for (int step = 0; step < steps; ++step) {
            reference::layered_iteration(ground, setup.params, std::uint32_t(step), conversions, water ? &*water : nullptr);
          }
        }));
      }
      rows.push_back(row("cpu", cpu_times, environment.cpu, variant.cpu_detail));
      if (!gpu_available) continue;
      const auto start = make_layered_ground<float>(setup.surface, setup.profile, setup.params, 0.0);
      const auto start_water = make_layered_water<float>(start.cells(), 0.0);
      gpu::LayeredGroundBuffers buffers(start, setup.params);
      std::optional<gpu::LayeredWaterBuffers> water;
      if (wet) water.emplace(buffers, start_water);
      const gpu::LayeredIteration iteration(wet);
      std::vector<double> gpu_times;
      for (int rep = 0; rep < options.reps; ++rep) {
        // Every rep from the start ground, as the CPU's: the upload is done before gpu_wall_ms's first
        // glFinish, so it stays out of the time.
        if (rep > 0) {
          buffers.upload(start);
          if (water) water->upload(start_water);
        }
        auto conversions = no_conversions(setup.params.bedrock_types.size());
        gpu_times.push_back(gpu_wall_ms([&] {
          for (int step = 0; step < steps; ++step) {
            iteration.step(buffers, std::uint32_t(step), conversions, water ? &*water : nullptr);
          }
        }));
      }
      rows.push_back(row("gpu", gpu_times, environment.gl_renderer, variant.gpu_detail));
    }
  }
  return rows;
}

}  // namespace

Algorithm layered_algorithm() {
  return {.name = "erosion.layered",
          .summary = "seed 001's layered ground: soil–rock layers over bedrock, creep and per-material talus, "
                     "vegetation and weathering, and with water the pipe flow, force, impact and dissolution erosion; a "
                     "ledger per material",
          .source = "seed 001 §3.1, §3.3–3.5, §3.10–3.17, §3.19, §4 (eq. 2.1–2.7, 3.1–3.12)",
          .params = &layered_case_param_specs(),
          .prepare = prepare_layered,
          .kind = CaseKind::custom,
          .benchmark = benchmark_layered,
          .expect_shape = {{"at_rest", true}},
          // The double state (5·2 components, 2 bedrock layers, types, surface, vegetation: ~112 B),
          // its snapshot each step and its start copy, 8 outflows (64 B), the float run's half of all
          // that, the pictures' grids: under 700 B a cell; 1000 kept. With water, the water's state
          // (14 values: 112 B in double, 56 in float, on the GPU twice over), the flow's copies of it
          // and its fractions (~150 B), impact erosion's pipe loads (20 values: 160 B), the material
          // masks' grids (8 × 8 B): about 700 B more; 1800 kept.
          .memory = [](const nlohmann::json& resolved, const LoadedInput& input) {
            const bool wet = resolved.value("initial_water", 0.0) > 0.0 || resolved.value("rain_rate", 0.0) > 0.0 ||
                             resolved.value("river", false);
            return memory_for(static_cast<double>(input.heights.size()), "cells", wet ? 1800 : 1000);
          }};
}

}  // namespace gt
